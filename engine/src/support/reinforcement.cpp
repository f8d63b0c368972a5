// Local reinforcement across joints in the cycle: anchors, element forces, their resultants.
#include "tessera/support/reinforcement.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/cables.hpp"
#include "tessera/support/liners.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {
Vec2 rotated(Vec2 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
// a - b wrapped into (-pi, pi].
double angle_between(double a, double b) {
  return std::remainder(a - b, 2.0 * M_PI);
}
}  // namespace

size_t Reinforcement::add(Bolt b, const std::vector<std::array<Anchor2, 2>>& sides, Vec2 axis) {
  b.first = static_cast<uint32_t>(size());
  b.count = static_cast<uint32_t>(sides.size());
  for (const auto& s : sides) {
    bolt.push_back(static_cast<uint32_t>(bolts.size()));
    side_a.push_back(s[0]), side_b.push_back(s[1]);
    axis0.push_back(axis);
    axial.push_back(0.0), shear.push_back(0.0), ua.push_back(0.0), us.push_back(0.0);
    state.push_back(0);
    point.push_back(Vec2::Zero()), force.push_back(Vec2::Zero());
  }
  bolts.push_back(std::move(b));
  return bolts.size() - 1;
}

Vec2 anchor_position(const Model& m, const Anchor2& p) {
  if (p.node[0] >= 0) {
    const Continuum& c = m.continuum;
    Vec2 x = Vec2::Zero();
    for (int k = 0; k < 3; ++k) x += p.w[k] * c.pos[static_cast<size_t>(p.node[k])];
    return x;
  }
  const Blocks& B = m.blocks;
  const auto b = static_cast<size_t>(p.block);
  return Vec2(B.x[b], B.y[b]) + rotated(Vec2(p.local[0], p.local[1]), B.theta[b]);
}

Vec2 anchor_velocity(const Model& m, const Anchor2& p) {
  if (p.node[0] >= 0) {
    const Continuum& c = m.continuum;
    Vec2 v = Vec2::Zero();
    for (int k = 0; k < 3; ++k) v += p.w[k] * c.vel[static_cast<size_t>(p.node[k])];
    return v;
  }
  const Blocks& B = m.blocks;
  const auto b = static_cast<size_t>(p.block);
  const Vec2 r = rotated(Vec2(p.local[0], p.local[1]), B.theta[b]);
  return {B.vx[b] - B.omega[b] * r.y(), B.vy[b] + B.omega[b] * r.x()};
}

double anchor_angle(const Model& m, const Anchor2& p) {
  if (p.node[0] >= 0) {
    const Continuum& c = m.continuum;
    const Vec2 e = c.pos[static_cast<size_t>(p.node[1])] - c.pos[static_cast<size_t>(p.node[0])];
    return std::atan2(e.y(), e.x());
  }
  return m.blocks.theta[static_cast<size_t>(p.block)];
}

Anchor2 make_anchor(const Model& m, size_t b, Vec2 p) {
  Anchor2 a;
  a.block = static_cast<int32_t>(b);
  const Blocks& B = m.blocks;
  if (!B.deformable[b]) {
    const Vec2 l = rotated(p - Vec2(B.x[b], B.y[b]), -B.theta[b]);
    a.local = {l.x(), l.y()};
    a.angle0 = B.theta[b];
    return a;
  }
  // The zone of this block holding p (or, on its outline, the nearest by its weights).
  const Continuum& c = m.continuum;
  const std::vector<int> owner = node_owners(m);
  double best = -1e300;
  for (size_t z = 0; z < c.zone_count(); ++z) {
    const auto& t = c.zones[z];
    const Vec2 p0 = c.pos[t[0]], p1 = c.pos[t[1]], p2 = c.pos[t[2]];
    const double area = cross(p1 - p0, p2 - p0);
    if (!(area > 0.0)) continue;
    const double w1 = cross(p - p0, p2 - p0) / area, w2 = cross(p1 - p0, p - p0) / area;
    const double w0 = 1.0 - w1 - w2, worst = std::min({w0, w1, w2});
    if (worst <= best || worst < -1e-6) continue;
    // Zones of other blocks are skipped.
    bool other = false;
    for (uint32_t n : t) other |= owner[n] >= 0 && owner[n] != static_cast<int>(b);
    if (other) continue;
    best = worst;
    a.node = {static_cast<int32_t>(t[0]), static_cast<int32_t>(t[1]), static_cast<int32_t>(t[2])};
    a.w = {w0, w1, w2};
  }
  if (a.node[0] < 0)
    throw ModelError("no zone of " + m.block_label(b) + " holds the point (" +
                     std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")");
  a.angle0 = anchor_angle(m, a);
  return a;
}

