#include "tessera/core/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tessera {

double signed_area(const std::vector<Vec2>& pts) {
  double a = 0.0;
  for (size_t i = 0, n = pts.size(); i < n; ++i) a += cross(pts[i], pts[(i + 1) % n]);
  return 0.5 * a;
}

PolygonProperties polygon_properties(const std::vector<Vec2>& pts) {
  PolygonProperties p;
  const size_t n = pts.size();
  if (n < 3) return p;
  // Shift to the first vertex to keep the sums well conditioned far from the origin.
  const Vec2 o = pts[0];
  double a2 = 0.0, jx = 0.0, jy = 0.0;
  Vec2 c = Vec2::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 u = pts[i] - o, v = pts[(i + 1) % n] - o;
    const double w = cross(u, v);
    a2 += w;
    c += w * (u + v);
    jx += w * (u.x() * u.x() + u.x() * v.x() + v.x() * v.x());
    jy += w * (u.y() * u.y() + u.y() * v.y() + v.y() * v.y());
  }
  p.area = 0.5 * a2;
  const Vec2 cl = c / (3.0 * a2);
  p.centroid = o + cl;
  // Second moments about the shifted origin, then parallel-axis to the centroid.
  const double j0 = (jx + jy) / 12.0;
  p.polar_moment = j0 - p.area * cl.squaredNorm();
  return p;
}

bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Collinear or touching cases: a point on the other segment.
  auto on_seg = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && on_seg(a, b, c)) || (d2 == 0 && on_seg(a, b, d)) ||
         (d3 == 0 && on_seg(c, d, a)) || (d4 == 0 && on_seg(c, d, b));
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& pts) {
  bool inside = false;
  for (size_t i = 0, n = pts.size(), j = n - 1; i < n; j = i++) {
    const Vec2 &a = pts[i], &b = pts[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

std::string polygon_problem(const std::vector<Vec2>& pts) {
  const size_t n = pts.size();
  if (n < 3) return "a block needs at least 3 vertices";
  for (const Vec2& p : pts)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return "a vertex is not a finite number";
  double size = 0.0;
  for (size_t i = 0; i < n; ++i) size = std::max(size, (pts[i] - pts[0]).norm());
  for (size_t i = 0; i < n; ++i) {
    if ((pts[(i + 1) % n] - pts[i]).norm() <= 1e-9 * size) {
      std::ostringstream s;
      s << "vertices " << i + 1 << " and " << (i + 1) % n + 1 << " coincide";
      return s.str();
    }
  }
  // Non-adjacent edges must not meet.
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;
      if (segments_intersect(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n])) {
        std::ostringstream s;
        s << "edges " << i + 1 << " and " << j + 1 << " cross (the polygon is self-intersecting)";
        return s.str();
      }
    }
  if (std::abs(signed_area(pts)) <= 1e-9 * size * size) return "the polygon has no area";
  return {};
}

std::vector<RoundedCorner> round_corners(const std::vector<Vec2>& pts, double d) {
  const size_t n = pts.size();
  std::vector<RoundedCorner> out(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec2& prev = pts[(i + n - 1) % n];
    const Vec2& p = pts[i];
    const Vec2& next = pts[(i + 1) % n];
    const double len_in = (p - prev).norm(), len_out = (next - p).norm();
    const Vec2 e1 = (p - prev) / len_in, e2 = (next - p) / len_out;
    const double turn = std::atan2(cross(e1, e2), e1.dot(e2));  // exterior turning angle
    RoundedCorner& c = out[i];
    c.convex = turn > 1e-12;
    if (!c.convex) {
      c.centre = p;
      continue;
    }
    c.length = std::min(d, 0.45 * std::min(len_in, len_out));
    // Interior angle is pi - turn; radius = length * tan(interior / 2) = length / tan(turn / 2).
    c.radius = c.length / std::tan(0.5 * turn);
    c.centre = p - e1 * c.length + perp(e1) * c.radius;
  }
  return out;
}

}  // namespace tessera
