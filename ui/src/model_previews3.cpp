// What a 3D Model dialog will make, drawn over the model before OK: boxes and prisms, the
// planes of a crack or a joint set within the blocks they cut, an opening's portal and end, a
// wall's bricks.
#include <Eigen/Geometry>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene3d.hpp"
#include "tessera/core/model.hpp"
#include "tessera/generation/cutting3.hpp"
#include "tessera/generation/generators.hpp"
#include "tessera/ui/command_dialog.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/vtk_view.hpp"

namespace tessera::ui {

namespace {
using Segments = std::vector<std::array<Vec3, 2>>;

// "a,b,c" (or fewer: the rest zero) as numbers; false unless `n` numbers are given.
bool numbers(const QString& text, int n, double* out) {
  const QStringList parts = text.split(',');
  if (parts.size() != n) return false;
  for (int k = 0; k < n; ++k) {
    bool ok = false;
    out[k] = parts[k].toDouble(&ok);
    if (!ok) return false;
  }
  return true;
}

bool point3(const QString& text, Vec3& p) {
  return numbers(text, 3, p.data());
}

bool number(const QString& text, double& v) {
  return numbers(text, 1, &v);
}

void add_loop(const std::vector<Vec3>& pts, Segments& out) {
  for (size_t k = 0; k < pts.size(); ++k) out.push_back({pts[k], pts[(k + 1) % pts.size()]});
}

// Corner i of a box (bits 1, 2, 4: x, y, z at their high end).
Vec3 box_corner(const Vec3& lo, const Vec3& hi, int i) {
  return {i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()};
}

void add_box(const Vec3& a, const Vec3& b, Segments& out) {
  const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  const auto corner = [&](int i) { return box_corner(lo, hi, i); };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) out.push_back({corner(i), corner(i | bit)});
}

// Two unit vectors across a direction.
void across(const Vec3& n, Vec3& e1, Vec3& e2) {
  e1 = n.unitOrthogonal(), e2 = n.normalized().cross(e1);
}

// The plane n.x = c within the box, as its outline (empty if it misses the box).
std::vector<Vec3> plane_in_box(const Vec3& n, double c, const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> pts;
  const auto corner = [&](int i) { return box_corner(lo, hi, i); };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4}) {
      if (i & bit) continue;
      const Vec3 a = corner(i), b = corner(i | bit);
      const double da = n.dot(a) - c, db = n.dot(b) - c;
      if ((da <= 0 && db > 0) || (da > 0 && db <= 0)) pts.push_back(a + da / (da - db) * (b - a));
    }
  return polygon_about(n, pts);
}

// An opening's cross-section (2D, its arch up) placed across the axis at `at`: up is +z as
// seen along the axis (+y for a vertical shaft), as the command builds it.
std::vector<Vec3> across_axis(const std::vector<Vec2>& section, const Vec3& at, const Vec3& axis) {
  const Vec3 a = axis.normalized();
  Vec3 up = Vec3::UnitZ() - a.z() * a;
  if (up.norm() < 1e-6) up = Vec3::UnitY() - a.y() * a;
  up.normalize();
  const Vec3 side = up.cross(a);
  std::vector<Vec3> out;
  for (const Vec2& p : section) out.push_back(at + p.x() * side + p.y() * up);
  return out;
}
}  // namespace

