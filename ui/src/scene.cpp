// Turns a snapshot and view options into drawables.
#include "tessera/ui/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "scene3d.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/support/reinforcement.hpp"
#include "tessera/zones/continuum.hpp"

namespace tessera::ui {

double block_value(const SnapshotBlock& b, ColourBy c) {
  switch (c) {
    case ColourBy::kDisplacement:
      return std::hypot(b.x - b.x_ref, b.y - b.y_ref, b.z - b.z_ref);
    case ColourBy::kXDisp:
      return b.x - b.x_ref;
    case ColourBy::kYDisp:
      return b.y - b.y_ref;
    case ColourBy::kZDisp:
      return b.z - b.z_ref;
    case ColourBy::kVelocity:
      return std::hypot(b.vx, b.vy, b.vz);
    case ColourBy::kRotation:
      return b.theta * 180.0 / std::numbers::pi;
    case ColourBy::kGroup:
      return b.group;
    case ColourBy::kMaterial:
      return b.material;
    default:
      return 0.0;  // zone quantities: see zone_value
  }
  return 0.0;
}

double zone_value(const SnapshotZone& z, ColourBy c) {
  double s1 = 0, s3 = 0;
  if (c == ColourBy::kSigma1 || c == ColourBy::kSigma3)
    principal_stresses(ZoneStress{z.sxx, z.syy, z.sxy, z.szz, z.syz, z.sxz}, s1, s3);
  switch (c) {
    case ColourBy::kSxx:
      return z.sxx / 1e6;
    case ColourBy::kSyy:
      return z.syy / 1e6;
    case ColourBy::kSxy:
      return z.sxy / 1e6;
    case ColourBy::kSzz:
      return z.szz / 1e6;
    case ColourBy::kSigma1:
      return s1 / 1e6;
    case ColourBy::kSigma3:
      return s3 / 1e6;
    case ColourBy::kZoneState:
      return zone_state_category(z.state);
    default:
      return 0.0;
  }
}

int zone_state_category(uint8_t state) {
  if (state & kShearNow) return 1;
  if (state & kTensionNow) return 2;
  if (state & (kShearPast | kTensionPast)) return 3;
  return 0;
}

std::string value_title(ColourBy c) {
  switch (c) {
    case ColourBy::kDisplacement:
      return "displacement [m]";
    case ColourBy::kXDisp:
      return "x displacement [m]";
    case ColourBy::kYDisp:
      return "y displacement [m]";
    case ColourBy::kZDisp:
      return "z displacement [m]";
    case ColourBy::kVelocity:
      return "velocity [m/s]";
    case ColourBy::kRotation:
      return "rotation [deg]";
    case ColourBy::kGroup:
      return "group";
    case ColourBy::kMaterial:
      return "material";
    case ColourBy::kSxx:
      return "sxx [MPa]";
    case ColourBy::kSyy:
      return "syy [MPa]";
    case ColourBy::kSxy:
      return "sxy [MPa]";
    case ColourBy::kSzz:
      return "szz [MPa]";
    case ColourBy::kSigma1:
      return "sigma1 [MPa]";
    case ColourBy::kSigma3:
      return "sigma3 [MPa]";
    case ColourBy::kZoneState:
      return "zone state";
  }
  return "";
}

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Colours of the zone states: elastic, yielding in shear or in tension now, yielded before.
const Rgb kStateColours[4] = {{215, 215, 215}, {220, 40, 40}, {200, 60, 200}, {250, 190, 120}};
const char* const kStateNames[4] = {"elastic", "shear now", "tension now", "yielded before"};
const Rgb kNoZones{200, 200, 200};  // rigid blocks in a picture of zones

// The legend's title and value range over the items (a range flatter than `flat` relative is
// widened so that it has a width); lo and hi are returned too. Over more than 100 items the
// range runs from the 1st to the 99th percentile when that is narrower, so that a few extreme
// values (a block falling free, a zone at a sharp corner) do not wash out the rest; the true
// extremes are kept for the caption.
template <class Items, class Value>
void set_range(Legend& L, ColourBy c, bool continuous, const Items& items, Value value, double flat,
               double& lo, double& hi) {
  L.title = value_title(c);
  L.continuous = continuous;
  std::vector<double> values;
  for (size_t i = 0; i < items.size(); ++i) values.push_back(value(items[i]));
  lo = 0, hi = 0;
  if (!values.empty()) {
    const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
    lo = *mn, hi = *mx;
  }
  L.min = lo, L.max = hi, L.clipped = false;
  if (continuous && values.size() > 100) {
    const auto at = [&](double q) {
      auto k = values.begin() + static_cast<std::ptrdiff_t>(q * double(values.size() - 1));
      std::nth_element(values.begin(), k, values.end());
      return *k;
    };
    const double p1 = at(0.01), p99 = at(0.99);
    if (p99 > p1 && (p1 > lo || p99 < hi)) lo = p1, hi = p99, L.clipped = true;
  }
  if (hi - lo < flat * std::max(1.0, std::abs(hi))) hi = lo + (lo == 0 ? 1.0 : std::abs(lo));
  L.lo = lo, L.hi = hi;
}

// A zone's colour for the quantity shown: its state's, or the ramp over the range lo..hi.
struct ZonePalette {
  ColourBy colour;
  double lo = 0, hi = 0;
  Rgb operator()(const SnapshotZone& z) const {
    const double v = zone_value(z, colour);
    return colour == ColourBy::kZoneState ? kStateColours[static_cast<int>(v)]
                                          : ramp((v - lo) / (hi - lo));
  }
};

// The legend of a picture of these zones (the states' key, or a ramp over their range) and the
// caption's note on the stresses; returns their palette. 2D and 3D alike.
ZonePalette zone_legend(const std::vector<SnapshotZone>& zones, const ViewOptions& o, Scene& out) {
  ZonePalette palette{o.colour};
  Legend& L = out.blocks_legend;
  const bool states = o.colour == ColourBy::kZoneState;
  set_range(
      L, o.colour, !states, zones, [&](const SnapshotZone& z) { return zone_value(z, o.colour); },
      1e-12, palette.lo, palette.hi);
  if (states)
    for (int k = 0; k < 4; ++k) L.entries.push_back({kStateNames[k], kStateColours[k]});
  else
    out.caption += o.colour == ColourBy::kSigma1 ? "   stresses tension +, sigma1 most compressive"
                   : o.colour == ColourBy::kSigma3
                       ? "   stresses tension +, sigma3 least compressive"
                       : "   stresses tension +";
  return palette;
}

// Zones of deformable blocks coloured by a zone quantity, with their legend.
void add_zones(const Snapshot& s, const ViewOptions& o, Scene& out) {
  const ZonePalette palette = zone_legend(s.zones, o, out);
  for (size_t i = 0; i < s.zones.size(); ++i) {
    const SnapshotZone& z = s.zones[i];
    ScenePolygon p;
    p.block = z.block;
    p.zone = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {  // a triangle's corners
      const uint32_t n = z.n[k];
      p.points.push_back(s.nodes_start[n] + o.magnify * (s.nodes[n] - s.nodes_start[n]));
    }
    p.colour = palette(z);
    out.zones.push_back(std::move(p));
  }
}

// Block b's outline as drawn (magnified), in the given colour.
ScenePolygon block_polygon(const Snapshot& s, size_t b, double magnify, Rgb colour) {
  const SnapshotBlock& blk = s.blocks[b];
  ScenePolygon p;
  p.block = static_cast<int>(b);
  for (uint32_t v = blk.vert_begin; v < blk.vert_end; ++v)
    p.points.push_back(shown_vertex(s, blk, v, magnify));
  p.colour = colour;
  return p;
}

// Colours the block polygons and fills their legend.
void add_blocks(const Snapshot& s, const ViewOptions& o, Scene& out) {
  if (colours_zones(o.colour) && s.three) {
    // Deformable blocks by their zones' surface triangles; rigid ones grey.
    std::vector<SnapshotZone> drawn;
    for (const SnapshotZone& z : s.zones)
      if (z.block >= 0) drawn.push_back(z);
    if (drawn.empty()) {
      out.blocks_legend.title = value_title(o.colour) + " (no zones)";
      return add_faces3(s, o, std::vector<Rgb>(s.blocks.size(), kNoZones), out);
    }
    const ZonePalette palette = zone_legend(drawn, o, out);
    return add_faces3(s, o, std::vector<Rgb>(s.blocks.size(), kNoZones), out,
                      [&](const SnapshotZone& z) -> std::optional<Rgb> {
                        if (z.block < 0) return std::nullopt;
                        return palette(z);
                      });
  }
  if (colours_zones(o.colour)) {
    add_zones(s, o, out);
    for (size_t b = 0; b < s.blocks.size(); ++b)
      out.polygons.push_back(block_polygon(s, b, o.magnify, kNoZones));
    return;
  }
  const bool categorical = o.colour == ColourBy::kGroup || o.colour == ColourBy::kMaterial;
  Legend& L = out.blocks_legend;
  double lo = 0, hi = 0;
  set_range(
      L, o.colour, !categorical, s.blocks,
      [&](const SnapshotBlock& b) { return block_value(b, o.colour); }, 1e-300, lo, hi);
  if (categorical) {
    // The groups (materials) some block has: an excavated group is not in the picture.
    const bool groups = o.colour == ColourBy::kGroup;
    const size_t n = groups ? s.groups.size() : s.materials.size();
    std::vector<uint8_t> used(n, 0);
    for (const SnapshotBlock& b : s.blocks) {
      const int i = static_cast<int>(block_value(b, o.colour));
      if (i >= 0 && static_cast<size_t>(i) < n) used[static_cast<size_t>(i)] = 1;
    }
    for (size_t i = 0; i < n; ++i)
      if (used[i])
        L.entries.push_back(
            {groups ? s.groups[i] : s.materials[i].name, category(static_cast<int>(i))});
  }
  std::vector<Rgb> colours;
  for (size_t b = 0; b < s.blocks.size(); ++b) {
    const double v = block_value(s.blocks[b], o.colour);
    colours.push_back(categorical ? category(static_cast<int>(v)) : ramp((v - lo) / (hi - lo)));
  }
  if (s.three) return add_faces3(s, o, colours, out);
  for (size_t b = 0; b < s.blocks.size(); ++b)
    out.polygons.push_back(block_polygon(s, b, o.magnify, colours[b]));
}

// Contact bars along the joint: width from the normal stress, colour from the option.
void add_contacts(const Snapshot& s, const ViewOptions& o, Scene& out, double size) {
  if (o.contacts == ContactShow::kOff || s.contacts.empty()) return;
  // A contact's normal stress (MPa): its force over its length (2D) or area (3D: 4 length^2).
  const auto stress = [&](const SnapshotContact& c) {
    const double extent = s.three ? 4.0 * c.length * c.length : c.length;
    return extent > 0.0 ? std::max(c.fn, 0.0) / extent * 1e-6 : 0.0;
  };
  double fmax = 0, smax = 0;
  std::vector<double> stresses;
  for (const auto& c : s.contacts) {
    const double sn = stress(c);
    fmax = std::max(fmax, sn), smax = std::max(smax, std::abs(c.shear_disp));
    if (sn > 0) stresses.push_back(sn);
  }
  // Full width at the 98th percentile of the stresses, so one spike does not thin all the rest.
  double fwide = fmax;
  if (stresses.size() > 50) {
    const auto k = stresses.begin() + static_cast<std::ptrdiff_t>(0.98 * double(stresses.size()));
    std::nth_element(stresses.begin(), k, stresses.end());
    fwide = *k;
  }
  double mean_length = 0;
  for (const auto& c : s.contacts) mean_length += c.length;
  mean_length /= static_cast<double>(s.contacts.size());
  const double wmax = std::clamp(0.25 * mean_length, 1e-4 * size, 0.02 * size);
  const double wmin = 0.08 * wmax;
  Legend& L = out.contacts_legend;
  if (o.contacts == ContactShow::kState) {
    L.title = "contacts";
    L.entries = {{"open", open_colour()},
                 {"elastic", elastic_colour()},
                 {"slipping", slipping_colour()},
                 {"bonded", bonded_colour()}};
  } else {
    L.continuous = true;
    L.title = o.contacts == ContactShow::kStress ? "normal stress [MPa]" : "shear displacement [m]";
    // Stresses coloured to the 98th percentile, as the widths (the largest is in the caption).
    L.lo = 0, L.hi = o.contacts == ContactShow::kStress ? fwide : smax;
    L.clipped = o.contacts == ContactShow::kStress && fwide < fmax, L.max = fmax;
    if (L.hi <= 0) L.hi = 1;
  }
  for (size_t i = 0; i < s.contacts.size(); ++i) {
    const SnapshotContact& c = s.contacts[i];
    const bool touching = c.flags & kTouching;
    Rgb colour;
    if (o.contacts == ContactShow::kState)
      colour = !touching             ? open_colour()
               : c.flags & kSlipping ? slipping_colour()
               : c.flags & kBonded   ? bonded_colour()
                                     : elastic_colour();
    else if (o.contacts == ContactShow::kStress)
      colour = ramp(stress(c) / L.hi);
    else
      colour = ramp(std::abs(c.shear_disp) / L.hi);
    const double w =
        touching && fwide > 0 ? wmin + (wmax - wmin) * std::min(stress(c) / fwide, 1.0) : wmin;
    // Along the stretch of joint the contact stands for; a lone contact gets a short bar.
    Vec2 a = c.from, b = c.to;
    if ((b - a).norm() < 2.0 * wmin) {
      const Vec2 t(-c.normal.y(), c.normal.x());
      const double half = 0.5 * std::max(c.length, 2.0 * wmin);
      a = c.point - half * t, b = c.point + half * t;
    }
    // Magnified like the blocks: the bar moves with block a.
    if (o.magnify != 1.0 && c.a >= 0 && static_cast<size_t>(c.a) < s.blocks.size()) {
      const SnapshotBlock& owner = s.blocks[static_cast<size_t>(c.a)];
      const Vec2 shift = (o.magnify - 1.0) * Vec2(owner.x - owner.x_ref, owner.y - owner.y_ref);
      a += shift, b += shift;
    }
    SceneBar bar;
    bar.contact = static_cast<int>(i);
    bar.colour = colour;
    bar.corners[0] = a - 0.5 * w * c.normal;
    bar.corners[1] = b - 0.5 * w * c.normal;
    bar.corners[2] = b + 0.5 * w * c.normal;
    bar.corners[3] = a + 0.5 * w * c.normal;
    out.bars.push_back(bar);
  }
  out.caption +=
      "   contact width" + std::string(o.contacts == ContactShow::kStress ? " and colour" : "") +
      ": normal stress, full at " + number(fwide) + " MPa (largest " + number(fmax) + ")";
}

// Displacement arrows at block centroids, the longest a tenth of the model's size (3D: in
// model coordinates, and projected for figures).
// Bolts and cables (2D) as narrow bars from crossing to crossing (node to node) over the
// contacts: each segment in the state of the worse crossing at its ends; the caption says the
// colours, how much is yielding and the largest force.
void add_bolts(const Snapshot& s, const ViewOptions& o, Scene& out, double size) {
  if (s.bolts.empty()) return;
  const Rgb elastic{170, 0, 170}, yielding{255, 140, 0}, broken{120, 120, 120};
  const double w = 0.004 * size;
  double fmax = 0.0, cmax = 0.0;
  size_t yielded = 0, crossings = 0, bolts = 0, cables = 0, slipping = 0, nodes = 0;
  size_t liners = 0, liner_nodes = 0, liner_yield = 0, liner_open = 0;
  double lmax = 0.0;
  for (const SnapshotBolt& b : s.bolts) {
    if (b.liner) {
      ++liners;
      // (A ring's last point is its first node again.)
      for (size_t k = 0; k + (b.closed ? 1 : 0) < b.points.size(); ++k) {
        ++liner_nodes, lmax = std::max(lmax, std::abs(b.axial[k]));
        liner_yield += (b.state[k] & kBoltAxialYield) != 0;
        liner_open += (b.state[k] & kLinerNodeOpen) != 0;
      }
      continue;
    }
    (b.cable ? cables : bolts) += 1;
    for (size_t k = 0; k < b.points.size(); ++k) {
      double& top = b.cable ? cmax : fmax;
      top = std::max(top, std::abs(b.axial[k]));
      if (b.cable) {
        ++nodes, slipping += b.state[k] != 0;
        continue;
      }
      if (k == 0 || k + 1 == b.points.size()) continue;
      ++crossings, yielded += (b.state[k] & (kBoltAxialYield | kBoltShearYield)) != 0;
    }
  }
  // Coloured by axial force: one scale for bolts and cables, compression to tension.
  double flo = 0.0, fhi = 0.0;
  for (const SnapshotBolt& b : s.bolts)
    for (double f : b.axial) flo = std::min(flo, f), fhi = std::max(fhi, f);
  if (!(fhi > flo)) fhi = flo + 1.0;
  for (const SnapshotBolt& b : s.bolts)
    for (size_t k = 0; k + 1 < b.points.size(); ++k) {
      auto shown = [&](size_t i) {
        const int blk = b.block[i];
        if (o.magnify == 1.0 || blk < 0 || static_cast<size_t>(blk) >= s.blocks.size())
          return b.points[i];
        const SnapshotBlock& owner = s.blocks[static_cast<size_t>(blk)];
        return Vec2(b.points[i] +
                    (o.magnify - 1.0) * Vec2(owner.x - owner.x_ref, owner.y - owner.y_ref));
      };
      const Vec2 p = shown(k), q = shown(k + 1);
      if (!((q - p).norm() > 0.0)) continue;
      const Vec2 n = perp((q - p).normalized());
      const uint8_t st = b.state[k] | b.state[k + 1];
      SceneBar bar;
      bar.support = static_cast<int>(&b - s.bolts.data()), bar.segment = static_cast<int>(k);
      bar.colour = st & kBoltBroken                           ? broken
                   : st & (kBoltAxialYield | kBoltShearYield) ? yielding
                                                              : elastic;
      if (o.support_force) {
        // A cable's segment its own force; a bolt's the crossing's at either end of it.
        const double f = b.cable || std::abs(b.axial[k]) >= std::abs(b.axial[k + 1])
                             ? b.axial[k]
                             : b.axial[k + 1];
        bar.colour = ramp((f - flo) / (fhi - flo));
      }
      bar.corners[0] = p - 0.5 * w * n, bar.corners[1] = q - 0.5 * w * n;
      bar.corners[2] = q + 0.5 * w * n, bar.corners[3] = p + 0.5 * w * n;
      out.bars.push_back(bar);
    }
  std::string kinds;
  for (const auto& [n, what] : {std::pair{bolts, "bolts"}, {cables, "cables"}, {liners, "liners"}})
    if (n > 0) kinds += (kinds.empty() ? "" : ", ") + std::string(what);
  out.support_legend.title = kinds;
  out.support_legend.entries = {{"elastic", elastic}, {"yielding", yielding}};
  if (bolts > 0) out.support_legend.entries.push_back({"broken", broken});
  if (o.support_force) {
    out.support_legend.title = s.three ? "axial force [N]" : "axial force [N/m]";
    out.support_legend.entries.clear();
    out.support_legend.continuous = true;
    out.support_legend.lo = flo, out.support_legend.hi = fhi;
  }
  // The caption: what the colours mean, how much yields, the largest force.
  const bool f = o.support_force;
  if (bolts > 0)
    out.caption += std::string("   bolts: ") +
                   (f ? "coloured by axial force (tension positive); "
                      : "purple elastic, orange yielding, grey broken; ") +
                   std::to_string(yielded) + " of " + std::to_string(crossings) +
                   " crossings yielding; largest axial force " + number(fmax) + " N/m";
  if (cables > 0)
    out.caption += std::string("   cables: ") +
                   (f ? "coloured by axial force (tension positive); "
                      : "purple elastic, orange yielding or grout slipping; ") +
                   std::to_string(slipping) + " of " + std::to_string(nodes) +
                   " nodes yielding or slipping; largest axial force " + number(cmax) +
                   (s.three ? " N; drawn through the rock" : " N/m");
  if (liners > 0)
    out.caption += std::string("   liners: ") +
                   (f ? "coloured by axial force (tension positive); "
                      : "purple elastic, orange at a capacity or slipping on the rock; ") +
                   std::to_string(liner_yield) + " of " + std::to_string(liner_nodes) +
                   " nodes at a capacity or slipping, " + std::to_string(liner_open) +
                   " open from the rock; largest thrust " + number(lmax) + " N/m";
}

// 3D support (cables): drawn as in 2D from their projected nodes, over the faces (it lies inside
// the rock), each bar with its depth and its segment's ends in model coordinates.
void add_support3(const Snapshot& s, const ViewOptions& o, Scene& out, double size) {
  if (s.bolts.empty()) return;
  const ViewAxes view(o);
  Snapshot flat;
  flat.three = true;
  flat.bolts = s.bolts;
  for (size_t i = 0; i < flat.bolts.size(); ++i)
    for (size_t k = 0; k < flat.bolts[i].points3.size(); ++k)
      flat.bolts[i].points[k] = view(shown_support3(s, o, s.bolts[i], k));
  ViewOptions plain = o;
  plain.magnify = 1.0;  // magnified above, in 3D
  const size_t first = out.bars.size();
  add_bolts(flat, plain, out, size);
  for (size_t i = first; i < out.bars.size(); ++i) {
    SceneBar& bar = out.bars[i];
    const SnapshotBolt& b = s.bolts[static_cast<size_t>(bar.support)];
    const auto k = static_cast<size_t>(bar.segment);
    const Vec3 p = shown_support3(s, o, b, k), q = shown_support3(s, o, b, k + 1);
    bar.over = true;
    bar.depth = view.depth(0.5 * (p + q));
    bar.world[0] = bar.world[3] = p, bar.world[1] = bar.world[2] = q;
  }
}

// Where a 3D bar is: its sub-contact's point, or its support segment's middle.
Vec3 bar_point3(const Snapshot& s, const ViewOptions& o, const SceneBar& bar) {
  if (bar.contact < 0) return 0.5 * (bar.world[0] + bar.world[1]);
  return shown_point3(s, o, s.contacts[static_cast<size_t>(bar.contact)]);
}

void add_arrows(const Snapshot& s, const ViewOptions& o, Scene& out, double size) {
  if (!o.vectors) return;
  const auto displacement = [&](const SnapshotBlock& b) {
    return Vec3(b.x - b.x_ref, b.y - b.y_ref, s.three ? b.z - b.z_ref : 0.0);
  };
  double dmax = 0;
  for (const auto& b : s.blocks) dmax = std::max(dmax, displacement(b).norm());
  if (dmax <= 0) return;
  out.arrow_scale = 0.1 * size / dmax;
  const ViewAxes view(o);
  for (const auto& b : s.blocks) {
    const Vec3 d = displacement(b);
    if (d.norm() < 1e-3 * dmax) continue;
    SceneArrow arrow;
    arrow.tail3 = Vec3(b.x_ref, b.y_ref, s.three ? b.z_ref : 0.0) + o.magnify * d;
    arrow.head3 = arrow.tail3 + out.arrow_scale * d;
    arrow.tail = s.three ? view(arrow.tail3) : Vec2(arrow.tail3.head<2>());
    arrow.head = s.three ? view(arrow.head3) : Vec2(arrow.head3.head<2>());
    out.arrows.push_back(arrow);
  }
  out.caption += "   arrows: largest displacement " + number(dmax) + " m";
}

// The 3D contact bars for a camera: a square in each sub-contact's plane, its side the length
// the sub-contact stands for, shrunk to 35% at no force (the bars' width shows the normal force),
// moving with block a like the faces.
void set_bar_squares3(const Snapshot& s, const ViewOptions& o, Scene& out) {
  double wmax = 0;
  for (const SceneBar& bar : out.bars)
    if (bar.contact >= 0) wmax = std::max(wmax, (bar.corners[3] - bar.corners[0]).norm());
  for (SceneBar& bar : out.bars) {
    if (bar.contact < 0) continue;  // support: its segment's ends (add_support3)
    const SnapshotContact& c = s.contacts[static_cast<size_t>(bar.contact)];
    const Vec3 at = shown_point3(s, o, c);
    const Vec3 n = c.normal3.norm() > 0 ? Vec3(c.normal3.normalized()) : Vec3::UnitZ();
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const double width = (bar.corners[3] - bar.corners[0]).norm(),
                 length = (bar.corners[1] - bar.corners[0]).norm();
    const double half = 0.5 * length * (0.35 + 0.65 * width / std::max(wmax, 1e-300));
    bar.world[0] = at - half * t1 - half * t2;
    bar.world[1] = at + half * t1 - half * t2;
    bar.world[2] = at + half * t1 + half * t2;
    bar.world[3] = at - half * t1 + half * t2;
  }
}
}  // namespace

