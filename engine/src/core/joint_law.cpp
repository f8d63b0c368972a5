#include "tessera/core/joint_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "coulomb_law.hpp"
#include "nonlinear_laws.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/plugin.hpp"

namespace tessera {

namespace {

// The Coulomb law (coulomb_law.hpp), registered as "coulomb" and "coulomb-residual".
class CoulombLaw final : public JointLaw {
 public:
  // residual: a failed bond keeps the residual cohesion and friction (law=coulomb-residual).
  explicit CoulombLaw(bool residual) : residual_(residual) {}
  const char* name() const override { return residual_ ? "coulomb-residual" : "coulomb"; }
  void update(const JointProperties& p, double L, double overlap, double dus, double dus2,
              JointState& s) const override {
    coulomb_update<false>(p, residual_, L, overlap, dus, dus2, s);
  }

 private:
  bool residual_;
};

const CoulombLaw kCoulomb(false), kCoulombResidual(true);
const JointLaw* const kLaws[] = {&kCoulomb, &kCoulombResidual, &cy_law(), &barton_bandis_law()};

}  // namespace

const JointLaw& coulomb_law(bool residual) {
  return residual ? kCoulombResidual : kCoulomb;
}

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
  inline_coulomb = impl == &kCoulomb ? 0 : impl == &kCoulombResidual ? 1 : -1;
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
