// Plane geometry of polygonal blocks: mass properties, validity checks and corner rounding.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace tessera {

using Vec2 = Eigen::Vector2d;

// z-component of the cross product of two plane vectors.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
// The vector turned 90 degrees counter-clockwise.
inline Vec2 perp(const Vec2& a) {
  return {-a.y(), a.x()};
}

// Area, centroid and polar second moment (about the centroid) of a simple polygon.
struct PolygonProperties {
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  double polar_moment = 0.0;  // integral of r^2 dA about the centroid
};

double signed_area(const std::vector<Vec2>& pts);
PolygonProperties polygon_properties(const std::vector<Vec2>& pts);

// Empty when the polygon is usable as a block; otherwise a sentence saying what is wrong.
std::string polygon_problem(const std::vector<Vec2>& pts);

// True if the two closed segments a-b and c-d cross or touch.
bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
// Distance from p to the closed segment a-b.
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);
// True if p lies strictly inside the polygon (even-odd rule).
bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& pts);

// The rounded corner of a counter-clockwise polygon (chapter 5.2.1): an arc tangent to both
// edges at `length` from the corner. Concave corners are not rounded (radius 0).
struct RoundedCorner {
  Vec2 centre = Vec2::Zero();  // arc centre
  double radius = 0.0;
  double length = 0.0;  // distance from the corner to the tangent points
  bool convex = false;
};

// Rounds every corner with length d, limited to 0.45 of the shorter adjacent edge.
std::vector<RoundedCorner> round_corners(const std::vector<Vec2>& ccw_pts, double d);

}  // namespace tessera
