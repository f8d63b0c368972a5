// Building 3D models: boxes and prisms, joint planes cut through them, brick walls, deletion.
#pragma once

#include <vector>

#include "tessera/core/model.hpp"
#include "tessera/generation/cutting3.hpp"

namespace tessera {

// Adds a convex block (world coordinates) with the density of its material; returns its index.
// Throws std::invalid_argument naming what is wrong with the polyhedron.
size_t add_block3(Model& m, const Polyhedron& p, int group, int material,
                  const std::vector<int>& face_tags = {});

// Cuts the selected blocks (all if empty) by the planes; pieces take their parent's group,
// material, fixity and velocity, and the model's blocks are renumbered (uncut blocks first, in
// order, then the pieces). Returns the number of blocks added.
size_t cut_model3(Model& m, const std::vector<size_t>& selection,
                  const std::vector<JointPlane>& planes);

// Cuts an opening through the selected blocks (all if empty) with `cut_opening`; the pieces
// inside round i join group round_groups[i], the rest keep their parent's group. With `join`,
// the rock pieces of each block cut are joined into one body (join_blocks3), so the planes that
// keep the pieces convex are no joints. Returns the number of blocks added.
size_t tunnel_model3(Model& m, const std::vector<size_t>& selection, const Opening3& o,
                     const std::vector<int>& round_groups, bool join = false);

// A running-bond wall one brick thick: courses along x stacked in z, the wall's thickness along
// y; every second course starts with a half brick.
struct WallSpec3 {
  Vec3 origin = Vec3::Zero();
  double length = 0.0, height = 0.0, width = 0.0;  // of a brick (x, z, y)
  int courses = 0, bricks = 0;
  int group = -1, material = -1, bed_tag = -1, head_tag = -1;
};
void add_wall3(Model& m, const WallSpec3& w);

// Removes blocks with their contacts (a piece of a concave block takes its whole body); histories
// of them end, the rest follow the renumbering.
void delete_blocks3(Model& m, const std::vector<size_t>& blocks);

// Joins the bodies of the selected blocks into one concave block (master: the lowest block);
// their contacts with each other go. Throws std::invalid_argument if a piece has no density.
void join_blocks3(Model& m, const std::vector<size_t>& blocks);

// The selection grown to whole bodies (every piece of each concave block touched).
std::vector<size_t> whole_bodies3(const Blocks3& B, const std::vector<size_t>& blocks);

}  // namespace tessera
