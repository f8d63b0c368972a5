// Liners in the cycle: beam elements, the interface to the rock, the nodes' motion.
#include "tessera/support/liners.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/damping.hpp"
#include "tessera/core/model.hpp"

namespace tessera {

int64_t Liners::next(size_t i) const {
  const Liner& l = liners[liner[i]];
  if (i + 1 < l.first + l.count) return static_cast<int64_t>(i + 1);
  return l.closed ? static_cast<int64_t>(l.first) : -1;
}

size_t Liners::add(Liner l, const std::vector<Anchor2>& hosts, const std::vector<Vec2>& at,
                   const std::vector<Vec2>& normals, const std::vector<double>& lengths) {
  l.first = static_cast<uint32_t>(size());
  l.count = static_cast<uint32_t>(hosts.size());
  for (size_t k = 0; k < hosts.size(); ++k) {
    liner.push_back(static_cast<uint32_t>(liners.size()));
    host.push_back(hosts[k]), pos0.push_back(at[k]), normal.push_back(normals[k]);
    length.push_back(lengths[k]);
    for (auto* v : {&disp, &vel, &force, &host_force}) v->push_back(Vec2::Zero());
    for (auto* v : {&rot, &spin, &mass, &inertia, &shear, &pressure, &moment_sum, &axial, &m_start,
                    &m_end, &v_shear, &plastic_axial, &hinge_start, &hinge_end})
      v->push_back(0.0);
    state.push_back(0);
  }
  liners.push_back(std::move(l));
  return liners.size() - 1;
}

namespace {
// Caps a moment at the capacity by moving the hinge's plastic rotation (the end's own
// stiffness 4 E I / L); true if it did.
bool cap_moment(double& m, double& hinge, double cap, double k4) {
  if (cap <= 0.0 || std::abs(m) < cap * (1.0 - 1e-12)) return false;
  const double target = std::copysign(cap, m);
  hinge += (m - target) / k4;
  m = target;
  return true;
}
}  // namespace

void update_liners(Model& m, double alpha) {
  Liners& L = m.liners;
  const double dt = m.dt;
  for (size_t i = 0; i < L.size(); ++i) {
    L.force[i].setZero(), L.moment_sum[i] = 0.0;
    L.state[i] = 0;
  }
  // Elements: forces from the nodes' displacements in the element's placed frame.
  for (size_t i = 0; i < L.size(); ++i) {
    const int64_t jn = L.next(i);
    if (jn < 0) continue;
    const auto j = static_cast<size_t>(jn);
    const LinerProperties& p = L.liners[L.liner[i]].props;
    const Vec2 d = L.pos0[j] - L.pos0[i];
    const double len = d.norm();
    const Vec2 t = d / len, n = perp(t);
    const double du = (L.disp[j] - L.disp[i]).dot(t), phi = (L.disp[j] - L.disp[i]).dot(n) / len;
    double N = p.ea / len * (du - L.plastic_axial[i]);
    if (p.thrust > 0.0 && std::abs(N) >= p.thrust * (1.0 - 1e-12)) {
      const double capped = std::copysign(p.thrust, N);
      L.plastic_axial[i] += (N - capped) * len / p.ea;
      N = capped, L.state[i] |= kLinerThrustYield;
    }
    const double k = p.ei / len;
    auto moments = [&](double& mi, double& mj) {
      const double ti = L.rot[i] - L.hinge_start[i], tj = L.rot[j] - L.hinge_end[i];
      mi = k * (4.0 * ti + 2.0 * tj - 6.0 * phi), mj = k * (2.0 * ti + 4.0 * tj - 6.0 * phi);
    };
    double mi = 0.0, mj = 0.0;
    moments(mi, mj);
    // Hinges at the ends: each capped in turn, the other end then follows.
    for (int pass = 0; pass < 2 && p.moment > 0.0; ++pass) {
      bool hinged = cap_moment(mi, L.hinge_start[i], p.moment, 4.0 * k);
      moments(mi, mj);
      hinged |= cap_moment(mj, L.hinge_end[i], p.moment, 4.0 * k);
      moments(mi, mj);
      if (hinged) L.state[i] |= kLinerHinge;
    }
    const double v = (mi + mj) / len;
    L.axial[i] = N, L.m_start[i] = mi, L.m_end[i] = mj, L.v_shear[i] = v;
    // On the nodes: the element's end forces reversed.
    L.force[i] += N * t - v * n, L.force[j] += -N * t + v * n;
    L.moment_sum[i] -= mi, L.moment_sum[j] -= mj;
  }
  // The interface, then each node's motion.
  L.balance.clear();
  for (size_t i = 0; i < L.size(); ++i) {
    const LinerProperties& p = L.liners[L.liner[i]].props;
    const Vec2 nrm = L.normal[i], s = perp(nrm);
    const Vec2 gap = liner_position(L, i) - anchor_position(m, L.host[i]);
    // Pressure: the liner pressed into the rock (tension negative, capped at the strength).
    double pr = p.kn * gap.dot(nrm);
    if (pr < -p.tension) pr = -p.tension, L.state[i] |= kLinerOpen;
    L.pressure[i] = pr;
    const double slip = dt * (L.vel[i] - anchor_velocity(m, L.host[i])).dot(s);
    double sh = L.shear[i] + p.ks * slip;
    if (p.cohesion > 0.0 || p.friction > 0.0) {
      const double cap = p.cohesion + std::tan(p.friction * M_PI / 180.0) * std::max(pr, 0.0);
      if (std::abs(sh) >= cap) sh = std::copysign(cap, sh), L.state[i] |= kLinerSlip;
    }
    L.shear[i] = sh;
    const Vec2 f_int = -L.length[i] * (pr * nrm + sh * s);
    // The node's round-off: its stiffness (to a factor of a few: the interface and two
    // elements' axial springs) times the model's round-off length. A force within it is none.
    const double noise =
        ((p.kn + p.ks) * L.length[i] + 4.0 * p.ea / L.length[i]) * m.roundoff_gap();
    L.host_force[i] = f_int.norm() > noise ? Vec2(-f_int) : Vec2::Zero();
    const Vec2 f = L.force[i] + f_int;
    if (L.mass[i] > 0.0) L.balance.add(f.norm(), L.force[i].norm() + f_int.norm(), noise);
    L.force[i] = f;
    if (L.mass[i] <= 0.0) continue;
    for (int c = 0; c < 2; ++c)
      L.vel[i][c] += dt * locally_damped(f[c], L.vel[i][c], alpha) / L.mass[i];
    L.spin[i] += dt * locally_damped(L.moment_sum[i], L.spin[i], alpha) / L.inertia[i];
    L.disp[i] += dt * L.vel[i];
    L.rot[i] += dt * L.spin[i];
  }
}

namespace {
// Row sums of the absolute stiffness at node i, translation and rotation (Gershgorin: with
// masses in proportion the scaled system's highest frequency is at most 1 / dt).
std::array<double, 2> row_stiffness(const Liners& L, size_t i) {
  const LinerProperties& p = L.liners[L.liner[i]].props;
  std::array<double, 2> k{(p.kn + p.ks) * L.length[i], 0.0};
  auto element = [&](size_t a, size_t b) {
    const double len = (L.pos0[b] - L.pos0[a]).norm(), e = p.ei;
    k[0] += 2.0 * p.ea / len + 24.0 * e / (len * len * len) + 12.0 * e / (len * len);
    k[1] += 12.0 * e / (len * len) + 6.0 * e / len;
  };
  if (const int64_t j = L.next(i); j >= 0) element(i, static_cast<size_t>(j));
  for (size_t h = L.liners[L.liner[i]].first;
       h < L.liners[L.liner[i]].first + L.liners[L.liner[i]].count; ++h)
    if (L.next(h) == static_cast<int64_t>(i)) element(h, i);
  return k;
}
}  // namespace

void scale_liner_nodes(Model& m, double dt) {
  Liners& L = m.liners;
  const bool dynamic = m.settings.damping == DampingMode::kNone;
  for (size_t i = 0; i < L.size(); ++i) {
    const auto k = row_stiffness(L, i);
    const LinerProperties& p = L.liners[L.liner[i]].props;
    const double mass = p.mass * L.length[i];
    if (dynamic && mass > 0.0) {
      L.mass[i] = mass, L.inertia[i] = mass * L.length[i] * L.length[i] / 12.0;
    } else {
      L.mass[i] = std::max(k[0] * dt * dt, 1e-300), L.inertia[i] = std::max(k[1] * dt * dt, 1e-300);
    }
  }
}

std::vector<double> liner_node_steps(const Model& m) {
  const Liners& L = m.liners;
  std::vector<double> out;
  for (size_t i = 0; i < L.size(); ++i) {
    const LinerProperties& p = L.liners[L.liner[i]].props;
    const double mass = p.mass * L.length[i];
    if (!(mass > 0.0)) continue;
    const auto k = row_stiffness(L, i);
    out.push_back(2.0 * std::sqrt(mass / k[0]));
    out.push_back(2.0 * std::sqrt(mass * L.length[i] * L.length[i] / 12.0 / k[1]));
  }
  return out;
}

double liner_thrust(const Liners& L, size_t i) {
  double sum = 0.0;
  int n = 0;
  if (L.next(i) >= 0) sum -= L.axial[i], ++n;
  const Liner& l = L.liners[L.liner[i]];
  for (uint32_t h = l.first; h < l.first + l.count; ++h)
    if (L.next(h) == static_cast<int64_t>(i)) sum -= L.axial[h], ++n;
  return n ? sum / n : 0.0;
}

double liner_moment(const Liners& L, size_t i) {
  // The node's moment on the element starting there, anticlockwise, is sagging towards the
  // opening: its negative puts the rock-side face in tension.
  if (L.next(i) >= 0) return -L.m_start[i];
  return i > 0 ? L.m_end[i - 1] : 0.0;
}

double liner_host_stiffness(const Model& m, size_t i) {
  const Liners& L = m.liners;
  const LinerProperties& p = L.liners[L.liner[i]].props;
  return std::max(p.kn, p.ks) * L.length[i];
}

}  // namespace tessera
