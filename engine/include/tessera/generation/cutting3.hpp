// Cutting convex polyhedral blocks by joint planes (3D block generation, chapter 5.3.1).
//
// Exact: while one command cuts, vertices are CGAL exact points; which side of a plane a vertex
// lies on is decided exactly, and a new vertex on an edge is computed once and shared by the
// pieces on both sides. A plane through a vertex or along an edge or face leaves no sliver, and
// the pieces' volumes add up to the block's. The pieces are rounded to doubles at the end, so
// neighbours share bit-identical vertices.
#pragma once

#include <cstdint>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"

namespace tessera {

// A block to cut or a piece made: its surface and the joint tag of each face (-1 none).
struct CutBlock {
  Polyhedron poly;
  std::vector<int> face_tags;
  size_t parent = 0;  // index of the input block it came from
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

// Unit normal (pointing up) of a plane from its dip and dip direction (degrees, dip direction
// clockwise from north = +y, x east, z up).
Vec3 normal_from_dip(double dip, double dip_direction);

}  // namespace tessera
