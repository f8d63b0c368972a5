// Block generators that script commands and benchmarks share.
#pragma once

#include <string>
#include <vector>

#include "tessera/core/model.hpp"
#include "tessera/generation/cutting.hpp"

namespace tessera {

// A running-bond wall: `courses` courses of `bricks` bricks each; every second course starts and
// ends with a half brick so that the vertical joints are staggered.
struct WallSpec {
  Vec2 origin = Vec2::Zero();  // lower-left corner of the wall
  double brick_length = 2.0, brick_height = 1.0;
  int courses = 1, bricks = 1;
  int group = -1, material = -1;
  int bed_tag = -1, head_tag = -1;  // joint tags of the bed (horizontal) and head joints
};

// Adds the bricks to the model (density from the material); returns the number added.
size_t add_running_bond_wall(Model& m, const WallSpec& spec);

// A semicircular or segmental arch of voussoirs between two abutment blocks. The voussoirs'
// joints are radial; the arch springs from the abutments on radial joints too.
struct ArchSpec {
  Vec2 centre = Vec2::Zero();  // centre of the intrados circle
  double radius = 1.0;         // intrados radius
  double thickness = 0.2;      // ring thickness
  double half_angle = 90.0;    // degrees from the crown to each springing (90: semicircular)
  int voussoirs = 9;
  double abutment = 0.0;  // abutment block height below the springing (0: none)
  int group = -1, abutment_group = -1, material = -1;
};
size_t add_arch(Model& m, const ArchSpec& spec);

// A joint set: parallel traces at an angle (degrees, anticlockwise from the x axis), spaced
// along their normal from a line through `origin`; traces of finite length are separated by
// rock bridges (`gap`). Every quantity has a mean and a standard deviation, drawn from a
// seeded stream. trace = 0: the traces are continuous lines.
struct JointSetSpec {
  double angle = 0.0, angle_sd = 0.0;
  double spacing = 1.0, spacing_sd = 0.0;
  double trace = 0.0, trace_sd = 0.0;
  double gap = 0.0, gap_sd = 0.0;
  Vec2 origin = Vec2::Zero();
  uint64_t seed = 1;
  bool extend = false;  // traces ending inside a block are extended to its boundary
};
// Traces covering the box [lo, hi].
std::vector<CutLine> joint_set_traces(const JointSetSpec& spec, const Vec2& lo, const Vec2& hi,
                                      int tag);

// Outline of an opening: circle of n segments, horseshoe (a half circle on walls), rectangle.
std::vector<Vec2> circle_outline(const Vec2& centre, double radius, int segments);
std::vector<Vec2> horseshoe_outline(const Vec2& centre, double width, double height, int segments);

// Voronoi cells of seeds spread over the box with mean cell size `size`: the cell walls as cuts.
std::vector<CutLine> voronoi_traces(const Vec2& lo, const Vec2& hi, double size, uint64_t seed,
                                    int tag);

// Cuts the chosen blocks (all if `chosen` is empty) along the lines; pieces keep their parent's
// group, material and fixity. Only before the first cycle: blocks are renumbered 1, 2, ... and
// contacts are made anew. A ring left around a hole is split by chords named "split" (joint
// tags). A piece below the check's area limit (2 d)^2, d the rounding length, is merged into the
// neighbour of its group, material and fixity it shares the most edge with, never across a closed
// cut (an opening's outline). Reports the slivers dropped, merged and left, and the chords added.
struct CutReport {
  size_t slivers_dropped = 0, splits = 0;
  size_t slivers_merged = 0, slivers_left = 0;
  double min_area = 0.0;  // the area below which a piece is a sliver
};
CutReport cut_blocks(Model& m, const std::vector<CutLine>& cuts, const std::vector<size_t>& chosen);

// Joins blocks that touch along edges into one (possibly concave) block; before the first
// cycle only. Throws ModelError saying why when the union is not one simple polygon.
void join_blocks(Model& m, const std::vector<size_t>& blocks);

// Deletes blocks at any time (excavation): their contacts go, their histories read NaN from now.
void delete_blocks(Model& m, const std::vector<size_t>& blocks);

// The tag of a named joint (joint set, crack, opening), made on first use.
int joint_tag(Model& m, const std::string& name);

}  // namespace tessera
