// A point fixed in a rigid 3D block, where support holds the rock.
#pragma once

#include <array>
#include <cstdint>

#include "tessera/contact3d/polyhedron.hpp"

namespace tessera {

struct Model;

// The point in the frame of the body that moves its block (the master of a concave block's
// pieces): `block` is the piece that holds it (deleting that piece deletes the anchor), `body`
// the block whose RigidBody3 carries it. (Trivially copyable: state files write its bytes.)
struct Anchor3 {
  std::array<double, 3> local{0.0, 0.0, 0.0};
  int32_t block = -1, body = -1;
};
static_assert(sizeof(Anchor3) == 32);

Vec3 anchor_position(const Model& m, const Anchor3& p);
Vec3 anchor_velocity(const Model& m, const Anchor3& p);
// An anchor at world point p in block b.
Anchor3 make_anchor3(const Model& m, size_t b, const Vec3& p);
// The block holding p, or the one whose surface is nearest within `tol`; -1 if none.
int block3_at(const Model& m, const Vec3& p, double tol);

}  // namespace tessera
