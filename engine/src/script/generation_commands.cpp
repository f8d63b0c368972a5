// Script commands that generate and cut blocks, and the geometry checks.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tessera/generation/generators.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"

namespace tessera {

namespace {
// Distance along d from p to where it leaves the polygon (p inside), or 0 if it does not.
double exit_distance(const Vec2& p, const Vec2& d, const std::vector<Vec2>& poly) {
  double best = 0.0;
  bool found = false;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2 &a = poly[i], e = poly[(i + 1) % n] - poly[i];
    const double den = cross(d, e);
    if (den == 0.0) continue;
    const double t = cross(a - p, e) / den, s = cross(a - p, d) / den;
    if (t > 0.0 && s >= 0.0 && s <= 1.0 && (!found || t < best)) best = t, found = true;
  }
  return best;
}

// What a cut did to slivers, as log lines.
std::vector<std::string> sliver_report(const std::string& command, const CutReport& r) {
  std::vector<std::string> out;
  char limit[32];
  std::snprintf(limit, sizeof limit, "%.3g", r.min_area);
  // Round-off dropped at T-junctions of earlier cuts is reported by jset only, as before.
  if (r.slivers_dropped && command == "jset")
    out.push_back(command + ": " + std::to_string(r.slivers_dropped) +
                  " sliver(s) below the snapping tolerance dropped");
  if (r.slivers_merged)
    out.push_back(command + ": " + std::to_string(r.slivers_merged) +
                  " sliver(s) below the area limit " + limit + " merged into neighbouring blocks");
  if (r.slivers_left)
    out.push_back(command + ": " + std::to_string(r.slivers_left) +
                  " sliver(s) below the area limit " + limit +
                  " left: no neighbour of their group and side of the opening to merge with");
  return out;
}
}  // namespace

std::pair<double, double> Interpreter::mean_sd(const std::string& text) const {
  const auto parts = split_top_level(text);
  if (parts.size() > 2) fail("'" + text + "' should be MEAN or MEAN,SD");
  const double sd = parts.size() == 2 ? num(parts[1]) : 0.0;
  if (sd < 0.0) fail("a standard deviation cannot be negative ('" + text + "')");
  return {num(parts[0]), sd};
}

std::vector<size_t> Interpreter::optional_selection(Args& a) {
  for (const char* k :
       {"x", "y", "z", "group", "block", "at", "circle", "polygon", "joints", "smaller"})
    for (const auto& kv : a.keys)
      if (kv.first == k) return select(a, true);
  if (std::find(a.words.begin(), a.words.end(), "all") != a.words.end()) return select(a, true);
  return {};
}

Interpreter::CutTarget Interpreter::cut_target(Args& a, const std::string& kind) {
  CutTarget t;
  t.name = kind + std::to_string(model_.joint_tags.size() + 1);
  take(a, "name", t.name);
  t.selection = optional_selection(a);
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  done(a);
  if (model_.blocks.size() == 0) fail("there are no blocks to cut: make a region first");
  t.blocks = t.selection;
  if (t.blocks.empty())
    for (size_t b = 0; b < model_.blocks.size(); ++b) t.blocks.push_back(b);
  t.lo = Vec2(1e300, 1e300), t.hi = Vec2(-1e300, -1e300);
  for (size_t b : t.blocks)
    for (const Vec2& p : model_.blocks.world_polygon(b))
      t.lo = t.lo.cwiseMin(p), t.hi = t.hi.cwiseMax(p);
  return t;
}

void Interpreter::cmd_region(Args& a) {
  if (a.words.size() != 2)
    fail("write 'region X0,Y0 X1,Y1 [group=G] [material=M]' (two opposite corners)");
  const Vec2 p = point(a.words[0]), q = point(a.words[1]);
  const Vec2 lo = p.cwiseMin(q), hi = p.cwiseMax(q);
  make_block({lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())}, a);
}

void Interpreter::cmd_crack(Args& a) {
  std::vector<Vec2> pts;
  std::vector<std::string> rest;
  for (const auto& w : a.words) {
    if (w == "all")
      rest.push_back(w);
    else
      pts.push_back(point(w));
  }
  a.words = rest;
  if (pts.size() < 2) fail("write 'crack X,Y X,Y [X,Y ...]' with at least two points");
  const CutTarget t = cut_target(a, "crack");
  const CutReport r = cut_blocks(model_, {CutLine{pts, joint_tag(model_, t.name)}}, t.selection);
  for (const std::string& s : sliver_report("crack", r)) log(s);
  overlap_checked_ = false;
}

