// Script commands of 3D models: the dimension, blocks, joint planes, walls and conditions.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "tessera/contact3d/common_plane.hpp"
#include "tessera/core/random.hpp"
#include "tessera/generation/generators.hpp"
#include "tessera/generation/generators3.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

const std::map<std::string, Interpreter::Handler>& Interpreter::handlers3() {
  static const std::map<std::string, Handler> h = [] {
    std::map<std::string, Handler> t = handlers();
    for (const char* only2d : {"voronoi", "arch", "round", "bolt", "liner"})
      t[only2d] = &Interpreter::cmd_only2d;
    t["block"] = &Interpreter::cmd_block3;
    t["region"] = &Interpreter::cmd_region3;
    t["crack"] = &Interpreter::cmd_crack3;
    t["jset"] = &Interpreter::cmd_jset3;
    t["tunnel"] = &Interpreter::cmd_tunnel3;
    t["wall"] = &Interpreter::cmd_wall3;
    t["fix"] = &Interpreter::cmd_fix3;
    t["velocity"] = &Interpreter::cmd_velocity3;
    t["gravity"] = &Interpreter::cmd_gravity3;
    t["delete"] = &Interpreter::cmd_delete3;
    t["join"] = &Interpreter::cmd_join3;
    return t;
  }();
  return h;
}

void Interpreter::cmd_only2d(Args& a) {
  if (a.command == "round")
    fail("3D blocks are not rounded: set the contact tolerance with 'tolerance T'");
  fail("'" + a.command + "' is not available in 3D models yet (this model is 'dimension 3')");
}

void Interpreter::cmd_dimension(Args& a) {
  if (a.words.size() != 1 || (a.words[0] != "2" && a.words[0] != "3"))
    fail("write 'dimension 2' or 'dimension 3' at the top of the script");
  done(a);
  const uint8_t d = a.words[0] == "3" ? 3 : 2;
  if (d != model_.dim && model_.block_count() > 0)
    fail("the dimension is set before the first block (this model has " +
         std::to_string(model_.block_count()) + " blocks in " + std::to_string(model_.dim) + "D)");
  model_.dim = d;
}

Vec3 Interpreter::point3(const std::string& text) const {
  const auto parts = split_top_level(text);
  if (parts.size() != 3) fail("'" + text + "' is not a 3D point: write it as x,y,z");
  return {num(parts[0]), num(parts[1]), num(parts[2])};
}

std::pair<int, int> Interpreter::group_material(Args& a) {
  std::string v;
  int group = -1, material = -1;
  if (take(a, "group", v)) group = model_.group_index(v, true);
  if (take(a, "material", v)) {
    material = model_.material_index(v);
    if (material < 0) fail("there is no material '" + v + "' (define it first)");
  }
  return {group, material};
}

void Interpreter::cmd_block3(Args& a) {
  if (a.words.empty()) fail("write 'block box X0,Y0,Z0 X1,Y1,Z1' or 'block prism ...'");
  const std::string shape = a.words[0];
  Polyhedron p;
  if (shape == "box") {
    if (a.words.size() != 3) fail("write 'block box X0,Y0,Z0 X1,Y1,Z1' (two opposite corners)");
    const Vec3 u = point3(a.words[1]), v = point3(a.words[2]);
    if (!((u - v).cwiseAbs().minCoeff() > 0.0)) fail("the box has no volume");
    p = box(u.cwiseMin(v), u.cwiseMax(v));
  } else if (shape == "prism") {
    std::vector<Eigen::Vector2d> base;
    for (size_t i = 1; i < a.words.size(); ++i) base.push_back(point(a.words[i]));
    std::string v;
    if (!take(a, "z", v)) missing(a, "z", "'block prism X,Y X,Y X,Y ...' (z=Z0,Z1)");
    const Vec2 z = point(v);
    if (base.size() < 3) fail("a prism needs a base of three or more points X,Y");
    if (const std::string why = polygon_problem(base); !why.empty())
      fail("the prism's base: " + why);
    if (signed_area(base) < 0.0) std::reverse(base.begin(), base.end());
    if (!(z.y() != z.x())) fail("the prism has no height (z=Z0,Z1 with Z1 > Z0)");
    p = prism(base, std::min(z.x(), z.y()), std::max(z.x(), z.y()));
  } else {
    fail("'" + shape + "' is not a block shape of 3D models (box or prism)" +
         suggest(shape, {"box", "prism"}));
  }
  const auto [group, material] = group_material(a);
  done(a);
  try {
    add_block3(model_, p, group, material);
  } catch (const std::invalid_argument& e) {
    fail("block " + std::to_string(model_.blocks3.size() + 1) + ": " + e.what());
  }
  overlap_checked_ = false;
}

