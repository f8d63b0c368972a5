// The continuously yielding joint model (Cundall and Lemos, 1990; UDEC's and 3DEC's CY law):
// normal and shear stiffness growing with normal stress, a bounding strength sigma_n tan phi_m
// that the shear stress approaches smoothly, phi_m decaying from the initial friction to the
// basic one with plastic shear, and dilation at the angle the stress ratio stands above basic
// friction.
#include <numbers>
#include <stdexcept>
#include <string>

#include "nonlinear_laws.hpp"
#include "tessera/core/angles.hpp"

namespace tessera {

namespace {

// The normal stress limit beyond which the stiffnesses stop growing.
double stress_cap(const JointProperties& p) {
  return p.smax > 0.0 ? p.smax : 10.0 * p.sref;
}

// Normal stress of dsigma/dun = kn (sigma/sref)^en from zero, linear past the cap; the tangent.
void normal_curve(const JointProperties& p, double un, double& sigma, double& tangent) {
  if (p.en == 0.0) {
    sigma = p.kn * un, tangent = p.kn;
    return;
  }
  const double cap = stress_cap(p), e1 = 1.0 - p.en;
  const double u_cap = p.sref * std::pow(cap / p.sref, e1) / (e1 * p.kn);
  const double k_cap = p.kn * std::pow(cap / p.sref, p.en);
  if (un >= u_cap) {
    sigma = cap + k_cap * (un - u_cap), tangent = k_cap;
    return;
  }
  sigma = p.sref * std::pow(e1 * p.kn * un / p.sref, 1.0 / e1);
  tangent = p.kn * std::pow(sigma / p.sref, p.en);
}

class CyLaw final : public JointLaw {
 public:
  const char* name() const override { return "cy"; }
  bool divides_strength() const override { return true; }

  void check(const JointProperties& j) const override {
    const std::string at = "joint '" + j.name + "': ";
    if (!(j.en >= 0.0 && j.en < 1.0 && j.es >= 0.0 && j.es < 1.0))
      throw std::invalid_argument(at + "the exponents en and es must be in [0, 1)");
    if (!(j.sref > 0.0) || j.smax < 0.0)
      throw std::invalid_argument(at + "sref must be positive and smax not negative");
    if (j.initial_friction >= 90.0 ||
        (j.initial_friction >= 0.0 && j.initial_friction < j.friction))
      throw std::invalid_argument(at + "ifriction must lie between friction and 90 degrees");
    if (j.roughness < 0.0 || (j.initial_friction > j.friction && !(j.roughness > 0.0)))
      throw std::invalid_argument(
          at + "roughness (m) must be positive when ifriction is above friction");
  }

  double closure(const JointProperties& p, double sigma_n) const override {
    if (p.en == 0.0 || sigma_n <= 0.0) return sigma_n / p.kn;
    const double cap = stress_cap(p), e1 = 1.0 - p.en;
    const double s = std::min(sigma_n, cap);
    const double un = p.sref * std::pow(s / p.sref, e1) / (e1 * p.kn);
    return un + (sigma_n - s) / (p.kn * std::pow(cap / p.sref, p.en));
  }

  void stiffness_bounds(const JointProperties& p, double& kn, double& ks) const override {
    const double r = stress_cap(p) / p.sref;
    kn = p.kn * std::pow(r, p.en), ks = p.ks * std::pow(r, p.es);
  }

  void update(const JointProperties& p, double L, double overlap, double dus, double dus2,
              JointState& s) const override {
    const auto curve = [&](double u, double& sigma, double& tangent) {
      normal_curve(p, u, sigma, tangent);
    };
    if (!normal_step(L, overlap, dus, dus2, s, curve)) return;
    const double sn = s.fn / L;
    const double ks =
        p.es == 0.0 ? p.ks : p.ks * std::pow(std::min(sn, stress_cap(p)) / p.sref, p.es);
    // The bounding strength: phi_m from its initial value towards basic friction.
    const double phi_m = p.roughness > 0.0 ? p.friction + (p.phi_initial - p.friction) *
                                                              std::exp(-s.plastic / p.roughness)
                                           : p.phi_initial;
    const double bound = s.fn * std::tan(phi_m * kDeg) / p.strength_divisor;
    ShearPair fs{s.fs, s.fs2};
    const double step = travel(dus, dus2);
    // No normal force, no shear strength: all the shear is plastic.
    if (!(bound > 0.0)) {
      s.fs = 0.0, s.fs2 = 0.0;
      s.plastic += step;
      s.flags |= kSlipping;
      return;
    }
    // Loading (the increment pushes the shear force further along itself): the stiffness times
    // F = 1 - |tau| / tau_m, the rest of the displacement plastic; unloading is elastic (F = 1).
    const bool loading = s.fs * dus + s.fs2 * dus2 <= 0.0;
    const double F = loading ? std::clamp(1.0 - fs.norm() / bound, 0.0, 1.0) : 1.0;
    double plastic = (1.0 - F) * step;
    s.fs -= F * ks * L * dus;
    s.fs2 -= F * ks * L * dus2;
    // Never above the bound: where it has fallen (roughness worn, normal stress dropped) the
    // stress follows it down, the elastic displacement given up becoming plastic.
    const double mag = fs.norm();
    if (mag > bound) {
      if (ks > 0.0) plastic += (mag - bound) / (ks * L);
      fs.scale_to(bound, mag);
    }
    if (fs.norm() >= 0.99 * bound) s.flags |= kSlipping;
    s.plastic += plastic;
    // Dilation at the angle the stress ratio stands above basic friction.
    if (plastic > 0.0 && s.fn > 0.0) {
      const double i = std::atan(fs.norm() * p.strength_divisor / s.fn) - p.friction * kDeg;
      if (i > 0.0) s.dilate(std::tan(i) * plastic * s.dilation_direction(dus, dus2));
    }
  }
};

const CyLaw kCy;

}  // namespace

const JointLaw& cy_law() {
  return kCy;
}

}  // namespace tessera
