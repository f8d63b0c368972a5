// The deformable zones' stage of the cycle: zone stresses and node forces, the contact forces
// handed to the outline nodes, node motion, and the blocks' outlines moved with their nodes.
// Contacts see the zones only through this and deformable.hpp (node velocities in, node forces
// out), the interface 3D tetrahedra will plug into.
#pragma once

#include "tessera/core/damping.hpp"

namespace tessera {

struct Model;

// What the zone stage leaves for the core's checks.
struct ZoneMotion {
  bool active = false;  // the model has zones
  double drift = 0.0;   // largest node displacement since the last detection pass
  double ratio = 0.0;   // the nodes' unbalanced-force ratio
};

// One step of the zones under the cycle's damping (local damping's alpha; global viscosity does
// not reach them). Throws ModelError if a node moves half the contact tolerance in one step.
ZoneMotion zone_stage(Model& m, const Damping& d);
// Twice the kinetic energy of the nodes (with their density-scaled inertia), and every node's
// velocity set to zero (kinetic damping; fixed components take theirs again when they move).
double twice_node_energy(const Model& m);
void stop_nodes(Model& m);

}  // namespace tessera
