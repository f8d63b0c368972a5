// Script commands of rock support: `bolt` (one bolt, or a pattern around an opening).
#include <algorithm>

#include "tessera/generation/generators.hpp"
#include "tessera/script/script.hpp"
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

int32_t Interpreter::bolt_element(Args& a) {
  const Reinforcement& R = model_.support;
  std::string name, at;
  if (!take(a, "bolt", name)) missing(a, "bolt", "a bolt history (the bolt's name)");
  const auto it =
      std::find_if(R.bolts.begin(), R.bolts.end(), [&](const Bolt& b) { return b.name == name; });
  if (it == R.bolts.end()) fail("no bolt is named '" + name + "'");
  // The crossing nearest the point, or the bolt's first.
  int32_t best = static_cast<int32_t>(it->first);
  if (take(a, "at", at)) {
    const Vec2 p = point(at);
    double d = 1e300;
    for (uint32_t e = it->first; e < it->first + it->count; ++e) {
      const Vec2 x =
          0.5 * (anchor_position(model_, R.side_a[e]) + anchor_position(model_, R.side_b[e]));
      if ((x - p).norm() < d) d = (x - p).norm(), best = static_cast<int32_t>(e);
    }
  }
  return best;
}

void Interpreter::cmd_bolt(Args& a) {
  std::string name;
  take(a, "name", name);
  const bool pattern = !a.words.empty() && a.words[0] == "pattern";
  std::string joints;
  if (pattern && !take(a, "joints", joints))
    missing(a, "joints", "'bolt pattern' (the opening's name)");
  // Default names: the opening's for a pattern (its bolts NAME-1, NAME-2, ...), boltN for one.
  if (name.empty())
    name = pattern ? joints : "bolt" + std::to_string(model_.support.bolts.size() + 1);
  for (const Bolt& b : model_.support.bolts)
    if (b.name == name || b.name.rfind(name + "-", 0) == 0)
      fail("a bolt named '" + name + "' exists already: give another name=");
  if (pattern) {
    std::string v;
    const auto& tags = model_.joint_tags;
    const auto it = std::find(tags.begin(), tags.end(), joints);
    if (it == tags.end()) fail("no joint set, crack or opening is named '" + joints + "'");
    double spacing = 0.0, length = 0.0, a0 = -180.0, a1 = 180.0;
    if (!take_num(a, "spacing", spacing)) missing(a, "spacing", "'bolt pattern'");
    if (!take_num(a, "length", length)) missing(a, "length", "'bolt pattern'");
    if (take(a, "angles", v)) {
      const Vec2 r = point(v);
      a0 = r.x(), a1 = r.y();
    }
    if (!(spacing > 0.0) || !(length > 0.0)) fail("the bolts' spacing and length must be positive");
    if (!(a1 > a0))
      fail("write angles=FROM,TO with TO above FROM (degrees, anticlockwise from +x)");
    const BoltProperties p = bolt_properties(a);
    a.words.erase(a.words.begin());
    done(a);
    const size_t before = model_.support.size();
    const size_t n = install_bolt_pattern(model_, name, static_cast<int>(it - tags.begin()),
                                          spacing, length, a0, a1, p);
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

}  // namespace tessera
