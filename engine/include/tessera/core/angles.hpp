// Degrees to radians: the scripts and joint data give angles in degrees.
#pragma once

#include <numbers>

namespace tessera {

inline constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace tessera
