// Script commands of rock support: `bolt` and `cable` (one, or a pattern around an opening).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "tessera/generation/generators.hpp"
#include "tessera/script/script.hpp"
#include "tessera/support/cables.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

BoltProperties Interpreter::bolt_properties(Args& a) {
  BoltProperties p;
  const bool ka = take_num(a, "ka", p.ka), ks = take_num(a, "ks", p.ks);
  if (!ka) missing(a, "ka", "a bolt (its axial stiffness, N/m)");
  if (!ks) missing(a, "ks", "a bolt (its shear stiffness, N/m)");
  take_num(a, "tension", p.tension);
  p.compression = p.tension;
  take_num(a, "compression", p.compression);
  take_num(a, "shear", p.shear);
  take_num(a, "rupture", p.rupture);
  double row = 1.0;
  take_num(a, "rowspacing", row);
  if (!(p.ka > 0.0) || !(p.ks > 0.0)) fail("a bolt's stiffnesses ka and ks must be positive");
  if (p.tension < 0.0 || p.compression < 0.0 || p.shear < 0.0 || p.rupture < 0.0)
    fail("a bolt's yield forces and rupture displacement cannot be negative (0: none)");
  if (!(row > 0.0)) fail("the bolts' row spacing must be positive");
  // A 2D model is a slice 1 m thick: rows of bolts `row` apart act as 1/row of a bolt.
  p.ka /= row, p.ks /= row, p.tension /= row, p.compression /= row, p.shear /= row;
  return p;
}

Interpreter::Pattern Interpreter::pattern_args(Args& a, const std::string& what) {
  Pattern p;
  std::string v;
  if (!take(a, "joints", p.joints)) missing(a, "joints", "'" + what + "' (the opening's name)");
  const auto& tags = model_.joint_tags;
  const auto it = std::find(tags.begin(), tags.end(), p.joints);
  if (it == tags.end()) fail("no joint set, crack or opening is named '" + p.joints + "'");
  p.tag = static_cast<int>(it - tags.begin());
  if (!take_num(a, "spacing", p.spacing)) missing(a, "spacing", "'" + what + "'");
  if (!take_num(a, "length", p.length)) missing(a, "length", "'" + what + "'");
  if (take(a, "angles", v)) {
    const Vec2 r = point(v);
    p.a0 = r.x(), p.a1 = r.y();
  }
  if (!(p.spacing > 0.0) || !(p.length > 0.0)) fail("the spacing and length must be positive");
  if (!(p.a1 > p.a0))
    fail("write angles=FROM,TO with TO above FROM (degrees, anticlockwise from +x)");
  return p;
}

void Interpreter::cmd_bolt(Args& a) {
  std::string name;
  take(a, "name", name);
  const bool pattern = !a.words.empty() && a.words[0] == "pattern";
  const Pattern pat = pattern ? pattern_args(a, "bolt pattern") : Pattern{};
  // Default names: the opening's for a pattern (its bolts NAME-1, NAME-2, ...), boltN for one.
  if (name.empty())
    name = pattern ? pat.joints : "bolt" + std::to_string(model_.support.bolts.size() + 1);
  for (const Bolt& b : model_.support.bolts)
    if (b.name == name || b.name.rfind(name + "-", 0) == 0)
      fail("a bolt named '" + name + "' exists already: give another name=");
  if (pattern) {
    const BoltProperties p = bolt_properties(a);
    a.words.erase(a.words.begin());
    done(a);
    const size_t before = model_.support.size();
    const size_t n =
        install_bolt_pattern(model_, name, pat.tag, pat.spacing, pat.length, pat.a0, pat.a1, p);
    log("bolt pattern '" + name + "': " + std::to_string(n) + " bolt(s), " +
        std::to_string(model_.support.size() - before) + " joint crossing(s)");
    return;
  }
  if (a.words.size() != 2)
    fail(
        "write 'bolt X,Y X,Y ka=.. ks=.. [tension=..] [shear=..]' or 'bolt pattern joints=NAME "
        "spacing=S length=L ...'");
  const Vec2 p0 = point(a.words[0]), p1 = point(a.words[1]);
  const BoltProperties p = bolt_properties(a);
  a.words.clear();
  done(a);
  const size_t b = install_bolt(model_, name, p0, p1, p);
  log("bolt '" + name + "': " + std::to_string(model_.support.bolts[b].count) +
      " joint crossing(s)");
}

