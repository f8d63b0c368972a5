// Contact detection of 3D blocks (contact3d/detection3.cpp).
#pragma once

#include <string>

#include "tessera/core/model.hpp"

namespace tessera {

// Detection pass: bounding boxes swept along the axis of widest spread, the common plane of
// each close pair; keeps the state of contacts that persist.
void detect_contacts3(Model& m);
// First pair of blocks overlapping beyond the tolerance, as a message; empty if none.
std::string find_overlap3(const Model& m);
// Cross-reference checks of the 3D block and contact arrays (contact3d/validate3.cpp).
void validate3d(const Model& m);

}  // namespace tessera
