// Transversely isotropic elasticity: moduli E1 in the plane of isotropy and E3 normal to it,
// Poisson's ratios nu12 (in the plane) and nu13, shear modulus G13 across it. The stiffness in
// x, y, z is made once (ZoneProperties::finalize) by rotating unit strains into the plane's
// axes; a step adds it times the strain increment.
#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "zone_law.hpp"

namespace tessera::zone_law {

namespace {
// Voigt order xx, yy, zz, yz, xz, xy with engineering shears, to and from tensors.
constexpr int kRow[6] = {0, 1, 2, 1, 0, 0}, kCol[6] = {0, 1, 2, 2, 2, 1};

Eigen::Matrix3d strain_tensor(const Eigen::Matrix<double, 6, 1>& v) {
  Eigen::Matrix3d e;
  for (int k = 0; k < 6; ++k) {
    const double f = k < 3 ? 1.0 : 0.5;
    e(kRow[k], kCol[k]) = f * v[k], e(kCol[k], kRow[k]) = f * v[k];
  }
  return e;
}

Eigen::Matrix<double, 6, 1> engineering(const Eigen::Matrix3d& e) {
  Eigen::Matrix<double, 6, 1> v;
  for (int k = 0; k < 6; ++k) v[k] = (k < 3 ? 1.0 : 2.0) * e(kRow[k], kCol[k]);
  return v;
}

Eigen::Matrix<double, 6, 1> stress_voigt(const Eigen::Matrix3d& s) {
  Eigen::Matrix<double, 6, 1> v;
  for (int k = 0; k < 6; ++k) v[k] = s(kRow[k], kCol[k]);
  return v;
}
}  // namespace

void anisotropic_stiffness(ZoneProperties& p) {
  const std::string what = "zone material '" + p.name + "' (transversely-isotropic)";
  if (!(p.e1 > 0 && p.e3 > 0 && p.g13 > 0))
    throw std::invalid_argument(what + " needs E1, E3 and G13 above zero");
  // Compliance in the plane's axes (1, 2 in it, 3 normal): Voigt 11, 22, 33, 23, 13, 12.
  Eigen::Matrix<double, 6, 6> compliance = Eigen::Matrix<double, 6, 6>::Zero();
  compliance(0, 0) = compliance(1, 1) = 1.0 / p.e1, compliance(2, 2) = 1.0 / p.e3;
  compliance(0, 1) = compliance(1, 0) = -p.nu12 / p.e1;
  compliance(0, 2) = compliance(2, 0) = compliance(1, 2) = compliance(2, 1) = -p.nu13 / p.e1;
  compliance(3, 3) = compliance(4, 4) = 1.0 / p.g13;
  compliance(5, 5) = 2.0 * (1.0 + p.nu12) / p.e1;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> check(compliance);
  if (!(check.eigenvalues().minCoeff() > 0))
    throw std::invalid_argument(what + ": E1, E3, nu12, nu13 make no stable material (need " +
                                "-1 < nu12 < 1 and nu13^2 < (1 - nu12) E1 / (2 E3))");
  const Eigen::Matrix<double, 6, 6> local = compliance.inverse();
  // Rows of r: the plane's axes in x, y, z.
  const auto axes = plane_axes(p);
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) r(i, k) = axes[static_cast<size_t>(i)][static_cast<size_t>(k)];
  // Column j: the stress of unit strain j, through the plane's axes and back.
  Eigen::Matrix<double, 6, 6> d;
  for (int j = 0; j < 6; ++j) {
    const Eigen::Matrix3d e =
        r * strain_tensor(Eigen::Matrix<double, 6, 1>::Unit(j)) * r.transpose();
    const Eigen::Matrix<double, 6, 1> sl = local * engineering(e);
    Eigen::Matrix3d s;
    for (int k = 0; k < 6; ++k) s(kRow[k], kCol[k]) = sl[k], s(kCol[k], kRow[k]) = sl[k];
    d.col(j) = stress_voigt(r.transpose() * s * r);
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) p.stiffness[static_cast<size_t>(6 * i + j)] = d(i, j);
  // The bounding isotropic moduli from the largest eigenvalue in Mandel's form.
  Eigen::Matrix<double, 6, 1> w;
  w << 1, 1, 1, std::sqrt(2.0), std::sqrt(2.0), std::sqrt(2.0);
  const Eigen::Matrix<double, 6, 6> mandel = w.asDiagonal() * local * w.asDiagonal();
  const double largest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(mandel).eigenvalues().maxCoeff();
  p.bulk = largest / 3.0, p.shear = largest / 2.0;
}

namespace {
Eigen::Matrix<double, 6, 6> stiffness_of(const ZoneProperties& p) {
  Eigen::Matrix<double, 6, 6> d;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) d(i, j) = p.stiffness[static_cast<size_t>(6 * i + j)];
  return d;
}

class AnisotropicModel final : public ZoneModel {
 public:
  const char* name() const override { return "transversely-isotropic"; }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    const double e[6] = {de.xx, de.yy, de.zz, 2 * de.yz, 2 * de.xz, 2 * de.xy};
    double ds[6] = {};
    for (size_t i = 0; i < 6; ++i)
      for (size_t j = 0; j < 6; ++j) ds[i] += p.stiffness[6 * i + j] * e[j];
    s.xx += ds[0], s.yy += ds[1], s.zz += ds[2], s.yz += ds[3], s.xz += ds[4], s.xy += ds[5];
    state &= kShearPast | kTensionPast;
  }
};
}  // namespace

const ZoneModel& anisotropic_model() {
  static const AnisotropicModel model;
  return model;
}

}  // namespace tessera::zone_law

namespace tessera {

double plane_strain_zz(const ZoneProperties& p, const ZoneStress& s) {
  if (p.model != "transversely-isotropic") {
    const double nu = (3 * p.bulk - 2 * p.shear) / (2 * (3 * p.bulk + p.shear));
    return nu * (s.xx + s.yy);
  }
  // ezz = 0: the compliance's z row on sxx, syy, sxy and szz.
  const Eigen::Matrix<double, 6, 6> c = zone_law::stiffness_of(p).inverse();
  return -(c(2, 0) * s.xx + c(2, 1) * s.yy + c(2, 5) * s.xy) / c(2, 2);
}

}  // namespace tessera
