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

void set_bar_depths3(const Snapshot& s, const ViewOptions& o, Scene& out) {
  const View view(o);
  for (SceneBar& bar : out.bars) {
    if (bar.contact < 0 || static_cast<size_t>(bar.contact) >= s.contacts.size()) continue;
    const SnapshotContact& c = s.contacts[static_cast<size_t>(bar.contact)];
    Vec3 at = c.point3;
    // Magnified like the blocks: the bar moves with block a.
    if (c.a >= 0 && static_cast<size_t>(c.a) < s.blocks.size())
      at += (o.magnify - 1.0) * displacement(s.blocks[static_cast<size_t>(c.a)]);
    bar.depth = at.dot(view.eye);
  }
}

void add_faces3(const Snapshot& s, const ViewOptions& o, const std::vector<Rgb>& colours,
                Scene& out,
                const std::function<std::optional<Rgb>(const SnapshotZone&)>& zone_colour) {
  const View view(o);
  // Shaded by how squarely the polygon faces the viewer.
  const auto shaded = [](Rgb base, double facing) {
    const double light = 0.6 + 0.4 * facing;
    const auto shade = [&](unsigned char x) {
      return static_cast<unsigned char>(std::lround(std::min(255.0, x * light)));
    };
    return Rgb{shade(base.r), shade(base.g), shade(base.b)};
  };
  // A polygon of world points if it faces the viewer.
  const auto show = [&](const std::vector<Vec3>& pts, int block, Rgb base, bool outline) {
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < pts.size(); ++k) n += pts[k].cross(pts[(k + 1) % pts.size()]);
    const double facing = n.normalized().dot(view.eye);
    if (!(facing > 1e-9)) return;
    ScenePolygon polygon;
    polygon.block = block;
    polygon.outline = outline;
    for (const Vec3& p : pts)
      polygon.points.push_back(view(p)), polygon.depth.push_back(p.dot(view.eye));
    polygon.colour = shaded(base, facing);
    out.polygons.push_back(std::move(polygon));
  };
  // Faces of deformable blocks drawn by their zones' surface triangles (tris3 come grouped by
  // face, in face order).
  std::vector<uint8_t> by_zones(s.faces3.size(), 0);
  if (zone_colour) {
    std::vector<Vec3> tri(3);
    for (const Snapshot::Tri3& t : s.tris3) {
      by_zones[t.face] = 1;
      const std::optional<Rgb> colour = zone_colour(s.zones[t.zone]);
      if (!colour) continue;
      for (int k = 0; k < 3; ++k)
        tri[static_cast<size_t>(k)] =
            s.nodes3_start[t.n[k]] + o.magnify * (s.nodes3[t.n[k]] - s.nodes3_start[t.n[k]]);
      show(tri, s.faces3[t.face].block, *colour, false);
    }
  }
  std::vector<Vec3> pts;
  for (size_t f = 0; f < s.faces3.size(); ++f) {
    if (by_zones[f]) continue;
    const Snapshot::Face3& face = s.faces3[f];
    const SnapshotBlock& b = s.blocks[static_cast<size_t>(face.block)];
    const Vec3 shift = (o.magnify - 1.0) * displacement(b);
    pts.clear();
    for (uint32_t k = face.begin; k < face.end; ++k) pts.push_back(s.points3[k] + shift);
    show(pts, face.block, colours[static_cast<size_t>(face.block)], true);
  }
}

}  // namespace tessera::ui
