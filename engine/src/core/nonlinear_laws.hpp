// The nonlinear joint laws (law=cy, law=barton-bandis) and what they share.
#pragma once

#include <algorithm>
#include <cmath>

#include "tessera/core/joint_law.hpp"

namespace tessera {

const JointLaw& cy_law();
const JointLaw& barton_bandis_law();

// A shear force in the joint plane: one component in 2D (the second zero, kept exact), two in 3D.
struct ShearPair {
  double& a;
  double& b;
  bool plane() const { return b == 0.0; }
  double norm() const { return plane() ? std::abs(a) : std::sqrt(a * a + b * b); }
  // Back onto a strength `limit` along its own direction.
  void scale_to(double limit, double mag) {
    if (plane()) {
      a = std::copysign(limit, a);
    } else {
      const double k = mag > 0.0 ? limit / mag : 0.0;
      a *= k, b *= k;
    }
  }
};

inline double travel(double d1, double d2) {
  return d2 == 0.0 ? std::abs(d1) : std::sqrt(d1 * d1 + d2 * d2);
}

// The first half of a nonlinear law's update: no bond, the shear displacement totals, and the
// normal force from the curve sigma(un) (curve(un, sigma, tangent)) - the incremental trial with
// the tangent at the new displacement, held between zero and the total form: on a stiffening law
// both stay on the curve, and a change of the contact's size never makes the force jump. False,
// with no force, when the joint is open.
template <class Curve>
bool normal_step(double size, double overlap, double dus, double dus2, JointState& s,
                 const Curve& curve) {
  s.flags &= static_cast<uint8_t>(~(kSlipping | kTouching | kBonded));
  const double un = overlap + s.dilation;
  const double dun = un - s.un_prev;
  s.un_prev = un;
  s.shear_disp += dus, s.shear_disp2 += dus2;
  if (un <= 0.0) {
    s.fn = 0.0, s.fs = 0.0, s.fs2 = 0.0;
    return false;
  }
  s.flags |= kTouching;
  double sigma = 0.0, tangent = 0.0;
  curve(un, sigma, tangent);
  s.fn = std::clamp(s.fn + tangent * size * dun, 0.0, sigma * size);
  return true;
}

}  // namespace tessera
