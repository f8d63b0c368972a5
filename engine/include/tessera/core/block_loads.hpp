// Whether a rigid block carries a load (the 'load' command): the one test that cutting, joining
// and zoning refuse by, and that the window lists loads by.
#pragma once

#include <cstddef>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/contact3d/blocks3.hpp"

namespace tessera {

inline bool loaded(const Blocks& B, size_t b) {
  return B.load_fx[b] != 0.0 || B.load_fy[b] != 0.0 || B.load_m[b] != 0.0;
}

// A 3D load is held by the body's master piece.
inline bool loaded(const Blocks3& B, size_t b) {
  const auto body = static_cast<size_t>(B.master[b]);
  return B.load_force[body] != Vec3::Zero() || B.load_moment[body] != Vec3::Zero();
}

}  // namespace tessera
