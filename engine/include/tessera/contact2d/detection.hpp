// Contact detection of 2D blocks (contact2d/detection.cpp).
#pragma once

#include <string>

#include "tessera/core/model.hpp"

namespace tessera {

// Detection pass: broad phase, corner search, merge with existing contacts.
void detect_contacts(Model& m);
// First pair of blocks that overlap beyond the contact tolerance, as a message; empty if none.
std::string find_overlap2d(const Model& m);
// Cross-reference checks of the 2D block and contact arrays (contact2d/validate.cpp).
void validate2d(const Model& m);

}  // namespace tessera
