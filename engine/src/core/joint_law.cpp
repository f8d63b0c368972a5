#include "tessera/core/joint_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nonlinear_laws.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/plugin.hpp"

namespace tessera {

namespace {

// Linear stiffness, Coulomb slip, cohesion and tensile strength lost for good on failure (or,
// as coulomb-residual, a residual cohesion and friction after a shear failure), dilation while
// slipping (up to an optional shear displacement).
class CoulombLaw final : public JointLaw {
 public:
  // residual: a failed bond keeps the residual cohesion and friction (law=coulomb-residual).
  explicit CoulombLaw(bool residual) : residual_(residual) {}
  const char* name() const override { return residual_ ? "coulomb-residual" : "coulomb"; }
  void update(const JointProperties& p, double L, double overlap, double dus, double dus2,
              JointState& s) const override {
    const bool bonded = s.flags & kBonded;
    s.flags &= static_cast<uint8_t>(~(kSlipping | kTouching));
    const double un = overlap + s.dilation;
    const double dun = un - s.un_prev;
    s.un_prev = un;
    // Open and unbonded: no force, and shear history is forgotten.
    if (!bonded && un <= 0.0) {
      s.fn = 0.0, s.fs = 0.0, s.fs2 = 0.0;
      return;
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
      return;
    }
    s.fs -= p.ks * L * dus;
    s.fs2 -= p.ks * L * dus2;
    s.shear_disp += dus;
    s.shear_disp2 += dus2;
    // Shear magnitude (the 2D form has one component and stays exact).
    const bool plane = s.fs2 == 0.0;
    const double mag = plane ? std::abs(s.fs) : std::sqrt(s.fs * s.fs + s.fs2 * s.fs2);
    // The strength: a bond's peak; a failed one's residual (coulomb-residual); else friction.
    const bool residual = residual_ && (s.flags & kBroken);
    double limit = bonded     ? p.cohesion * L + s.fn * p.tan_friction
                   : residual ? p.residual_cohesion * L + s.fn * p.tan_residual
                              : s.fn * p.tan_friction;
    if (mag > std::max(limit, 0.0)) {
      // Shear failure of a bond leaves friction only.
      if (bonded) {
        s.flags = static_cast<uint8_t>((s.flags & ~kBonded) | kBroken);
        s.fn = std::max(s.fn, 0.0);
        limit = residual_ ? p.residual_cohesion * L + s.fn * p.tan_residual : s.fn * p.tan_friction;
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
        s.dilation +=
            p.tan_dilation * (dus2 == 0.0 ? std::abs(dus) : std::sqrt(dus * dus + dus2 * dus2));
    }
  }

 private:
  bool residual_;
};

const CoulombLaw kCoulomb(false), kCoulombResidual(true);
const JointLaw* const kLaws[] = {&kCoulomb, &kCoulombResidual, &cy_law(), &barton_bandis_law()};

}  // namespace

const JointLaw* find_joint_law(const std::string& name) {
  for (const JointLaw* l : kLaws)
    if (name == l->name()) return l;
  return plugin_joint_law(name);
}

std::vector<std::string> joint_law_names() {
  std::vector<std::string> out;
  for (const JointLaw* l : kLaws) out.emplace_back(l->name());
  for (std::string& n : plugin_law_names(false)) out.push_back(std::move(n));
  return out;
}

Dashpot contact_dashpot(const JointProperties& p, double size, double share, double m_eff,
                        double closing, double sliding, double sliding2, bool slipping) {
  Dashpot d;
  if (!(m_eff > 0.0) || !(share > 0.0)) return d;
  const double m = m_eff * share;
  d.fn = 2.0 * p.normal_damping * std::sqrt(p.kn * size * m) * closing;
  if (!slipping) {
    const double cs = 2.0 * p.shear_damping * std::sqrt(p.ks * size * m);
    d.fs = -cs * sliding, d.fs2 = -cs * sliding2;
  }
  return d;
}

void JointProperties::finalize() {
  impl = find_joint_law(law);
  if (!impl) throw std::invalid_argument("unknown joint law '" + law + "'");
  impl->check(*this);
  tan_friction = std::tan(friction * std::numbers::pi / 180.0);
  tan_dilation = std::tan(dilation * std::numbers::pi / 180.0);
  tan_residual = residual_friction < 0.0 ? tan_friction
                                         : std::tan(residual_friction * std::numbers::pi / 180.0);
  phi_initial = initial_friction < 0.0 ? friction : initial_friction;
  peak_disp = dpeak > 0.0 ? dpeak : lj / 500.0 * std::pow(jrc / lj, 0.33);
  impl->stiffness_bounds(*this, kn_max, ks_max);
}

}  // namespace tessera