void MainWindow::preview3(const QString& name, const CommandDialog& d) {
  Segments lines;
  // The box of the blocks a cut acts on: the selection's, or the whole model's.
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  if (shown_)
    for (const Snapshot::Face3& f : shown_->faces3) {
      if (!selected_.empty() &&
          std::find(selected_.begin(), selected_.end(), f.block) == selected_.end())
        continue;
      for (uint32_t k = f.begin; k < f.end; ++k)
        lo = lo.cwiseMin(shown_->points3[k]), hi = hi.cwiseMax(shown_->points3[k]);
    }
  const bool model = hi.x() >= lo.x();
  const double size = model ? (hi - lo).norm() : 0.0;
  // A hair outside the blocks, so that planes along a face still show.
  if (model) lo -= Vec3::Constant(1e-3 * size), hi += Vec3::Constant(1e-3 * size);
  Vec3 a, b, origin = Vec3::Zero(), axis;
  double v = 0, w = 0, dip = 0, ddir = 0;
  if ((name == "box" || name == "region") && point3(d.value("#a"), a) && point3(d.value("#b"), b)) {
    add_box(a, b, lines);
  } else if (name == "prism" && numbers(d.value("z"), 2, a.data())) {
    std::vector<Vec3> base, top;
    for (const QString& corner : d.value("#base").split(' ', Qt::SkipEmptyParts)) {
      double xy[2];
      if (!numbers(corner, 2, xy)) return view_->setPreview3({});
      base.emplace_back(xy[0], xy[1], a.x()), top.emplace_back(xy[0], xy[1], a.y());
    }
    add_loop(base, lines), add_loop(top, lines);
    for (size_t k = 0; k < base.size(); ++k) lines.push_back({base[k], top[k]});
  } else if ((name == "crack" || name == "jset") &&
             number(d.value("dip").section(',', 0, 0), dip) &&
             number(d.value("ddir").section(',', 0, 0), ddir)) {
    const Vec3 n = normal_from_dip(dip, ddir);
    const bool through = point3(d.value("origin"), origin);
    if (name == "crack" && through && number(d.value("radius"), v) && v > 0) {
      // A disc: its rim.
      Vec3 e1, e2;
      across(n, e1, e2);
      std::vector<Vec3> rim;
      for (int k = 0; k < 48; ++k) {
        const double t = 2 * std::numbers::pi * k / 48;
        rim.push_back(origin + v * (std::cos(t) * e1 + std::sin(t) * e2));
      }
      add_loop(rim, lines);
    } else if (name == "crack" && through && model) {
      add_loop(plane_in_box(n, n.dot(origin), lo, hi), lines);
    } else if (name == "jset" && model && number(d.value("spacing").section(',', 0, 0), v) &&
               v > 0) {
      // Planes S apart from the origin, across the box (at most 200).
      double from = 1e300, to = -1e300;
      for (int i = 0; i < 8; ++i) {
        const double c = n.dot(box_corner(lo, hi, i));
        from = std::min(from, c), to = std::max(to, c);
      }
      const double o = n.dot(origin);
      if ((to - from) / v < 200)
        for (double k = std::ceil((from - o) / v); o + k * v <= to; ++k)
          add_loop(plane_in_box(n, o + k * v, lo, hi), lines);
    }
  } else if ((name == "tunnel" || name == "horseshoe") && point3(d.value("centre"), origin) &&
             point3(d.value("axis"), axis) && axis.norm() > 0 && number(d.value("length"), v) &&
             v > 0) {
    const int segments = std::clamp(d.value("segments").toInt(), 2, 2000);
    std::vector<Vec2> section;
    if (name == "tunnel" && number(d.value("radius"), w) && w > 0)
      section = circle_outline(Vec2::Zero(), w, std::max(segments, 3));
    double width = 0, height = 0;
    if (name == "horseshoe" && number(d.value("width"), width) &&
        number(d.value("height"), height) && width > 0 && height > width / 2)
      section = horseshoe_outline(Vec2::Zero(), width, height, segments);
    if (!section.empty()) {
      const std::vector<Vec3> portal = across_axis(section, origin, axis),
                              end = across_axis(section, origin + v * axis.normalized(), axis);
      add_loop(portal, lines), add_loop(end, lines);
      for (size_t k = 0; k < portal.size(); k += std::max<size_t>(1, portal.size() / 8))
        lines.push_back({portal[k], end[k]});
    }
  } else if (name == "cable" && point3(d.value("#a"), a) && point3(d.value("#b"), b)) {
    lines.push_back({a, b});
  } else if (name == "wall") {
    // The 2D running-bond pattern on the wall's face, and the wall's box.
    double brick[3];
    const int courses = d.value("courses").toInt(), bricks = d.value("bricks").toInt();
    if (!point3(d.value("origin"), origin)) origin = Vec3::Zero();
    if (numbers(d.value("brick"), 3, brick) && brick[0] > 0 && brick[1] > 0 && brick[2] > 0 &&
        courses > 0 && bricks > 0 && courses * bricks < 20000) {
      Model scratch;
      WallSpec spec;
      spec.brick_length = brick[0], spec.brick_height = brick[1];
      spec.courses = courses, spec.bricks = bricks;
      scratch.settings.rounding = 0.01 * std::min(brick[0], brick[1]);
      add_running_bond_wall(scratch, spec);
      Vec3 top = origin;
      for (size_t k = 0; k < scratch.blocks.size(); ++k) {
        std::vector<Vec3> face;
        for (const Vec2& p : scratch.blocks.world_polygon(k)) {
          face.push_back(origin + Vec3(p.x(), 0, p.y()));
          top = top.cwiseMax(face.back());
        }
        add_loop(face, lines);
      }
      add_box(origin, top + Vec3(0, brick[2], 0), lines);
    }
  }
  view_->setPreview3(lines);
}

}  // namespace tessera::ui