CableProperties Interpreter::cable_properties(Args& a) {
  CableProperties p;
  if (!take_num(a, "ea", p.ea)) missing(a, "ea", "a cable (its axial stiffness E A, N)");
  if (!take_num(a, "kbond", p.kbond))
    missing(a, "kbond", "a cable (the grout's shear stiffness, N/m per m of cable)");
  if (!take_num(a, "sbond", p.sbond))
    missing(a, "sbond", "a cable (the grout's bond strength, N per m of cable; 0: none)");
  take_num(a, "tension", p.tension);
  p.compression = p.tension;
  take_num(a, "compression", p.compression);
  take_num(a, "pretension", p.pretension);
  take_num(a, "mass", p.mass);
  // Bond strength rising with confinement (in zones): friction angle and grout perimeter.
  double friction = 0.0;
  if (take_num(a, "sfriction", friction)) {
    if (!(friction >= 0.0 && friction < 90.0))
      fail("a cable's sfriction (the grout's friction angle) must be from 0 to 90 degrees");
    if (!take_num(a, "perimeter", p.perimeter) || !(p.perimeter > 0.0))
      fail("a cable with sfriction needs perimeter=P, the grout's perimeter (m, positive)");
    p.bond_friction = std::tan(friction * std::numbers::pi / 180.0);
  }
  double row = 1.0;
  if (take_num(a, "rowspacing", row) && model_.dim == 3)
    fail("rowspacing= is for 2D models (a slice 1 m thick); a 3D cable is one cable");
  if (!(p.ea > 0.0) || !(p.kbond > 0.0))
    fail("a cable's stiffnesses ea and kbond must be positive");
  if (p.tension < 0.0 || p.compression < 0.0 || p.sbond < 0.0 || p.mass < 0.0)
    fail("a cable's yield forces, bond strength and mass cannot be negative (0: none)");
  if (p.tension > 0.0 && p.pretension > p.tension)
    fail("a cable's pretension cannot exceed its tensile yield force");
  if (!(row > 0.0)) fail("the cables' row spacing must be positive");
  // A 2D model is a slice 1 m thick: rows `row` apart act as 1/row of a cable.
  for (double* v : {&p.ea, &p.tension, &p.compression, &p.kbond, &p.sbond, &p.pretension, &p.mass,
                    &p.perimeter})
    *v /= row;
  return p;
}

