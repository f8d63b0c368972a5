// The zones' stage of the cycle.
#include "tessera/zones/zone_stage.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/step.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

ZoneMotion zone_stage(Model& m, const Damping& d) {
  Continuum& zc = m.continuum;
  ZoneMotion out;
  if (zc.zone_count() == 0) return out;
  out.active = true;
  zc.gravity = m.settings.gravity;
  zc.local_damping = d.alpha;
  zc.dt = m.dt;
  zone_forces(zc);
  add_contact_forces_to_nodes(m);
  const double node_move = move_nodes(zc);
  update_deformable_world(m);
  // A node that moves half the contact tolerance in one step has left explicit dynamics.
  if (!std::isfinite(node_move) || node_move > 0.5 * m.tolerance())
    throw ModelError("the run diverged at cycle " + std::to_string(m.cycle) +
                     ": a node of a deformable block moved " + std::to_string(node_move) +
                     " m in one step (time step too large, or blocks overlapping badly)");
  if (m.det_node.size() != zc.node_count()) m.det_node = zc.pos0;
  for (size_t k = 0; k < zc.node_count(); ++k)
    out.drift = std::max(out.drift, (zc.pos[k] - m.det_node[k]).norm());
  out.ratio = zc.ratio;
  return out;
}

}  // namespace tessera
