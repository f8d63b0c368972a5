// Grouted cables in the cycle: segment and grout forces, the nodes' axial motion, and their
// reactions on the rock.
#include "tessera/support/cables.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/damping.hpp"
#include "tessera/core/model.hpp"
#include "tessera/support/anchor3.hpp"

namespace tessera {

template <int D>
size_t CablesT<D>::add(Cable c, const std::vector<Host>& hosts, const std::vector<double>& len) {
  c.first = static_cast<uint32_t>(size());
  c.count = static_cast<uint32_t>(hosts.size());
  for (size_t i = 0; i < hosts.size(); ++i) {
    cable.push_back(static_cast<uint32_t>(cables.size()));
    host.push_back(hosts[i]);
    bonded.push_back(len[i]);
    for (auto* v : {&slip, &slip_plastic, &vel, &inertia, &bond, &rest, &plastic})
      v->push_back(0.0);
    axial.push_back(i + 1 < hosts.size() ? c.props.pretension : 0.0);
    state.push_back(0);
    pos.push_back(V::Zero()), axis.push_back(V::Zero()), host_force.push_back(V::Zero());
  }
  cables.push_back(std::move(c));
  return cables.size() - 1;
}

template struct CablesT<2>;
template struct CablesT<3>;

namespace {
// Node axes from the host points: along the chord through the neighbours (one-sided at ends).
template <int D>
void node_axes(const Model& m, CablesT<D>& K, const Cable& c,
               std::vector<typename CablesT<D>::V>& h) {
  h.resize(c.count);
  for (uint32_t k = 0; k < c.count; ++k) h[k] = anchor_position(m, K.host[c.first + k]);
  for (uint32_t k = 0; k < c.count; ++k) {
    const typename CablesT<D>::V d = h[std::min(k + 1, c.count - 1)] - h[k > 0 ? k - 1 : 0];
    const double n = d.norm();
    if (n > 0.0) K.axis[c.first + k] = d / n;
  }
}

// The grout's confinement at node i (compression positive): the mean of the normal stresses
// across the cable's axis t in the zone that hosts the node (in 2D the in-plane normal and the
// out-of-plane stress); zero in a rigid block, which carries no stress.
template <int D>
double confinement(const Model& m, CablesT<D>& K, size_t i, const typename CablesT<D>::V& t) {
  const auto& a = K.host[i];
  if (a.node[0] < 0) return 0.0;
  const ContinuumT<D>& c = [&]() -> const ContinuumT<D>& {
    if constexpr (D == 3)
      return m.continuum3;
    else
      return m.continuum;
  }();
  const auto hosts = [&](int32_t z) {
    if (z < 0 || static_cast<size_t>(z) >= c.zone_count()) return false;
    for (int k = 0; k <= D; ++k)
      if (c.zones[static_cast<size_t>(z)][static_cast<size_t>(k)] !=
          static_cast<uint32_t>(a.node[k]))
        return false;
    return true;
  };
  int32_t& z = K.zone[i];
  if (!hosts(z)) {
    z = -1;
    for (size_t k = 0; k < c.zone_count() && z < 0; ++k)
      if (hosts(static_cast<int32_t>(k))) z = static_cast<int32_t>(k);
  }
  if (z < 0) return 0.0;
  const ZoneStress& s = c.stress[static_cast<size_t>(z)];
  if constexpr (D == 2) {
    const double nx = -t.y(), ny = t.x();
    return -0.5 * (s.xx * nx * nx + 2.0 * s.xy * nx * ny + s.yy * ny * ny + s.zz);
  } else {
    Eigen::Matrix3d S;
    S << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
    return -0.5 * (S.trace() - t.dot(S * t));
  }
}

template <int D>
void update(Model& m, CablesT<D>& K, double alpha) {
  if (K.zone.size() != K.size()) K.zone.assign(K.size(), -1);
  using V = typename CablesT<D>::V;
  const double dt = m.dt;
  std::vector<V> h;
  K.balance.clear();
  for (const Cable& c : K.cables) {
    const CableProperties& p = c.props;
    node_axes(m, K, c, h);
    const uint32_t n0 = c.first, n1 = c.first + c.count;
    for (uint32_t i = n0; i < n1; ++i) K.pos[i] = h[i - n0] - K.slip[i] * K.axis[i];
    // Segments: total elongation past the rest length, less the plastic part, capped.
    for (uint32_t i = n0; i + 1 < n1; ++i) {
      const double len = (K.pos[i + 1] - K.pos[i]).norm();
      double f = p.pretension + p.ea * (len - K.rest[i] - K.plastic[i]) / K.rest[i];
      K.state[i] &= static_cast<uint8_t>(~kCableYield);
      // At the cap (to round-off) a segment is yielding, also once its plastic flow settles.
      const double cap = f > 0.0 ? p.tension : p.compression;
      if (cap > 0.0 && std::abs(f) >= cap * (1.0 - 1e-12)) {
        f = std::copysign(cap, f);
        K.plastic[i] = len - K.rest[i] - (f - p.pretension) * K.rest[i] / p.ea;
        K.state[i] |= kCableYield;
      }
      K.axial[i] = f;
    }
    for (uint32_t i = n0; i < n1; ++i) {
      const V t = K.axis[i];
      // The segments' pull on the node.
      V f = V::Zero();
      if (i + 1 < n1) f += K.axial[i] * (K.pos[i + 1] - K.pos[i]).normalized();
      if (i > n0) f -= K.axial[i - 1] * (K.pos[i] - K.pos[i - 1]).normalized();
      const V vh = anchor_velocity(m, K.host[i]);
      // The node's round-off: its stiffness times the model's round-off length. A force within
      // it is none (an unloaded cable's noise handed to a free block would be all its load).
      const double rest = K.rest[i + 1 < n1 || i == n0 ? i : i - 1];
      const double axial_k = rest > 0.0 ? 2.0 * p.ea / rest : 0.0;
      const double noise = (axial_k + p.kbond * K.bonded[i]) * m.roundoff_gap();
      if (c.head && i == n0) {
        // A faceplate: the node moves with its rock and hands it the segment's pull.
        K.vel[i] = vh.dot(t), K.host_force[i] = f.norm() > noise ? f : V::Zero(), K.bond[i] = 0.0;
        continue;
      }
      // The grout: elastic slip, capped at the bond strength (rising with confinement).
      double s = p.kbond * (K.slip[i] - K.slip_plastic[i]);
      K.state[i] &= static_cast<uint8_t>(~kCableBondYield);
      const bool limited = p.sbond > 0.0 || p.bond_friction > 0.0;
      const double strength =
          p.bond_friction > 0.0
              ? std::max(0.0, p.sbond + p.bond_friction * p.perimeter * confinement(m, K, i, t))
              : p.sbond;
      if (limited && std::abs(s) >= strength * (1.0 - 1e-12) && K.bonded[i] > 0.0) {
        s = std::copysign(strength, s);
        K.slip_plastic[i] = K.slip[i] - s / p.kbond;
        K.state[i] |= kCableBondYield;
      }
      K.bond[i] = K.bonded[i] > 0.0 ? s : 0.0;
      const double grout = K.bond[i] * K.bonded[i];
      K.host_force[i] = std::abs(grout) > noise ? V(-grout * t) : V::Zero();
      // The node's motion along the axis; the host's motion across it carries the node along.
      const double fa = f.dot(t) + grout;
      if (K.inertia[i] > 0.0) {
        K.balance.add(std::abs(fa), std::abs(f.dot(t)) + std::abs(grout), noise);
        K.vel[i] += dt * locally_damped(fa, K.vel[i], alpha) / K.inertia[i];
      }
      K.slip[i] += dt * (vh.dot(t) - K.vel[i]);
    }
  }
}

// Each node's axial stiffness: its grout and the segments on either side.
template <int D>
double node_stiffness(const CablesT<D>& K, const Cable& c, uint32_t i) {
  double k = c.props.kbond * K.bonded[i];
  if (i + 1 < c.first + c.count) k += c.props.ea / K.rest[i];
  if (i > c.first) k += c.props.ea / K.rest[i - 1];
  return k;
}
// The steel's share of mass at each node (without a mass per metre, steel of the section that
// gives EA: 7,850 kg/m3 over E = 200 GPa).
template <int D>
double node_mass(const CablesT<D>& K, const Cable& c, uint32_t i) {
  double len = 0.0;
  if (i + 1 < c.first + c.count) len += 0.5 * K.rest[i];
  if (i > c.first) len += 0.5 * K.rest[i - 1];
  const double per_metre = c.props.mass > 0.0 ? c.props.mass : 7850.0 * c.props.ea / 2e11;
  return per_metre * len;
}

template <int D>
void scale_nodes(CablesT<D>& K, bool dynamic, double dt) {
  for (const Cable& c : K.cables)
    for (uint32_t i = c.first; i < c.first + c.count; ++i) {
      // Static: the inertia whose own step 2 sqrt(I / k) is twice dt, the blocks' safety.
      const double k = node_stiffness(K, c, i), mass = node_mass(K, c, i);
      K.inertia[i] = dynamic ? mass : std::max(mass, k * dt * dt);
    }
}

template <int D>
void node_steps(const CablesT<D>& K, std::vector<double>& out) {
  for (const Cable& c : K.cables)
    for (uint32_t i = c.first; i < c.first + c.count; ++i) {
      const double k = node_stiffness(K, c, i), mass = node_mass(K, c, i);
      if (k > 0.0 && mass > 0.0 && !(c.head && i == c.first))
        out.push_back(2.0 * std::sqrt(mass / k));
    }
}
}  // namespace

void update_cables(Model& m, double alpha) {
  if (m.dim == 3)
    update(m, m.cables3, alpha);
  else
    update(m, m.cables, alpha);
}

template <int D>
double cable_host_stiffness(const CablesT<D>& K, size_t i) {
  const Cable& c = K.cables[K.cable[i]];
  if (c.head && i == c.first) return c.count > 1 ? c.props.ea / K.rest[i] : 0.0;
  return c.props.kbond * K.bonded[i];
}

template double cable_host_stiffness(const CablesT<2>&, size_t);
template double cable_host_stiffness(const CablesT<3>&, size_t);

void scale_cable_nodes(Model& m, double dt) {
  const bool dynamic = m.settings.damping == DampingMode::kNone;
  scale_nodes(m.cables, dynamic, dt);
  scale_nodes(m.cables3, dynamic, dt);
}

void add_cable_forces3(Model& m) {
  Blocks3& B = m.blocks3;
  const Cables3& K = m.cables3;
  // In node order, onto the body (the master of a concave block's pieces).
  for (size_t i = 0; i < K.size(); ++i) {
    if (K.host[i].node[0] >= 0) continue;  // in a zone: add_cable_forces_to_nodes3
    const auto b = static_cast<size_t>(K.host[i].body);
    const Vec3 f = K.host_force[i];
    B.force[b] += f, B.torque[b] += (K.pos[i] - B.body[b].position).cross(f);
    B.applied[b] += f.norm();
  }
}

std::vector<double> cable_stiffness3(const Model& m) {
  const Cables3& K = m.cables3;
  std::vector<double> k(m.blocks3.size(), 0.0);
  for (size_t i = 0; i < K.size(); ++i)
    if (K.host[i].node[0] < 0) k[static_cast<size_t>(K.host[i].body)] += cable_host_stiffness(K, i);
  return k;
}

std::vector<double> cable_node_steps(const Model& m) {
  std::vector<double> out;
  node_steps(m.cables, out);
  node_steps(m.cables3, out);
  return out;
}

}  // namespace tessera
