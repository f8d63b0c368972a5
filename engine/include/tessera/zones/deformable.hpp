// Deformable blocks in the model: zoning a block, its outline following its nodes, contact
// forces reaching nodes, and removal (the link between Blocks and the Continuum kernel).
#pragma once

#include <cstdint>
#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

// Zones block b (zone edges up to `max_edge`, optionally graded) and makes it deformable: its
// outline becomes its boundary nodes in order. Throws std::invalid_argument if its material
// has no elastic constants or the block is deformable already.
void make_deformable(Model& m, size_t b, double max_edge, const ZoneGrading* grading = nullptr);
// Copies the model's materials into the continuum's zone materials (after a material change).
void sync_zone_materials(Model& m);
// Refreshes the world outline of every deformable block from its nodes.
void update_deformable_world(Model& m);
// The block each node belongs to (-1 for none).
std::vector<int> node_owners(const Model& m);
// `fix`, `free` and `velocity` on a deformable block (2D or 3D), whose motion is its nodes':
// holds (or frees) the translations `bits` (node_fix_bit per axis, as the blocks' kFixX...) of
// its every node, at `velocity` (x, y[, z]; null: each node's velocity now). Sets the velocity of
// the free nodes' axes in `set_velocity` (a velocity= of free nodes). Returns the node count.
size_t set_block_nodes(Model& m, size_t b, uint8_t bits, bool free, const double* velocity,
                       uint8_t set_velocity = 0);
// Drops the nodes and zones of the doomed blocks (before Blocks::remove with the same flags);
// returns each old node's new number (-1 dropped), or nothing if no node changed.
std::vector<int64_t> drop_deformable(Model& m, const std::vector<uint8_t>& doomed);
// Velocity of a contact's side: of block a's corner, or of the point on block b's feature.
Vec2 contact_side_velocity(const Model& m, size_t contact, bool side_b);
// Adds the contact forces on deformable blocks to their nodes (continuum.force), gathered in
// a fixed order per block.
void add_contact_forces_to_nodes(Model& m);
// Each node's own stable step of the model's dimension (1e300 for a massless node): its zones',
// and for an outline node its mass against the joints (empty without zones).
std::vector<double> node_timesteps(const Model& m);

}  // namespace tessera