void Interpreter::cmd_cable(Args& a) {
  std::string name;
  take(a, "name", name);
  const bool pattern = !a.words.empty() && a.words[0] == "pattern";
  if (pattern && model_.dim == 3)
    fail("cable patterns are for 2D models; place 3D cables one by one: cable X,Y,Z X,Y,Z ...");
  const Pattern pat = pattern ? pattern_args(a, "cable pattern") : Pattern{};
  // Default names as for bolts: the opening's for a pattern, cableN for one.
  const Cables& K = model_.cables;
  const std::vector<Cable>& existing = model_.dim == 3 ? model_.cables3.cables : K.cables;
  if (name.empty()) name = pattern ? pat.joints : "cable" + std::to_string(existing.size() + 1);
  for (const Cable& c : existing)
    if (c.name == name || c.name.rfind(name + "-", 0) == 0)
      fail("a cable named '" + name + "' exists already: give another name=");
  double segments = 0.0, free = 0.0;
  std::string head = "off";
  if (!take_num(a, "segments", segments)) missing(a, "segments", "a cable (how many segments)");
  if (!(segments >= 1.0) || segments != std::floor(segments) || segments > 10000)
    fail("a cable's segments must be a whole number from 1 to 10000");
  take_num(a, "free", free);
  take(a, "head", head);
  if (head != "on" && head != "off")
    fail("write head=on (tied to the rock: a faceplate) or head=off");
  if (free < 0.0) fail("a cable's free (unbonded) length cannot be negative");
  const CableProperties p = cable_properties(a);
  const int n = static_cast<int>(segments);
  if (pattern) {
    a.words.erase(a.words.begin());
    done(a);
    const size_t before = K.size();
    std::vector<std::string> skipped;
    const size_t placed = install_pattern(
        model_, pat.tag, pat.spacing, pat.length, pat.a0, pat.a1, [&](size_t k, Vec2 p0, Vec2 p1) {
          try {
            install_cable(model_, name + "-" + std::to_string(k), p0, p1, n, p, free, head == "on");
          } catch (const ModelError& e) {
            skipped.push_back(e.what());
            throw;
          }
        });
    log("cable pattern '" + name + "': " + std::to_string(placed) + " cable(s), " +
        std::to_string(K.size() - before) + " node(s)");
    // A cable the pattern could not place is named with the reason.
    for (const std::string& why : skipped) log("cable pattern '" + name + "': skipped " + why);
    return;
  }
  if (a.words.size() != 2 && model_.dim == 3)
    fail("write 'cable X,Y,Z X,Y,Z segments=N ea=.. kbond=.. sbond=.. [tension=..]'");
  if (a.words.size() != 2)
    fail(
        "write 'cable X,Y X,Y segments=N ea=.. kbond=.. sbond=.. [tension=..]' or 'cable pattern "
        "joints=NAME spacing=S length=L segments=N ...'");
  const std::string w0 = a.words[0], w1 = a.words[1];
  a.words.clear();
  done(a);
  if (model_.dim == 3)
    install_cable3(model_, name, point3(w0), point3(w1), n, p, free, head == "on");
  else
    install_cable(model_, name, point(w0), point(w1), n, p, free, head == "on");
  log("cable '" + name + "': " + std::to_string(n) + " segment(s)");
}

void Interpreter::cmd_liner(Args& a) {
  std::string name, joints, v;
  take(a, "name", name);
  if (!take(a, "joints", joints)) missing(a, "joints", "a liner (the opening's name)");
  const auto& tags = model_.joint_tags;
  const auto it = std::find(tags.begin(), tags.end(), joints);
  if (it == tags.end()) fail("no joint set, crack or opening is named '" + joints + "'");
  if (name.empty()) name = joints;
  for (const Liner& l : model_.liners.liners)
    if (l.name == name) fail("a liner named '" + name + "' exists already: give another name=");
  double a0 = -180.0, a1 = 180.0;
  if (take(a, "angles", v)) {
    const Vec2 r = point(v);
    a0 = r.x(), a1 = r.y();
    if (!(a1 > a0))
      fail("write angles=FROM,TO with TO above FROM (degrees, anticlockwise from +x)");
  }
  LinerProperties p;
  // The section: ea= and ei= (per metre), or e= and thickness= (plane strain with nu=).
  double e = 0.0, t = 0.0, nu = 0.0, density = 0.0, row = 1.0;
  const bool has_ea = take_num(a, "ea", p.ea), has_ei = take_num(a, "ei", p.ei);
  const bool has_e = take_num(a, "e", e), has_t = take_num(a, "thickness", t);
  take_num(a, "nu", nu);
  if (has_e || has_t) {
    if (!has_e) missing(a, "e", "a liner given by its thickness (Young's modulus, Pa)");
    if (!has_t) missing(a, "thickness", "a liner given by its modulus (its thickness, m)");
    if (!(e > 0.0) || !(t > 0.0) || !(nu >= 0.0 && nu < 0.5))
      fail("a liner's e and thickness must be positive and nu in [0, 0.5)");
    p.ea = e * t / (1.0 - nu * nu), p.ei = e * t * t * t / (12.0 * (1.0 - nu * nu));
  } else {
    if (!has_ea)
      missing(a, "ea", "a liner (its axial stiffness E A, N per metre; or e= thickness=)");
    if (!has_ei) missing(a, "ei", "a liner (its bending stiffness E I, N m2 per metre)");
  }
  if (!(p.ea > 0.0) || !(p.ei > 0.0)) fail("a liner's ea and ei must be positive");
  if (!take_num(a, "kn", p.kn))
    missing(a, "kn", "a liner (the interface's normal stiffness, Pa/m)");
  if (!take_num(a, "ks", p.ks))
    missing(a, "ks", "a liner (the interface's shear stiffness, Pa/m; 0: full slip)");
  take_num(a, "thrust", p.thrust), take_num(a, "moment", p.moment);
  take_num(a, "tension", p.tension), take_num(a, "cohesion", p.cohesion);
  take_num(a, "friction", p.friction), take_num(a, "mass", p.mass);
  if (take_num(a, "density", density)) {
    if (!has_t) fail("density= needs the liner's thickness=; give mass= (kg per metre) instead");
    p.mass = density * t;
  }
  take_num(a, "rowspacing", row);
  double spacing = 0.0;
  if (take_num(a, "spacing", spacing) && !(spacing > 0.0))
    fail("the liner's node spacing must be positive (leave it out: a node at each wall vertex)");
  if (!(p.kn > 0.0) || p.ks < 0.0) fail("a liner's kn must be positive and ks zero or more");
  if (p.thrust < 0.0 || p.moment < 0.0 || p.tension < 0.0 || p.cohesion < 0.0 || p.friction < 0.0 ||
      p.mass < 0.0)
    fail("a liner's capacities, strengths and mass cannot be negative (0: none)");
  if (!(row > 0.0)) fail("the liner's row spacing must be positive");
  // Per metre of tunnel: a lining of ribs `row` apart is 1/row of a rib.
  for (double* x : {&p.ea, &p.ei, &p.thrust, &p.moment, &p.mass}) *x /= row;
  a.words.clear();
  done(a);
  const size_t n =
      install_liner(model_, name, static_cast<int>(it - tags.begin()), a0, a1, p, spacing);
  log("liner '" + name + "': " + std::to_string(n) + " node(s)" +
      (model_.liners.liners.back().closed ? ", a closed ring" : ""));
}

