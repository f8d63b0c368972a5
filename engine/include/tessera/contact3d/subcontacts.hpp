// The 3D contact stages of the cycle (contact3d/subcontacts.cpp): where a 3D contact's
// geometry and force are computed.
#pragma once

#include "tessera/core/model.hpp"

namespace tessera {

// Moves a contact's common plane with its blocks and rebuilds or follows its sub-contacts.
void update_plane3(const Model& m, Contact3& c);
// Whether update_plane3 will only follow the plane of a face, reading the blocks' face planes
// but not their vertices or edge directions (refresh: plane_refresh_drift(m)).
inline bool follows_face_plane(const Contact3& c, double refresh) {
  return c.drift < refresh && c.kind != kPlaneEdges;
}
// How far the blocks may move against each other before a contact re-fits its plane.
inline double plane_refresh_drift(const Model& m) {
  return 0.01 * m.tolerance();
}
// The joint law at each sub-contact, and the contact's resultant force and torques (on a; b
// takes the opposite). Returns the deepest overlap of its sub-contacts (0 if none overlaps).
double joint_forces3(const Model& m, Contact3& c);

}  // namespace tessera
