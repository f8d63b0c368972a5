// The Coulomb joint law's update, inline so that the 2D and 3D cycles call it directly for the
// joint sets that use it (nearly every model) instead of through the law's virtual call; the
// registered law (joint_law.cpp) runs the same code.
#pragma once

#include <algorithm>
#include <cmath>

#include "tessera/core/joint_law.hpp"

namespace tessera {

// The registered Coulomb laws: plain, and with a residual strength after shear failure.
const JointLaw& coulomb_law(bool residual);

// Linear stiffness, Coulomb slip, cohesion and tensile strength lost for good on failure (or,
// residual, a residual cohesion and friction after a shear failure), dilation while slipping
// (up to an optional shear displacement). Plane: one shear component (2D); the general form with
// dus2 = 0 and fs2 = 0 gives the same numbers, this one skips the second component's arithmetic.
// Returns the shear force's magnitude after the update (s.shear(), bit for bit: the caller that
// sums it need not take the square root again).
template <bool Plane>
inline double coulomb_update(const JointProperties& p, bool residual_law, double L, double overlap,
                             double dus, double dus2, JointState& s) {
  const bool bonded = s.flags & kBonded;
  s.flags &= static_cast<uint8_t>(~(kSlipping | kTouching));
  const double un = overlap + s.dilation;
  const double dun = un - s.un_prev;
  s.un_prev = un;
  // Open and unbonded: no force, and shear history is forgotten.
  if (!bonded && un <= 0.0) {
    s.fn = 0.0, s.fs = 0.0, s.fs2 = 0.0;
    return 0.0;
  }
  s.flags |= kTouching;
  // Incremental normal force, held between zero (or the bond) and the total-form value.
  const double kn = p.kn * L, total = kn * un;
  const double trial = s.fn + kn * dun;
  if (!bonded)
    s.fn = std::clamp(trial, 0.0, total);
  else
    s.fn = un >= 0.0 ? std::min(trial, total) : std::max(trial, total);
  // Tensile failure breaks the bond for good.
  if (bonded && s.fn < -p.tension * L) {
    s.flags = static_cast<uint8_t>((s.flags & ~(kBonded | kTouching)) | kBroken);
    s.fn = 0.0, s.fs = 0.0, s.fs2 = 0.0;
    return 0.0;
  }
  s.fs -= p.ks * L * dus;
  s.shear_disp += dus;
  if constexpr (!Plane) {
    s.fs2 -= p.ks * L * dus2;
    s.shear_disp2 += dus2;
  }
  // Shear magnitude (the 2D form has one component and stays exact; with fs2 = 0 the square root
  // of fs^2 is |fs| exactly, so the value is s.shear()'s).
  const bool plane = Plane || s.fs2 == 0.0;
  const double mag = plane ? std::abs(s.fs) : std::sqrt(s.fs * s.fs + s.fs2 * s.fs2);
  // The strength: a bond's peak; a failed one's residual (coulomb-residual); else friction.
  const bool residual = residual_law && (s.flags & kBroken);
  double limit = bonded     ? p.cohesion * L + s.fn * p.tan_friction
                 : residual ? p.residual_cohesion * L + s.fn * p.tan_residual
                            : s.fn * p.tan_friction;
  if (mag > std::max(limit, 0.0)) {
    // Shear failure of a bond leaves friction only.
    if (bonded) {
      s.flags = static_cast<uint8_t>((s.flags & ~kBonded) | kBroken);
      s.fn = std::max(s.fn, 0.0);
      limit =
          residual_law ? p.residual_cohesion * L + s.fn * p.tan_residual : s.fn * p.tan_friction;
    }
    // Back to the slip surface along the trial shear's direction.
    if (plane) {
      s.fs = std::copysign(std::max(limit, 0.0), s.fs);
    } else {
      const double scale = std::max(limit, 0.0) / mag;
      s.fs *= scale, s.fs2 *= scale;
    }
    s.flags |= kSlipping;
    const double travel =
        plane ? std::abs(s.shear_disp)
              : std::sqrt(s.shear_disp * s.shear_disp + s.shear_disp2 * s.shear_disp2);
    if (p.tan_dilation > 0.0 && (p.dilation_limit <= 0.0 || travel < p.dilation_limit))
      s.dilate(p.tan_dilation * s.dilation_direction(dus, dus2) *
               (Plane || dus2 == 0.0 ? std::abs(dus) : std::sqrt(dus * dus + dus2 * dus2)));
    return s.shear();
  }
  return mag;
}

// The law of joint set p on one contact: the Coulomb laws inline, any other through its class.
// Returns the shear force's magnitude after the update (s.shear()).
template <bool Plane>
inline double joint_update(const JointProperties& p, double size, double overlap, double dus,
                           double dus2, JointState& s) {
  if (p.inline_coulomb >= 0)
    return coulomb_update<Plane>(p, p.inline_coulomb == 1, size, overlap, dus, dus2, s);
  p.impl->update(p, size, overlap, dus, dus2, s);
  return s.shear();
}

}  // namespace tessera
