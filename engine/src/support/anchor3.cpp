// Points fixed in 3D blocks (rigid bodies or zones): where they are, how they move, how they
// follow a deletion, and which block holds one.
#include "tessera/support/anchor3.hpp"

#include <algorithm>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

Vec3 anchor_position(const Model& m, const Anchor3& p) {
  if (p.node[0] >= 0) {
    Vec3 x = Vec3::Zero();
    for (int k = 0; k < 4; ++k) x += p.w[k] * m.continuum3.pos[static_cast<size_t>(p.node[k])];
    return x;
  }
  const RigidBody3& body = m.blocks3.body[static_cast<size_t>(p.body)];
  return body.position + body.orientation * Vec3(p.local[0], p.local[1], p.local[2]);
}

Vec3 anchor_velocity(const Model& m, const Anchor3& p) {
  if (p.node[0] >= 0) {
    Vec3 v = Vec3::Zero();
    for (int k = 0; k < 4; ++k) v += p.w[k] * m.continuum3.vel[static_cast<size_t>(p.node[k])];
    return v;
  }
  const auto b = static_cast<size_t>(p.body);
  const RigidBody3& body = m.blocks3.body[b];
  return body.velocity + m.blocks3.omega[b].cross(anchor_position(m, p) - body.position);
}

Anchor3 make_anchor3(const Model& m, size_t b, const Vec3& p) {
  Anchor3 a;
  a.block = static_cast<int32_t>(b);
  const Blocks3& B = m.blocks3;
  a.body = B.master[b];
  if (B.deformable[b]) {
    // The zone of this body holding p (or, on its surface, the nearest by its weights): a body
    // of joined pieces is zoned as one mesh.
    const Continuum3& c = m.continuum3;
    double best = -1e300;
    for (size_t piece = 0; piece < B.size(); ++piece) {
      if (B.master[piece] != a.body || !B.deformable[piece]) continue;
      for (uint32_t z = B.zone_begin[piece]; z < B.zone_end[piece]; ++z) {
        const auto& t = c.zones[z];
        Eigen::Matrix3d J;
        for (int k = 0; k < 3; ++k) J.col(k) = c.pos[t[k + 1]] - c.pos[t[0]];
        if (!(std::abs(J.determinant()) > 0.0)) continue;
        const Vec3 l = J.inverse() * (p - c.pos[t[0]]);
        const std::array<double, 4> w{1.0 - l.sum(), l.x(), l.y(), l.z()};
        const double worst = *std::min_element(w.begin(), w.end());
        if (worst <= best || worst < -1e-6) continue;
        best = worst, a.w = w;
        for (int k = 0; k < 4; ++k) a.node[k] = static_cast<int32_t>(t[k]);
      }
    }
    if (a.node[0] < 0)
      throw ModelError("no zone of block " + std::to_string(B.id[b]) + " holds the point (" +
                       std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
                       std::to_string(p.z()) + ")");
    return a;
  }
  const RigidBody3& body = m.blocks3.body[static_cast<size_t>(a.body)];
  const Vec3 local = body.orientation.conjugate() * (p - body.position);
  a.local = {local.x(), local.y(), local.z()};
  return a;
}

bool follow_anchor(Anchor3& a, const std::vector<int>& map, const std::vector<int64_t>& node_map) {
  if (a.block < 0 || map[static_cast<size_t>(a.block)] < 0) return false;
  if (map[static_cast<size_t>(a.body)] < 0) return false;
  a.block = map[static_cast<size_t>(a.block)], a.body = map[static_cast<size_t>(a.body)];
  return renumber_nodes(a.node, node_map);
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
