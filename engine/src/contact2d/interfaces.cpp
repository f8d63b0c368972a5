// The 2D contact stages: each corner's feature, gap, normal and point (rounded corners,
// chapter 5.2.1), then per interface the contacts' shares of joint length and the joint law,
// giving each contact's force.
#include "tessera/contact2d/interfaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/backend.hpp"
#include "core/coulomb_law.hpp"
#include "tessera/contact2d/contact_geometry.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {

// Velocity of a block's material point p.
inline Vec2 point_velocity(const Blocks& B, uint32_t b, const Vec2& p) {
  return {B.vx[b] - B.omega[b] * (p.y() - B.y[b]), B.vy[b] + B.omega[b] * (p.x() - B.x[b])};
}

// The effective mass of two blocks for contact damping (a held block counts as infinite).
double pair_mass(const Blocks& B, uint32_t a, uint32_t b) {
  const auto inverse = [&](uint32_t k) { return B.fixity[k] == kFixAll ? 0.0 : B.inv_mass[k]; };
  const double inv = inverse(a) + inverse(b);
  return inv > 0.0 ? 1.0 / inv : 0.0;
}

// Whether corner v is inside block b at about the overlap's depth: its distance to b's outline
// at least half the overlap (a toe sunk into a soft joint), not at b's edge or vertex.
bool corner_buried(const Blocks& B, uint32_t v, uint32_t b, double overlap) {
  const std::vector<Vec2> poly = B.world_polygon(b);
  const Vec2& p = B.world_vertex[v];
  if (!point_in_polygon(p, poly)) return false;
  for (size_t k = 0; k < poly.size(); ++k)
    if (segment_distance(p, poly[k], poly[(k + 1) % poly.size()]) < 0.5 * overlap) return false;
  return true;
}

// Contact geometry from the current positions for contacts [i0, i1): the nearest feature of the
// other block to each corner (searched around last cycle's feature), gap, normal, contact point
// and chord (into `length`, Contacts::length). The outputs are restrict: the compiler may then keep
// the block arrays' addresses in registers across a contact instead of reloading them after every
// store.
void corner_chunk(const Blocks& B, const Contacts& C, size_t i0, size_t i1,
                  uint8_t* __restrict kind, uint32_t* __restrict feature, double* __restrict gap,
                  Vec2* __restrict normal, Vec2* __restrict point, double* __restrict chord) {
  FeatureHit hit;  // every path below fills it before reading it
  constexpr double kFar = std::numeric_limits<double>::infinity();
  for (size_t i = i0; i < i1; ++i) {
    const uint32_t a = C.a[i], b = C.b[i], v = C.corner[i];
    const bool lost = kind[i] == kLost;
    const CornerArc arc = corner_arc(B, a, v);
    const double depth = max_contact_depth(B, a, b);
    // A corner in a notch keeps its face: valid or lost, no search.
    if (C.flags[i] & kNotch) {
      if (kind[i] == kCornerEdge && edge_feature(B, b, feature[i], arc, depth, hit, nullptr)) {
        gap[i] = hit.gap, normal[i] = hit.normal, point[i] = hit.point, chord[i] = hit.chord;
      } else {
        kind[i] = kLost, gap[i] = kFar, chord[i] = 0.0;
      }
      continue;
    }
    // Fast path: still well inside the span of the same edge.
    double margin = -1.0;
    if (kind[i] == kCornerEdge && edge_feature(B, b, feature[i], arc, depth, hit, &margin) &&
        margin > 0.0) {
      gap[i] = hit.gap, normal[i] = hit.normal, point[i] = hit.point, chord[i] = hit.chord;
      continue;
    }
    const int first = lost ? 0 : local_feature(B, b, kind[i], feature[i]) - 2;
    const int all = 2 * static_cast<int>(B.vertex_count(b));
    bool found = nearest_feature(B, b, arc, a < b, first, lost ? all : 5, depth, hit);
    // An overlap past the arc's radius is rare and suspect: the whole block is searched for a
    // nearer feature, and it is believed only if the owner's sharp corner is inside b (a toe
    // sunk into a soft joint is; a corner at the tip of a thin sliver of b, measured against
    // the sliver's far side, is not).
    if (found && hit.gap < -arc.radius)
      found = (lost || nearest_feature(B, b, arc, a < b, 0, all, depth, hit)) &&
              (hit.gap >= -arc.radius || corner_buried(B, v, b, -hit.gap));
    if (!found) {
      // The corner has left the reach of every feature: it carries nothing until found again.
      kind[i] = kLost, gap[i] = kFar, chord[i] = 0.0;
      continue;
    }
    kind[i] = hit.kind, feature[i] = hit.feature, gap[i] = hit.gap;
    normal[i] = hit.normal, point[i] = hit.point, chord[i] = hit.chord;
  }
}

