// The zones' stage of the cycle, the same in 2D and 3D.
#include "tessera/zones/zone_stage.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/step.hpp"
#include "tessera/support/reinforcement.hpp"
#include "tessera/zones/deformable.hpp"
#include "tessera/zones/deformable3.hpp"

namespace tessera {

namespace {
template <int D>
ZoneMotion step_zones(Model& m, ContinuumT<D>& zc, const typename ContinuumT<D>::Vec& gravity,
                      std::vector<typename ContinuumT<D>::Vec>& det_node, const Damping& d) {
  ZoneMotion out;
  if (zc.zone_count() == 0) return out;
  out.active = true;
  zc.gravity = gravity;
  zc.local_damping = d.alpha;
  zc.dt = m.dt;
  zone_forces(zc);
  // Contact forces reach the nodes (node velocities in, node forces out), then the nodes move
  // and the blocks' outlines (2D) or corners and faces (3D) follow them.
  if constexpr (D == 2) {
    add_contact_forces_to_nodes(m);
    add_reinforcement_forces_to_nodes(m);
  } else {
    add_contact_forces_to_nodes3(m);
    add_cable_forces_to_nodes3(m);
  }
  const double node_move = move_nodes(zc);
  if constexpr (D == 2) {
    update_deformable_world(m);
  } else {
    update_deformable_world3(m);
  }
  // A node that moves half the contact tolerance in one step has left explicit dynamics (a model
  // of one block may have no tolerance: then a hundredth of its size).
  double limit = 0.5 * m.tolerance();
  if (!(limit > 0)) {
    typename ContinuumT<D>::Vec lo = zc.pos0[0], hi = zc.pos0[0];
    for (const auto& p : zc.pos0) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    limit = 0.01 * (hi - lo).norm();
  }
  if (!std::isfinite(node_move) || node_move > limit)
    throw ModelError("the run diverged at cycle " + std::to_string(m.cycle) +
                     ": a node of a deformable block moved " + std::to_string(node_move) +
                     " m in one step (time step too large, or blocks overlapping badly)");
  if (det_node.size() != zc.node_count()) det_node = zc.pos0;
  for (size_t k = 0; k < zc.node_count(); ++k)
    out.drift = std::max(out.drift, (zc.pos[k] - det_node[k]).norm());
  out.ratio = zc.ratio;
  return out;
}
}  // namespace

namespace {
template <int D>
double twice_energy(const ContinuumT<D>& c) {
  double e = 0.0;
  for (size_t n = 0; n < c.node_count(); ++n) e += c.inertia[n] * c.vel[n].squaredNorm();
  return e;
}
}  // namespace

double twice_node_energy(const Model& m) {
  return m.dim == 3 ? twice_energy(m.continuum3) : twice_energy(m.continuum);
}

void stop_nodes(Model& m) {
  for (auto& v : m.continuum.vel) v.setZero();
  for (auto& v : m.continuum3.vel) v.setZero();
}

ZoneMotion zone_stage(Model& m, const Damping& d) {
  if (m.dim == 3) return step_zones(m, m.continuum3, m.settings.gravity3, m.det_node3, d);
  return step_zones(m, m.continuum, m.settings.gravity, m.det_node, d);
}

}  // namespace tessera
