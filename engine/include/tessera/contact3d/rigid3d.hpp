// Rigid-body motion of a 3D block (chapter 5.3): translation by central differences, rotation
// as an orientation quaternion moved by the splitting of Dullweber, Reich and Leimkuhler (1997)
// with the angular momentum at half steps:
// the torque-free part is composed of exact rotations about the principal axes, so angular
// momentum is kept exactly and kinetic energy to O(dt^2) without drift, and the orientation
// stays a rotation (the quaternion is renormalised, so the shape cannot shear).
#pragma once

#include <Eigen/Geometry>

#include "tessera/contact3d/polyhedron.hpp"

namespace tessera {

struct RigidBody3 {
  double mass = 0.0;
  Vec3 principal = Vec3::Ones();               // principal moments of inertia (kg m^2)
  Eigen::Quaterniond orientation{1, 0, 0, 0};  // principal frame -> world
  Vec3 position = Vec3::Zero(), velocity = Vec3::Zero();
  Vec3 momentum = Vec3::Zero();  // angular momentum about the centroid, world frame

  // Angular velocity in the world frame, and the kinetic energy.
  Vec3 angular_velocity() const;
  double kinetic_energy() const;
};

// A body from a polyhedron's properties and a density; `orientation` holds the principal axes.
RigidBody3 make_body(const SolidProperties& s, double density);

// One step of dt under a force and a torque (world frame, about the centroid) at the present
// position: leapfrog, with velocity and angular momentum at half steps - a torque kick, then
// the free rotation; a force kick, then translation. inv_moment: the principal moments'
// reciprocals (formed by a caller that needs them as well).
void step_body(RigidBody3& b, const Vec3& force, const Vec3& torque, double dt,
               const Vec3& inv_moment);
inline void step_body(RigidBody3& b, const Vec3& force, const Vec3& torque, double dt) {
  step_body(b, force, torque, dt, b.principal.cwiseInverse());
}

}  // namespace tessera
