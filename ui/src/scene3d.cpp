#include "scene3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/generation/cutting3.hpp"

namespace tessera::ui {

ViewAxes::ViewAxes(double azimuth, double elevation) {
  const double a = azimuth * std::numbers::pi / 180, e = elevation * std::numbers::pi / 180;
  eye = Vec3(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
  right = Vec3(-std::cos(a), std::sin(a), 0.0);
  up = eye.cross(right);
}

namespace {
// The near plane's distance from the eye, as a share of the focal distance.
constexpr double kNear = 0.01;
}  // namespace

ViewAxes::ViewAxes(const ViewOptions& o) : ViewAxes(o.azimuth, o.elevation) {
  if (o.perspective && o.has_camera && o.distance > 0)
    perspective = true, focus = o.focus, distance = o.distance;
}

Vec2 ViewAxes::operator()(const Vec3& p) const {
  if (!perspective) return {p.dot(right), p.dot(up)};
  const Vec3 q = p - focus;
  const double k = distance / std::max(distance - q.dot(eye), kNear * distance);
  return Vec2(focus.dot(right), focus.dot(up)) + k * Vec2(q.dot(right), q.dot(up));
}

double ViewAxes::depth(const Vec3& p) const {
  if (!perspective) return p.dot(eye);
  const double h = (p - focus).dot(eye);
  return distance * h / std::max(distance - h, kNear * distance);
}

bool ViewAxes::in_front(const Vec3& p) const {
  return !perspective || distance - (p - focus).dot(eye) >= kNear * distance;
}

double ViewAxes::facing(const Vec3& n, const Vec3& p) const {
  return perspective ? n.dot((focus + distance * eye - p).normalized()) : n.dot(eye);
}

CameraFit fit_camera(const std::vector<Vec3>& pts, double azimuth, double elevation,
                     double aspect) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& w : pts) lo = lo.cwiseMin(w), hi = hi.cwiseMax(w);
  if (!(hi.x() >= lo.x())) lo = hi = Vec3::Zero();
  CameraFit fit;
  fit.focus = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 1e-9);
  // The scale that fits the projected points in the viewport.
  const ViewAxes v(azimuth, elevation);
  double half_w = 1e-9, half_h = 1e-9;
  for (const Vec3& w : pts) {
    const Vec2 q = v(w - fit.focus);
    half_w = std::max(half_w, std::abs(q.x())), half_h = std::max(half_h, std::abs(q.y()));
  }
  const double a = aspect > 0 ? aspect : 1.0;
  const double tangent = std::tan(kViewAngle * std::numbers::pi / 360);
  fit.scale = 1.08 * std::max(half_h, half_w / a);
  // Far enough that a perspective view shows the same at the focal point, outside the points'
  // sphere, and with every point in view (the nearer, the larger drawn).
  fit.distance = std::max(fit.scale / tangent, 1.5 * radius);
  for (const Vec3& w : pts) {
    const Vec2 q = v(w - fit.focus);
    const double ahead = (w - fit.focus).dot(v.eye);
    fit.distance = std::max(
        fit.distance, ahead + 1.08 * std::max(std::abs(q.y()), std::abs(q.x()) / a) / tangent);
  }
  return fit;
}

namespace {
// The cut's upward normal (the engine's rule for a plane by dip and dip direction).
Vec3 cut_normal(const ViewOptions& o) {
  return normal_from_dip(o.cut_dip, o.cut_dip_direction);
}

// Where the segment a-b crosses the cut, if it does (signed heights da, db).
void add_crossing(const Vec3& a, const Vec3& b, double da, double db, std::vector<Vec3>& out) {
  if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + da / (da - db) * (b - a));
}

// A polygon's part where a plane's signed height is not above zero (Sutherland-Hodgman).
template <class Height>
void clip(const std::vector<Vec3>& in, std::vector<Vec3>& out, const Height& height) {
  out.clear();
  for (size_t k = 0; k < in.size(); ++k) {
    const Vec3 &a = in[k], &b = in[(k + 1) % in.size()];
    const double da = height(a), db = height(b);
    if (da <= 0) out.push_back(a);
    add_crossing(a, b, da, db, out);
  }
}

