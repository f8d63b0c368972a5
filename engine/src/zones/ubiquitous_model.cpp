// Ubiquitous joints (FLAC's ubiquitous-joint model): a Mohr-Coulomb matrix with a plane of
// weakness of one orientation everywhere in it. The matrix is corrected first; then the stress
// resolved on the plane (normal traction sn, shear traction tau) is checked against the joint's
// Coulomb line tau = c_j - sn tan(phi_j) (tension positive) and cut-off sn = sigma_t, and
// corrected by the flow of the plane: plastic strain lambda (sym(t n) + tan(psi_j) n n) in
// shear (t the shear traction's direction), lambda n n in tension.
#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "zone_law.hpp"

namespace tessera::zone_law {

std::array<std::array<double, 3>, 3> plane_axes(const ZoneProperties& p) {
  if (p.orientation == 2) {
    // 2D: the plane at jangle from x; z (out of the plane of the model) lies in it.
    const double a = p.jangle * kDeg;
    return {{{std::cos(a), std::sin(a), 0.0}, {0.0, 0.0, 1.0}, {-std::sin(a), std::cos(a), 0.0}}};
  }
  if (p.orientation == 3) {
    // 3D: the upward normal from dip and dip direction; the strike, and the line of dip.
    const double d = p.jdip * kDeg, a = p.jdipdir * kDeg;
    const Eigen::Vector3d n(std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d));
    const Eigen::Vector3d strike(std::cos(a), -std::sin(a), 0.0), dip = n.cross(strike);
    return {
        {{strike.x(), strike.y(), strike.z()}, {dip.x(), dip.y(), dip.z()}, {n.x(), n.y(), n.z()}}};
  }
  throw std::invalid_argument("zone material '" + p.name + "' (" + p.model +
                              ") needs its plane: jangle= (2D) or jdip= and jdipdir= (3D)");
}

namespace {
Eigen::Matrix3d tensor(const ZoneStress& s) {
  Eigen::Matrix3d m;
  m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
  return m;
}

// The joint's correction of the stress on its plane; false if the plane holds.
bool joint_correct(const ZoneProperties& p, ZoneStress& s, uint8_t& state) {
  const Eigen::Vector3d n(p.normal[0], p.normal[1], p.normal[2]);
  const Eigen::Matrix3d m = tensor(s);
  const Eigen::Vector3d traction = m * n;
  const double sn = n.dot(traction);
  const Eigen::Vector3d shear = traction - sn * n;
  const double tau = shear.norm();
  const double tphi = std::tan(p.jfriction * kDeg), tpsi = std::tan(p.jdilation * kDeg);
  // The tensile strength cannot exceed the apex of the Coulomb line.
  double st = p.jtension;
  if (tphi > 0) st = std::min(st, p.jcohesion / tphi);
  const double fs = tau + sn * tphi - p.jcohesion;
  const double ft = sn - st;
  if (fs <= 0 && ft <= 0) return false;
  const double a1 = p.bulk + 4.0 * p.shear / 3.0, a2 = p.bulk - 2.0 * p.shear / 3.0;
  // Which failure: the line h = 0 through the corner (st, tau_p) bisects the two regions.
  const double tau_p = p.jcohesion - tphi * st;
  const double alpha_p = std::sqrt(1 + tphi * tphi) - tphi;
  const double h = tau - tau_p - alpha_p * (sn - st);
  const Eigen::Matrix3d nn = n * n.transpose(),
                        iso = a2 * Eigen::Matrix3d::Identity() + 2.0 * p.shear * nn;
  Eigen::Matrix3d ds;
  // Shear: tau drops by G lambda, sn by a1 tan(psi) lambda, onto the line - unless that leaves
  // the plane beyond its cut-off (then the corner, below).
  const double lambda = fs / (p.shear + a1 * tphi * tpsi);
  if (fs > 0 && h > 0 && sn - a1 * tpsi * lambda <= st) {
    const Eigen::Vector3d t = tau > 0 ? Eigen::Vector3d(shear / tau) : Eigen::Vector3d::Zero();
    ds = -lambda * (p.shear * (t * n.transpose() + n * t.transpose()) + tpsi * iso);
    state |= kShearNow | kShearPast;
  } else {
    // Tension: sn back to the cut-off, and a shear traction above the line's strength there
    // (the corner) down to it.
    ds = -(ft / a1) * iso;
    if (tau > std::max(tau_p, 0.0)) {
      const Eigen::Vector3d t = shear / tau;
      ds -= (tau - std::max(tau_p, 0.0)) * (t * n.transpose() + n * t.transpose());
      state |= kShearNow | kShearPast;
    }
    state |= kTensionNow | kTensionPast;
  }
  s.xx += ds(0, 0), s.yy += ds(1, 1), s.zz += ds(2, 2);
  s.xy += ds(0, 1), s.yz += ds(1, 2), s.xz += ds(0, 2);
  return true;
}

class UbiquitousModel final : public ZoneModel {
 public:
  const char* name() const override { return "ubiquitous-joint"; }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    state &= kShearPast | kTensionPast;
    elastic_step(p.bulk, p.shear, de, s);
    // The matrix, then the plane of weakness.
    mohr_coulomb_correct(p.bulk, p.shear, {p.friction, p.cohesion, p.tension, p.dilation}, s,
                         state);
    joint_correct(p, s, state);
  }
};
}  // namespace

const ZoneModel& ubiquitous_model() {
  static const UbiquitousModel model;
  return model;
}

}  // namespace tessera::zone_law