void update_corner_contacts(Model& m) {
  Contacts& C = m.contacts;
  parallel_for(C.size(), [&](size_t i0, size_t i1) {
    corner_chunk(m.blocks, C, i0, i1, C.kind.data(), C.feature.data(), C.gap.data(),
                 C.normal.data(), C.point.data(), C.length.data());
  });
}

// The stretch of joint a corner stands for when it is alone on its joint line (its neighbour
// has lifted off): the corner as a sharp wedge cut by the other block's surface, each of its two
// edges overlapping up to where it leaves that surface (at most the edge's straight part), and
// half of that extent, since a spring bed under a wedge carries kn o s / 2. Without it the
// length is the arc's chord, which vanishes as the overlap passes 2d, and a toppling block on
// soft joints sinks through its base on its toe. Just after the neighbour lifts, the wedge runs
// the whole face and the length is the share the two had: (w - 2d) / 2. Corner v of block a,
// with the contact's normal, point and gap.
double wedge_length(const Blocks& B, uint32_t a, uint32_t v, const Vec2& nrm, const Vec2& point,
                    double gap) {
  const uint32_t vp = B.prev_vertex(a, v);
  const Vec2 t = perp(nrm);
  // Depth of the sharp corner below the other block's surface (normals point to the owner).
  const Vec2 surface = point - 0.5 * gap * nrm;
  const double depth = (surface - B.world_vertex[v]).dot(nrm);
  if (!(depth > 0.0)) return 0.0;
  const uint32_t v0 = B.vert_begin[a], n = B.vertex_count(a);
  const uint32_t next = v0 + (v - v0 + 1) % n;
  double width = 0.0;
  // One edge leaving the corner along u: it rises out of the surface after depth / rise.
  const auto edge = [&](const Vec2& u, double straight) {
    const double rise = u.dot(nrm), cap = std::max(straight, 0.0);
    const double s = rise * cap > depth ? depth / rise : cap;
    width += s * std::abs(u.dot(t));
  };
  edge(B.world_edge_dir[v], B.edge_length[v] - B.round_length[v] - B.round_length[next]);
  edge(-B.world_edge_dir[vp], B.edge_length[vp] - B.round_length[vp] - B.round_length[v]);
  return 0.5 * width;
}

