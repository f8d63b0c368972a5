// The Barton-Bandis joint model: Bandis's hyperbolic normal closure, and Barton's shear strength
// sigma_n tan(phi_r + JRC_mob log10(JCS / sigma_n)) (phi_r + JRC log10(JCS / sigma_n) at most 70
// degrees) with the roughness mobilised along his
// dimensionless curve of plastic shear displacement over the displacement at peak, dilating at
// half the mobilised roughness angle.
#include <array>
#include <numbers>
#include <stdexcept>
#include <string>

#include "nonlinear_laws.hpp"
#include "tessera/core/angles.hpp"

namespace tessera {

namespace {

// Barton's cap on the mobilised friction angle phi_r + i (degrees).
constexpr double kMaxAngle = 70.0;

// Barton (1982): JRC_mob / JRC_peak against delta / delta_peak; the first row is where the
// mobilised angle is zero (filled in per call), the second where it is phi_r.
constexpr std::array<double, 8> kRatio{0.0, 0.3, 0.6, 1.0, 2.0, 4.0, 10.0, 100.0};
constexpr std::array<double, 8> kMobilised{0.0, 0.0, 0.75, 1.0, 0.85, 0.70, 0.50, 0.0};

// The closure at which the hyperbola's tangent kn / (1 - u/vm)^2 reaches the cap, and its stress.
double kn_cap(const JointProperties& p) {
  return p.kn_cap > 0.0 ? p.kn_cap : 10.0 * p.kn;
}
double u_cap(const JointProperties& p) {
  return p.vm * (1.0 - std::sqrt(p.kn / kn_cap(p)));
}

// Bandis: sigma_n = kn u / (1 - u / vm), then linear at the cap; the tangent.
void closure_curve(const JointProperties& p, double un, double& sigma, double& tangent) {
  const double uc = u_cap(p);
  const double u = std::min(un, uc), r = 1.0 - u / p.vm;
  sigma = p.kn * u / r, tangent = p.kn / (r * r);
  if (un > uc) sigma += tangent * (un - uc);
}

class BartonBandisLaw final : public JointLaw {
 public:
  const char* name() const override { return "barton-bandis"; }
  bool divides_strength() const override { return true; }

  void check(const JointProperties& j) const override {
    const std::string at = "joint '" + j.name + "': ";
    if (!(j.jrc >= 0.0 && j.jrc <= 20.0))
      throw std::invalid_argument(at + "jrc must be in [0, 20]");
    if (!(j.jcs > 0.0 && j.vm > 0.0))
      throw std::invalid_argument(at + "jcs (Pa) and vm (m) must be positive");
    if (j.dpeak < 0.0 || !(j.lj > 0.0) || (j.kn_cap != 0.0 && !(j.kn_cap > j.kn)))
      throw std::invalid_argument(
          at + "dpeak cannot be negative, lj must be positive and knmax above kn");
  }

  double closure(const JointProperties& p, double sigma_n) const override {
    if (sigma_n <= 0.0) return 0.0;
    const double uc = u_cap(p), sc = p.kn * uc / (1.0 - uc / p.vm);
    if (sigma_n <= sc) return sigma_n * p.vm / (p.kn * p.vm + sigma_n);
    return uc + (sigma_n - sc) / kn_cap(p);
  }

  void stiffness_bounds(const JointProperties& p, double& kn, double& ks) const override {
    kn = kn_cap(p), ks = p.ks;
  }

  void update(const JointProperties& p, double L, double overlap, double dus, double dus2,
              JointState& s) const override {
    const auto curve = [&](double u, double& sigma, double& tangent) {
      closure_curve(p, u, sigma, tangent);
    };
    if (!normal_step(L, overlap, dus, dus2, s, curve)) return;
    s.fs -= p.ks * L * dus;
    s.fs2 -= p.ks * L * dus2;
    // The strength mobilised at the plastic displacement travelled so far.
    double angle = 0.0, dilation = 0.0;
    mobilised(p, s.fn / L, s.plastic, angle, dilation);
    const double strength = s.fn * std::tan(angle * kDeg) / p.strength_divisor;
    ShearPair fs{s.fs, s.fs2};
    const double mag = fs.norm();
    if (mag <= strength) return;
    const double plastic = (mag - strength) / (p.ks * L);
    fs.scale_to(strength, mag);
    s.flags |= kSlipping;
    s.plastic += plastic;
    s.dilate(std::tan(dilation * kDeg) * plastic * s.dilation_direction(dus, dus2));
  }

  // The mobilised friction and dilation angles (degrees) at normal stress sn after plastic
  // shear `up`: the roughness angle JRC log10(JCS / sn) scaled along Barton's curve.
  static void mobilised(const JointProperties& p, double sn, double up, double& angle,
                        double& dilation) {
    // The roughness angle, at most what keeps phi_r + i within Barton's cap.
    const double i = sn > 0.0 && sn < p.jcs ? std::clamp(p.jrc * std::log10(p.jcs / sn), 0.0,
                                                         std::max(0.0, kMaxAngle - p.friction))
                                            : 0.0;
    // (No displacement at peak - JRC 0 - leaves phi_r from the start.)
    const double r = p.peak_disp > 0.0 ? up / p.peak_disp : kRatio.back();
    double m = 0.0;  // JRC_mob / JRC above the row at 0.3; the angle itself below it
    if (r < kRatio[1]) {
      angle = p.friction * r / kRatio[1];
      dilation = 0.0;
      return;
    }
    if (r < kRatio.back()) {
      size_t k = 1;
      while (r >= kRatio[k + 1]) ++k;
      const double t = (r - kRatio[k]) / (kRatio[k + 1] - kRatio[k]);
      m = kMobilised[k] + t * (kMobilised[k + 1] - kMobilised[k]);
    }
    angle = p.friction + m * i;
    dilation = 0.5 * m * i;
  }
};

const BartonBandisLaw kBartonBandis;

}  // namespace

const JointLaw& barton_bandis_law() {
  return kBartonBandis;
}

}  // namespace tessera
