// A speed-of-light kernel for the 2D wall: the least a rigid-block explicit code must do per
// cycle, written for speed and nothing else, run beside Tessera on the same blocks and contacts
// so that `tessera-bench --kernel` reports Tessera's cost as a ratio to it.
#pragma once

#include <cstdint>

#include "tessera/core/model.hpp"

namespace tessera::bench {

struct KernelResult {
  double ms_per_cycle = 0;
  double top_y = 0;  // centroid height of the last block, a check that the wall held up
};

// Cycles a copy of the model's 2D blocks under gravity with its contact list fixed: per contact
// linear normal and shear springs on the relative motion at the contact point (stiffness times
// the contact's length), tension cut off, shear capped by Coulomb friction; per block local
// damping (alpha 0.8) and central differences. One thread, packed records.
KernelResult run_kernel(const Model& m, uint64_t cycles);

}  // namespace tessera::bench