// Shares a joint line's length among its contacts, given as (position along the line, index):
// L = RQ1/2 + RQ2/2 with the neighbours as Q1, Q2, never less than a contact's own chord (which
// `length` holds on the way in, Contacts::length).
// Contacts closer than `merge` stand at one point (two corners meeting face to face): the
// point's share is split evenly, so that round-off in their order cannot move the length from
// one to the other from cycle to cycle. A line of one point (a corner whose neighbour lifted
// off) has no neighbours to share with: its contacts take their corners' wedge lengths
// (`wedge(i)`).
template <class Wedge>
inline void share_length(std::vector<std::pair<double, uint32_t>>& along, double merge,
                         double* length, const Wedge& wedge) {
  const size_t k = along.size();
  // Order by position, then index (std::pair's order, written out: its three-way comparison
  // costs twice the instructions).
  const auto before = [](const std::pair<double, uint32_t>& x,
                         const std::pair<double, uint32_t>& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  };
  // Two contacts apart (the usual line): each takes half the distance between them, as below.
  if (k == 2) {
    if (before(along[1], along[0])) std::swap(along[0], along[1]);
    if (along[1].first - along[0].first > merge) {
      const double len = 0.5 * (along[1].first - along[0].first);
      for (const auto& [x, i] : along) length[i] = std::max(len, length[i]);
      return;
    }
  }
  // Insertion sort: a line has a handful of contacts, mostly in order already.
  for (size_t j = 1; j < k; ++j)
    for (size_t q = j; q > 0 && before(along[q], along[q - 1]); --q)
      std::swap(along[q], along[q - 1]);
  // Centre of the group of contacts starting at g0; g1 receives the index past the group.
  auto group = [&](size_t g0, size_t& g1) {
    g1 = g0 + 1;
    double sum = along[g0].first;
    while (g1 < k && along[g1].first - along[g1 - 1].first <= merge) sum += along[g1++].first;
    return sum / static_cast<double>(g1 - g0);
  };
  size_t g0 = 0, g1 = 0;
  double prev = 0.0, centre = k ? group(0, g1) : 0.0;
  if (k && g1 == k) {
    for (size_t j = 0; j < k; ++j) {
      const uint32_t i = along[j].second;
      length[i] = std::max(wedge(i) / static_cast<double>(k), length[i]);
    }
    return;
  }
  while (g0 < k) {
    size_t g2 = g1;
    const double next = g1 < k ? group(g1, g2) : centre;
    const double len = 0.5 * ((g0 > 0 ? centre - prev : 0.0) + (next - centre));
    for (size_t j = g0; j < g1; ++j) {
      const uint32_t i = along[j].second;
      length[i] = std::max(len / static_cast<double>(g1 - g0), length[i]);
    }
    prev = centre, centre = next, g0 = g1, g1 = g2;
  }
}

// Stops the run on contact i, as UDEC's "contact overlap too great" does.
[[noreturn]] void throw_overlap(const Model& m, uint32_t i) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const uint32_t a = C.a[i], b = C.b[i];
  std::ostringstream where, what;
  where << "x=" << C.point[i].x() << ", y=" << C.point[i].y();
  what << "corner " << C.corner[i] - B.vert_begin[a] + 1 << " of block " << B.id[a]
       << " against the " << (C.kind[i] == kCornerEdge ? "edge from vertex " : "corner ")
       << C.feature[i] - B.vert_begin[b] + 1 << " of block " << B.id[b];
  throw_overlap(m, a, b, -C.gap[i], kOverlapLimit * max_contact_depth(B, a, b), where.str(),
                what.str());
}

// What the interfaces stage reads beside the model, once per stage.
struct StageInputs {
  double dt, merge, roundoff;
  bool plastic, damped;
};

