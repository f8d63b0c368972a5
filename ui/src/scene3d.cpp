#include "scene3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace tessera::ui {

namespace {
// View axes: right and up on the screen, and towards the viewer.
struct View {
  Vec3 right, up, eye;
  explicit View(const ViewOptions& o) {
    const double a = o.azimuth * std::numbers::pi / 180, e = o.elevation * std::numbers::pi / 180;
    eye = Vec3(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
    right = Vec3(-std::cos(a), std::sin(a), 0.0);
    up = eye.cross(right);
  }
  Vec2 operator()(const Vec3& p) const { return {p.dot(right), p.dot(up)}; }
};

Vec3 displacement(const SnapshotBlock& b) {
  return {b.x - b.x_ref, b.y - b.y_ref, b.z - b.z_ref};
}
}  // namespace

Snapshot flatten3(const Snapshot& s, const ViewOptions& o) {
  const View view(o);
  Snapshot flat;
  flat.three = true;
  flat.blocks = s.blocks;
  for (SnapshotBlock& b : flat.blocks) {
    const Vec2 at = view(Vec3(b.x, b.y, b.z)), ref = view(Vec3(b.x_ref, b.y_ref, b.z_ref));
    b.x = at.x(), b.y = at.y(), b.x_ref = ref.x(), b.y_ref = ref.y();
  }
  flat.contacts = s.contacts;
  for (SnapshotContact& c : flat.contacts) {
    c.point = c.from = c.to = view(c.point3);
    // The bar lies across the projected normal; a normal along the line of sight shows as a
    // square (any screen direction).
    const Vec2 n = view(c.normal3);
    c.normal = n.norm() > 1e-6 ? Vec2(n.normalized()) : Vec2(0, 1);
  }
  return flat;
}

void add_faces3(const Snapshot& s, const ViewOptions& o, const std::vector<Rgb>& colours,
                Scene& out) {
  const View view(o);
  struct Shown {
    double depth;
    ScenePolygon polygon;
  };
  std::vector<Shown> shown;
  for (const Snapshot::Face3& f : s.faces3) {
    const SnapshotBlock& b = s.blocks[static_cast<size_t>(f.block)];
    const Vec3 shift = (o.magnify - 1.0) * displacement(b);
    // Outward normal (Newell) and depth of the face.
    Vec3 n = Vec3::Zero(), c = Vec3::Zero();
    for (uint32_t k = f.begin; k < f.end; ++k) {
      const Vec3& p = s.points3[k];
      const Vec3& q = s.points3[k + 1 < f.end ? k + 1 : f.begin];
      n += p.cross(q), c += p;
    }
    const double facing = n.normalized().dot(view.eye);
    if (!(facing > 1e-9)) continue;
    Shown v;
    v.depth = (c / static_cast<double>(f.end - f.begin) + shift).dot(view.eye);
    v.polygon.block = f.block;
    for (uint32_t k = f.begin; k < f.end; ++k)
      v.polygon.points.push_back(view(s.points3[k] + shift));
    const Rgb base = colours[static_cast<size_t>(f.block)];
    const double light = 0.6 + 0.4 * facing;
    const auto shade = [&](unsigned char x) {
      return static_cast<unsigned char>(std::lround(std::min(255.0, x * light)));
    };
    v.polygon.colour = Rgb{shade(base.r), shade(base.g), shade(base.b)};
    shown.push_back(std::move(v));
  }
  std::stable_sort(shown.begin(), shown.end(),
                   [](const Shown& p, const Shown& q) { return p.depth < q.depth; });
  for (Shown& v : shown) out.polygons.push_back(std::move(v.polygon));
}

}  // namespace tessera::ui
