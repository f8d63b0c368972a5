// Points, snapping and commands of the drawing tools.
#include "tessera/ui/draw_tool.hpp"

#include <cmath>
#include <cstdio>

namespace tessera::ui {

namespace {
// A coordinate as the script reads it back: shortest form, no trailing zeros.
std::string coordinate(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}
}  // namespace

void Drawing::add(Vec2 p) {
  if (mode_ == DrawMode::kNone || mode_ == DrawMode::kSelect) return;
  if (!points_.empty() && (points_.back() - p).norm() == 0.0) return;
  points_.push_back(p);
}

bool Drawing::complete() const {
  return points_.size() >= (mode_ == DrawMode::kBlock ? 3u : 2u);
}

std::string Drawing::command(const std::string& group, const std::string& material) const {
  if (!complete() || mode_ == DrawMode::kNone || mode_ == DrawMode::kSelect) return {};
  std::string out = mode_ == DrawMode::kBlock ? "block" : "crack";
  // Appended piece by piece (GCC 12 warns falsely on " " + std::string temporaries).
  for (const Vec2& p : points_) {
    out.append(" ").append(coordinate(p.x())).append(",").append(coordinate(p.y()));
  }
  if (mode_ == DrawMode::kBlock) {
    if (!group.empty()) out.append(" group=").append(group);
    if (!material.empty()) out.append(" material=").append(material);
  }
  return out;
}

Vec2 Drawing::snap(Vec2 p, const Scene& scene, double grid, double reach) {
  double best = reach;
  Vec2 found = p;
  bool hit = false;
  for (const auto& poly : scene.polygons)
    for (const Vec2& v : poly.points)
      if (const double d = (v - p).norm(); d <= best) best = d, found = v, hit = true;
  if (hit) return found;
  if (grid > 0) return {grid * std::round(p.x() / grid), grid * std::round(p.y() / grid)};
  return p;
}

}  // namespace tessera::ui
