#include "tessera/contact3d/rigid3d.hpp"

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
// that axis at the rate pi_k / I_k (pi: the angular momentum in the body frame); the world
// angular momentum does not change, so pi turns the other way in the body frame.
void rotate_about(RigidBody3& b, Vec3& pi, const Vec3& inv_moment, int k, double h) {
  const double half = 0.5 * h * inv_moment[k] * pi[k];
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
  // pi turned by minus the whole angle about k.
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double ct = c * c - s * s, st = 2.0 * c * s;
  const double pi_i = ct * pi[i] + st * pi[j], pi_j = -st * pi[i] + ct * pi[j];
  pi[i] = pi_i, pi[j] = pi_j;
}
}  // namespace

void step_body(RigidBody3& b, const Vec3& force, const Vec3& torque, double dt,
               const Vec3& inv_moment) {
  // Momenta live at half steps, as in the 2D cycle: a whole kick with the torque at the present
  // orientation, then the free rotation with the new momentum (a half kick on each side of the
  // rotation would apply each torque a step late, and the lag feeds energy into rocking).
  b.momentum += dt * torque;
  // (The turns multiply by the moments' reciprocals: no divisions chained through the step.)
  Vec3 pi = b.orientation.conjugate() * b.momentum;
  const Vec3 turn = dt * pi.cwiseProduct(inv_moment);  // body-frame rotation vector
  if (turn.cwiseAbs().maxCoeff() < 1e-8) {
    // Below 1e-8 rad a step, the composition differs from one rotation by the rotation vector
    // by less than round-off (its error is of the order of the angle squared).
    const Eigen::Quaterniond q = b.orientation;
    const Vec3 h = 0.5 * turn, v = q.w() * h + q.vec() + q.vec().cross(h);
    b.orientation = Eigen::Quaterniond(q.w() - q.vec().dot(h), v.x(), v.y(), v.z());
  } else {
    // Symmetric composition: axes 0, 1 for half steps around axis 2 for a whole one.
    rotate_about(b, pi, inv_moment, 0, 0.5 * dt);
    rotate_about(b, pi, inv_moment, 1, 0.5 * dt);
    rotate_about(b, pi, inv_moment, 2, dt);
    rotate_about(b, pi, inv_moment, 1, 0.5 * dt);
    rotate_about(b, pi, inv_moment, 0, 0.5 * dt);
  }
  // Back to unit length: a step leaves it off by round-off only, so one Newton step for 1/|q|
  // (error of the order of that round-off squared) instead of a square root and a division; an
  // orientation given off unit length (a script's, a file's) is normalised in full.
  const double q2 = b.orientation.squaredNorm();
  if (std::abs(q2 - 1.0) < 1e-6)
    b.orientation.coeffs() *= 1.5 - 0.5 * q2;
  else
    b.orientation.normalize();
  if (b.mass > 0) b.velocity += (dt / b.mass) * force;
  b.position += dt * b.velocity;
}

}  // namespace tessera
