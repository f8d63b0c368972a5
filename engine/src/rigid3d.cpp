#include "tessera/rigid3d.hpp"

#include <cmath>

namespace tessera {

Vec3 RigidBody3::angular_velocity() const {
  const Vec3 body = orientation.conjugate() * momentum;
  return orientation * body.cwiseQuotient(principal);
}

double RigidBody3::kinetic_energy() const {
  const Vec3 body = orientation.conjugate() * momentum;
  return 0.5 * mass * velocity.squaredNorm() +
         0.5 * body.cwiseProduct(body).cwiseQuotient(principal).sum();
}

RigidBody3 make_body(const SolidProperties& s, double density) {
  RigidBody3 b;
  b.mass = density * s.volume;
  b.principal = density * s.principal_moments;
  b.orientation = Eigen::Quaterniond(s.principal_axes);
  b.orientation.normalize();
  b.position = s.centroid;
  return b;
}

namespace {
// The exact flow of the kinetic energy about principal axis k for time h: the body turns about
// that axis at the rate pi_k / I_k; the world angular momentum does not change.
void rotate_about(RigidBody3& b, int k, double h) {
  const Vec3 body = b.orientation.conjugate() * b.momentum;
  const double half = 0.5 * h * body[k] / b.principal[k];
  // cos and sin of the half angle; below 1e-4 rad their series are exact in double precision.
  const double h2 = half * half;
  const double c = h2 < 1e-8 ? 1.0 - 0.5 * h2 + h2 * h2 / 24.0 : std::cos(half);
  const double s = h2 < 1e-8 ? half * (1.0 - h2 / 6.0) : std::sin(half);
  // q * (c, s e_k), written out.
  const Eigen::Quaterniond& q = b.orientation;
  const Vec3 v = q.vec();
  Vec3 e = Vec3::Zero();
  e[k] = s;
  const Vec3 vec = q.w() * e + c * v + v.cross(e);
  b.orientation = Eigen::Quaterniond(q.w() * c - v[k] * s, vec.x(), vec.y(), vec.z());
}
}  // namespace

void step_body(RigidBody3& b, const Vec3& force, const Vec3& torque, double dt) {
  // Momenta live at half steps, as in the 2D cycle: a whole kick with the torque at the present
  // orientation, then the free rotation with the new momentum (a half kick on each side of the
  // rotation would apply each torque a step late, and the lag feeds energy into rocking).
  b.momentum += dt * torque;
  // Symmetric composition: axes 0, 1 for half steps around axis 2 for a whole one.
  rotate_about(b, 0, 0.5 * dt);
  rotate_about(b, 1, 0.5 * dt);
  rotate_about(b, 2, dt);
  rotate_about(b, 1, 0.5 * dt);
  rotate_about(b, 0, 0.5 * dt);
  b.orientation.normalize();
  if (b.mass > 0) b.velocity += dt * force / b.mass;
  b.position += dt * b.velocity;
}

}  // namespace tessera
