// Triangles scan-converted into a colour image and a depth buffer.
#include "depth_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tessera::ui {

namespace {
// A point on the image: pixel coordinates and the height towards the viewer.
struct Pixel {
  double x, y, z;
};

class Raster {
 public:
  static constexpr double kSlack = 1e-9;

  explicit Raster(QSize size)
      : image_(size, QImage::Format_ARGB32),
        depth_(static_cast<size_t>(size.width()) * static_cast<size_t>(size.height()),
               -std::numeric_limits<double>::infinity()) {
    image_.fill(Qt::transparent);
  }

  // Fills the pixels whose centres lie in the triangle where it is the nearest so far.
  void triangle(const Pixel& a, const Pixel& b, const Pixel& c, QRgb colour) {
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (!(std::abs(area) > 1e-12)) return;
    const int w = image_.width(), h = image_.height();
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(w - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(h - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y) {
      auto* row = reinterpret_cast<QRgb*>(image_.scanLine(y));
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Barycentric weights of the pixel's centre (all of one sign inside).
        const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
        const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
        const double wc = 1.0 - wa - wb;
        // A hair of slack, so that a pixel centre on an edge two triangles share is covered.
        if (wa < -kSlack || wb < -kSlack || wc < -kSlack) continue;
        const double z = wa * a.z + wb * b.z + wc * c.z;
        double& nearest =
            depth_[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
        if (z < nearest) continue;
        nearest = z, row[x] = colour;
      }
    }
  }

  // A segment `width` pixels wide, as two triangles.
  void segment(const Pixel& a, const Pixel& b, double width, QRgb colour) {
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (!(len > 0)) return;
    const double nx = -dy / len * 0.5 * width, ny = dx / len * 0.5 * width;
    const double ex = dx / len * 0.5 * width, ey = dy / len * 0.5 * width;  // square caps
    const Pixel p0{a.x + nx - ex, a.y + ny - ey, a.z}, p1{a.x - nx - ex, a.y - ny - ey, a.z},
        p2{b.x - nx + ex, b.y - ny + ey, b.z}, p3{b.x + nx + ex, b.y + ny + ey, b.z};
    triangle(p0, p1, p2, colour);
    triangle(p0, p2, p3, colour);
  }

  QImage take() { return std::move(image_); }

 private:
  QImage image_;
  std::vector<double> depth_;
};
}  // namespace

QImage depth_raster(const Scene& s, QSize size, const std::function<QPointF(const Vec2&)>& map,
                    double edge_px) {
  Raster r(size);
  // Outlines and bars sit this far in front of their faces: a ten-thousandth of the depth the
  // scene spans, far less than blocks are apart in front of one another.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& poly : s.polygons)
    for (double z : poly.depth) lo = std::min(lo, z), hi = std::max(hi, z);
  const double span = std::max(hi - lo, (s.hi - s.lo).norm());
  const double lift = 1e-4 * std::max(span, 1e-12);
  const auto pixel = [&](const Vec2& v, double z) {
    const QPointF q = map(v);
    return Pixel{q.x(), q.y(), z};
  };
  // Faces, fanned into triangles (they are convex).
  for (const auto& poly : s.polygons) {
    if (poly.points.size() < 3 || poly.depth.size() != poly.points.size()) continue;
    const QRgb colour = qRgb(poly.colour.r, poly.colour.g, poly.colour.b);
    const Pixel first = pixel(poly.points[0], poly.depth[0]);
    for (size_t k = 1; k + 1 < poly.points.size(); ++k)
      r.triangle(first, pixel(poly.points[k], poly.depth[k]),
                 pixel(poly.points[k + 1], poly.depth[k + 1]), colour);
  }
  const QRgb edge = qRgb(60, 60, 60);
  for (const auto& poly : s.polygons) {
    if (!poly.outline || poly.depth.size() != poly.points.size()) continue;
    for (size_t k = 0; k < poly.points.size(); ++k) {
      const size_t j = (k + 1) % poly.points.size();
      r.segment(pixel(poly.points[k], poly.depth[k] + lift),
                pixel(poly.points[j], poly.depth[j] + lift), edge_px, edge);
    }
  }
  for (const auto& bar : s.bars) {
    const QRgb colour = qRgb(bar.colour.r, bar.colour.g, bar.colour.b);
    // (3D support lies inside the rock: drawn over every face)
    const double z = bar.over ? std::numeric_limits<double>::max() : bar.depth + 2 * lift;
    r.triangle(pixel(bar.corners[0], z), pixel(bar.corners[1], z), pixel(bar.corners[2], z),
               colour);
    r.triangle(pixel(bar.corners[0], z), pixel(bar.corners[2], z), pixel(bar.corners[3], z),
               colour);
  }
  return r.take();
}

}  // namespace tessera::ui
