// The 2D contact stages of the cycle (contact2d/interfaces.cpp): where a 2D contact's
// geometry and force are computed.
#pragma once

#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

// Each contact's feature, gap, normal, point and chord from the current positions: the nearest
// feature of the other block to its rounded corner, searched around last cycle's.
void update_contact_geometry(Model& m);
// Per interface (pair of blocks): each contact's share of joint length, then the joint law,
// giving its force. Stops the run (ModelError, "contact overlap too great") on an overlap beyond
// half the deepest plausible one.
void update_interfaces(Model& m);

// The stretch of joint a contact stands for, along its joint in world coordinates.
struct ContactStretch {
  Vec2 from, to;
};
// Every contact's stretch (contact2d/joint_lines.cpp), for drawing: its length as the cycle last
// shared it, placed on its part of its joint line, so that a contact at the end of a joint (at
// an opening's edge, a block's end) is drawn on the joint, not half over the opening. A lost
// contact's is its point.
std::vector<ContactStretch> contact_stretches(const Model& m);

}  // namespace tessera