void Interpreter::cmd_jset(Args& a) {
  JointSetSpec j;
  std::string v;
  if (!take(a, "angle", v)) missing(a, "angle", "'jset'");
  std::tie(j.angle, j.angle_sd) = mean_sd(v);
  if (!take(a, "spacing", v)) missing(a, "spacing", "'jset'");
  std::tie(j.spacing, j.spacing_sd) = mean_sd(v);
  if (j.spacing <= 0.0) fail("the joint spacing must be positive");
  if (take(a, "trace", v)) std::tie(j.trace, j.trace_sd) = mean_sd(v);
  if (take(a, "gap", v)) std::tie(j.gap, j.gap_sd) = mean_sd(v);
  if (j.trace < 0.0 || j.gap < 0.0) fail("trace length and gap cannot be negative");
  if (take(a, "origin", v)) j.origin = point(v);
  if (take(a, "seed", v)) j.seed = static_cast<uint64_t>(integer(v, 0));
  const auto it = std::find(a.words.begin(), a.words.end(), "extend");
  if (it != a.words.end()) j.extend = true, a.words.erase(it);
  const CutTarget target = cut_target(a, "jset");
  std::vector<CutLine> traces =
      joint_set_traces(j, target.lo, target.hi, joint_tag(model_, target.name));
  if (j.extend) {
    // A trace end inside a block runs on to the block's boundary.
    for (CutLine& t : traces)
      for (int end = 0; end < 2; ++end) {
        Vec2& p = t.points[static_cast<size_t>(end)];
        const Vec2 dir = (p - t.points[static_cast<size_t>(1 - end)]).normalized();
        for (size_t b : target.blocks) {
          const auto poly = model_.blocks.world_polygon(b);
          if (!point_in_polygon(p, poly)) continue;
          // Just past the boundary, so that the trace crosses it; exactly through a corner
          // if it passes that close to one, so that no sliver is cut off the corner.
          const double size = 2.0 * model_.blocks.bound_radius[b];
          p += dir * (exit_distance(p, dir, poly) + 1e-7 * size);
          for (const Vec2& corner : poly)
            if ((corner - p).norm() < 1e-5 * size) p = corner;
          break;
        }
      }
  }
  const CutReport r = cut_blocks(model_, traces, target.selection);
  for (const std::string& s : sliver_report("jset", r)) log(s);
  overlap_checked_ = false;
}

void Interpreter::cmd_tunnel(Args& a) {
  if (a.words.empty()) fail("write 'tunnel circle|horseshoe|rectangle|polygon ...'");
  const std::string shape = a.words[0];
  a.words.erase(a.words.begin());
  std::vector<Vec2> outline;
  std::string v;
  if (shape == "circle") {
    if (!take(a, "centre", v)) missing(a, "centre", "'tunnel circle'");
    const Vec2 c = point(v);
    double r = 0.0, n = 24;
    if (!take_num(a, "radius", r)) missing(a, "radius", "'tunnel circle'");
    take_num(a, "segments", n);
    if (r <= 0.0 || n < 3 || n > 1e5)
      fail("a circle needs a positive radius and 3 to 100,000 segments");
    outline = circle_outline(c, r, static_cast<int>(n));
  } else if (shape == "horseshoe") {
    if (!take(a, "centre", v)) missing(a, "centre", "'tunnel horseshoe' (the middle of its floor)");
    const Vec2 c = point(v);
    double w = 0.0, h = 0.0, n = 12;
    if (!take_num(a, "width", w)) missing(a, "width", "'tunnel horseshoe'");
    if (!take_num(a, "height", h)) missing(a, "height", "'tunnel horseshoe'");
    take_num(a, "segments", n);
    if (w <= 0.0 || h < 0.5 * w || n < 2)
      fail("a horseshoe needs width > 0, height >= width/2 and segments >= 2");
    outline = horseshoe_outline(c, w, h, static_cast<int>(n));
  } else if (shape == "rectangle") {
    if (a.words.size() != 2) fail("write 'tunnel rectangle X0,Y0 X1,Y1'");
    const Vec2 p = point(a.words[0]), q = point(a.words[1]);
    outline = {p, Vec2(q.x(), p.y()), q, Vec2(p.x(), q.y())};
    a.words.clear();
  } else if (shape == "polygon") {
    for (const auto& w : a.words) outline.push_back(point(w));
    a.words.clear();
    if (const std::string why = polygon_problem(outline); !why.empty()) fail("the opening: " + why);
  } else {
    fail("'" + shape + "' is not an opening shape" +
         suggest(shape, {"circle", "horseshoe", "rectangle", "polygon"}));
  }
  std::string name = "tunnel" + std::to_string(model_.joint_tags.size() + 1), group;
  take(a, "name", name);
  if (!take(a, "group", group)) group = name;
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  done(a);
  if (model_.blocks.size() == 0) fail("there are no blocks to cut: make a region first");
  outline.push_back(outline.front());
  const CutReport r = cut_blocks(model_, {CutLine{outline, joint_tag(model_, name)}}, {});
  for (const std::string& s : sliver_report("tunnel", r)) log(s);
  if (r.splits > 0)
    log("tunnel: the rock around the opening is split by a horizontal joint named 'split' (blocks "
        "cannot have holes); give it properties that keep it shut, e.g. 'joint assign NAME "
        "joints=split' with a high tensile strength and cohesion");
  // The blocks inside the outline form a group, ready to be excavated with 'delete'. Each is
  // tested at a point inside it: the centroid of a piece the opening bites into lies outside it.
  const int g = model_.group_index(group, true);
  outline.pop_back();
  for (size_t b = 0; b < model_.blocks.size(); ++b)
    if (point_in_polygon(interior_point(model_.blocks.world_polygon(b)), outline))
      model_.blocks.group[b] = g;
  overlap_checked_ = false;
}