std::vector<BoltPoint> bolt_path(const Model& m, size_t bolt) {
  const Reinforcement& R = m.support;
  const Bolt& b = R.bolts[bolt];
  std::vector<BoltPoint> path{{anchor_position(m, b.end0), -1}};
  for (uint32_t e = b.first; e < b.first + b.count; ++e)
    path.push_back({0.5 * (anchor_position(m, R.side_a[e]) + anchor_position(m, R.side_b[e])),
                    static_cast<int32_t>(e)});
  path.push_back({anchor_position(m, b.end1), -1});
  return path;
}

void update_reinforcement(Model& m) {
  Reinforcement& R = m.support;
  const double dt = m.dt;
  for (size_t e = 0; e < R.size(); ++e) {
    const BoltProperties& p = R.bolts[R.bolt[e]].props;
    const Anchor2 &a = R.side_a[e], &b = R.side_b[e];
    R.point[e] = 0.5 * (anchor_position(m, a) + anchor_position(m, b));
    if (R.state[e] & kBoltBroken) {
      R.force[e].setZero();
      continue;
    }
    // The axis turns with the mean rotation of the rock on both sides.
    const double turn = 0.5 * (angle_between(anchor_angle(m, a), a.angle0) +
                               angle_between(anchor_angle(m, b), b.angle0));
    const Vec2 t = rotated(R.axis0[e], turn), n = perp(t);
    const Vec2 du = dt * (anchor_velocity(m, b) - anchor_velocity(m, a));
    const double dua = du.dot(t), dus = du.dot(n);
    R.ua[e] += dua, R.us[e] += dus;
    // Incremental springs, each capped at its yield force.
    double fa = R.axial[e] + p.ka * dua, fs = R.shear[e] + p.ks * dus;
    uint8_t st = 0;
    if (p.tension > 0.0 && fa > p.tension) fa = p.tension, st |= kBoltAxialYield;
    if (p.compression > 0.0 && fa < -p.compression) fa = -p.compression, st |= kBoltAxialYield;
    if (p.shear > 0.0 && std::abs(fs) > p.shear)
      fs = std::copysign(p.shear, fs), st |= kBoltShearYield;
    if (p.rupture > 0.0 && R.ua[e] > p.rupture) fa = 0.0, fs = 0.0, st = kBoltBroken;
    R.axial[e] = fa, R.shear[e] = fs, R.state[e] = st;
    // Tension pulls side b back towards a: the force on a is along +t.
    R.force[e] = fa * t + fs * n;
  }
}

void add_reinforcement_forces(Model& m) {
  const Reinforcement& R = m.support;
  Blocks& B = m.blocks;
  // In element order, one thread: the sums are the same at every thread count.
  for (size_t e = 0; e < R.size(); ++e) {
    const Vec2 f = R.force[e];
    const double mag = f.norm();
    for (int side = 0; side < 2; ++side) {
      const Anchor2& a = side ? R.side_b[e] : R.side_a[e];
      if (a.node[0] >= 0) continue;
      const auto b = static_cast<size_t>(a.block);
      const Vec2 fb = side ? Vec2(-f) : f;
      const Vec2 r = R.point[e] - Vec2(B.x[b], B.y[b]);
      B.fx[b] += fb.x(), B.fy[b] += fb.y(), B.moment[b] += cross(r, fb);
      B.applied[b] += mag;
    }
  }
  // Cable nodes' pull on rigid hosts, in node order.
  const Cables& K = m.cables;
  for (size_t i = 0; i < K.size(); ++i) {
    const Anchor2& a = K.host[i];
    if (a.node[0] >= 0) continue;
    const auto b = static_cast<size_t>(a.block);
    const Vec2 f = K.host_force[i], r = K.pos[i] - Vec2(B.x[b], B.y[b]);
    B.fx[b] += f.x(), B.fy[b] += f.y(), B.moment[b] += cross(r, f);
    B.applied[b] += f.norm();
  }
  // Liner nodes' push on rigid hosts, in node order.
  const Liners& L = m.liners;
  for (size_t i = 0; i < L.size(); ++i) {
    const Anchor2& a = L.host[i];
    if (a.node[0] >= 0) continue;
    const auto b = static_cast<size_t>(a.block);
    const Vec2 f = L.host_force[i], r = anchor_position(m, a) - Vec2(B.x[b], B.y[b]);
    B.fx[b] += f.x(), B.fy[b] += f.y(), B.moment[b] += cross(r, f);
    B.applied[b] += f.norm();
  }
}