// A polygon's part below the cut.
void clip_below(const ViewOptions& o, const std::vector<Vec3>& in, std::vector<Vec3>& out) {
  const Vec3 n = cut_normal(o);
  clip(in, out, [&](const Vec3& p) { return n.dot(p - o.cut_point); });
}

// A polygon's part in front of the eye's near plane (perspective).
void clip_near(const ViewAxes& v, const std::vector<Vec3>& in, std::vector<Vec3>& out) {
  clip(in, out, [&](const Vec3& p) { return (p - v.focus).dot(v.eye) - (1 - kNear) * v.distance; });
}

Vec3 displacement(const SnapshotBlock& b) {
  return {b.x - b.x_ref, b.y - b.y_ref, b.z - b.z_ref};
}
}  // namespace

std::vector<Vec3> polygon_about(const Vec3& n, std::vector<Vec3> pts) {
  if (pts.size() < 3) return {};
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  Vec3 mid = Vec3::Zero();
  for (const Vec3& p : pts) mid += p;
  mid /= static_cast<double>(pts.size());
  std::sort(pts.begin(), pts.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2((a - mid).dot(t2), (a - mid).dot(t1)) <
           std::atan2((b - mid).dot(t2), (b - mid).dot(t1));
  });
  // A crossing found from both faces of an edge, once.
  double size = 0;
  for (const Vec3& p : pts) size = std::max(size, (p - mid).norm());
  std::vector<Vec3> out;
  for (const Vec3& p : pts)
    if (out.empty() || (p - out.back()).norm() > 1e-9 * size) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9 * size) out.pop_back();
  return out.size() >= 3 ? out : std::vector<Vec3>{};
}

bool cut_away(const ViewOptions& o, const Vec3& p) {
  return o.cut && cut_normal(o).dot(p - o.cut_point) > 0;
}

ViewOptions with_camera(const Snapshot& s, const ViewOptions& o) {
  if (!o.perspective || o.has_camera) return o;
  std::vector<Vec3> pts, kept;
  for (const Snapshot::Face3& f : s.faces3) {
    const Vec3 shift = (o.magnify - 1.0) * displacement(s.blocks[static_cast<size_t>(f.block)]);
    for (uint32_t k = f.begin; k < f.end; ++k) pts.push_back(s.points3[k] + shift);
  }
  for (const Vec3& p : pts)
    if (!cut_away(o, p)) kept.push_back(p);
  const CameraFit fit = fit_camera(kept.empty() ? pts : kept, o.azimuth, o.elevation, 1.5);
  ViewOptions out = o;
  out.has_camera = true, out.focus = fit.focus, out.distance = fit.distance;
  return out;
}

Snapshot flatten3(const Snapshot& s, const ViewOptions& o) {
  const ViewAxes view(o);
  Snapshot flat;
  flat.three = true;
  flat.blocks = s.blocks;
  for (SnapshotBlock& b : flat.blocks) {
    const Vec2 at = view(Vec3(b.x, b.y, b.z)), ref = view(Vec3(b.x_ref, b.y_ref, b.z_ref));
    b.x = at.x(), b.y = at.y(), b.x_ref = ref.x(), b.y_ref = ref.y();
    // In perspective the contacts are placed where they are drawn, magnified: no shift left.
    if (view.perspective) b.x_ref = b.x, b.y_ref = b.y;
  }
  flat.contacts = s.contacts;
  for (SnapshotContact& c : flat.contacts) {
    const Vec3 at = view.perspective ? shown_point3(s, o, c) : c.point3;
    c.point = c.from = c.to = view(at);
    // The bar lies across the projected normal; a normal along the line of sight shows as a
    // square (any screen direction). In perspective it is shorter the farther it is.
    const Vec2 n(c.normal3.dot(view.right), c.normal3.dot(view.up));
    c.normal = n.norm() > 1e-6 ? Vec2(n.normalized()) : Vec2(0, 1);
    if (view.perspective) c.length *= (view(at + view.right) - c.point).norm();
  }
  return flat;
}

Vec3 shown_point3(const Snapshot& s, const ViewOptions& o, const SnapshotContact& c) {
  if (c.a < 0 || static_cast<size_t>(c.a) >= s.blocks.size()) return c.point3;
  return c.point3 + (o.magnify - 1.0) * displacement(s.blocks[static_cast<size_t>(c.a)]);
}