void Interpreter::cmd_region3(Args& a) {
  if (a.words.size() != 2)
    fail("write 'region X0,Y0,Z0 X1,Y1,Z1 [group=G] [material=M]' (two opposite corners)");
  a.words.insert(a.words.begin(), "box");
  cmd_block3(a);
}

std::vector<size_t> Interpreter::cut_selection3(Args& a, bool selectable) {
  const auto sel = selectable ? optional_selection(a) : std::vector<size_t>{};
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  done(a);
  if (model_.blocks3.size() == 0) fail("there are no blocks to cut: make a region first");
  // Pieces of a joined block keep their shapes in its frame: cut first, then join.
  for (size_t b = 0; b < model_.blocks3.size(); ++b) {
    const bool chosen = sel.empty() || std::find(sel.begin(), sel.end(), b) != sel.end();
    if (chosen && whole_bodies3(model_.blocks3, {b}).size() > 1)
      fail("block " + std::to_string(model_.blocks3.id[b]) +
           " is a piece of a joined block: cut before joining");
  }
  return sel;
}

void Interpreter::cut3(Args& a, std::vector<JointPlane> planes, const std::string& what) {
  std::string name = what + std::to_string(model_.joint_tags.size() + 1);
  take(a, "name", name);
  const auto sel = cut_selection3(a);
  const int tag = joint_tag(model_, name);
  for (JointPlane& p : planes) p.tag = tag;
  const size_t before = model_.blocks3.size();
  const size_t added = cut_model3(model_, sel, planes);
  log(a.command + " " + name + ": " + std::to_string(before) + " -> " +
      std::to_string(model_.blocks3.size()) + " blocks (" + std::to_string(added) + " pieces)");
  overlap_checked_ = false;
}