Scene build_scene(const Snapshot& s, const ViewOptions& options, bool camera) {
  Scene out;
  out.camera = camera && s.three;
  // A figure in perspective gets its camera; the window's camera projects world points itself.
  ViewOptions o = s.three ? with_camera(s, options) : options;
  if (out.camera) o.perspective = false;
  out.title = o.title.empty() ? s.title : o.title;
  char buf[120];
  std::snprintf(buf, sizeof buf, "cycle %llu   time %.4g s   ratio %.2e",
                static_cast<unsigned long long>(s.cycle), s.time, s.ratio);
  out.caption = buf;
  if (o.magnify != 1.0) out.caption += "   displacements x" + number(o.magnify);
  add_blocks(s, o, out);
  if (out.blocks_legend.clipped)
    out.caption += "   colours: 1st to 99th percentile (all values " +
                   number(out.blocks_legend.min) + " to " + number(out.blocks_legend.max) + ")";
  out.three = s.three;
  if (s.three) {
    // Contacts and arrows of the projected model; the view box from the faces drawn.
    const Snapshot flat = flatten3(s, o);
    Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
    for (const auto& p : out.polygons)
      for (const Vec2& v : p.points) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    if (out.polygons.empty()) lo = hi = Vec2::Zero();
    const double size = std::max((hi - lo).norm(), 1e-9);
    add_contacts(flat, o, out, size);
    set_bar_depths3(s, o, out);
    if (out.camera) set_bar_squares3(s, o, out);
    add_arrows(s, o, out, size);
    add_support3(s, o, out, size);
    if (o.cut) {
      // What the cut takes away: sub-contacts and arrows above the plane.
      // (at the point drawn: magnified with block a, as the faces are)
      std::erase_if(out.bars,
                    [&](const SceneBar& bar) { return cut_away(o, bar_point3(s, o, bar)); });
      std::erase_if(out.arrows, [&](const SceneArrow& a) { return cut_away(o, a.tail3); });
      char cut[120];
      std::snprintf(cut, sizeof cut, "   cut by the plane %.0f/%03.0f through %s, %s, %s",
                    o.cut_dip, o.cut_dip_direction, number(o.cut_point.x()).c_str(),
                    number(o.cut_point.y()).c_str(), number(o.cut_point.z()).c_str());
      out.caption += cut;
    }
    // In perspective: nothing behind the eye.
    if (const ViewAxes view(o); view.perspective) {
      std::erase_if(out.bars,
                    [&](const SceneBar& bar) { return !view.in_front(bar_point3(s, o, bar)); });
      std::erase_if(out.arrows, [&](const SceneArrow& a) {
        return !view.in_front(a.tail3) || !view.in_front(a.head3);
      });
    }
    out.lo = lo, out.hi = hi;
    out.azimuth = o.azimuth, out.elevation = o.elevation;
    out.perspective = ViewAxes(o).perspective;
    char view[80];
    std::snprintf(view, sizeof view, "   view from azimuth %.0f, elevation %.0f%s", o.azimuth,
                  o.elevation, options.perspective ? ", in perspective" : "");
    out.caption += view;
  } else {
    const double size = std::max((s.hi - s.lo).norm(), 1e-9);
    add_contacts(s, o, out, size);
    add_bolts(s, o, out, size);
    add_arrows(s, o, out, size);
    out.lo = s.lo, out.hi = s.hi;
  }
  for (const auto& b : s.blocks) out.deformable_blocks.push_back(b.deformable);
  // Magnified shapes may leave the box the live model fills.
  for (const auto& list : {&out.polygons, &out.zones})
    for (const auto& p : *list)
      for (const Vec2& v : p.points) out.lo = out.lo.cwiseMin(v), out.hi = out.hi.cwiseMax(v);
  if (o.has_window) out.lo = o.lo, out.hi = o.hi;
  if (out.hi.x() <= out.lo.x()) out.hi.x() = out.lo.x() + 1;
  if (out.hi.y() <= out.lo.y()) out.hi.y() = out.lo.y() + 1;
  return out;
}

