// Points fixed in rigid 3D blocks: where they are, how they move, and which block holds one.
#include "tessera/support/anchor3.hpp"

#include <algorithm>

#include "tessera/core/model.hpp"

namespace tessera {

Vec3 anchor_position(const Model& m, const Anchor3& p) {
  const RigidBody3& body = m.blocks3.body[static_cast<size_t>(p.body)];
  return body.position + body.orientation * Vec3(p.local[0], p.local[1], p.local[2]);
}

Vec3 anchor_velocity(const Model& m, const Anchor3& p) {
  const auto b = static_cast<size_t>(p.body);
  const RigidBody3& body = m.blocks3.body[b];
  return body.velocity + m.blocks3.omega[b].cross(anchor_position(m, p) - body.position);
}

Anchor3 make_anchor3(const Model& m, size_t b, const Vec3& p) {
  Anchor3 a;
  a.block = static_cast<int32_t>(b);
  a.body = m.blocks3.master[b];
  const RigidBody3& body = m.blocks3.body[static_cast<size_t>(a.body)];
  const Vec3 local = body.orientation.conjugate() * (p - body.position);
  a.local = {local.x(), local.y(), local.z()};
  return a;
}

int block3_at(const Model& m, const Vec3& p, double tol) {
  const Blocks3& B = m.blocks3;
  // The search ends at a block holding the point; without a tolerance only those count.
  int best = -1;
  double nearest = std::max(tol, 0.0);
  for (size_t b = 0; b < B.size() && (best < 0 || nearest > 0.0); ++b) {
    double outside = -1e300;
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f)
      outside = std::max(outside, B.world_normal[f].dot(p) - B.world_offset[f]);
    if (B.contains(b, p)) outside = 0.0;
    if (outside <= nearest) nearest = outside, best = static_cast<int>(b);
  }
  return best;
}

}  // namespace tessera
