// The common plane of two 3D blocks (chapter 5.3.1, contact3d/common_plane.cpp): candidates
// from a face of either block or an edge of each, and the gap each gives.
#pragma once

#include "tessera/contact3d/blocks3.hpp"

namespace tessera {

// A common-plane candidate and the gap it gives (see contacts3.hpp).
struct PlaneFit {
  uint8_t kind = 0;
  uint32_t ia = 0, ib = 0;
  Vec3 normal = Vec3::UnitZ();
  double gap = -1e300;
  double lo_a = 0.0, hi_b = 0.0;  // support values of a and b along the normal
};
// Support values of block b along n: the least and greatest n . x over its vertices.
double min_dot(const Blocks3& B, uint32_t b, const Vec3& n);
double max_dot(const Blocks3& B, uint32_t b, const Vec3& n);
// The normal and gap of one candidate; the gap is -1e300 for a degenerate one (parallel edges).
PlaneFit evaluate_plane(const Blocks3& B, uint32_t a, uint32_t b, uint8_t kind, uint32_t ia,
                        uint32_t ib);
// The best of every candidate for blocks a and b.
PlaneFit best_plane(const Blocks3& B, uint32_t a, uint32_t b);

}  // namespace tessera