namespace {
bool inside(const Vec2* pts, size_t n, Vec2 p) {
  bool in = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 &a = pts[i], &b = pts[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}
}  // namespace

int block_at(const Scene& scene, Vec2 p) {
  if (scene.three) {
    // The nearest face there: its height at p from the fan triangle holding p.
    int best = -1;
    double nearest = -1e300;
    for (const auto& poly : scene.polygons) {
      const auto& v = poly.points;
      if (v.size() < 3 || poly.depth.size() != v.size()) continue;
      for (size_t k = 1; k + 1 < v.size(); ++k) {
        const Vec2 a = v[0], b = v[k], c = v[k + 1];
        const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (!(std::abs(area) > 0)) continue;
        const double wb = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / area;
        const double wc = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        if (wb < 0 || wc < 0 || wb + wc > 1) continue;
        const double z =
            (1 - wb - wc) * poly.depth[0] + wb * poly.depth[k] + wc * poly.depth[k + 1];
        if (z > nearest) nearest = z, best = poly.block;
        break;
      }
    }
    return best;
  }
  // The polygon drawn last wins.
  for (auto it = scene.polygons.rbegin(); it != scene.polygons.rend(); ++it)
    if (it->points.size() >= 3 && inside(it->points.data(), it->points.size(), p)) return it->block;
  return -1;
}

int zone_at(const Scene& scene, Vec2 p) {
  for (const auto& z : scene.zones)
    if (z.zone >= 0 && z.points.size() >= 3 && inside(z.points.data(), z.points.size(), p))
      return z.zone;
  return -1;
}

int bar_at(const Scene& scene, Vec2 p) {
  for (const auto& bar : scene.bars)
    if (inside(bar.corners, 4, p)) return bar.contact;
  return -1;
}

}  // namespace tessera::ui
