// Zoning: a block cut into the uniform-strain triangles of a deformable block (§5.2.1).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "tessera/core/geometry.hpp"

namespace tessera {

struct ZoneMesh {
  std::vector<Vec2> nodes;
  std::vector<uint8_t> on_boundary;                // per node: lies on the block's outline
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise
  double min_angle = 0.0;                          // smallest zone angle, degrees
  double max_edge = 0.0;                           // longest zone edge
};

// Finer zones near a point: edge `fine_edge` within `radius` of `centre`, growing by `growth`
// per metre beyond it, up to the mesh's largest size (one rule for triangles and tetrahedra).
template <class Point>
struct Grading {
  Point centre = Point::Zero();
  double radius = 0.0, fine_edge = 0.0, growth = 0.25;
  double size_at(const Point& p, double max_edge) const {
    const double d = std::max(0.0, (p - centre).norm() - radius);
    return std::min(max_edge, fine_edge + growth * d);
  }
};
using ZoneGrading = Grading<Vec2>;

// Triangulates a simple polygon (counter-clockwise, convex or not) with CGAL's constrained
// Delaunay refinement: zone edges no longer than `max_edge`, angles of about 20 degrees or more
// where the outline allows. Every polygon vertex is a node. Throws std::invalid_argument for a
// degenerate outline or a size that would make more than `max_zones` zones.
// With a grading, zones are finer near its centre.
ZoneMesh zone_polygon(const std::vector<Vec2>& polygon, double max_edge, size_t max_zones = 2000000,
                      const ZoneGrading* grading = nullptr);

}  // namespace tessera
