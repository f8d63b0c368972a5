// Rock support of 2D models: local reinforcement across joints (UDEC's bolt model).
//
// A bolt is a straight segment the user places; where it crosses a joint between two blocks it
// becomes an element: an axial and a shear spring joining a point of one block to the same point
// of the other. Each cycle the relative velocity of the two points, times the step, loads the
// springs incrementally; each force is capped at its yield force (perfectly plastic), and a bolt
// stretched past its rupture displacement carries nothing from then on. Between crossings the
// steel is not modelled: the rock on either side of a joint is taken as rigid anchorage.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tessera/core/geometry.hpp"

namespace tessera {

struct Model;

// A point fixed in a 2D block: in a rigid block's own frame, or in a zone of a deformable block
// (its three nodes and the point's weights). `angle0` is the block's (or the zone's first edge's)
// orientation when the point was placed, so the bolt's axis can turn with the rock. (Laid out
// without padding and trivially copyable: state files write it as its bytes.)
struct Anchor2 {
  std::array<double, 2> local{0.0, 0.0};
  std::array<double, 3> w{0.0, 0.0, 0.0};
  double angle0 = 0.0;
  int32_t block = -1;
  std::array<int32_t, 3> node{-1, -1, -1};
};
static_assert(sizeof(Anchor2) == 64);

// A bolt's properties, per metre out of the plane (the user's values over the row spacing).
struct BoltProperties {
  double ka = 0.0, ks = 0.0;                             // axial and shear stiffness, N/m
  double tension = 0.0, compression = 0.0, shear = 0.0;  // yield forces, N (0: none)
  double rupture = 0.0;  // axial displacement at which it breaks, m (0: never)
};

// One bolt as placed: its name, properties, ends (for drawing) and its elements.
struct Bolt {
  std::string name;
  BoltProperties props;
  Anchor2 end0, end1;
  uint32_t first = 0, count = 0;  // elements [first, first + count)
};

// Element states.
enum BoltState : uint8_t { kBoltAxialYield = 1, kBoltShearYield = 2, kBoltBroken = 4 };

struct Reinforcement {
  std::vector<Bolt> bolts;
  // Per element (a crossing of a joint): its bolt, the points on both sides, the bolt's axis
  // when placed, forces (axial: tension positive; shear: along the axis turned +90 degrees,
  // the force on side a), total relative displacements along them, and state bits.
  std::vector<uint32_t> bolt;
  std::vector<Anchor2> side_a, side_b;
  std::vector<Vec2> axis0;
  std::vector<double> axial, shear, ua, us;
  std::vector<uint8_t> state;
  // The cycle's results: the crossing in world coordinates, and the force on side a.
  std::vector<Vec2> point, force;

  size_t size() const { return bolt.size(); }
  bool empty() const { return bolts.empty(); }
  // Appends a bolt and its elements (side pairs and axes); returns its index.
  size_t add(Bolt b, const std::vector<std::array<Anchor2, 2>>& sides, Vec2 axis);
};

// Where an anchor is now, how fast it moves, and how far its rock has turned since it was set.
Vec2 anchor_position(const Model& m, const Anchor2& p);
Vec2 anchor_velocity(const Model& m, const Anchor2& p);
double anchor_angle(const Model& m, const Anchor2& p);
// An anchor at world point p in block b (in the zone holding p if b is deformable).
Anchor2 make_anchor(const Model& m, size_t b, Vec2 p);
// After blocks are deleted (map: old block index to new, -1 gone) and nodes renumbered
// (node_map, empty if unchanged): the anchor follows its block and nodes; false if its rock is
// gone.
bool follow_anchor(Anchor2& a, const std::vector<int>& map, const std::vector<int64_t>& node_map);
// A zone anchor's nodes renumbered by node_map (empty: unchanged); false if one is gone.
template <size_t N>
bool renumber_nodes(std::array<int32_t, N>& node, const std::vector<int64_t>& node_map) {
  if (node[0] < 0 || node_map.empty()) return true;
  for (const int32_t n : node)
    if (node_map[static_cast<size_t>(n)] < 0) return false;
  for (int32_t& n : node) n = static_cast<int32_t>(node_map[static_cast<size_t>(n)]);
  return true;
}

// A bolt drawn as a polyline in world coordinates: its first end, each crossing, its last end,
// with the element at each point (-1 at the ends).
struct BoltPoint {
  Vec2 at;
  int32_t element = -1;
};
std::vector<BoltPoint> bolt_path(const Model& m, size_t bolt);

// The cycle: element forces from the blocks' velocities (after the joint forces), then their
// share of the block resultants (rigid blocks) and of the node forces (deformable blocks).
void update_reinforcement(Model& m);
void add_reinforcement_forces(Model& m);
void add_reinforcement_forces_to_nodes(Model& m);
// The stiffest spring each block carries (N/m), for the time step; zero without bolts.
std::vector<double> reinforcement_stiffness(const Model& m);
// After blocks are deleted (map: old index to new, -1 gone) and nodes renumbered (node_map,
// empty if unchanged): elements whose rock is gone are dropped, the rest follow.
void remap_reinforcement(Model& m, const std::vector<int>& map,
                         const std::vector<int64_t>& node_map);

// Places a bolt from p0 to p1: an element at each crossing of a joint between two blocks.
// Throws ModelError naming the bolt if it crosses no block or no joint.
size_t install_bolt(Model& m, const std::string& name, Vec2 p0, Vec2 p1,
                    const BoltProperties& props);
// The block whose outline (world polygons `polys`) holds p, or -1.
int block_at(const Model& m, const std::vector<std::vector<Vec2>>& polys, Vec2 p);

// The wall of an excavated opening: the outline edges along joint tag `tag` that face empty
// space, each from its end first met going anticlockwise about the wall's centre, with its
// unit normal into the rock and its block, sorted by angle about the centre (-pi to pi).
// Throws ModelError if there is none.
struct WallEdge {
  Vec2 from, to, inward;
  int block = -1;
  double angle = 0.0;
};
struct OpeningWall {
  std::vector<WallEdge> edges;
  Vec2 centre = Vec2::Zero();
};
OpeningWall opening_wall(const Model& m, int tag);

// Places bolts (or cables) of length L every `spacing` along the wall of an excavated opening:
// calls place(k, p0, p1) for the k-th (from 1) with p0 on the wall and p1 in the rock; a place
// that throws ModelError is skipped. Returns how many were placed (see install_bolt_pattern).
size_t install_pattern(Model& m, int tag, double spacing, double length, double a0, double a1,
                       const std::function<void(size_t, Vec2, Vec2)>& place);
// Places bolts of length L every `spacing` along the wall of an excavated opening (the outline
// edges along joint tag `tag` that face empty space), normal to the wall into the rock, within
// the angles [a0, a1] (degrees, counter-clockwise from +x about the opening's centre). Returns
// how many were placed.
size_t install_bolt_pattern(Model& m, const std::string& name, int tag, double spacing,
                            double length, double a0, double a1, const BoltProperties& props);

}  // namespace tessera
