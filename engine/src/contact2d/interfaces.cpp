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
// and chord. The outputs are restrict: the compiler may then keep the block arrays' addresses in
// registers across a contact instead of reloading them after every store.
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
                 C.normal.data(), C.point.data(), C.chord.data());
  });
}

// The stretch of joint a corner stands for when it is alone on its joint line (its neighbour
// has lifted off): the corner as a sharp wedge cut by the other block's surface, each of its two
// edges overlapping up to where it leaves that surface (at most the edge's straight part), and
// half of that extent, since a spring bed under a wedge carries kn o s / 2. Without it the
// length is the arc's chord, which vanishes as the overlap passes 2d, and a toppling block on
// soft joints sinks through its base on its toe. Just after the neighbour lifts, the wedge runs
// the whole face and the length is the share the two had: (w - 2d) / 2.
double wedge_length(const Blocks& B, const Contacts& C, uint32_t i) {
  const uint32_t a = C.a[i], v = C.corner[i];
  const uint32_t vp = B.prev_vertex(a, v);
  const Vec2 nrm = C.normal[i], t = perp(nrm);
  // Depth of the sharp corner below the other block's surface (normals point to the owner).
  const Vec2 surface = C.point[i] - 0.5 * C.gap[i] * nrm;
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
// L = RQ1/2 + RQ2/2 with the neighbours as Q1, Q2, never less than a contact's own chord.
// Contacts closer than `merge` stand at one point (two corners meeting face to face): the
// point's share is split evenly, so that round-off in their order cannot move the length from
// one to the other from cycle to cycle. A line of one point (a corner whose neighbour lifted
// off) has no neighbours to share with: its contacts take their corners' wedge lengths.
void share_length(std::vector<std::pair<double, uint32_t>>& along, double merge, const Blocks& B,
                  Contacts& C) {
  // Insertion sort: a line has a handful of contacts, mostly in order already.
  for (size_t j = 1; j < along.size(); ++j)
    for (size_t q = j; q > 0 && along[q] < along[q - 1]; --q) std::swap(along[q], along[q - 1]);
  const size_t k = along.size();
  // Centre of the group of contacts starting at g0; g1 receives the index past the group.
  auto group = [&](size_t g0, size_t& g1) {
    g1 = g0 + 1;
    double sum = along[g0].first;
    while (g1 < k && along[g1].first - along[g1 - 1].first <= merge) sum += along[g1++].first;
    return sum / static_cast<double>(g1 - g0);
  };
  // Two contacts apart (the usual line): each takes half the distance between them, as below.
  if (k == 2 && along[1].first - along[0].first > merge) {
    const double len = 0.5 * (along[1].first - along[0].first);
    for (const auto& [x, i] : along) C.length[i] = std::max(len, C.chord[i]);
    return;
  }
  size_t g0 = 0, g1 = 0;
  double prev = 0.0, centre = k ? group(0, g1) : 0.0;
  if (k && g1 == k) {
    for (size_t j = 0; j < k; ++j) {
      const uint32_t i = along[j].second;
      C.length[i] = std::max(wedge_length(B, C, i) / static_cast<double>(k), C.chord[i]);
    }
    return;
  }
  while (g0 < k) {
    size_t g2 = g1;
    const double next = g1 < k ? group(g1, g2) : centre;
    const double len = 0.5 * ((g0 > 0 ? centre - prev : 0.0) + (next - centre));
    for (size_t j = g0; j < g1; ++j) {
      const uint32_t i = along[j].second;
      C.length[i] = std::max(len / static_cast<double>(g1 - g0), C.chord[i]);
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

// Per interface: the length of each contact, then the joint law for each contact, giving its
// force. Contacts facing the same way form one joint line (a concave block can touch another
// along two faces); each line shares its length on its own.
}  // namespace

void update_interfaces(Model& m) {
  const Blocks& B = m.blocks;
  Contacts& C = m.contacts;
  const double dt = m.dt;
  const double merge = 0.25 * m.settings.rounding;
  const double roundoff = m.roundoff_gap();
  // The first contact (lowest index, whatever the threads) whose overlap is beyond belief.
  FirstFlagged too_deep;
  // Laws other than Coulomb's (cy, barton-bandis, plug-ins) keep a plastic shear history.
  if (std::any_of(m.joints.begin(), m.joints.end(),
                  [](const JointProperties& j) { return j.inline_coulomb < 0; }))
    C.hold(C.plastic);
  const bool plastic = !C.plastic.empty();
  // Damped joints keep their dashpot's forces beside the springs' (released when none is).
  const bool damped = std::any_of(m.joints.begin(), m.joints.end(), [](const JointProperties& j) {
    return j.normal_damping > 0.0 || j.shear_damping > 0.0;
  });
  if (damped) {
    C.hold(C.damp_fn), C.hold(C.damp_fs);
  } else {
    std::vector<double>().swap(C.damp_fn), std::vector<double>().swap(C.damp_fs);
  }
  parallel_for(
      C.pair_count(),
      [&](size_t p0, size_t p1) {
        std::vector<std::pair<double, uint32_t>> along;
        std::vector<uint8_t> placed;
        // Normals point towards the owner: compare them turned to point the same way.
        const auto facing = [&](uint32_t q) {
          return C.a[q] < C.b[q] ? C.normal[q] : Vec2(-C.normal[q]);
        };
        // Contacts of a pair split into joint lines by the way they face (a concave block can
        // touch another along two faces); each line shares its length on its own.
        const auto general_lines = [&](uint32_t c0, uint32_t c1) {
          placed.assign(c1 - c0, 0);
          for (uint32_t i = c0; i < c1; ++i) C.length[i] = 0.0;
          for (uint32_t i = c0; i < c1; ++i) {
            if (C.kind[i] == kLost || placed[i - c0]) continue;
            const Vec2 n0 = facing(i), t = perp(n0);
            along.clear();
            for (uint32_t q = i; q < c1; ++q)
              if (C.kind[q] != kLost && !placed[q - c0] && facing(q).dot(n0) > 0.8) {
                placed[q - c0] = 1;
                along.emplace_back(C.point[q].dot(t), q);
              }
            share_length(along, merge, B, C);
          }
        };
        for (size_t p = p0; p < p1; ++p) {
          const uint32_t c0 = C.pair_begin[p], c1 = C.pair_begin[p + 1];
          // Fast path (convex blocks, nearly every pair): all contacts face one way, so they
          // form one joint line, the same list the general path below would build.
          bool one_line = true;
          Vec2 n_first = Vec2::Zero(), t_first = Vec2::Zero();
          along.clear();
          for (uint32_t i = c0; i < c1 && one_line; ++i) {
            C.length[i] = 0.0;
            if (C.kind[i] == kLost) continue;
            const Vec2 f = facing(i);
            if (along.empty())
              n_first = f, t_first = perp(f);
            else if (!(f.dot(n_first) > 0.8))
              one_line = false;
            along.emplace_back(C.point[i].dot(t_first), i);
          }
          if (one_line) {
            if (!along.empty()) share_length(along, merge, B, C);
          } else {
            general_lines(c0, c1);
          }
          // The pair's blocks (either may own a contact), whether one is deformable, and the
          // deepest overlap believed.
          const uint32_t pa = C.a[c0], pb = C.b[c0];
          const bool soft = B.deformable[pa] || B.deformable[pb];
          const double depth_limit = kOverlapLimit * max_contact_depth(B, pa, pb);
          // A node of a deformable block stands for its own stretch of outline at most: a
          // light node alone against a long edge must not take the edge's stiffness.
          // (A pair's contacts can be owned by either block: checked per contact.)
          if (soft)
            for (uint32_t i = c0; i < c1; ++i) {
              const uint32_t blk = C.a[i];
              if (!B.deformable[blk]) continue;
              const double own = B.vertex_share(blk, C.corner[i]);
              C.length[i] = std::min(C.length[i], std::max(own, C.chord[i]));
            }
          double pair_length = -1.0;  // summed once, for contact damping
          for (uint32_t i = c0; i < c1; ++i) {
            if (C.kind[i] == kLost) {
              if (C.flags[i] & kBonded)
                C.flags[i] = static_cast<uint8_t>((C.flags[i] & ~kBonded) | kBroken);
              C.flags[i] &= static_cast<uint8_t>(~(kTouching | kSlipping));
              C.fn[i] = 0.0, C.fs[i] = 0.0, C.un_prev[i] = 0.0;
              if (damped) C.damp_fn[i] = 0.0, C.damp_fs[i] = 0.0;
              continue;
            }
            const double overlap = without_roundoff(-C.gap[i] + C.closure_at(i), roundoff);
            if (-C.gap[i] > depth_limit) too_deep.flag(i);
            const double un = overlap + C.dilation[i];
            if (stays_open(un, C.fn[i], C.flags[i])) {
              C.fs[i] = 0.0, C.un_prev[i] = un;
              if (damped) C.damp_fn[i] = 0.0, C.damp_fs[i] = 0.0;
              C.flags[i] &= static_cast<uint8_t>(~kPreload);
              continue;
            }
            // An in-situ shear stress becomes a force once the contact has its length.
            if (C.flags[i] & kPreload) {
              C.fs[i] *= C.length[i];
              C.flags[i] &= static_cast<uint8_t>(~kPreload);
            }
            // Shear displacement increment of a relative to b over the last step.
            const Vec2 n = C.normal[i], tn = perp(n);
            const Vec2 dv =
                soft ? Vec2(contact_side_velocity(m, i, false) - contact_side_velocity(m, i, true))
                     : Vec2(point_velocity(B, C.a[i], C.point[i]) -
                            point_velocity(B, C.b[i], C.point[i]));
            const double dus = dv.dot(tn) * dt;
            JointState s{C.fn[i],    C.fs[i], C.un_prev[i], C.dilation[i],  C.shear_disp[i],
                         C.flags[i], 0.0,     0.0,          C.plastic_at(i)};
            const JointProperties& jp = m.joints[C.joint[i]];
            joint_update<true>(jp, C.length[i], overlap, dus, 0.0, s);
            C.fn[i] = s.fn, C.fs[i] = s.fs, C.un_prev[i] = s.un_prev, C.dilation[i] = s.dilation;
            C.shear_disp[i] = s.shear_disp, C.flags[i] = s.flags;
            if (plastic) C.plastic[i] = s.plastic;
            if (!damped) continue;
            C.damp_fn[i] = 0.0, C.damp_fs[i] = 0.0;
            if ((jp.normal_damping > 0.0 || jp.shear_damping > 0.0) && (s.flags & kTouching)) {
              if (pair_length < 0.0) {
                pair_length = 0.0;
                for (uint32_t q = c0; q < c1; ++q) pair_length += C.length[q];
              }
              const Dashpot d = contact_dashpot(jp, C.length[i], C.length[i] / pair_length,
                                                pair_mass(B, C.a[i], C.b[i]), -dv.dot(n),
                                                dv.dot(tn), 0.0, s.flags & kSlipping);
              C.damp_fn[i] = d.fn, C.damp_fs[i] = d.fs;
            }
          }
        }
      },
      64);
  if (too_deep.any()) throw_overlap(m, too_deep.index());
}

void update_contact_geometry(Model& m) {
  update_corner_contacts(m);
}

}  // namespace tessera