// The interfaces of pairs [p0, p1): each contact's share of joint length, then the joint law.
// The geometry comes in read-only, and every array the stage writes as its own restrict pointer
// (plastic, damp_fn and damp_fs null when not held), with the pair's sums for the block sums
// (pair_force, pair_moment, pair_load, Contacts): the compiler may then keep the addresses
// of the arrays it reads in registers, which a store through a flag (a byte, which may alias
// anything) would otherwise make it reload.
void pair_chunk(const Model& m, size_t p0, size_t p1, const StageInputs& in, FirstFlagged& too_deep,
                const uint8_t* kind, const double* gap, const Vec2* normal, const Vec2* point,
                uint8_t* __restrict flags, double* __restrict length, double* __restrict fn,
                double* __restrict fs, double* __restrict un_prev, double* __restrict dilation,
                double* __restrict shear_disp, double* __restrict plastic,
                double* __restrict damp_fn, double* __restrict damp_fs, Vec2* __restrict pair_force,
                double* __restrict pair_moment, double* __restrict pair_load) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  std::vector<std::pair<double, uint32_t>> along;
  std::vector<uint8_t> placed;
  std::vector<double> chords;
  const auto wedge = [&](uint32_t i) {
    return wedge_length(B, C.a[i], C.corner[i], normal[i], point[i], gap[i]);
  };
  // Normals point towards the owner: compare them turned to point the same way.
  const auto facing = [&](uint32_t q) { return C.a[q] < C.b[q] ? normal[q] : Vec2(-normal[q]); };
  // Contacts of a pair split into joint lines by the way they face (a concave block can touch
  // another along two faces); each line shares its length on its own.
  const auto general_lines = [&](uint32_t c0, uint32_t c1) {
    placed.assign(c1 - c0, 0);
    for (uint32_t i = c0; i < c1; ++i) {
      if (kind[i] == kLost || placed[i - c0]) continue;
      const Vec2 n0 = facing(i), t = perp(n0);
      along.clear();
      for (uint32_t q = i; q < c1; ++q)
        if (kind[q] != kLost && !placed[q - c0] && facing(q).dot(n0) > 0.8) {
          placed[q - c0] = 1;
          along.emplace_back(point[q].dot(t), q);
        }
      share_length(along, in.merge, length, wedge);
    }
  };
  for (size_t p = p0; p < p1; ++p) {
    const uint32_t c0 = C.pair_begin[p], c1 = C.pair_begin[p + 1];
    // The pair's blocks (either may own a contact), and the deepest overlap believed.
    const uint32_t pa = C.a[c0], pb = C.b[c0];
    const double depth_limit = kOverlapLimit * max_contact_depth(B, pa, pb);
    // Whether a block is deformable: its nodes' clipping below needs the chords the shares
    // replace in `length` (a lost contact's is 0, and its length stays 0).
    const bool soft = B.deformable[pa] || B.deformable[pb];
    if (soft) chords.assign(length + c0, length + c1);
    // Fast path (convex blocks, nearly every pair): all contacts face one way, so they form one
    // joint line, the same list the general path below would build.
    bool one_line = true;
    Vec2 n_first = Vec2::Zero(), t_first = Vec2::Zero();
    along.clear();
    for (uint32_t i = c0; i < c1 && one_line; ++i) {
      if (kind[i] == kLost) continue;
      const Vec2 f = facing(i);
      if (along.empty())
        n_first = f, t_first = perp(f);
      else if (!(f.dot(n_first) > 0.8))
        one_line = false;
      along.emplace_back(point[i].dot(t_first), i);
    }
    if (one_line) {
      if (!along.empty()) share_length(along, in.merge, length, wedge);
    } else {
      general_lines(c0, c1);
    }
    // A node of a deformable block stands for its own stretch of outline at most: a light node
    // alone against a long edge must not take the edge's stiffness. (A pair's contacts can be
    // owned by either block: checked per contact.)
    if (soft)
      for (uint32_t i = c0; i < c1; ++i) {
        const uint32_t blk = C.a[i];
        if (!B.deformable[blk]) continue;
        const double own = B.vertex_share(blk, C.corner[i]);
        length[i] = std::min(length[i], std::max(own, chords[i - c0]));
      }
    double pair_length = -1.0;  // summed once, for contact damping
    // The pair's sums for the block sums: force on pa, moment about its centroid, load.
    Vec2 force = Vec2::Zero();
    double moment = 0.0, load = 0.0;
    const double xa = B.x[pa], ya = B.y[pa];
    for (uint32_t i = c0; i < c1; ++i) {
      if (kind[i] == kLost) {
        if (flags[i] & kBonded) flags[i] = static_cast<uint8_t>((flags[i] & ~kBonded) | kBroken);
        flags[i] &= static_cast<uint8_t>(~(kTouching | kSlipping));
        fn[i] = 0.0, fs[i] = 0.0, un_prev[i] = 0.0;
        if (in.damped) damp_fn[i] = 0.0, damp_fs[i] = 0.0;
        continue;
      }
      const double overlap = without_roundoff(-gap[i] + C.closure_at(i), in.roundoff);
      if (-gap[i] > depth_limit) too_deep.flag(i);
      const double un = overlap + dilation[i];
      if (stays_open(un, fn[i], flags[i])) {
        fs[i] = 0.0, un_prev[i] = un;
        if (in.damped) damp_fn[i] = 0.0, damp_fs[i] = 0.0;
        flags[i] &= static_cast<uint8_t>(~kPreload);
        continue;
      }
      // An in-situ shear stress becomes a force once the contact has its length.
      if (flags[i] & kPreload) {
        fs[i] *= length[i];
        flags[i] &= static_cast<uint8_t>(~kPreload);
      }
      // Shear displacement increment of a relative to b over the last step (a deformable side's
      // velocity from its nodes, through the model).
      const Vec2 n = normal[i], tn = perp(n);
      const Vec2 dv =
          soft ? Vec2(contact_side_velocity(m, i, false) - contact_side_velocity(m, i, true))
               : Vec2(point_velocity(B, C.a[i], point[i]) - point_velocity(B, C.b[i], point[i]));
      const double dus = dv.dot(tn) * in.dt;
      JointState s{fn[i],       fs[i],         un_prev[i],
                   dilation[i], shear_disp[i], flags[i],
                   0.0,         0.0,           in.plastic ? plastic[i] : 0.0};
      const JointProperties& jp = m.joints[C.joint[i]];
      joint_update<true>(jp, length[i], overlap, dus, 0.0, s);
      fn[i] = s.fn, fs[i] = s.fs, un_prev[i] = s.un_prev, dilation[i] = s.dilation;
      shear_disp[i] = s.shear_disp, flags[i] = s.flags;
      if (in.plastic) plastic[i] = s.plastic;
      double total_fn = s.fn, total_fs = s.fs;
      if (in.damped) {
        damp_fn[i] = 0.0, damp_fs[i] = 0.0;
        if ((jp.normal_damping > 0.0 || jp.shear_damping > 0.0) && (s.flags & kTouching)) {
          if (pair_length < 0.0) {
            pair_length = 0.0;
            for (uint32_t q = c0; q < c1; ++q) pair_length += length[q];
          }
          const Dashpot d =
              contact_dashpot(jp, length[i], length[i] / pair_length, pair_mass(B, C.a[i], C.b[i]),
                              -dv.dot(n), dv.dot(tn), 0.0, s.flags & kSlipping);
          damp_fn[i] = d.fn, damp_fs[i] = d.fs;
        }
        total_fn += damp_fn[i], total_fs += damp_fs[i];
      }
      // The contact's force on the pair's block a (on its own block a: the same or opposite).
      const double sign = Contacts::side_sign(C.a[i] != pa);
      const Vec2 on_a = sign * Contacts::force_of(total_fn, total_fs, n);
      force += on_a;
      moment += (point[i].x() - xa) * on_a.y() - (point[i].y() - ya) * on_a.x();
      load += std::abs(total_fn) + std::abs(total_fs);
    }
    pair_force[p] = force, pair_moment[p] = moment, pair_load[p] = load;
  }
}

}  // namespace