void Interpreter::cmd_voronoi(Args& a) {
  double size = 0.0, seed = 1;
  if (!take_num(a, "size", size)) missing(a, "size", "'voronoi' (mean cell size)");
  take_num(a, "seed", seed);
  if (size <= 0.0) fail("the cell size must be positive");
  const CutTarget t = cut_target(a, "voronoi");
  if ((t.hi - t.lo).x() * (t.hi - t.lo).y() / (size * size) > 2e5)
    fail("that would make more than 200,000 cells");
  const CutReport r = cut_blocks(
      model_,
      voronoi_traces(t.lo, t.hi, size, static_cast<uint64_t>(seed), joint_tag(model_, t.name)),
      t.selection);
  for (const std::string& s : sliver_report("voronoi", r)) log(s);
  overlap_checked_ = false;
}

void Interpreter::cmd_arch(Args& a) {
  if (model_.settings.rounding <= 0.0)
    fail("set the rounding length with 'round D' before the first block");
  ArchSpec s;
  std::string v;
  if (!take(a, "centre", v)) missing(a, "centre", "'arch' (centre of the intrados)");
  s.centre = point(v);
  if (!take_num(a, "radius", s.radius)) missing(a, "radius", "'arch' (intrados radius)");
  if (!take_num(a, "thickness", s.thickness)) missing(a, "thickness", "'arch'");
  double n = 0;
  if (!take_num(a, "voussoirs", n)) missing(a, "voussoirs", "'arch'");
  s.voussoirs = static_cast<int>(n);
  take_num(a, "half_angle", s.half_angle);
  take_num(a, "abutment", s.abutment);
  if (take(a, "group", v)) s.group = model_.group_index(v, true);
  s.abutment_group = s.group;
  if (take(a, "abutment_group", v)) s.abutment_group = model_.group_index(v, true);
  if (take(a, "material", v)) {
    s.material = model_.material_index(v);
    if (s.material < 0) fail("there is no material '" + v + "' (define it first)");
  }
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  done(a);
  if (s.radius <= 0.0 || s.thickness <= 0.0 || n < 1 || n > 1e5 || n != std::floor(n))
    fail("an arch needs radius > 0, thickness > 0 and a whole number of voussoirs up to 100,000");
  if (s.half_angle <= 0.0 || s.half_angle > 90.0) fail("half_angle must be in (0, 90] degrees");
  add_arch(model_, s);
  overlap_checked_ = false;
}

void Interpreter::cmd_join(Args& a) {
  const auto sel = select(a);
  done(a);
  join_blocks(model_, sel);
  overlap_checked_ = false;
}

void Interpreter::cmd_delete(Args& a) {
  const auto sel = select(a);
  done(a);
  delete_blocks(model_, sel);
  log("delete: " + std::to_string(sel.size()) + " block(s) removed");
}

void Interpreter::cmd_check(Args& a) {
  if (a.words.size() == 1 && (a.words[0] == "proceed" || a.words[0] == "strict")) {
    proceed_on_errors_ = a.words[0] == "proceed";
    done(a);
    return;
  }
  take_num(a, "min_area", limits_.min_area);
  take_num(a, "min_thickness", limits_.min_thickness);
  take_num(a, "min_angle", limits_.min_angle);
  if (!a.words.empty())
    fail("unexpected word '" + a.words[0] + "' (write 'check', 'check proceed' or 'check strict')");
  done(a);
  for (size_t b = 0; b < model_.blocks.size(); ++b) model_.blocks.update_world(b);
  run_checks(false);
}

void Interpreter::run_checks(bool before_run) {
  const std::vector<Finding> found = check_geometry(model_, limits_);
  size_t errors = 0;
  std::string first_error;
  for (const Finding& f : found) {
    if (f.error)
      log(file_ + ":" + std::to_string(line_) + ": " + f.text());
    else
      warn(f.text().substr(f.text().find(' ') + 1));
    if (f.error && !errors++) first_error = f.text();
  }
  if (!before_run)
    log("check: " + std::to_string(found.size()) + " finding(s), " + std::to_string(errors) +
        " error(s)");
  // An error stops the script here as it would stop the run (a batch run exits 1 and its
  // summary says why), unless the user has said to proceed.
  if (errors && !proceed_on_errors_)
    fail(first_error + (errors > 1 ? " (and " + std::to_string(errors - 1) + " more)" : "") +
         (before_run ? "; the run does not start" : "; the script stops") +
         " (fix the model, or write 'check proceed' to go on anyway)");
}

}  // namespace tessera
