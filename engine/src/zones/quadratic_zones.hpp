// Quadratic (10-node) tetrahedra: shape-function gradients at the integration points, the zone's
// stage of the cycle, its strain, its stable time step. Internal to the zone kernel
// (continuum.cpp), which keeps the data (see continuum.hpp).
#pragma once

#include <array>
#include <vector>

#include "tessera/zones/continuum.hpp"

namespace tessera {

// Corners of the six edges in VTK's quadratic-tetrahedron order.
inline constexpr int kTetEdge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
// Lumped masses: the share of the zone's mass at a corner and at a mid-edge node.
inline constexpr double kCornerMass = 1.0 / 36.0, kMidMass = 4.0 / 27.0;

// Each integration point's position in volume coordinates: (a, b, b, b) and its permutations.
double gauss_coordinate(int point, int corner);
// The gradients of a straight-edged zone's volume coordinates (the linear tetrahedron's,
// constant in it) from its corners; `volume` receives its volume.
std::array<Vec3, 4> volume_gradients(const std::array<Vec3, 4>& corners, double& volume);
// The ten shape functions' gradients at integration point `point` (corners first, then mid-edge
// nodes), from the volume coordinates' gradients.
std::array<Vec3, 10> quadratic_gradients(const std::array<Vec3, 4>& dl, int point);
// The zone's ten nodes: corners, then mid-edge nodes.
std::array<uint32_t, 10> quadratic_nodes(const Continuum3& c, size_t z);
// One cycle of quadratic zone z: strain increments at its integration points from the nodes'
// velocities, the law there, and the nodal forces of their stresses added to `c.force` (and
// their sizes to `scale`). Sets the zone's mean stress and state.
void quadratic_zone_forces(Continuum3& c, size_t z, std::vector<double>& scale);
// The zone's mean strain from its nodes' displacements on the initial shape.
StrainIncrement quadratic_total_strain(const Continuum3& c, size_t z);
// The zone's own stable step, alone: Gershgorin's 2 sqrt(m / r) at its worst node.
double quadratic_zone_step(const Continuum3& c, size_t z);
// The largest absolute row sum of the zone's stiffness over each node's three rows: summed over
// the zones around a node and set against its mass, Gershgorin's bound on the mesh's highest
// frequency there (deformable3.cpp: node_timesteps3).
std::array<double, 10> quadratic_row_sums(const Continuum3& c, size_t z, double* volume = nullptr);

}  // namespace tessera
