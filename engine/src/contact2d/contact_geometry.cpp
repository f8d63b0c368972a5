#include "tessera/contact2d/contact_geometry.hpp"

#include <cmath>

#include "tessera/contact2d/contacts.hpp"

namespace tessera {

namespace {

// Outward unit normal of the edge starting at global vertex v (counter-clockwise blocks).
inline Vec2 edge_normal(const Blocks& B, uint32_t v) {
  const Vec2& u = B.world_edge_dir[v];
  return {u.y(), -u.x()};
}

// Chord of two overlapping circles (radius r1, r2, centres D apart).
inline double circle_chord(double d, double r1, double r2) {
  if (d <= 0.0 || d >= r1 + r2 || d <= std::abs(r1 - r2)) return 0.0;
  const double k = (-d + r1 - r2) * (-d - r1 + r2) * (-d + r1 + r2) * (d + r1 + r2);
  return k > 0.0 ? std::sqrt(k) / d : 0.0;
}

// Whether p lies inside block b's outline (crossing number over its world vertices).
bool inside_outline(const Blocks& B, uint32_t b, const Vec2& p) {
  bool in = false;
  const uint32_t v0 = B.vert_begin[b], v1 = B.vert_begin[b + 1];
  for (uint32_t i = v0, j = v1 - 1; i < v1; j = i++) {
    const Vec2 &a = B.world_vertex[i], &c = B.world_vertex[j];
    if ((a.y() > p.y()) != (c.y() > p.y()) &&
        p.x() < (c.x() - a.x()) * (p.y() - a.y()) / (c.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

}  // namespace

bool corner_feature(const Blocks& B, uint32_t b, uint32_t vk, const CornerArc& arc,
                    double max_depth, FeatureHit& h) {
  const Vec2& c = arc.centre;
  const double r = arc.radius;
  const uint32_t vp = B.prev_vertex(b, vk);
  const Vec2& cb = B.world_arc_centre[vk];
  Vec2 dv = c - cb;
  double d = dv.norm();
  if (d <= 0.0) return false;
  // The owner's arc towards the other: along the line of centres if the arc faces that
  // way, else from the end of the arc nearer to the other one.
  Vec2 qa = c;
  double ra = r;
  if (!arc_faces(arc, -dv / d)) {
    const Vec2 e0 = c + r * arc.n_in, e1 = c + r * arc.n_out;
    qa = (e0 - cb).squaredNorm() <= (e1 - cb).squaredNorm() ? e0 : e1, ra = 0.0;
    dv = qa - cb, d = dv.norm();
    if (d <= 0.0) return false;
  }
  const double slack = 1e-9 * d;
  if (cross(edge_normal(B, vp), dv) < -slack || cross(dv, edge_normal(B, vk)) < -slack)
    return false;
  const double rb = B.arc_radius[vk];
  h.kind = kCornerCorner, h.feature = vk, h.gap = d - ra - rb, h.normal = dv / d;
  if (h.gap < -max_depth) return false;
  h.point = qa - h.normal * (ra + 0.5 * h.gap);
  h.chord = circle_chord(d, ra, rb);
  return true;
}

bool nearest_feature(const Blocks& B, uint32_t b, const CornerArc& arc, bool corners, int first,
                     int count, double max_depth, FeatureHit& hit) {
  const uint32_t v0 = B.vert_begin[b];
  const int n = static_cast<int>(B.vertex_count(b));
  const int nf = 2 * n;
  bool found = false;
  double best = 0.0;
  FeatureHit h;
  // Feature f, from `first` onwards around the block (wrapped once here, then by a compare: the
  // signed divisions of a modulo per feature cost a fifth of the search).
  int f = (first % nf + nf) % nf;
  for (int s = 0; s < count && s < nf; ++s, f = f + 1 == nf ? 0 : f + 1) {
    const uint32_t vk = v0 + static_cast<uint32_t>(f >> 1);
    if (f & 1) {
      if (!edge_feature(B, b, vk, arc, max_depth, h, nullptr)) continue;
      // Deep behind an edge's line (a tenth of the deepest contact allowed) yet outside the
      // block: a corner beside a thin tip of the block, met at the tip's corner, not in it.
      if (h.gap < -0.1 * max_depth && !inside_outline(B, b, h.point + 0.5 * h.gap * h.normal))
        continue;
    } else {
      // Rounded corner: valid inside the cone of its two edge normals. A straight node of a
      // deformable block (no rounding) is met through the edges on either side of it.
      if (!corners || !B.convex[vk] || B.arc_radius[vk] <= 0.0) continue;
      if (!corner_feature(B, b, vk, arc, max_depth, h)) continue;
    }
    if (found && std::abs(h.gap) >= best) continue;
    found = true, best = std::abs(h.gap), hit = h;
  }
  return found;
}

}  // namespace tessera
