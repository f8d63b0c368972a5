// The 2D contact stages of the cycle (contact2d/interfaces.cpp): where a 2D contact's
// geometry and force are computed.
#pragma once

#include "tessera/core/model.hpp"

namespace tessera {

// Each contact's feature, gap, normal, point and chord from the current positions: the nearest
// feature of the other block to its rounded corner, searched around last cycle's.
void update_contact_geometry(Model& m);
// Per interface (pair of blocks): each contact's share of joint length, then the joint law,
// giving its force. Stops the run (ModelError, "contact overlap too great") on an overlap beyond
// half the deepest plausible one.
void update_interfaces(Model& m);

}  // namespace tessera