int32_t Interpreter::support_point(Args& a, HistoryQuantity q, std::string& name) {
  // The members of the kind the quantity is of: names, ranges, and how far each point is from
  // a given one.
  struct Member {
    std::string name;
    uint32_t first = 0, count = 0;
  };
  std::vector<Member> members;
  std::string at;
  const bool has_at = take(a, "at", at);
  const bool three = model_.dim == 3;
  const Vec2 p2 = has_at && !three ? point(at) : Vec2::Zero();
  const Vec3 p3 = has_at && three ? point3(at) : Vec3::Zero();
  std::function<double(uint32_t)> distance;
  const char* kind = "bolt";
  const Reinforcement& R = model_.support;
  const Liners& L = model_.liners;
  if (is_bolt_quantity(q)) {
    for (const Bolt& b : R.bolts) members.push_back({b.name, b.first, b.count});
    distance = [&](uint32_t e) {
      return (0.5 * (anchor_position(model_, R.side_a[e]) + anchor_position(model_, R.side_b[e])) -
              p2)
          .norm();
    };
  } else if (is_cable_quantity(q)) {
    kind = "cable";
    for (const Cable& c : three ? model_.cables3.cables : model_.cables.cables)
      members.push_back({c.name, c.first, c.count});
    distance = [&](uint32_t i) {
      return three ? (model_.cables3.pos[i] - p3).norm() : (model_.cables.pos[i] - p2).norm();
    };
  } else {
    kind = "liner";
    for (const Liner& l : L.liners) members.push_back({l.name, l.first, l.count});
    distance = [&](uint32_t i) { return (L.pos0[i] - p2).norm(); };
  }
  if (!take(a, kind, name))
    missing(a, kind, std::string("a ") + kind + " history (the " + kind + "'s name)");
  const auto it =
      std::find_if(members.begin(), members.end(), [&](const Member& o) { return o.name == name; });
  if (it == members.end()) fail(std::string("no ") + kind + " is named '" + name + "'");
  // The point nearest at=, or the member's first.
  int32_t best = static_cast<int32_t>(it->first);
  double d = 1e300;
  for (uint32_t i = it->first; has_at && i < it->first + it->count; ++i)
    if (distance(i) < d) d = distance(i), best = static_cast<int32_t>(i);
  return best;
}

}  // namespace tessera
