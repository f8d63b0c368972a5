// Geometry of a rounded corner against a block (chapter 5.2.2, cases 2 and 3).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/contact2d/contacts.hpp"

namespace tessera {

// The feature of a block nearest to a rounded corner, with the contact geometry it gives.
struct FeatureHit {
  uint8_t kind = 0;            // ContactKind
  uint32_t feature = 0;        // global vertex index: the corner, or the start of the edge
  double gap = 0.0;            // negative when overlapping
  Vec2 normal = Vec2::Zero();  // unit, from the block towards the corner
  Vec2 point = Vec2::Zero();   // middle of the overlap
  double chord = 0.0;          // chord of the arc across the edge or the other arc
};

// A convex corner's rounded arc: centre, radius, and the outward normals of the edges before and
// after the corner, which bound it (the arc runs counter-clockwise from n_in to n_out). A flat
// corner (a many-sided opening's outline) has a large radius and a narrow arc: its full circle
// reaches far beyond the block, so contacts are measured from the arc itself.
struct CornerArc {
  Vec2 centre = Vec2::Zero();
  double radius = 0.0;
  Vec2 n_in = Vec2::Zero(), n_out = Vec2::Zero();
};

// Searches the features of block b nearest to the arc. Features are
// numbered 2k (corner k) and 2k+1 (edge from vertex k to k+1), k local to b; the search covers
// `count` features starting at `first` (modulo the block's feature count). Corners of b are
// skipped unless `corners` is set; features the arc would overlap by more than `max_depth` are
// the far side of the block, not a contact, and are skipped. Returns false when no feature has
// c within its reach.
bool nearest_feature(const Blocks& blocks, uint32_t b, const CornerArc& arc, bool corners,
                     int first, int count, double max_depth, FeatureHit& hit);

// The rounded corner vk of block b against the arc (along the line of the two arcs' centres);
// false if that line leaves the corner's cone of edge normals or the overlap passes max_depth.
bool corner_feature(const Blocks& blocks, uint32_t b, uint32_t vk, const CornerArc& arc,
                    double max_depth, FeatureHit& hit);

// Deepest plausible overlap between two blocks: a quarter of the smaller one's size.
inline double max_contact_depth(const Blocks& blocks, uint32_t a, uint32_t b) {
  return 0.25 * std::min(blocks.bound_radius[a], blocks.bound_radius[b]);
}

// Whether the unit direction m points into the arc (between its end normals).
inline bool arc_faces(const CornerArc& arc, const Vec2& m) {
  constexpr double slack = 1e-12;
  return cross(arc.n_in, m) >= -slack && cross(m, arc.n_out) >= -slack;
}

// The arc of corner v of block b, from the world cache (inline: the contact update calls it for
// every contact every cycle).
inline CornerArc corner_arc(const Blocks& B, uint32_t b, uint32_t v) {
  const Vec2& ui = B.world_edge_dir[B.prev_vertex(b, v)];
  const Vec2& uo = B.world_edge_dir[v];
  return {B.world_arc_centre[v], B.arc_radius[v], Vec2(ui.y(), -ui.x()), Vec2(uo.y(), -uo.x())};
}

// The straight part of the edge starting at global vertex vk of block b against the arc; false
// if the arc centre does not project onto it. The gap is that of the arc's point nearest the
// edge's line: straight towards it when the arc faces the edge, else the nearer end of the arc.
// `margin`, if given, is positive when no other feature of the block can be nearer, so that the
// search may stop here: the arc centre lies outside a convex block (the edge's Voronoi region), or
// deep inside the span.
inline bool edge_feature(const Blocks& B, uint32_t b, uint32_t vk, const CornerArc& arc,
                         double max_depth, FeatureHit& hit, double* margin) {
  const Vec2& c = arc.centre;
  const double r = arc.radius;
  const uint32_t vn = vk + 1 < B.vert_begin[b + 1] ? vk + 1 : B.vert_begin[b];
  const Vec2& p = B.world_vertex[vk];
  const Vec2& u = B.world_edge_dir[vk];
  const double len = B.edge_length[vk];
  const Vec2 d = c - p;
  const double t = d.dot(u);
  // A hair of slack at the span's ends, so that round-off never leaves a corner that sits
  // exactly at a tangent point without a feature. (A concave corner's rounding length is 0.)
  const double slack = 1e-9 * len;
  const double lo = B.round_length[vk] - slack;
  const double hi = len - B.round_length[vn] + slack;
  if (t < lo || t > hi) return false;
  const Vec2 nrm(u.y(), -u.x());
  const double s = d.dot(nrm);
  // The arc's point nearest the edge's line. An arc that does not face the edge (its circle
  // would, reaching past the block's own outline) comes nearest at one of its ends, where it
  // meets the block's straight edges.
  const bool facing = arc_faces(arc, -nrm);
  const Vec2 q = facing                                    ? Vec2(c - r * nrm)
                 : arc.n_in.dot(nrm) <= arc.n_out.dot(nrm) ? Vec2(c + r * arc.n_in)
                                                           : Vec2(c + r * arc.n_out);
  const double gap = (q - p).dot(nrm);
  if (gap < -max_depth) return false;
  hit.kind = kCornerEdge, hit.feature = vk, hit.gap = gap, hit.normal = nrm;
  hit.point = q - nrm * (0.5 * gap);
  const double o = -gap;
  hit.chord = facing && o > 0.0 ? 2.0 * std::sqrt(o * std::max(2.0 * r - o, 0.0)) : 0.0;
  // Outside a convex block, a point over an edge's span is in that edge's Voronoi region.
  if (margin)
    *margin = (s >= 0.0 && B.all_convex[b]) ? 1.0 : std::min(t - lo, hi - t) - 4.0 * std::abs(s);
  return true;
}

// Local feature number of a hit, for a later local search around it.
inline int local_feature(const Blocks& blocks, uint32_t b, uint8_t kind, uint32_t feature) {
  return 2 * static_cast<int>(feature - blocks.vert_begin[b]) + (kind == 0 ? 1 : 0);
}

}  // namespace tessera
