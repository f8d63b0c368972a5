// Exact cutting of blocks by cracks, joint traces and opening outlines.
//
// All input edges and cut segments go into one CGAL arrangement with exact constructions, so
// that intersections are computed once and shared by the blocks on both sides: a cut through a
// vertex or along an existing edge leaves no sliver. A segment splits a block only where it
// crosses it from boundary to boundary; a trace that ends inside a block leaves it whole (as in
// UDEC). A piece that would enclose a hole (an opening cut inside a single block) is split by
// a horizontal crack through the hole, since blocks are simple polygons: a fictitious joint with
// its own tag, so that it can be given properties that keep it shut. The pieces' vertices
// are rounded to doubles and snapped together within a tolerance, the same way for every
// piece, so that neighbours keep matching vertices. A piece too small to be a block (a corner
// clipped where a cut passes near a vertex) is merged, exactly, into the neighbour it shares the
// most edge length with. Only cutting.cpp includes CGAL.
#pragma once

#include <string>
#include <vector>

#include "tessera/core/geometry.hpp"

namespace tessera {

// An open polyline to cut along, with the joint tag its new edges get.
struct CutLine {
  std::vector<Vec2> points;
  int tag = -1;
};

// A polygon with a tag per edge (the edge that starts at each vertex); -1 is "no tag".
struct TaggedPolygon {
  std::vector<Vec2> points;
  std::vector<int> edge_tags;
};

struct CutResult {
  std::vector<TaggedPolygon> pieces;  // counter-clockwise, in a canonical order
  std::vector<size_t> parent;         // index of the input polygon each piece came from
  size_t slivers_dropped = 0;         // pieces that snapping reduced to nothing
  size_t slivers_merged = 0;          // pieces below SliverMerge::min_area merged into a neighbour
  size_t slivers_left = 0;            // such pieces that had no neighbour to merge with
  double smallest_merged = 0.0;       // area of the smallest one merged
  size_t splits = 0;                  // chords added to split rings around holes
};

// Which pieces count as slivers and what they may merge with. A sliver is a piece of an input
// polygon the cuts split, of area below `min_area` (0: none); it merges into the adjacent piece
// of at least that area with which it shares the most edge length, if the union is a simple
// polygon, the two come from polygons of the same `kind` (one per polygon; empty: all alike) and
// no edge between them lies on a closed cut line (an opening's outline stays where it is).
struct SliverMerge {
  double min_area = 0.0;
  std::vector<int> kind;
};

// Cuts the polygons (which must not overlap) along the lines. `snap`: vertices closer than this
// become one. Edges along a cut take its tag; where cuts overlap, the later one's tag. Chords
// that split rings around holes take `split_tag`.
CutResult cut_polygons(const std::vector<TaggedPolygon>& polygons, const std::vector<CutLine>& cuts,
                       double snap, int split_tag = -1, const SliverMerge& merge = {});

// A point strictly inside a simple polygon (the middle of its widest horizontal chord).
Vec2 interior_point(const std::vector<Vec2>& pts);

}  // namespace tessera

namespace tessera {

// The union of polygons that touch along edges, as one simple polygon (counter-clockwise), with
// the tags of the outer edges kept. Empty, with `why` set, when the union is not one simple
// polygon (the blocks do not touch, or they enclose a hole).
TaggedPolygon join_polygons(const std::vector<TaggedPolygon>& polygons, std::string& why);

}  // namespace tessera
