// The 3D contact stages of the cycle (contact3d/subcontacts.cpp): where a 3D contact's
// geometry and force are computed.
#pragma once

#include "tessera/core/model.hpp"

namespace tessera {

// The moving body of a contact's block a: its sub-contacts' points are kept in its frame.
inline const RigidBody3& frame_body(const Blocks3& B, const Contact3& c) {
  return B.body[static_cast<size_t>(B.master[c.a])];
}
// A sub-contact's point in world axes, and a world point in the frame of a's moving body.
inline Vec3 world_point(const Blocks3& B, const Contact3& c, const SubContact& s) {
  return frame_body(B, c).position + B.rotation[c.a] * s.local;
}
inline Vec3 frame_point(const Blocks3& B, const Contact3& c, const Vec3& x) {
  return B.rotation[c.a].transpose() * (x - frame_body(B, c).position);
}

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
// turn_speed: each block's Blocks3::turn_speed, if the caller formed them once for all its
// contacts (else formed here).
double joint_forces3(const Model& m, Contact3& c, const double* turn_speed = nullptr);
// A contact's cycle, update_plane3 then joint_forces3, with the same results: a pair of rigid
// blocks whose sub-contacts all stay open (the wall's head joints) is done in the plane's pass.
double contact_cycle3(const Model& m, Contact3& c, const double* turn_speed);

}  // namespace tessera