void update_interfaces(Model& m) {
  Contacts& C = m.contacts;
  // Laws other than Coulomb's (cy, barton-bandis, plug-ins) keep a plastic shear history.
  if (std::any_of(m.joints.begin(), m.joints.end(),
                  [](const JointProperties& j) { return j.inline_coulomb < 0; }))
    C.hold(C.plastic);
  // Damped joints keep their dashpot's forces beside the springs' (released when none is).
  const bool damped = std::any_of(m.joints.begin(), m.joints.end(), [](const JointProperties& j) {
    return j.normal_damping > 0.0 || j.shear_damping > 0.0;
  });
  if (damped) {
    C.hold(C.damp_fn), C.hold(C.damp_fs);
  } else {
    std::vector<double>().swap(C.damp_fn), std::vector<double>().swap(C.damp_fs);
  }
  // The interfaces' sums for the block sums, one per pair (dropped by detection passes).
  C.pair_force.resize(C.pair_count()), C.pair_moment.resize(C.pair_count());
  C.pair_load.resize(C.pair_count());
  const StageInputs in{m.dt, 0.25 * m.settings.rounding, m.roundoff_gap(), !C.plastic.empty(),
                       damped};
  // The first contact (lowest index, whatever the threads) whose overlap is beyond belief.
  FirstFlagged too_deep;
  const auto held = [](std::vector<double>& v) { return v.empty() ? nullptr : v.data(); };
  parallel_for(
      C.pair_count(),
      [&](size_t p0, size_t p1) {
        pair_chunk(m, p0, p1, in, too_deep, C.kind.data(), C.gap.data(), C.normal.data(),
                   C.point.data(), C.flags.data(), C.length.data(), C.fn.data(), C.fs.data(),
                   C.un_prev.data(), C.dilation.data(), C.shear_disp.data(), held(C.plastic),
                   held(C.damp_fn), held(C.damp_fs), C.pair_force.data(), C.pair_moment.data(),
                   C.pair_load.data());
      },
      64);
  if (too_deep.any()) throw_overlap(m, too_deep.index());
}

void update_contact_geometry(Model& m) {
  update_corner_contacts(m);
}

}  // namespace tessera
