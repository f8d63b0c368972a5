// Script commands of deformable blocks: zone, boundary (node conditions and stresses), insitu.
#include <cmath>
#include <limits>

#include "tessera/core/insitu.hpp"
#include "tessera/script/expr.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"
#include "tessera/zones/deformable3.hpp"
#include "tessera/zones/zoning3.hpp"

namespace tessera {

// A box of nodes from x=X0,X1, y=Y0,Y1 and (3D) z=Z0,Z1 (any may be left out).
struct NodeBox {
  Vec3 lo = Vec3::Constant(-std::numeric_limits<double>::infinity()), hi = -lo;
  bool given = false;
  bool holds(const Vec2& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  }
  bool holds(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

namespace {

// Fixity bits from the axes named, e.g. "xz" (x and y in 2D; x, y and z in 3D), or 0.
uint8_t axis_bits(const std::string& axes, int dim) {
  uint8_t bits = 0;
  for (char ch : axes) {
    const int k = ch - 'x';
    if (k < 0 || k >= dim || (bits & node_fix_bit(k))) return 0;
    bits |= node_fix_bit(k);
  }
  return bits;
}

// Holds, frees or drives the nodes in the box; returns how many.
template <int D>
size_t set_nodes(ContinuumT<D>& c, const NodeBox& box, bool free, uint8_t bits,
                 const typename ContinuumT<D>::Vec* velocity) {
  size_t count = 0;
  for (size_t n = 0; n < c.node_count(); ++n) {
    if (!box.holds(c.pos[n])) continue;
    if (free)
      c.fixity[n] = 0;
    else
      c.fixity[n] |= bits;
    for (int k = 0; k < D; ++k)
      if (bits & node_fix_bit(k)) c.fixed_vel[n][k] = velocity ? (*velocity)[k] : 0.0;
    ++count;
  }
  return count;
}

// The centroid of zone z.
template <int D>
typename ContinuumT<D>::Vec zone_centre(const ContinuumT<D>& c, size_t z) {
  typename ContinuumT<D>::Vec p = ContinuumT<D>::Vec::Zero();
  for (uint32_t n : c.zones[z]) p += c.pos[n];
  return p / (D + 1.0);
}

// Excavates the zones whose centroid is in the box; returns how many.
template <int D>
size_t null_zones(ContinuumT<D>& c, const NodeBox& box) {
  size_t count = 0;
  for (size_t z = 0; z < c.zone_count(); ++z) {
    if (c.material[z] == 0 || !box.holds(zone_centre(c, z))) continue;
    c.material[z] = 0, set_zone_stress(c, z, ZoneStress{}, 0), ++count;
  }
  if (count) lump_masses(c);
  return count;
}
}  // namespace

NodeBox Interpreter::node_box(Args& a) {
  NodeBox box;
  std::string v;
  for (int k = 0; k < model_.dim; ++k)
    if (take(a, std::string(1, static_cast<char>('x' + k)), v)) {
      const std::string axis(1, static_cast<char>('x' + k));
      if (split_top_level(v).size() != 2)
        fail("'" + axis + "=" + v + "' is not a range: write " + axis + "=" +
             static_cast<char>('X' + k) + "0," + static_cast<char>('X' + k) + "1");
      const Vec2 r = point(v);
      box.lo[k] = std::min(r.x(), r.y()), box.hi[k] = std::max(r.x(), r.y()), box.given = true;
    }
  if (model_.dim == 2 && take(a, "z", v)) fail("z= bounds boxes of 3D models; this model is 2D");
  return box;
}

void Interpreter::cmd_zone(Args& a) {
  if (a.words.empty()) fail("write 'zone generate edge=H [selection]' or 'zone null [box]'");
  const std::string verb = a.words[0];
  a.words.erase(a.words.begin());
  const bool three = model_.dim == 3;
  if (verb == "generate") {
    double edge = 0;
    if (!take_num(a, "edge", edge)) missing(a, "edge", "zone generate");
    if (!(edge > 0)) fail("the zone edge must be positive");
    double order = 1;
    if (take_num(a, "order", order) && order != 1 && order != 2)
      fail("write order=1 (4-node zones) or order=2 (10-node tetrahedra, 3D)");
    if (order == 2 && !three)
      fail("order=2 (10-node tetrahedra) is for 3D models; 2D zones are 3-node triangles");
    ZoneGrading grade;
    ZoneGrading3 grade3;
    const bool graded = take_num(a, "fine", grade.fine_edge);
    std::string v;
    if (take(a, "near", v)) {
      if (three)
        grade3.centre = point3(v);
      else
        grade.centre = point(v);
    }
    take_num(a, "radius", grade.radius);
    take_num(a, "growth", grade.growth);
    grade3.fine_edge = grade.fine_edge, grade3.radius = grade.radius, grade3.growth = grade.growth;
    if (graded && !(grade.fine_edge > 0 && grade.fine_edge <= edge))
      fail("the fine zone edge must be positive and at most edge=");
    std::vector<size_t> sel = optional_selection(a);
    done(a);
    if (sel.empty())
      for (size_t b = 0; b < model_.block_count(); ++b) sel.push_back(b);
    // A block zoned already keeps its zones (its nodes carry its state): say so, and refuse a
    // command that would zone nothing.
    size_t zoned = 0;
    int first_zoned = -1;
    for (size_t b : sel)
      if (three ? model_.blocks3.deformable[b] : model_.blocks.deformable[b])
        if (++zoned == 1) first_zoned = block_id(b);
    if (zoned == sel.size())
      fail(std::string(zoned == 1 ? "block " : "blocks ") + std::to_string(first_zoned) +
           (zoned == 1 ? " is" : " and the rest are") +
           " zoned already; a block is zoned once (re-zoning is not supported)");
    if (zoned > 0)
      warn(std::to_string(zoned) + " block(s) zoned already (block " + std::to_string(first_zoned) +
           " ...) keep their zones");
    size_t fixed_blocks = 0;
    const auto report_fixed = [&] {
      if (fixed_blocks > 0)
        log("zone: the nodes of " + std::to_string(fixed_blocks) +
            " fixed block(s) are held as the block was");
    };
    if (three) {
      Continuum3& c = model_.continuum3;
      const size_t before = c.zone_count();
      ZoningReport worst;
      for (size_t b : sel) {
        if (model_.blocks3.deformable[b]) continue;
        // A fixed block's nodes are held as the block was (its translations, at its velocity).
        const uint8_t held = model_.blocks3.fixity[b] & (kFix3X | kFix3Y | kFix3Z);
        const Vec3 held_v = model_.blocks3.fixed_v[b];
        try {
          const ZoningReport r =
              make_deformable3(model_, b, edge, graded ? &grade3 : nullptr, stop_, order == 2);
          if (held) set_block_nodes(model_, b, held, false, held_v.data()), ++fixed_blocks;
          if (r.min_dihedral < worst.min_dihedral)
            worst.min_dihedral = r.min_dihedral, worst.worst_at = r.worst_at;
          worst.poor += r.poor;
        } catch (const std::invalid_argument& e) {
          fail("block " + std::to_string(model_.blocks3.id[b]) + ": " + e.what());
        } catch (const ZoningStopped&) {
          // A stop (signal, Stop button) while meshing: the blocks zoned so far stay zoned, this
          // one and the rest rigid; the script ends before its next line.
          log("zone generate stopped while meshing block " + std::to_string(model_.blocks3.id[b]) +
              ": it and the blocks after it are left rigid");
          break;
        }
      }
      if (c.zone_count() > before)
        log("zone: " + std::to_string(c.zone_count() - before) +
            (order == 2 ? " 10-node tetrahedra, " : " tetrahedra, ") +
            std::to_string(c.node_count()) + " nodes in all; smallest dihedral angle " +
            std::to_string(worst.min_dihedral).substr(0, 5) + " degrees");
      if (worst.poor > 0) {
        const Vec3& p = worst.worst_at;
        log("warning: " + std::to_string(worst.poor) + " zones have a dihedral angle under " +
            std::to_string(static_cast<int>(ZoneMesh3::kPoorDihedral)) +
            " degrees (the smallest near " + point_text(p) +
            "): answers near such slivers are poor (a plastic zone's extent can be out by a "
            "third); a slightly different edge= or fine= usually avoids them");
      }
      report_fixed();
      overlap_checked_ = false;
      return;
    }
    Continuum& c = model_.continuum;
    const size_t before = c.zone_count();
    for (size_t b : sel) {
      if (model_.blocks.deformable[b]) continue;
      const uint8_t held = model_.blocks.fixity[b] & (kFixX | kFixY);
      const double held_v[2] = {model_.blocks.fixed_vx[b], model_.blocks.fixed_vy[b]};
      try {
        make_deformable(model_, b, edge, graded ? &grade : nullptr);
        if (held) set_block_nodes(model_, b, held, false, held_v), ++fixed_blocks;
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
    report_fixed();
    overlap_checked_ = false;
  } else if (verb == "null") {
    // Excavation: zones whose centroid is in the box.
    const NodeBox box = node_box(a);
    done(a);
    if (!box.given)
      fail(three ? "write 'zone null x=X0,X1 y=Y0,Y1 z=Z0,Z1'"
                 : "write 'zone null x=X0,X1 y=Y0,Y1'");
    const size_t count =
        three ? null_zones(model_.continuum3, box) : null_zones(model_.continuum, box);
    if (!count) fail("no zone has its centre in that box");
    model_.touch();
    log("zone null: " + std::to_string(count) + " zones excavated");
  } else {
    fail("'" + verb + "' is not a zone command" + suggest(verb, {"generate", "null"}));
  }
}

void Interpreter::cmd_boundary(Args& a) {
  const bool three = model_.dim == 3;
  if ((three ? model_.continuum3.node_count() : model_.continuum.node_count()) == 0)
    fail("there are no zones: 'zone generate' makes blocks deformable");
  const NodeBox box = node_box(a);
  std::string fix, vel, stress, joints;
  const bool has_fix = take(a, "fix", fix);
  bool has_vel = take(a, "velocity", vel);
  // vx= vy= vz=: only the axes named are driven (a smooth platen), the others left as they are.
  uint8_t axis_vel_bits = 0;
  double axis_vel[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < (three ? 3 : 2); ++k)
    if (take_num(a, std::string("v") + "xyz"[k], axis_vel[k]))
      axis_vel_bits |= static_cast<uint8_t>(1u << k);
  if (axis_vel_bits) {
    if (has_vel)
      fail("give velocity= (all axes) or vx= vy=" + std::string(three ? " vz=" : "") +
           " (those named), not both");
    has_vel = true;
  }
  bool has_stress = take(a, "stress", stress);
  // A pressure P is the stress -P on every axis: on the wall of an opening it pushes into the rock.
  double pressure = 0;
  if (take_num(a, "pressure", pressure)) {
    if (has_stress) fail("give stress= or pressure=, not both");
    const std::string p = std::to_string(-pressure);
    stress = three ? p + "," + p + "," + p + ",0,0,0" : p + "," + p + ",0";
    has_stress = true;
  }
  // Only the outline edges (faces) along a named joint set, crack or opening.
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
    fail(three ? "write one of 'boundary fix=x|y|z|xy|xz|yz|xyz', 'boundary velocity=VX,VY,VZ' "
                 "(or vx= vy= vz=), "
                 "'boundary stress=SXX,SYY,SZZ,SXY,SYZ,SXZ' or 'boundary free', with x=X0,X1 "
                 "y=Y0,Y1 z=Z0,Z1"
               : "write one of 'boundary fix=x|y|xy', 'boundary velocity=VX,VY' (or vx= vy=), "
                 "'boundary stress=SXX,SYY,SXY' or 'boundary free', with x=X0,X1 y=Y0,Y1");
  if (has_stress) {
    const auto parts = split_top_level(stress);
    if (parts.size() != (three ? 6u : 3u))
      fail(three ? "write stress=SXX,SYY,SZZ,SXY,SYZ,SXZ (tension positive, Pa)"
                 : "write stress=SXX,SYY,SXY (tension positive, Pa)");
    ZoneStress s;
    if (three)
      s = {num(parts[0]), num(parts[1]), num(parts[3]),
           num(parts[2]), num(parts[4]), num(parts[5])};
    else
      s = {num(parts[0]), num(parts[1]), num(parts[2]), 0};
    const size_t count = three ? boundary_stress3(box, s, tag) : boundary_stress2(box, s, tag);
    const char* what = three ? "surface triangle" : "outline edge";
    if (!count)
      fail(tag >= 0 ? std::string("no ") + what + " of a deformable block along '" + joints +
                          "' lies in that box"
                    : std::string("no ") + what + " of a deformable block lies in that box");
    log("boundary stress on " + std::to_string(count) + (three ? " surface triangles" : " edges"));
    return;
  }
  uint8_t bits = 0;
  if (has_fix && !(bits = axis_bits(fix, model_.dim)))
    fail(three ? "write fix= with the axes held: x, y, z, xy, xz, yz or xyz"
               : "write fix=x, fix=y or fix=xy");
  size_t count = 0;
  if (three) {
    const Vec3 v = axis_vel_bits ? Vec3(axis_vel[0], axis_vel[1], axis_vel[2])
                   : has_vel     ? point3(vel)
                                 : Vec3::Zero();
    if (has_vel) bits = axis_vel_bits ? axis_vel_bits : 7;
    count = set_nodes(model_.continuum3, box, free, bits, has_vel ? &v : nullptr);
  } else {
    const Vec2 v = axis_vel_bits ? Vec2(axis_vel[0], axis_vel[1])
                   : has_vel     ? point(vel)
                                 : Vec2::Zero();
    if (has_vel) bits = axis_vel_bits ? axis_vel_bits : kFixX | kFixY;
    count = set_nodes(model_.continuum, box, free, bits, has_vel ? &v : nullptr);
  }
  if (!count) fail("no node lies in that box");
  log("boundary: " + std::to_string(count) + " nodes");
}

size_t Interpreter::boundary_stress2(const NodeBox& box, const ZoneStress& s, int tag) {
  // Tractions on the outline edges of deformable blocks whose both ends are in the box.
  Continuum& c = model_.continuum;
  const Blocks& B = model_.blocks;
  size_t count = 0;
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
  return count;
}

size_t Interpreter::boundary_stress3(const NodeBox& box, const ZoneStress& s, int tag) {
  // Tractions on the surface triangles of deformable blocks whose three corners are in the box.
  Continuum3& c = model_.continuum3;
  const Blocks3& B = model_.blocks3;
  size_t count = 0;
  for (size_t f = 0; f + 1 < B.ftri_begin.size(); ++f) {
    if (tag >= 0 && B.face_tag[f] != tag) continue;
    for (uint32_t k = B.ftri_begin[f]; k < B.ftri_begin[f + 1]; ++k) {
      const auto& t = B.ftri[k];
      if (!box.holds(c.pos[t[0]]) || !box.holds(c.pos[t[1]]) || !box.holds(c.pos[t[2]])) continue;
      // Outward normal times area, then the traction sigma . n, shared among its nodes.
      const Vec3 n = 0.5 * (c.pos[t[1]] - c.pos[t[0]]).cross(c.pos[t[2]] - c.pos[t[0]]);
      const Vec3 tr(s.xx * n.x() + s.xy * n.y() + s.xz * n.z(),
                    s.xy * n.x() + s.yy * n.y() + s.yz * n.z(),
                    s.xz * n.x() + s.yz * n.y() + s.zz * n.z());
      const Vec3 share = traction_shares(t, c.edge_node);
      for (int i = 0; i < 3; ++i) c.applied[t[i]] += share[i] * tr;
      ++count;
    }
  }
  return count;
}

void Interpreter::cmd_insitu(Args& a) {
  const bool three = model_.dim == 3;
  std::string v;
  if (!take(a, "stress", v)) missing(a, "stress", "insitu");
  auto parts = split_top_level(v);
  // 2D: SXX,SYY,SXY (and szz=); 3D: SXX,SYY,SZZ,SXY,SYZ,SXZ.
  const auto tensor = [&](const std::vector<std::string>& p) {
    return three ? ZoneStress{num(p[0]), num(p[1]), num(p[3]), num(p[2]), num(p[4]), num(p[5])}
                 : ZoneStress{num(p[0]), num(p[1]), num(p[2]), 0};
  };
  const size_t want = three ? 6 : 3;
  if (parts.size() != want)
    fail(three ? "write stress=SXX,SYY,SZZ,SXY,SYZ,SXZ (tension positive, Pa)"
               : "write stress=SXX,SYY,SXY (tension positive, Pa)");
  ZoneStress s0 = tensor(parts), g;
  bool has_zz = three;
  if (!three && take(a, "szz", v)) s0.zz = num(v), has_zz = true;
  const char* gradient = three ? "zgradient" : "ygradient";
  double v0 = 0;
  if (take(a, gradient, v)) {
    parts = split_top_level(v);
    if (parts.size() != want)
      fail(three ? "write zgradient=GXX,GYY,GZZ,GXY,GYZ,GXZ (Pa per metre of height)"
                 : "write ygradient=GXX,GYY,GXY (Pa per metre of height)");
    g = tensor(parts);
  }
  take_num(a, three ? "z0" : "y0", v0);
  done(a);
  if (model_.block_count() == 0) fail("there are no blocks to take the stress");
  if (three) {
    Continuum3& c = model_.continuum3;
    initialize_stress(c, s0, g, v0);
    const size_t loaded = preload_contacts(model_, StressField{s0, g, v0});
    if (c.zone_count() == 0 && loaded == 0)
      fail("nothing takes the stress: there are no zones and no shut joints");
    log("insitu: stresses set in " + std::to_string(c.zone_count()) + " zones and on " +
        std::to_string(loaded) + " joint contacts");
    return;
  }
  Continuum& c = model_.continuum;
  initialize_stress(c, s0, g, v0);
  // The out-of-plane stress of plane strain, unless given: nu (sxx + syy) per zone (a
  // transversely isotropic zone's from its compliance).
  if (!has_zz)
    for (size_t z = 0; z < c.zone_count(); ++z) {
      const ZoneProperties& p = c.materials[c.material[z]];
      if (!p.impl->solid()) continue;
      c.stress[z].zz = plane_strain_zz(p, c.stress[z]);
    }
  // The joints: tractions of the same field on every shut contact.
  const size_t loaded = preload_contacts(model_, StressField{s0, g, v0});
  if (c.zone_count() == 0 && loaded == 0)
    fail("nothing takes the stress: there are no zones and no shut joints");
  log("insitu: stresses set in " + std::to_string(c.zone_count()) + " zones and on " +
      std::to_string(loaded) + " joint contacts");
}

}  // namespace tessera
