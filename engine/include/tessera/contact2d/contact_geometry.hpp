// Geometry of a rounded corner against a block (chapter 5.2.2, cases 2 and 3).
#pragma once

#include <algorithm>
#include <cstdint>

#include "tessera/contact2d/blocks.hpp"

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

// The arc of corner v of block b, from the world cache.
CornerArc corner_arc(const Blocks& blocks, uint32_t b, uint32_t v);

// Searches the features of block b nearest to the arc. Features are
// numbered 2k (corner k) and 2k+1 (edge from vertex k to k+1), k local to b; the search covers
// `count` features starting at `first` (modulo the block's feature count). Corners of b are
// skipped unless `corners` is set; features the arc would overlap by more than `max_depth` are
// the far side of the block, not a contact, and are skipped. Returns false when no feature has
// c within its reach.
bool nearest_feature(const Blocks& blocks, uint32_t b, const CornerArc& arc, bool corners,
                     int first, int count, double max_depth, FeatureHit& hit);

// Deepest plausible overlap between two blocks: a quarter of the smaller one's size.
inline double max_contact_depth(const Blocks& blocks, uint32_t a, uint32_t b) {
  return 0.25 * std::min(blocks.bound_radius[a], blocks.bound_radius[b]);
}

// The straight part of the edge starting at global vertex vk of block b against the arc; false
// if the arc centre does not project onto it. The gap is that of the arc's point nearest the
// edge's line: straight towards it when the arc faces the edge, else the nearer end of the arc.
// `margin`, if given, is positive when no other feature of the block can be nearer, so that the
// search may stop here: the arc centre lies outside a convex block (the edge's Voronoi region), or
// deep inside the span.
bool edge_feature(const Blocks& blocks, uint32_t b, uint32_t vk, const CornerArc& arc,
                  double max_depth, FeatureHit& hit, double* margin);

// Local feature number of a hit, for a later local search around it.
inline int local_feature(const Blocks& blocks, uint32_t b, uint8_t kind, uint32_t feature) {
  return 2 * static_cast<int>(feature - blocks.vert_begin[b]) + (kind == 0 ? 1 : 0);
}

}  // namespace tessera
