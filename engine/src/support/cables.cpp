// Grouted cables in the cycle: segment and grout forces, the nodes' axial motion, and their
// reactions on the rock.
#include "tessera/support/cables.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/damping.hpp"
#include "tessera/core/model.hpp"

namespace tessera {

size_t Cables::add(Cable c, const std::vector<Anchor2>& hosts, const std::vector<double>& len) {
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
    pos.push_back(Vec2::Zero()), axis.push_back(Vec2::Zero()), host_force.push_back(Vec2::Zero());
  }
  cables.push_back(std::move(c));
  return cables.size() - 1;
}

namespace {
// Node axes from the host points: along the chord through the neighbours (one-sided at ends).
void node_axes(const Model& m, const Cable& c, std::vector<Vec2>& h) {
  Cables& K = const_cast<Model&>(m).cables;
  h.resize(c.count);
  for (uint32_t k = 0; k < c.count; ++k) h[k] = anchor_position(m, K.host[c.first + k]);
  for (uint32_t k = 0; k < c.count; ++k) {
    const Vec2 d = h[std::min(k + 1, c.count - 1)] - h[k > 0 ? k - 1 : 0];
    const double n = d.norm();
    if (n > 0.0) K.axis[c.first + k] = d / n;
  }
}
}  // namespace

void update_cables(Model& m, double alpha) {
  Cables& K = m.cables;
  const double dt = m.dt;
  std::vector<Vec2> h;
  for (const Cable& c : K.cables) {
    const CableProperties& p = c.props;
    node_axes(m, c, h);
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
      const Vec2 t = K.axis[i];
      // The segments' pull on the node.
      Vec2 f = Vec2::Zero();
      if (i + 1 < n1) f += K.axial[i] * (K.pos[i + 1] - K.pos[i]).normalized();
      if (i > n0) f -= K.axial[i - 1] * (K.pos[i] - K.pos[i - 1]).normalized();
      const Vec2 vh = anchor_velocity(m, K.host[i]);
      if (c.head && i == n0) {
        // A faceplate: the node moves with its rock and hands it the segment's pull.
        K.vel[i] = vh.dot(t), K.host_force[i] = f, K.bond[i] = 0.0;
        continue;
      }
      // The grout: elastic slip, capped at the bond strength.
      double s = p.kbond * (K.slip[i] - K.slip_plastic[i]);
      K.state[i] &= static_cast<uint8_t>(~kCableBondYield);
      if (p.sbond > 0.0 && std::abs(s) >= p.sbond * (1.0 - 1e-12) && K.bonded[i] > 0.0) {
        s = std::copysign(p.sbond, s);
        K.slip_plastic[i] = K.slip[i] - s / p.kbond;
        K.state[i] |= kCableBondYield;
      }
      K.bond[i] = K.bonded[i] > 0.0 ? s : 0.0;
      const double grout = K.bond[i] * K.bonded[i];
      K.host_force[i] = -grout * t;
      // The node's motion along the axis; the host's motion across it carries the node along.
      const double fa = f.dot(t) + grout;
      if (K.inertia[i] > 0.0) K.vel[i] += dt * locally_damped(fa, K.vel[i], alpha) / K.inertia[i];
      K.slip[i] += dt * (vh.dot(t) - K.vel[i]);
    }
  }
}

namespace {
// Each node's axial stiffness: its grout and the segments on either side.
double node_stiffness(const Cables& K, const Cable& c, uint32_t i) {
  double k = c.props.kbond * K.bonded[i];
  if (i + 1 < c.first + c.count) k += c.props.ea / K.rest[i];
  if (i > c.first) k += c.props.ea / K.rest[i - 1];
  return k;
}
// The steel's share of mass at each node (without a mass per metre, steel of the section that
// gives EA: 7,850 kg/m3 over E = 200 GPa).
double node_mass(const Cables& K, const Cable& c, uint32_t i) {
  double len = 0.0;
  if (i + 1 < c.first + c.count) len += 0.5 * K.rest[i];
  if (i > c.first) len += 0.5 * K.rest[i - 1];
  const double per_metre = c.props.mass > 0.0 ? c.props.mass : 7850.0 * c.props.ea / 2e11;
  return per_metre * len;
}
}  // namespace

double cable_host_stiffness(const Model& m, size_t i) {
  const Cables& K = m.cables;
  const Cable& c = K.cables[K.cable[i]];
  if (c.head && i == c.first) return c.count > 1 ? c.props.ea / K.rest[i] : 0.0;
  return c.props.kbond * K.bonded[i];
}

void scale_cable_nodes(Model& m, double dt) {
  Cables& K = m.cables;
  const bool dynamic = m.settings.damping == DampingMode::kNone;
  for (const Cable& c : K.cables)
    for (uint32_t i = c.first; i < c.first + c.count; ++i) {
      // Static: the inertia whose own step 2 sqrt(I / k) is twice dt, the blocks' safety.
      const double k = node_stiffness(K, c, i), mass = node_mass(K, c, i);
      K.inertia[i] = dynamic ? mass : std::max(mass, k * dt * dt);
    }
}

std::vector<double> cable_node_steps(const Model& m) {
  const Cables& K = m.cables;
  std::vector<double> out;
  for (const Cable& c : K.cables)
    for (uint32_t i = c.first; i < c.first + c.count; ++i) {
      const double k = node_stiffness(K, c, i), mass = node_mass(K, c, i);
      if (k > 0.0 && mass > 0.0 && !(c.head && i == c.first))
        out.push_back(2.0 * std::sqrt(mass / k));
    }
  return out;
}

}  // namespace tessera
