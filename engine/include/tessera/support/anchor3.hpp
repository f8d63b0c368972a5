// A point fixed in a 3D block, where support holds the rock: in a rigid block's body, or in a
// zone of a deformable block.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"

namespace tessera {

struct Model;

// `block` is the block that holds the point (deleting it deletes the anchor). In a rigid block
// the point is `local`, in the frame of `body`, the block whose RigidBody3 moves it (the master
// of a concave block's pieces). In a deformable block it is in the tetrahedron of the corner
// nodes `node` (node[0] >= 0), at the weights `w` (of a 10-node zone, its corners: the force
// they take has the same resultant and moment). Trivially copyable: state files write its bytes.
struct Anchor3 {
  std::array<double, 3> local{0.0, 0.0, 0.0};
  std::array<double, 4> w{0.0, 0.0, 0.0, 0.0};
  int32_t block = -1, body = -1;
  std::array<int32_t, 4> node{-1, -1, -1, -1};
};
static_assert(sizeof(Anchor3) == 80);

Vec3 anchor_position(const Model& m, const Anchor3& p);
Vec3 anchor_velocity(const Model& m, const Anchor3& p);
// An anchor at world point p in block b (in the zone holding p if b is deformable). Throws
// ModelError if no zone of a deformable block holds it.
Anchor3 make_anchor3(const Model& m, size_t b, const Vec3& p);
// After blocks are deleted and nodes renumbered, as follow_anchor for 2D anchors.
bool follow_anchor(Anchor3& a, const std::vector<int>& map, const std::vector<int64_t>& node_map);
// The block holding p, or the one whose surface is nearest within `tol`; -1 if none.
int block3_at(const Model& m, const Vec3& p, double tol);

}  // namespace tessera
