// The common plane of two convex blocks: the separating-axis candidates and the best of them.
#include "tessera/contact3d/common_plane.hpp"

#include <cmath>

#include "tessera/contact3d/detection3.hpp"
#include "tessera/contact3d/subcontacts.hpp"

namespace tessera {

double min_dot(const Blocks3& B, uint32_t b, const Vec3& n) {
  double lo = 1e300;
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
    lo = std::min(lo, n.dot(B.world_vertex[v]));
  return lo;
}

double max_dot(const Blocks3& B, uint32_t b, const Vec3& n) {
  double hi = -1e300;
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
    hi = std::max(hi, n.dot(B.world_vertex[v]));
  return hi;
}

PlaneFit evaluate_plane(const Blocks3& B, uint32_t a, uint32_t b, uint8_t kind, uint32_t ia,
                        uint32_t ib) {
  PlaneFit f;
  f.kind = kind, f.ia = ia, f.ib = ib;
  if (kind == kPlaneFaceB) {
    f.normal = B.world_normal[ib];
    f.lo_a = min_dot(B, a, f.normal), f.hi_b = B.world_offset[ib];
    f.gap = f.lo_a - f.hi_b;
  } else if (kind == kPlaneFaceA) {
    f.normal = -B.world_normal[ia];
    f.lo_a = -B.world_offset[ia], f.hi_b = max_dot(B, b, f.normal);
    f.gap = f.lo_a - f.hi_b;
  } else {
    Vec3 n = B.world_dir[ia].cross(B.world_dir[ib]);
    const double len = n.norm();
    if (len < 1e-3) return f;
    n /= len;
    // Either sign of the cross product: the one that separates better.
    const double lo_up = min_dot(B, a, n), hi_up = max_dot(B, b, n);
    const double lo_down = -max_dot(B, a, n), hi_down = -min_dot(B, b, n);
    if (lo_up - hi_up >= lo_down - hi_down)
      f.normal = n, f.lo_a = lo_up, f.hi_b = hi_up;
    else
      f.normal = -n, f.lo_a = lo_down, f.hi_b = hi_down;
    f.gap = f.lo_a - f.hi_b;
  }
  return f;
}

PlaneFit best_plane(const Blocks3& B, uint32_t a, uint32_t b) {
  PlaneFit best;
  const auto consider = [&](const PlaneFit& f, double margin) {
    if (f.gap > best.gap + margin) best = f;
  };
  for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f)
    consider(evaluate_plane(B, a, b, kPlaneFaceB, 0, f), 0.0);
  for (uint32_t f = B.face_begin[a]; f < B.face_begin[a + 1]; ++f)
    consider(evaluate_plane(B, a, b, kPlaneFaceA, f, 0), 0.0);
  // Edge crossings only where they beat every face clearly (between parallel faces an edge
  // pair gives the same plane again).
  const double margin = 1e-9 * (B.bound_radius[a] + B.bound_radius[b]);
  for (uint32_t i = B.dir_begin[a]; i < B.dir_begin[a + 1]; ++i)
    for (uint32_t j = B.dir_begin[b]; j < B.dir_begin[b + 1]; ++j)
      consider(evaluate_plane(B, a, b, kPlaneEdges, i, j), margin);
  return best;
}

}  // namespace tessera
