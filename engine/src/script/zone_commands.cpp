// Script commands of deformable blocks: zone, boundary (node conditions and stresses), insitu.
#include <cmath>
#include <limits>

#include "tessera/core/insitu.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {
// A box of nodes from x=X0,X1 and y=Y0,Y1 (either may be left out).
struct NodeBox {
  double x0 = -std::numeric_limits<double>::infinity(), x1 = -x0;
  double y0 = x0, y1 = x1;
  bool holds(const Vec2& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
};
}  // namespace

void Interpreter::cmd_zone(Args& a) {
  if (a.words.empty()) fail("write 'zone generate edge=H [selection]' or 'zone null [selection]'");
  const std::string verb = a.words[0];
  a.words.erase(a.words.begin());
  Continuum& c = model_.continuum;
  if (verb == "generate") {
    double edge = 0;
    if (!take_num(a, "edge", edge)) missing(a, "edge", "zone generate");
    if (!(edge > 0)) fail("the zone edge must be positive");
    ZoneGrading grade;
    const bool graded = take_num(a, "fine", grade.fine_edge);
    std::string v;
    if (take(a, "near", v)) grade.centre = point(v);
    take_num(a, "radius", grade.radius);
    take_num(a, "growth", grade.growth);
    if (graded && !(grade.fine_edge > 0 && grade.fine_edge <= edge))
      fail("the fine zone edge must be positive and at most edge=");
    std::vector<size_t> sel = optional_selection(a);
    done(a);
    if (sel.empty())
      for (size_t b = 0; b < model_.blocks.size(); ++b) sel.push_back(b);
    const size_t before = c.zone_count();
    for (size_t b : sel) {
      if (model_.blocks.deformable[b]) continue;
      try {
        make_deformable(model_, b, edge, graded ? &grade : nullptr);
      } catch (const std::invalid_argument& e) {
        fail("block " + std::to_string(model_.blocks.id[b]) + ": " + e.what());
      }
    }
    double worst = 180;
    for (size_t z = before; z < c.zone_count(); ++z) {
      const auto& t = c.zones[z];
      for (int k = 0; k < 3; ++k) {
        const Vec2 u = c.pos[t[(k + 1) % 3]] - c.pos[t[k]], w = c.pos[t[(k + 2) % 3]] - c.pos[t[k]];
        worst = std::min(worst, std::atan2(std::abs(cross(u, w)), u.dot(w)) * 180 / M_PI);
      }
    }
    log("zone: " + std::to_string(c.zone_count() - before) + " zones, " +
        std::to_string(c.node_count()) + " nodes in all; smallest zone angle " +
        std::to_string(worst).substr(0, 5) + " degrees");
    overlap_checked_ = false;
  } else if (verb == "null") {
    // Excavation: zones whose centroid is in the selected blocks' box or the given box.
    NodeBox box;
    std::string v;
    bool boxed = false;
    if (take(a, "x", v)) {
      const Vec2 r = point(v);
      box.x0 = std::min(r.x(), r.y()), box.x1 = std::max(r.x(), r.y()), boxed = true;
    }
    if (take(a, "y", v)) {
      const Vec2 r = point(v);
      box.y0 = std::min(r.x(), r.y()), box.y1 = std::max(r.x(), r.y()), boxed = true;
    }
    done(a);
    if (!boxed) fail("write 'zone null x=X0,X1 y=Y0,Y1'");
    size_t count = 0;
    for (size_t z = 0; z < c.zone_count(); ++z) {
      const auto& t = c.zones[z];
      if (c.material[z] == 0 || !box.holds((c.pos[t[0]] + c.pos[t[1]] + c.pos[t[2]]) / 3.0))
        continue;
      c.material[z] = 0, c.stress[z] = ZoneStress{}, c.state[z] = 0, ++count;
    }
    if (!count) fail("no zone has its centre in that box");
    lump_masses(c);
    model_.touch();
    log("zone null: " + std::to_string(count) + " zones excavated");
  } else {
    fail("'" + verb + "' is not a zone command" + suggest(verb, {"generate", "null"}));
  }
}

