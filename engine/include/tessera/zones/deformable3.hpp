// Deformable 3D blocks (§5.3.1): zoning a polyhedral block into tetrahedra, its corners and face
// planes following its nodes, contact forces reaching its surface nodes, and its time step.
// The 3D counterpart of deformable.hpp, on the same Continuum kernel.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

// How zoning went: the smallest dihedral angle of the zones (degrees), where, and how many
// zones are poor (under ZoneMesh3::kPoorDihedral).
struct ZoningReport {
  double min_dihedral = 180.0;
  Vec3 worst_at = Vec3::Zero();
  size_t poor = 0;
};
// Zones 3D block b (zone edges up to `max_edge`, optionally graded) and makes it deformable:
// its corners become nodes and each face is covered by the surface triangles of its zones. A
// piece of a joined (concave) body zones the whole body as one mesh that conforms across the
// faces between its pieces (they share nodes: no joint there); each piece keeps its own zones,
// material and face triangles, and all share the body's node range. `quadratic`: 10-node zones
// (a node at the middle of every zone edge; each face's surface triangles are the zones' faces
// split in four). Throws std::invalid_argument if a material has no elastic constants, the
// block is deformable already or the mesher left a zone of no volume inside it (a flat one on
// its surface is dropped), and ZoningStopped (the model unchanged) when `stop` is set while it
// meshes.
ZoningReport make_deformable3(Model& m, size_t b, double max_edge,
                              const ZoneGrading3* grading = nullptr,
                              const std::atomic<bool>* stop = nullptr, bool quadratic = false);
// Refreshes the corners and face planes of every deformable 3D block from its nodes.
void update_deformable_world3(Model& m);
// Adds the sub-contact forces on deformable 3D blocks to their nodes, in a fixed order per block.
void add_contact_forces_to_nodes3(Model& m);
// Adds the pull of cable nodes hosted in zones to the zones' corner nodes, by weight.
void add_cable_forces_to_nodes3(Model& m);
// Each node's own stable step (1e300 for a massless node): its zones' (node_steps), and for a
// surface node its mass against the stiffest joint pair over its share of the surface.
std::vector<double> node_timesteps3(const Model& m);
// Drops the nodes and zones of the doomed blocks (before Blocks3::remove with the same flags);
// returns each old node's new index (-1: gone), or nothing if no node went.
std::vector<int64_t> drop_deformable3(Model& m, const std::vector<uint8_t>& doomed);

}  // namespace tessera
