// Geometry checks before a run and on demand: blocks too small or thin, edges too short for the
// rounding, corners too sharp to round, overlapping blocks, blocks with nothing to rest on.
#pragma once

#include <string>
#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

struct Finding {
  bool error = false;         // an error stops a run unless the script says to go on
  int block = 0;              // the user's block number
  Vec3 where = Vec3::Zero();  // the block's centroid (z unused in 2D)
  std::string message;
  bool three = false;        // a 3D model's block: the centroid is printed with z
  std::string text() const;  // "error: block 12 at (3.5, 1.2): ...", "(3.5, 1.2, 0.4)" in 3D
};

struct CheckLimits {
  double min_area = 0.0;       // 0: (2 d)^2 with d the rounding length
  double min_thickness = 0.0;  // 0: d (thickness = 2 area / perimeter)
  double min_angle = 10.0;     // degrees
};

std::vector<Finding> check_geometry(const Model& m, const CheckLimits& limits);

}  // namespace tessera