Vec3 shown_support3(const Snapshot& s, const ViewOptions& o, const SnapshotBolt& b, size_t k) {
  const int blk = b.block[k];
  if (o.magnify == 1.0 || blk < 0 || static_cast<size_t>(blk) >= s.blocks.size())
    return b.points3[k];
  return b.points3[k] + (o.magnify - 1.0) * displacement(s.blocks[static_cast<size_t>(blk)]);
}

void set_bar_depths3(const Snapshot& s, const ViewOptions& o, Scene& out) {
  const ViewAxes view(o);
  for (SceneBar& bar : out.bars) {
    if (bar.contact < 0 || static_cast<size_t>(bar.contact) >= s.contacts.size()) continue;
    bar.depth = view.depth(shown_point3(s, o, s.contacts[static_cast<size_t>(bar.contact)]));
  }
}

void add_faces3(const Snapshot& s, const ViewOptions& o, const std::vector<Rgb>& colours,
                Scene& out,
                const std::function<std::optional<Rgb>(const SnapshotZone&)>& zone_colour) {
  const ViewAxes view(o);
  // Shaded by how squarely the polygon faces the viewer.
  const auto shaded = [](Rgb base, double facing) {
    const double light = 0.6 + 0.4 * facing;
    const auto shade = [&](unsigned char x) {
      return static_cast<unsigned char>(std::lround(std::min(255.0, x * light)));
    };
    return Rgb{shade(base.r), shade(base.g), shade(base.b)};
  };
  // A polygon of world points, if it faces the viewer or a camera or cut may show its inside
  // (clipped by the cut unless it is a section lying on it).
  std::vector<Vec3> below, near;
  const auto show = [&](const std::vector<Vec3>& face, int block, Rgb base, bool outline,
                        bool section = false, int zone = -1) {
    if (face.size() < 3) return;
    Vec3 n = Vec3::Zero(), mid = Vec3::Zero();
    for (size_t k = 0; k < face.size(); ++k)
      n += face[k].cross(face[(k + 1) % face.size()]), mid += face[k];
    n.normalize();
    // Turned away from the eye (in perspective: from where it is, not the line of sight).
    if (!(view.facing(n, mid / static_cast<double>(face.size())) > 1e-9) && !out.camera && !o.cut)
      return;
    if (o.cut && !section) clip_below(o, face, below);
    const std::vector<Vec3>* pts = o.cut && !section ? &below : &face;
    if (view.perspective) clip_near(view, *pts, near), pts = &near;
    if (pts->size() < 3) return;
    ScenePolygon polygon;
    polygon.block = block;
    polygon.zone = zone;
    polygon.outline = outline;
    for (const Vec3& p : *pts)
      polygon.points.push_back(view(p)), polygon.depth.push_back(view.depth(p));
    if (out.camera) polygon.world = *pts;
    polygon.colour = out.camera ? base : shaded(base, std::abs(n.dot(view.eye)));
    out.polygons.push_back(std::move(polygon));
  };
  // Faces of deformable blocks drawn by their zones' surface triangles (tris3 come grouped by
  // face, in face order).
  std::vector<uint8_t> by_zones(s.faces3.size(), 0);
  const auto node = [&](uint32_t k) {
    return Vec3(s.nodes3_start[k] + o.magnify * (s.nodes3[k] - s.nodes3_start[k]));
  };
  const auto face_shift = [&](const Snapshot::Face3& f) {
    return Vec3((o.magnify - 1.0) * displacement(s.blocks[static_cast<size_t>(f.block)]));
  };
  // With a cut: each block's and zone's lowest and highest point against the plane. What has no
  // point below it is cut away whole, faces on the plane included (they belong to the block
  // below); only what has points on both sides gets a section.
  const Vec3 up = cut_normal(o);
  const auto height = [&](const Vec3& p) { return up.dot(p - o.cut_point); };
  std::vector<double> block_lo(s.blocks.size(), 1e300), block_hi(s.blocks.size(), -1e300);
  std::vector<double> zone_lo, zone_hi;
  if (o.cut) {
    for (const Snapshot::Face3& f : s.faces3) {
      const Vec3 shift = face_shift(f);
      const auto b = static_cast<size_t>(f.block);
      for (uint32_t k = f.begin; k < f.end; ++k) {
        const double h = height(s.points3[k] + shift);
        block_lo[b] = std::min(block_lo[b], h), block_hi[b] = std::max(block_hi[b], h);
      }
    }
    if (zone_colour && !s.tris3.empty()) {
      zone_lo.assign(s.zones.size(), 1e300), zone_hi.assign(s.zones.size(), -1e300);
      for (size_t z = 0; z < s.zones.size(); ++z)
        for (uint32_t n : s.zones[z].n) {
          const double h = height(node(n));
          zone_lo[z] = std::min(zone_lo[z], h), zone_hi[z] = std::max(zone_hi[z], h);
        }
    }
  }
  if (zone_colour) {
    std::vector<Vec3> tri(3);
    for (const Snapshot::Tri3& t : s.tris3) {
      by_zones[t.face] = 1;
      if (o.cut && !(zone_lo[t.zone] < 0)) continue;  // its zone is cut away
      const std::optional<Rgb> colour = zone_colour(s.zones[t.zone]);
      if (!colour) continue;
      for (int k = 0; k < 3; ++k) tri[static_cast<size_t>(k)] = node(t.n[k]);
      show(tri, s.faces3[t.face].block, *colour, false, false, static_cast<int>(t.zone));
    }
  }
  std::vector<Vec3> pts;
  for (size_t f = 0; f < s.faces3.size(); ++f) {
    if (by_zones[f]) continue;
    const Snapshot::Face3& face = s.faces3[f];
    if (o.cut && !(block_lo[static_cast<size_t>(face.block)] < 0)) continue;  // cut away
    const Vec3 shift = face_shift(face);
    pts.clear();
    for (uint32_t k = face.begin; k < face.end; ++k) pts.push_back(s.points3[k] + shift);
    show(pts, face.block, colours[static_cast<size_t>(face.block)], true);
  }
  if (!o.cut) return;
  // The section on the cut's plane: each zone it crosses in the zone's colour (deformable blocks
  // drawn by zones), and a cap across each other block (its faces' crossings, in turn about the
  // plane's normal: blocks are convex pieces).
  std::vector<Vec3> section;
  if (zone_colour && !s.tris3.empty())
    for (size_t i = 0; i < s.zones.size(); ++i) {
      const SnapshotZone& z = s.zones[i];
      if (z.block < 0 || !(zone_lo[i] < 0 && zone_hi[i] > 0)) continue;
      Vec3 c[4];
      double d[4];
      for (int k = 0; k < 4; ++k) c[k] = node(z.n[k]), d[k] = height(c[k]);
      section.clear();
      for (int a = 0; a < 4; ++a) {
        if (d[a] == 0) section.push_back(c[a]);  // a corner on the plane
        for (int b = a + 1; b < 4; ++b) add_crossing(c[a], c[b], d[a], d[b], section);
      }
      const std::vector<Vec3> cut = polygon_about(up, section);
      const std::optional<Rgb> colour = zone_colour(z);
      if (!cut.empty() && colour) show(cut, z.block, *colour, false, true, static_cast<int>(i));
    }
  std::vector<std::vector<Vec3>> caps(s.blocks.size());
  for (size_t f = 0; f < s.faces3.size(); ++f) {
    if (by_zones[f]) continue;
    const Snapshot::Face3& face = s.faces3[f];
    const auto blk = static_cast<size_t>(face.block);
    if (!(block_lo[blk] < 0 && block_hi[blk] > 0)) continue;  // not across the plane
    const Vec3 shift = face_shift(face);
    for (uint32_t k = face.begin; k < face.end; ++k) {
      const uint32_t next = k + 1 < face.end ? k + 1 : face.begin;
      const Vec3 a = s.points3[k] + shift, b = s.points3[next] + shift;
      const double ha = height(a);
      if (ha == 0) caps[blk].push_back(a);
      add_crossing(a, b, ha, height(b), caps[blk]);
    }
  }
  for (size_t b = 0; b < caps.size(); ++b)
    if (const std::vector<Vec3> cap = polygon_about(up, caps[b]); !cap.empty())
      show(cap, static_cast<int>(b), colours[b], true, true);
}

}  // namespace tessera::ui
