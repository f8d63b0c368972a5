// Block generators that script commands and benchmarks share.
#pragma once

#include "tessera/model.hpp"

namespace tessera {

// A running-bond wall: `courses` courses of `bricks` bricks each; every second course starts and
// ends with a half brick so that the vertical joints are staggered.
struct WallSpec {
  Vec2 origin = Vec2::Zero();  // lower-left corner of the wall
  double brick_length = 2.0, brick_height = 1.0;
  int courses = 1, bricks = 1;
  int group = -1, material = -1;
};

// Adds the bricks to the model (density from the material); returns the number added.
size_t add_running_bond_wall(Model& m, const WallSpec& spec);

}  // namespace tessera
