// Cutting convex polyhedral blocks by joint planes (3D block generation, chapter 5.3.1).
//
// Exact: while one command cuts, vertices are CGAL exact points; which side of a plane a vertex
// lies on is decided exactly (one within a billionth of the block's size of it counts as on it),
// and a new vertex on an edge is computed once and shared by the pieces on both sides. A plane
// through or a hair's breadth from a vertex, edge or face leaves no sliver, and
// the pieces' volumes add up to the block's. The pieces are rounded to doubles at the end, so
// neighbours share bit-identical vertices.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"

namespace tessera {

// A block to cut or a piece made: its surface and the joint tag of each face (-1 none).
struct CutBlock {
  Polyhedron poly;
  std::vector<int> face_tags;
  size_t parent = 0;  // index of the input block it came from
  int label = -1;     // what the cutter says the piece is (an opening's round), -1 nothing
};

// A joint plane: unit normal and a point; `radius` > 0 makes it a disc about the point that
// cuts only the blocks whose section lies entirely inside it. `persistence` < 1: each block the
// plane crosses is cut with that probability, from the seeded stream (`seed` per plane).
struct JointPlane {
  Vec3 normal = Vec3::UnitZ(), point = Vec3::Zero();
  int tag = -1;
  double radius = 0.0, persistence = 1.0;
  uint64_t seed = 0;
};

// Every block cut by every plane in turn; pieces keep their parent's face tags, and the new
// faces take the plane's tag. Blocks no plane crosses come back whole.
std::vector<CutBlock> cut_blocks(const std::vector<CutBlock>& blocks,
                                 const std::vector<JointPlane>& planes);

// An opening along an axis (a 3D tunnel): a convex cross-section, counter-clockwise in the frame
// of `opening_frame(axis)`, about `start` (the portal), running `length` along the axis in
// `rounds` equal rounds of advance.
struct Opening3 {
  Vec3 start = Vec3::Zero(), axis = Vec3::UnitY();
  std::vector<Eigen::Vector2d> section;
  double length = 0.0;
  int rounds = 1;
  int wall_tag = -1, split_tag = -1;  // tags of the opening's walls and of the other new faces
};

// The cross-section's frame (across, up) of an axis: up is +z as seen along it (+y for a
// vertical axis), and across x up = the axis.
std::pair<Vec3, Vec3> opening_frame(const Vec3& axis);

// Cuts the blocks the opening reaches exactly along its walls: the rock around it in one piece
// per sector between two corners (split by planes through the axis) and, where a block reaches
// past the portal or the end, cut across there; the inside in one piece per round (label: the
// round from 0) and the rock past the portal or the end. New faces on the walls take
// `wall_tag`, all others `split_tag`. Blocks the opening does not reach come back whole.
std::vector<CutBlock> cut_opening(const std::vector<CutBlock>& blocks, const Opening3& o);

// Unit normal (pointing up) of a plane from its dip and dip direction (degrees, dip direction
// clockwise from north = +y, x east, z up).
Vec3 normal_from_dip(double dip, double dip_direction);

}  // namespace tessera