void Interpreter::cmd_boundary(Args& a) {
  Continuum& c = model_.continuum;
  if (c.node_count() == 0) fail("there are no zones: 'zone generate' makes blocks deformable");
  NodeBox box;
  std::string v;
  if (take(a, "x", v)) {
    const Vec2 r = point(v);
    box.x0 = std::min(r.x(), r.y()), box.x1 = std::max(r.x(), r.y());
  }
  if (take(a, "y", v)) {
    const Vec2 r = point(v);
    box.y0 = std::min(r.x(), r.y()), box.y1 = std::max(r.x(), r.y());
  }
  std::string fix, vel, stress, joints;
  const bool has_fix = take(a, "fix", fix), has_vel = take(a, "velocity", vel);
  bool has_stress = take(a, "stress", stress);
  // A pressure P is the stress -P, -P, 0: on the wall of an opening it pushes into the rock.
  double pressure = 0;
  if (take_num(a, "pressure", pressure)) {
    if (has_stress) fail("give stress= or pressure=, not both");
    stress = std::to_string(-pressure) + "," + std::to_string(-pressure) + ",0";
    has_stress = true;
  }
  // Only the outline edges along a named joint set, crack or opening.
  int tag = -1;
  if (take(a, "joints", joints)) {
    for (size_t k = 0; k < model_.joint_tags.size(); ++k)
      if (model_.joint_tags[k] == joints) tag = static_cast<int>(k);
    if (tag < 0)
      fail("there are no joints named '" + joints + "'" + suggest(joints, model_.joint_tags));
  }
  const bool free = !a.words.empty() && a.words[0] == "free";
  if (free) a.words.erase(a.words.begin());
  if (!a.words.empty()) fail("unexpected word '" + a.words[0] + "'");
  done(a);
  if (int(has_fix) + int(has_vel) + int(has_stress) + int(free) != 1)
    fail(
        "write one of 'boundary fix=x|y|xy', 'boundary velocity=VX,VY', "
        "'boundary stress=SXX,SYY,SXY' or 'boundary free', with x=X0,X1 y=Y0,Y1");
  size_t count = 0;
  if (has_stress) {
    // Tractions on the outline edges of deformable blocks whose both ends are in the box.
    const auto parts = split_top_level(stress);
    if (parts.size() != 3) fail("write stress=SXX,SYY,SXY (tension positive, Pa)");
    const ZoneStress s{num(parts[0]), num(parts[1]), num(parts[2]), 0};
    const Blocks& B = model_.blocks;
    for (size_t b = 0; b < B.size(); ++b) {
      if (!B.deformable[b]) continue;
      for (uint32_t k = B.vert_begin[b]; k < B.vert_begin[b + 1]; ++k) {
        const uint32_t next = k + 1 < B.vert_begin[b + 1] ? k + 1 : B.vert_begin[b];
        const auto n0 = static_cast<size_t>(B.node[k]), n1 = static_cast<size_t>(B.node[next]);
        if (!box.holds(c.pos[n0]) || !box.holds(c.pos[n1])) continue;
        if (tag >= 0 && B.edge_tag[k] != tag) continue;
        const Vec2 d = c.pos[n1] - c.pos[n0];
        const Vec2 nl(d.y(), -d.x());  // outward normal times length (outline counter-clockwise)
        const Vec2 t(s.xx * nl.x() + s.xy * nl.y(), s.xy * nl.x() + s.yy * nl.y());
        c.applied[n0] += 0.5 * t, c.applied[n1] += 0.5 * t, ++count;
      }
    }
    if (!count)
      fail(tag >= 0
               ? "no outline edge of a deformable block along '" + joints + "' lies in that box"
               : std::string("no outline edge of a deformable block lies in that box"));
    log("boundary stress on " + std::to_string(count) + " edges");
    return;
  }
  uint8_t bits = 0;
  Vec2 velocity = Vec2::Zero();
  if (has_fix) {
    if (fix == "x")
      bits = kFixX;
    else if (fix == "y")
      bits = kFixY;
    else if (fix == "xy")
      bits = kFixX | kFixY;
    else
      fail("write fix=x, fix=y or fix=xy");
  }
  if (has_vel) velocity = point(vel), bits = kFixX | kFixY;
  for (size_t n = 0; n < c.node_count(); ++n) {
    if (!box.holds(c.pos[n])) continue;
    if (free)
      c.fixity[n] = 0;
    else
      c.fixity[n] |= bits;
    if (has_vel) c.fixed_vel[n] = velocity;
    if (has_fix) {
      if (bits & kFixX) c.fixed_vel[n].x() = 0;
      if (bits & kFixY) c.fixed_vel[n].y() = 0;
    }
    ++count;
  }
  if (!count) fail("no node lies in that box");
  log("boundary: " + std::to_string(count) + " nodes");
}

void Interpreter::cmd_insitu(Args& a) {
  Continuum& c = model_.continuum;
  std::string v;
  if (!take(a, "stress", v)) missing(a, "stress", "insitu");
  auto parts = split_top_level(v);
  if (parts.size() != 3) fail("write stress=SXX,SYY,SXY (tension positive, Pa)");
  ZoneStress s0{num(parts[0]), num(parts[1]), num(parts[2]), 0}, g;
  bool has_zz = false;
  if (take(a, "szz", v)) s0.zz = num(v), has_zz = true;
  double y0 = 0;
  if (take(a, "ygradient", v)) {
    parts = split_top_level(v);
    if (parts.size() != 3) fail("write ygradient=GXX,GYY,GXY (Pa per metre of height)");
    g = {num(parts[0]), num(parts[1]), num(parts[2]), 0};
  }
  take_num(a, "y0", y0);
  done(a);
  if (model_.blocks.size() == 0) fail("there are no blocks to take the stress");
  initialize_stress(c, s0, g, y0);
  // The out-of-plane stress of plane strain, unless given: nu (sxx + syy) per zone.
  if (!has_zz)
    for (size_t z = 0; z < c.zone_count(); ++z) {
      const ZoneProperties& p = c.materials[c.material[z]];
      if (!p.impl->solid()) continue;
      const double nu = (3 * p.bulk - 2 * p.shear) / (2 * (3 * p.bulk + p.shear));
      c.stress[z].zz = nu * (c.stress[z].xx + c.stress[z].yy);
    }
  // The joints: tractions of the same field on every shut contact.
  const size_t loaded = preload_contacts(model_, StressField{s0, g, y0});
  if (c.zone_count() == 0 && loaded == 0)
    fail("nothing takes the stress: there are no zones and no shut joints");
  log("insitu: stresses set in " + std::to_string(c.zone_count()) + " zones and on " +
      std::to_string(loaded) + " joint contacts");
}

}  // namespace tessera
