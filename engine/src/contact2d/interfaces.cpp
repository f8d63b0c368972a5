// The 2D contact stages: each corner's feature, gap, normal and point (rounded corners,
// chapter 5.2.1), then per interface the contacts' shares of joint length and the joint law,
// giving each contact's force.
#include "tessera/contact2d/interfaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "contact2d/joint_lines.hpp"
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
  double dt, merge, roundoff, tolerance;
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
  std::vector<LinePoint> along;
  std::vector<uint8_t> placed;
  std::vector<double> chords;
  const auto wedge = [&](uint32_t i) {
    return wedge_length(B, C.a[i], C.corner[i], normal[i], point[i], gap[i]);
  };
  // Each contact's share of its joint line, never less than its own chord (`length` on the way
  // in).
  const auto store = [&](uint32_t i, double share, double, double) {
    length[i] = std::max(share, length[i]);
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
    const auto joined = joined_test(B, C, c0, in.tolerance, gap, point);
    for_each_joint_line(C, c0, c1, kind, normal, point, along, placed,
                        [&](std::vector<LinePoint>& line, const Vec2&) {
                          share_length(line, in.merge, joined, wedge, store);
                        });
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
  const StageInputs in{m.dt,          contact_merge(m),   m.roundoff_gap(),
                       m.tolerance(), !C.plastic.empty(), damped};
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
