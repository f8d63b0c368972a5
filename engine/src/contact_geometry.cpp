#include "tessera/contact_geometry.hpp"

#include <cmath>

#include "tessera/contacts.hpp"

namespace tessera {

namespace {

// Outward unit normal of edge k of a counter-clockwise block (vertex indices global).
inline Vec2 edge_normal(const Vec2& p, const Vec2& q) {
  const Vec2 u = (q - p).normalized();
  return {u.y(), -u.x()};
}

// Chord of two overlapping circles (radius r1, r2, centres D apart).
inline double circle_chord(double d, double r1, double r2) {
  if (d <= 0.0 || d >= r1 + r2 || d <= std::abs(r1 - r2)) return 0.0;
  const double k = (-d + r1 - r2) * (-d - r1 + r2) * (-d + r1 + r2) * (d + r1 + r2);
  return k > 0.0 ? std::sqrt(k) / d : 0.0;
}

}  // namespace

bool nearest_feature(const Blocks& B, uint32_t b, const Vec2& c, double r, bool corners,
                     int first, int count, double max_depth, FeatureHit& hit) {
  const uint32_t v0 = B.vert_begin[b];
  const int n = static_cast<int>(B.vertex_count(b));
  const int nf = 2 * n;
  bool found = false;
  double best = 0.0;
  for (int s = 0; s < count && s < nf; ++s) {
    const int f = ((first + s) % nf + nf) % nf;
    const int k = f / 2;
    const uint32_t vk = v0 + static_cast<uint32_t>(k);
    if (f % 2 == 1) {
      // Straight part of edge k: between the tangent points of the rounded corners.
      const uint32_t vn = v0 + static_cast<uint32_t>((k + 1) % n);
      const Vec2 &p = B.world_vertex[vk], &q = B.world_vertex[vn];
      const Vec2 e = q - p;
      const double len = e.norm();
      const Vec2 u = e / len;
      const double t = (c - p).dot(u);
      // A hair of slack at the span's ends, so that round-off never leaves a corner that sits
      // exactly at a tangent point without a feature.
      const double slack = 1e-9 * len;
      const double lo = (B.convex[vk] ? B.round_length[vk] : 0.0) - slack;
      const double hi = len - (B.convex[vn] ? B.round_length[vn] : 0.0) + slack;
      if (t < lo || t > hi) continue;
      const Vec2 nrm(u.y(), -u.x());
      const double gap = (c - p).dot(nrm) - r;
      if (gap < -max_depth || (found && std::abs(gap) >= best)) continue;
      found = true, best = std::abs(gap);
      hit.kind = kCornerEdge, hit.feature = vk, hit.gap = gap, hit.normal = nrm;
      hit.point = c - nrm * (r + 0.5 * gap);
      const double o = -gap;
      hit.chord = o > 0.0 ? 2.0 * std::sqrt(o * std::max(2.0 * r - o, 0.0)) : 0.0;
    } else {
      // Rounded corner k: valid inside the cone of its two edge normals.
      if (!corners || !B.convex[vk]) continue;
      const uint32_t vp = v0 + static_cast<uint32_t>((k + n - 1) % n);
      const uint32_t vn = v0 + static_cast<uint32_t>((k + 1) % n);
      const Vec2 n_prev = edge_normal(B.world_vertex[vp], B.world_vertex[vk]);
      const Vec2 n_next = edge_normal(B.world_vertex[vk], B.world_vertex[vn]);
      const Vec2 dv = c - B.world_arc_centre[vk];
      const double d = dv.norm();
      const double slack = 1e-9 * d;
      if (cross(n_prev, dv) < -slack || cross(dv, n_next) < -slack) continue;
      if (d <= 0.0) continue;
      const double rb = B.arc_radius[vk];
      const double gap = d - r - rb;
      if (gap < -max_depth || (found && std::abs(gap) >= best)) continue;
      found = true, best = std::abs(gap);
      hit.kind = kCornerCorner, hit.feature = vk, hit.gap = gap, hit.normal = dv / d;
      hit.point = c - hit.normal * (r + 0.5 * gap);
      hit.chord = circle_chord(d, r, rb);
    }
  }
  return found;
}

}  // namespace tessera