void add_reinforcement_forces_to_nodes(Model& m) {
  const Reinforcement& R = m.support;
  Continuum& c = m.continuum;
  for (size_t e = 0; e < R.size(); ++e)
    for (int side = 0; side < 2; ++side) {
      const Anchor2& a = side ? R.side_b[e] : R.side_a[e];
      if (a.node[0] < 0) continue;
      const Vec2 f = side ? Vec2(-R.force[e]) : R.force[e];
      for (int k = 0; k < 3; ++k) add_node_force(c, static_cast<size_t>(a.node[k]), a.w[k] * f);
    }
  const Cables& K = m.cables;
  for (size_t i = 0; i < K.size(); ++i) {
    const Anchor2& a = K.host[i];
    for (int k = 0; a.node[0] >= 0 && k < 3; ++k)
      add_node_force(c, static_cast<size_t>(a.node[k]), a.w[k] * K.host_force[i]);
  }
  const Liners& L = m.liners;
  for (size_t i = 0; i < L.size(); ++i) {
    const Anchor2& a = L.host[i];
    for (int k = 0; a.node[0] >= 0 && k < 3; ++k)
      add_node_force(c, static_cast<size_t>(a.node[k]), a.w[k] * L.host_force[i]);
  }
}

std::vector<double> reinforcement_stiffness(const Model& m) {
  const Reinforcement& R = m.support;
  std::vector<double> k(m.blocks.size(), 0.0);
  for (size_t e = 0; e < R.size(); ++e) {
    const BoltProperties& p = R.bolts[R.bolt[e]].props;
    for (const Anchor2* a : {&R.side_a[e], &R.side_b[e]})
      k[static_cast<size_t>(a->block)] += std::max(p.ka, p.ks);
  }
  const Cables& K = m.cables;
  for (size_t i = 0; i < K.size(); ++i)
    k[static_cast<size_t>(K.host[i].block)] += cable_host_stiffness(m.cables, i);
  for (size_t i = 0; i < m.liners.size(); ++i)
    k[static_cast<size_t>(m.liners.host[i].block)] += liner_host_stiffness(m, i);
  return k;
}

bool follow_anchor(Anchor2& a, const std::vector<int>& map, const std::vector<int64_t>& node_map) {
  if (a.block < 0 || map[static_cast<size_t>(a.block)] < 0) return false;
  a.block = map[static_cast<size_t>(a.block)];
  return renumber_nodes(a.node, node_map);
}

void remap_reinforcement(Model& m, const std::vector<int>& map,
                         const std::vector<int64_t>& node_map) {
  Reinforcement& R = m.support;
  if (R.empty()) return;
  auto follow = [&](Anchor2& a) { return follow_anchor(a, map, node_map); };
  Reinforcement kept;
  std::vector<int32_t> element_map(R.size(), -1);
  for (size_t i = 0; i < R.bolts.size(); ++i) {
    Bolt b = R.bolts[i];
    std::vector<std::array<Anchor2, 2>> sides;
    std::vector<size_t> from;
    for (uint32_t e = b.first; e < b.first + b.count; ++e) {
      Anchor2 sa = R.side_a[e], sb = R.side_b[e];
      if (follow(sa) && follow(sb)) sides.push_back({sa, sb}), from.push_back(e);
    }
    if (sides.empty()) continue;  // every crossing of this bolt was in excavated rock
    // An end in deleted rock moves to its nearest kept crossing.
    if (!follow(b.end0)) b.end0 = sides.front()[0];
    if (!follow(b.end1)) b.end1 = sides.back()[1];
    const Vec2 axis = R.axis0[from.front()];
    kept.add(b, sides, axis);
    for (size_t k = 0; k < from.size(); ++k) {
      const size_t e = kept.size() - from.size() + k, o = from[k];
      element_map[o] = static_cast<int32_t>(e);
      kept.axis0[e] = R.axis0[o];
      kept.axial[e] = R.axial[o], kept.shear[e] = R.shear[o];
      kept.ua[e] = R.ua[o], kept.us[e] = R.us[o], kept.state[e] = R.state[o];
      kept.point[e] = R.point[o], kept.force[e] = R.force[o];
    }
  }
  R = std::move(kept);
  // Histories at a crossing follow it; those at a removed one end.
  for (auto& s : m.histories.series)
    if (s.element >= 0 && is_bolt_quantity(s.quantity))
      s.element = element_map[static_cast<size_t>(s.element)];
}

}  // namespace tessera