void Interpreter::cmd_tunnel3(Args& a) {
  if (a.words.empty())
    fail("write 'tunnel circle|horseshoe centre=X,Y,Z axis=DX,DY,DZ length=L ...'");
  const std::string shape = a.words[0];
  a.words.erase(a.words.begin());
  if (shape != "circle" && shape != "horseshoe")
    fail("'" + shape + "' is not an opening shape of 3D models (circle or horseshoe)" +
         suggest(shape, {"circle", "horseshoe"}));
  const std::string what = "'tunnel " + shape + "'";
  const auto flag = std::find(a.words.begin(), a.words.end(), "join");
  const bool join = flag != a.words.end();
  if (join) a.words.erase(flag);
  Opening3 o;
  std::string v;
  if (!take(a, "centre", v))
    missing(a, "centre",
            what + (shape == "circle" ? " (the centre of the portal)"
                                      : " (the middle of the portal's floor)"));
  o.start = point3(v);
  if (!take(a, "axis", v)) missing(a, "axis", what + " (the direction it runs in, DX,DY,DZ)");
  o.axis = point3(v);
  if (!(o.axis.norm() > 0.0)) fail("the axis " + v + " has no direction");
  if (!take_num(a, "length", o.length)) missing(a, "length", what);
  if (!(o.length > 0.0)) fail("the length must be positive");
  double rounds = 1, n = shape == "circle" ? 24 : 12;
  take_num(a, "rounds", rounds);
  take_num(a, "segments", n);
  if (rounds != std::floor(rounds) || rounds < 1 || rounds > 1000)
    fail("rounds is a whole number of rounds of advance from 1 to 1000");
  o.rounds = static_cast<int>(rounds);
  if (shape == "circle") {
    double r = 0.0;
    if (!take_num(a, "radius", r)) missing(a, "radius", what);
    if (r <= 0.0 || n < 3 || n > 1e4)
      fail("a circle needs a positive radius and 3 to 10,000 segments");
    o.section = circle_outline(Vec2::Zero(), r, static_cast<int>(n));
  } else {
    double w = 0.0, h = 0.0;
    if (!take_num(a, "width", w)) missing(a, "width", what);
    if (!take_num(a, "height", h)) missing(a, "height", what);
    if (w <= 0.0 || h < 0.5 * w || n < 2 || n > 1e4)
      fail("a horseshoe needs width > 0, height >= width/2 and 2 to 10,000 segments");
    o.section = horseshoe_outline(Vec2::Zero(), w, h, static_cast<int>(n));
  }
  std::string name = "tunnel" + std::to_string(model_.joint_tags.size() + 1), group;
  take(a, "name", name);
  if (!take(a, "group", group)) group = name;
  // 'group=' names the opening's group, so the opening cuts every block it reaches.
  const auto sel = cut_selection3(a, false);
  // One group per round of advance: G, or G_1 ... G_N.
  std::vector<int> groups;
  std::vector<std::string> names;
  for (int r = 1; r <= o.rounds; ++r) {
    names.push_back(o.rounds == 1 ? group : group + "_" + std::to_string(r));
    groups.push_back(model_.group_index(names.back(), true));
  }
  o.wall_tag = joint_tag(model_, name);
  o.split_tag = joint_tag(model_, "split");
  const size_t before = model_.blocks3.size();
  try {
    tunnel_model3(model_, sel, o, groups, join);
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  std::vector<size_t> count(groups.size(), 0);
  for (size_t b = 0; b < model_.blocks3.size(); ++b)
    for (size_t r = 0; r < groups.size(); ++r) count[r] += model_.blocks3.group[b] == groups[r];
  std::string rounds_text;
  for (size_t r = 0; r < groups.size(); ++r)
    rounds_text += (r ? ", " : "") + names[r] + " (" + std::to_string(count[r]) + ")";
  if (std::all_of(count.begin(), count.end(), [](size_t c) { return c == 0; }))
    fail("the opening reaches no block");
  log("tunnel " + name + ": " + std::to_string(before) + " -> " +
      std::to_string(model_.blocks3.size()) + " blocks; to excavate: " + rounds_text);
  if (join)
    log("tunnel: the rock each block keeps around the opening is one body again (joined; zoned as "
        "one mesh)");
  else
    log("tunnel: the rock around the opening is split by planes through its axis and across it "
        "at the portal and the end, a joint named 'split' (blocks are convex); give it properties "
        "that keep it shut, e.g. 'joint assign NAME joints=split' with a high tensile strength "
        "and cohesion, or add 'join' to keep each block's rock one body");
  overlap_checked_ = false;
}

void Interpreter::cmd_crack3(Args& a) {
  JointPlane p;
  double dip = 0, ddir = 0;
  if (!take_num(a, "dip", dip)) missing(a, "dip", "a 3D crack (a plane: dip=, ddir=, origin=)");
  if (!take_num(a, "ddir", ddir)) missing(a, "ddir", "a 3D crack (dip direction)");
  std::string v;
  if (!take(a, "origin", v)) missing(a, "origin", "a 3D crack (a point X,Y,Z on the plane)");
  p.point = point3(v);
  take_num(a, "radius", p.radius);
  if (dip < 0.0 || dip > 90.0) fail("dip must be in [0, 90] degrees");
  if (p.radius < 0.0) fail("radius must be positive (or absent for a plane without end)");
  p.normal = normal_from_dip(dip, ddir);
  cut3(a, {p}, "crack");
}

void Interpreter::cmd_jset3(Args& a) {
  std::string v;
  if (!take(a, "dip", v)) missing(a, "dip", "a 3D joint set (dip=, ddir=, spacing=)");
  const auto [dip, dip_sd] = mean_sd(v);
  if (!take(a, "ddir", v)) missing(a, "ddir", "a 3D joint set (dip direction)");
  const auto [ddir, ddir_sd] = mean_sd(v);
  if (!take(a, "spacing", v)) missing(a, "spacing", "a 3D joint set");
  const auto [spacing, spacing_sd] = mean_sd(v);
  Vec3 origin = Vec3::Zero();
  if (take(a, "origin", v)) origin = point3(v);
  double persistence = 1.0, seed = 1.0;
  take_num(a, "persistence", persistence);
  take_num(a, "seed", seed);
  if (dip < 0.0 || dip > 90.0) fail("dip must be in [0, 90] degrees");
  if (!(spacing > 0.0)) fail("the spacing must be positive");
  if (!(persistence >= 0.0 && persistence <= 1.0)) fail("persistence must be in [0, 1]");
  // The extent to cover: the blocks' box, projected on the mean normal.
  const Blocks3& B = model_.blocks3;
  if (B.size() == 0) fail("there are no blocks to cut: make a region first");
  const Vec3 n0 = normal_from_dip(dip, ddir);
  double lo = 1e300, hi = -1e300;
  for (const Vec3& x : B.world_vertex)
    lo = std::min(lo, n0.dot(x - origin)), hi = std::max(hi, n0.dot(x - origin));
  if ((hi - lo) / spacing > 1e5) fail("the spacing would make more than 100,000 planes");
  Random draw(static_cast<uint64_t>(seed));
  std::vector<JointPlane> planes;
  const auto plane_at = [&](double s) {
    JointPlane p;
    p.normal = normal_from_dip(std::clamp(draw.normal(dip, dip_sd), 0.0, 90.0),
                               draw.normal(ddir, ddir_sd));
    p.point = origin + s * n0;
    p.persistence = persistence;
    p.seed = static_cast<uint64_t>(seed) * 1000003u + planes.size();
    planes.push_back(p);
  };
  for (double s = 0.0; s <= hi; s += std::max(draw.normal(spacing, spacing_sd), 0.1 * spacing))
    if (s >= lo) plane_at(s);
  for (double s = -std::max(draw.normal(spacing, spacing_sd), 0.1 * spacing); s >= lo;
       s -= std::max(draw.normal(spacing, spacing_sd), 0.1 * spacing))
    if (s <= hi) plane_at(s);
  cut3(a, planes, "jset");
}

void Interpreter::cmd_wall3(Args& a) {
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  WallSpec3 w;
  std::string v;
  if (take(a, "origin", v)) w.origin = point3(v);
  if (!take(a, "brick", v)) missing(a, "brick", "'wall' (brick=L,H,W: length, height, width)");
  const Vec3 brick = point3(v);
  w.length = brick.x(), w.height = brick.y(), w.width = brick.z();
  if (!(brick.minCoeff() > 0.0)) fail("brick sizes must be positive");
  const WallLayout l = wall_layout(a);
  w.courses = l.courses, w.bricks = l.bricks, w.group = l.group, w.material = l.material;
  w.bed_tag = l.bed_tag, w.head_tag = l.head_tag;
  add_wall3(model_, w);
  overlap_checked_ = false;
}

void Interpreter::cmd_fix3(Args& a) {
  const auto sel = select(a, true);
  done(a);
  const uint8_t bits = fixity_words(a.words);
  Blocks3& B = model_.blocks3;
  const uint8_t moves = kFix3X | kFix3Y | kFix3Z;
  std::vector<size_t> rigid;
  for (size_t b : sel) {
    // A deformable block moves with its nodes: they are held (at their velocity now).
    if (B.deformable[b]) {
      if (!(bits & moves))
        fail("block " + std::to_string(B.id[b]) +
             " is deformable: its nodes have no rotation to fix (fix x, y, z or some of them)");
      set_block_nodes(model_, b, bits & moves, false, nullptr);
      continue;
    }
    rigid.push_back(b);
  }
  // A piece of a joined body holds the whole body: every piece shows it, its master moves it,
  // at the velocity it has now unless 'velocity' says otherwise.
  for (size_t b : whole_bodies3(B, rigid)) {
    B.fixity[b] |= bits;
    if (B.is_slave(b)) continue;
    for (int k = 0; k < 3; ++k)
      if (bits & (1 << k)) B.fixed_v[b][k] = B.body[b].velocity[k];
    if (bits & kFix3Rot) B.fixed_w[b] = Vec3::Zero();
  }
  model_.touch();
}

void Interpreter::cmd_velocity3(Args& a) {
  const auto sel = select(a);
  double v[3] = {0, 0, 0}, w[3] = {0, 0, 0};
  bool has[3], turns[3];
  has[0] = take_num(a, "vx", v[0]), has[1] = take_num(a, "vy", v[1]),
  has[2] = take_num(a, "vz", v[2]);
  turns[0] = take_num(a, "wx", w[0]), turns[1] = take_num(a, "wy", w[1]),
  turns[2] = take_num(a, "wz", w[2]);
  done(a);
  const bool spin = turns[0] || turns[1] || turns[2];
  if (!has[0] && !has[1] && !has[2] && !spin)
    fail("'velocity' needs vx=, vy=, vz= or an angular velocity wx=, wy=, wz=");
  // As in 2D: a fixed component takes its new velocity at the next integration.
  Blocks3& B = model_.blocks3;
  for (size_t b : sel) {
    if (B.deformable[b]) {
      if (spin)
        fail("block " + std::to_string(B.id[b]) +
             " is deformable: its nodes take vx=, vy=, vz= (no angular velocity)");
      set_block_nodes(model_, b, 0, false, v,
                      static_cast<uint8_t>((has[0] ? 1 : 0) | (has[1] ? 2 : 0) | (has[2] ? 4 : 0)));
      continue;
    }
    // (A piece of a joined body: the body's velocity.)
    const auto mb = static_cast<size_t>(B.master[b]);
    RigidBody3& body = B.body[mb];
    for (int k = 0; k < 3; ++k) {
      if (!has[k]) continue;
      B.fixed_v[mb][k] = v[k];
      if (!(B.fixity[mb] & (1 << k))) body.velocity[k] = v[k];
    }
    if (!spin) continue;
    // The angular velocity (world axes, rad/s), the components not given kept: a held body
    // turns at it, a free one takes the angular momentum that spins it so.
    const bool held = B.fixity[mb] == kFix3All;
    if ((B.fixity[mb] & kFix3Rot) && !held)
      fail("block " + std::to_string(B.id[b]) +
           " has its rotation fixed: free it, or fix it whole, to turn it");
    Vec3 omega = held ? B.fixed_w[mb] : body.angular_velocity();
    for (int k = 0; k < 3; ++k)
      if (turns[k]) omega[k] = w[k];
    if (held) {
      B.fixed_w[mb] = omega;
    } else {
      const Mat3 r = body.orientation.toRotationMatrix();
      body.momentum = r * body.principal.cwiseProduct(r.transpose() * omega);
    }
    B.omega[mb] = omega;
  }
}

void Interpreter::cmd_gravity3(Args& a) {
  if (a.words.size() != 3) fail("write 'gravity GX GY GZ' (m/s^2), e.g. 'gravity 0 0 -9.81'");
  model_.settings.gravity3 = Vec3(num(a.words[0]), num(a.words[1]), num(a.words[2]));
}

void Interpreter::cmd_join3(Args& a) {
  const auto sel = select(a);
  done(a);
  const std::vector<size_t> body = whole_bodies3(model_.blocks3, sel);
  const size_t pieces = body.size();
  if (pieces < 2) fail("'join' needs two or more blocks");
  // The pieces must make one body: each touches another (within the tolerance), all connected.
  const Blocks3& B = model_.blocks3;
  std::vector<size_t> root(pieces);
  for (size_t i = 0; i < pieces; ++i) root[i] = i;
  const auto find = [&](size_t x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  for (size_t i = 0; i < pieces; ++i)
    for (size_t j = i + 1; j < pieces; ++j)
      if (find(i) != find(j) &&
          best_plane(B, static_cast<uint32_t>(body[i]), static_cast<uint32_t>(body[j])).gap <=
              model_.tolerance())
        root[find(i)] = find(j);
  for (size_t i = 1; i < pieces; ++i)
    if (find(i) != find(0))
      fail("block " + std::to_string(B.id[body[i]]) + " does not touch the other blocks to join (" +
           "no chain of pieces within the tolerance " + std::to_string(model_.tolerance()) +
           " m joins it to block " + std::to_string(B.id[body[0]]) + ")");
  join_blocks3(model_, sel);
  const auto master = static_cast<size_t>(model_.blocks3.master[sel.front()]);
  log("join: block " + std::to_string(model_.blocks3.id[master]) + " now moves " +
      std::to_string(pieces) + " pieces as one body");
  overlap_checked_ = false;
}

void Interpreter::cmd_delete3(Args& a) {
  const auto sel = select(a);
  done(a);
  delete_blocks3(model_, sel);
  log("delete: " + std::to_string(sel.size()) + " block(s) removed");
}

}  // namespace tessera
