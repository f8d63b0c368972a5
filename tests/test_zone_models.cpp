// Strain-softening, ubiquitous-joint and transversely isotropic zones against closed forms: at a
// material point (the model's update driven along a stress path, lateral stresses held by
// Newton iterations on the strain) and in zoned blocks run by scripts. Softening: the axial
// stress at yield in triaxial compression is the Mohr-Coulomb strength of the tables' cohesion
// and friction at the accumulated plastic shear strain. Ubiquitous joints: the strength against
// the joint's angle follows Jaeger's single plane of weakness where the joint governs, the
// matrix strength elsewhere. Transverse isotropy: strains of uniaxial stress along, across and
// at 45 degrees to the plane of isotropy follow the rotated compliance (plane strain in 2D).
// Script runs: zoned samples hold 2% below their closed-form strength and fail 2% above it; a
// transversely isotropic square and cube strain as the compliance says; the plastic strain is
// written to VTK and kept by state files (also at a quadratic zone's integration points).
// 3D Mohr-Coulomb's shortcut past the eigen-decomposition skips no stress outside its surface.
#include <Eigen/Dense>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "support.hpp"
#include "tessera/zones/zone_model.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
constexpr double kDeg = std::numbers::pi / 180;

// Components in the structs' order: xx, yy, xy, zz, yz, xz.
double& at(ZoneStress& s, int k) {
  double* v[6] = {&s.xx, &s.yy, &s.xy, &s.zz, &s.yz, &s.xz};
  return *v[k];
}
double& at(StrainIncrement& e, int k) {
  double* v[6] = {&e.xx, &e.yy, &e.xy, &e.zz, &e.yz, &e.xz};
  return *v[k];
}
enum { XX, YY, XY, ZZ, YZ, XZ };

// A material point: stress, state and history, driven by strain increments in which the
// `given` components take the given values, the `held` ones are solved for so that their
// stresses reach `target`, and the rest stay zero (plane strain in 2D: zz, yz, xz).
struct Point {
  const ZoneProperties& p;
  ZoneStress s;
  uint8_t state = 0;
  double history = 0;

  // Runs the model on increment `de` from the current state, into copies (a trial).
  ZoneStress trial(const StrainIncrement& de) const {
    ZoneStress t = s;
    uint8_t st = state;
    double h = history;
    p.impl->update(p, de, t, st, h);
    return t;
  }
  // One step: Newton on the held strains with a finite-difference Jacobian (the returns are
  // piecewise linear in the strain, so it lands in one or two iterations), then the real update;
  // returns the increment applied.
  StrainIncrement step(const std::vector<std::pair<int, double>>& given,
                       const std::vector<int>& held, const std::vector<double>& target) {
    const auto n = static_cast<Eigen::Index>(held.size());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const auto increment = [&](const Eigen::VectorXd& v) {
      StrainIncrement de;
      for (auto [k, d] : given) at(de, k) = d;
      for (Eigen::Index i = 0; i < n; ++i) at(de, held[static_cast<size_t>(i)]) = v[i];
      return de;
    };
    const auto residual = [&](const Eigen::VectorXd& v) {
      ZoneStress t = trial(increment(v));
      Eigen::VectorXd r(n);
      for (Eigen::Index i = 0; i < n; ++i)
        r[i] = at(t, held[static_cast<size_t>(i)]) - target[static_cast<size_t>(i)];
      return r;
    };
    for (int it = 0; it < 30; ++it) {
      const Eigen::VectorXd r = residual(x);
      if (r.cwiseAbs().maxCoeff() < 1e-4) break;  // Pa
      Eigen::MatrixXd j(n, n);
      const double eps = 1e-8;
      for (Eigen::Index c = 0; c < n; ++c) {
        Eigen::VectorXd y = x;
        y[c] += eps;
        j.col(c) = (residual(y) - r) / eps;
      }
      x -= j.fullPivLu().solve(r);
    }
    const StrainIncrement de = increment(x);
    p.impl->update(p, de, s, state, history);
    return de;
  }
};

std::array<double, 3> principal(const ZoneStress& s) {
  return principal_3d(s).s;
}

double nphi(double deg) {
  const double sn = std::sin(deg * kDeg);
  return (1 + sn) / (1 - sn);
}

// Mohr-Coulomb strength (compression positive) at confinement s3.
double coulomb(double s3, double c, double phi) {
  return s3 * nphi(phi) + 2 * c * std::sqrt(nphi(phi));
}

// Jaeger's single plane of weakness: the axial stress at which the plane slips, its normal at
// beta to the axis (compression positive); infinite where it cannot slip.
double jaeger(double s3, double cj, double phij, double beta) {
  const double t = std::tan(phij * kDeg), b = beta * kDeg;
  const double d = (1 - t / std::tan(b)) * std::sin(2 * b);
  if (!(beta > phij && beta < 90 && d > 0)) return 1e300;
  return s3 + 2 * (cj + s3 * t) / d;
}

// Triaxial (3D: axial z) or plane-strain biaxial (2D: axial y) loading: the strains solved for
// (held) and the stresses they keep, the confinement s3 across the axis and no shear.
struct Confined {
  int axial;
  std::vector<int> held;
  std::vector<double> target;
};
Confined confined(int dims, double s3) {
  if (dims == 2) return {YY, {XX, XY}, {-s3, 0}};
  return {ZZ, {XX, YY, XY, YZ, XZ}, {-s3, -s3, 0, 0, 0}};
}

ZoneProperties base(const std::string& model) {
  ZoneProperties p;
  p.name = "rock";
  p.model = model;
  p.density = 2600;
  elastic_from_young(10e9, 0.25, p.bulk, p.shear);
  return p;
}

// The transversely isotropic test material: plane of isotropy stiffer.
constexpr double kE1 = 20e9, kE3 = 5e9, kNu12 = 0.2, kNu13 = 0.25, kG13 = 3e9;

ZoneProperties transverse(int dims, double a, double b = 0) {
  ZoneProperties p = base("transversely-isotropic");
  p.bulk = p.shear = 0;
  p.e1 = kE1, p.e3 = kE3, p.nu12 = kNu12, p.nu13 = kNu13, p.g13 = kG13;
  p.orientation = static_cast<uint8_t>(dims);
  if (dims == 2) p.jangle = a;
  if (dims == 3) p.jdip = a, p.jdipdir = b;
  p.finalize();
  return p;
}

// Compliance of the transversely isotropic material in its own axes (1, 2 in the plane, 3
// normal), engineering shears in the order 23, 13, 12.
Eigen::Matrix<double, 6, 6> local_compliance() {
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Zero();
  s(0, 0) = s(1, 1) = 1 / kE1, s(2, 2) = 1 / kE3;
  s(0, 1) = s(1, 0) = -kNu12 / kE1;
  s(0, 2) = s(2, 0) = s(1, 2) = s(2, 1) = -kNu13 / kE1;
  s(3, 3) = s(4, 4) = 1 / kG13, s(5, 5) = 2 * (1 + kNu12) / kE1;
  return s;
}

// Lekhnitskii's modulus along a direction at theta to the normal of the plane of isotropy.
double directional_modulus(double theta) {
  const double c = std::cos(theta * kDeg), s = std::sin(theta * kDeg);
  return 1 / (std::pow(s, 4) / kE1 + std::pow(c, 4) / kE3 +
              (1 / kG13 - 2 * kNu13 / kE1) * s * s * c * c);
}

// Its plane-strain counterpart when the out-of-plane axis z lies in the plane of isotropy (2D
// zones): the reduced compliances S'ij = Sij - Si2 S2j / S22 in the model's plane.
double plane_strain_modulus(double theta) {
  const double c = std::cos(theta * kDeg), s = std::sin(theta * kDeg);
  const double s11 = (1 - kNu12 * kNu12) / kE1, s33 = 1 / kE3 - kNu13 * kNu13 / kE1;
  const double s13 = -kNu13 * (1 + kNu12) / kE1;
  return 1 / (std::pow(s, 4) * s11 + std::pow(c, 4) * s33 + (2 * s13 + 1 / kG13) * s * s * c * c);
}

// An axial boundary stress (compression, Pa) on the top of the sample below, added to the loads.
std::string axial_stress(double s) {
  return "boundary stress=0," + std::to_string(-s) + ",0 y=1.95,2.05\n";
}

// A 1 x 2 m zoned sample of rock with the given zone model (plane strain): rollers at its foot
// (one node held in x), a lateral boundary stress of 2 MPa and an axial one of `axial` Pa
// (compression; 0: none yet), the top's settlement recorded as "uy".
std::string sample(const std::string& model, double axial) {
  return "round 0.01\nmaterial define rock density=2600 E=10e9 nu=0.25 " + model +
         "\nblock 0,0 1,0 1,2 0,2 material=rock\nzone generate edge=0.25\n"
         "boundary fix=y y=-0.001,0.001\nboundary fix=x x=-0.001,0.001 y=-0.001,0.001\n"
         "boundary stress=-2e6,0,0 x=-0.001,0.001\nboundary stress=-2e6,0,0 x=0.999,1.001\n" +
         (axial > 0 ? axial_stress(axial) : std::string()) + "history ydisp at=1,2 label=uy\n";
}

double last(const Model& m, const std::string& label) {
  const Histories& h = m.histories;
  return h.at(h.rows() - 1, static_cast<size_t>(h.find(label)));
}
}  // namespace

class TestZoneModels : public QObject {
  Q_OBJECT
 private slots:
  void tableValues() {
    const std::vector<double> t{0, 2e6, 0.01, 0.5e6, 0.02, 0.4e6};
    QCOMPARE(table_value(t, 0.0, 9), 2e6);
    QCOMPARE(table_value(t, 0.005, 9), 1.25e6);
    QCOMPARE(table_value(t, 0.015, 9), 0.45e6);
    QCOMPARE(table_value(t, 1.0, 9), 0.4e6);  // beyond the end the last value holds
    QCOMPARE(table_value({}, 0.5, 9), 9.0);
    ZoneProperties p = base("strain-softening");
    p.ctable = {0, 2e6, 0.01, 0.5e6, 0.005, 0.4e6};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, p.finalize());
    p.ctable = {0, 2e6, 0.01};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, p.finalize());
    p.ctable = {0, 2e6, 0.01, -1};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, p.finalize());
  }

  // A model written for the four-argument update (a plug-in from before histories) is what the
  // zone loops' five-argument call runs; the history is left alone.
  void modelsWithoutHistoryStillWork() {
    struct Old final : ZoneModel {
      const char* name() const override { return "old"; }
      void update(const ZoneProperties&, const StrainIncrement& de, ZoneStress& s,
                  uint8_t& state) const override {
        s.xx += de.xx, state = 7;
      }
    };
    const Old old;
    const ZoneModel& m = old;
    ZoneStress s;
    uint8_t state = 0;
    double history = 0.25;
    m.update(base("elastic"), {1.0}, s, state, history);
    QCOMPARE(s.xx, 1.0);
    QCOMPARE(state, uint8_t(7));
    QCOMPARE(history, 0.25);
  }

  // 3D Mohr-Coulomb skips the eigen-decomposition of stresses surely inside its surface: no
  // stress outside may be skipped. Rotated principal stresses (two or three of them equal, where
  // the closed-form roots are least accurate) inside, on and outside the shear surface by 1e-7
  // and 1e-5 of the strength, at confinements from tension to 8 MPa: after an update with no
  // strain, every stress inside is untouched and every stress outside has been corrected.
  void mohrCoulombSkipsOnlyElasticStresses() {
    ZoneProperties p = base("mohr-coulomb");
    p.friction = 35, p.cohesion = 1e6, p.tension = 0.4e6, p.dilation = 5;
    p.finalize();
    const double nphi = (1 + std::sin(35 * kDeg)) / (1 - std::sin(35 * kDeg));
    const double shear_cap = 2e6 * std::sqrt(nphi);
    const Eigen::Matrix3d rot = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                                 Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
    int inside = 0, outside = 0;
    for (const double s3 : {-8e6, -2e6, 0.0, 0.3e6}) {
      for (const double mid_share : {0.0, 0.5, 1.0}) {  // s2 at s1, between, at s3
        for (const double off : {-1e-5, -1e-7, 0.0, 1e-7, 1e-5}) {
          // s1 on the shear surface for this s3, moved out by `off` of the strength.
          const double s1 = s3 * nphi - shear_cap - off * shear_cap;
          const double s2 = s1 + mid_share * (s3 - s1);
          const Eigen::Matrix3d m =
              rot * Eigen::Vector3d(s1, s2, s3).asDiagonal() * rot.transpose();
          ZoneStress st{m(0, 0), m(1, 1), m(0, 1), m(2, 2), m(1, 2), m(0, 2)};
          const ZoneStress before = st;
          uint8_t state = 0;
          double history = 0;
          p.impl->update(p, StrainIncrement{}, st, state, history);
          const QString where = QString("s3 %1 share %2 off %3").arg(s3).arg(mid_share).arg(off);
          if (off < 0) {
            ++inside;
            QVERIFY2(state == 0 && st.xx == before.xx && st.xz == before.xz, qPrintable(where));
          } else if (off > 0) {
            ++outside;
            QVERIFY2(state != 0 && st.xx != before.xx, qPrintable(where));
          }
        }
      }
    }
    QCOMPARE(inside, 24);
    QCOMPARE(outside, 24);
  }

  // Triaxial (3D) and biaxial plane-strain (2D) compression at 1 MPa confinement: at every
  // yielding step the principal stresses lie on the Coulomb line of the tables at the plastic
  // shear strain reached before the step (to 1e-6 of the strength), and the axial stress at
  // the peak, halfway down the softening branch and at the residual matches
  // s3 Nphi(e) + 2 c(e) sqrt(Nphi(e)) at the current strain within the lag of one step.
  void strainSofteningFollowsTheTables() {
    ZoneProperties p = base("strain-softening");
    p.friction = 35, p.cohesion = 2e6, p.tension = 1e6;
    p.ctable = {0, 2e6, 0.01, 0.5e6};
    p.ftable = {0, 35, 0.01, 30};
    p.finalize();
    const double s3 = 1e6;
    for (int dims : {2, 3}) {
      Point pt{p, {-s3, -s3, 0, -s3, 0, 0}};
      const auto [axial, held, target] = confined(dims, s3);
      double worst_line = 0, peak = 0, half = 0, residual = 0;
      double half_strain = 0, residual_strain = 0;
      int yielding = 0;
      for (int i = 0; i < 20000 && pt.history < 0.015; ++i) {
        const double before = pt.history;
        pt.step({{axial, -2e-6}}, held, target);
        if (!(pt.state & kShearNow)) continue;
        ++yielding;
        // On the line of the strength at the strain before the step.
        const auto v = principal(pt.s);
        const double phi = table_value(p.ftable, before, 0), c = table_value(p.ctable, before, 0);
        const double fs = v[0] - v[2] * nphi(phi) + 2 * c * std::sqrt(nphi(phi));
        worst_line = std::max(worst_line, std::abs(fs) / coulomb(s3, c, phi));
        const double q = -at(pt.s, axial);
        if (before == 0) peak = std::max(peak, q);
        if (half == 0 && pt.history >= 0.005) half = q, half_strain = pt.history;
        if (pt.history >= 0.012) residual = q, residual_strain = pt.history;
      }
      const double want_peak = coulomb(s3, 2e6, 35);
      const double want_half =
          coulomb(s3, table_value(p.ctable, half_strain, 0), table_value(p.ftable, half_strain, 0));
      const double want_res = coulomb(s3, 0.5e6, 30);
      qInfo(
          "%dD: %d yielding steps, worst |fs| %.2e of the strength; peak %.4f MPa (closed form "
          "%.4f), at e_p = %.5f %.4f (%.4f), residual at e_p = %.4f %.4f (%.4f)",
          dims, yielding, worst_line, peak / 1e6, want_peak / 1e6, half_strain, half / 1e6,
          want_half / 1e6, residual_strain, residual / 1e6, want_res / 1e6);
      QVERIFY(yielding > 100);
      QVERIFY(worst_line < 1e-6);
      QVERIFY(std::abs(peak / want_peak - 1) < 1e-6);
      // One step adds at most ~2e-6 of plastic strain: the tables move 3e-4 of the strength.
      QVERIFY(std::abs(half / want_half - 1) < 1e-3);
      QVERIFY(std::abs(residual / want_res - 1) < 1e-6);
    }
  }

  // Drucker-Prager, matched to Mohr-Coulomb in plane strain (FLAC's q_phi = 3 tan(phi) /
  // sqrt(9 + 12 tan^2 phi) on the mean stress, k_phi = 3 c / sqrt(..)): with associated flow a
  // biaxial test (2D, plane strain; the out-of-plane stress finds its place) fails at the
  // Mohr-Coulomb strength, and a triaxial one (3D, sigma_2 = sigma_3 = p) where
  // (s1 - p) / sqrt(3) - q_phi (s1 + 2 p) / 3 = k_phi: 6.297 MPa at phi = 30 degrees, c = 1 MPa,
  // p = 2 MPa. (An independent check found the friction term a third of FLAC's: 4.76 and
  // 4.20 MPa.)
  void druckerPragerMatchesMohrCoulombInPlaneStrain() {
    for (const double phi : {20.0, 30.0, 40.0}) {
      ZoneProperties p = base("drucker-prager");
      p.friction = phi, p.dilation = phi, p.cohesion = 1e6, p.tension = 1e7;
      p.finalize();
      const double s3 = 2e6, t = std::tan(phi * kDeg), r = std::sqrt(9 + 12 * t * t);
      const double q = 3 * t / r, k = 3 * 1e6 / r;
      const double want_3d =
          (k + s3 / std::sqrt(3.0) + 2 * s3 * q / 3) / (1 / std::sqrt(3.0) - q / 3);
      for (int dims : {2, 3}) {
        Point pt{p, {-s3, -s3, 0, -s3, 0, 0}};
        const auto [axial, held, target] = confined(dims, s3);
        double peak = 0;
        for (int i = 0; i < 4000; ++i) {
          pt.step({{axial, -5e-6}}, held, target);
          peak = std::max(peak, -at(pt.s, axial));
        }
        const double want = dims == 2 ? coulomb(s3, 1e6, phi) : want_3d;
        qInfo("phi %.0f, %dD: peak %.4f MPa, closed form %.4f MPa", phi, dims, peak / 1e6,
              want / 1e6);
        QVERIFY(pt.state & kShearNow);
        // In plane strain the out-of-plane stress reaches its place as the flow sets in.
        QVERIFY(std::abs(peak / want - 1) < (dims == 2 ? 1e-4 : 1e-6));
      }
    }
  }

  // Biaxial (2D, plane strain) and triaxial (3D) strength at 2 MPa confinement against the
  // angle beta between the axis and the joint's normal: Jaeger where the joint slips first,
  // Mohr-Coulomb of the matrix where it does not (beta below phi_j, near 90 degrees).
  void ubiquitousJointFollowsJaeger() {
    ZoneProperties p = base("ubiquitous-joint");
    p.friction = 40, p.cohesion = 5e6, p.tension = 5e6;
    p.jfriction = 25, p.jcohesion = 0.5e6, p.jtension = 0;
    const double s3 = 2e6;
    const double matrix = coulomb(s3, 5e6, 40);
    for (int dims : {2, 3}) {
      int joint_governs = 0, matrix_governs = 0;
      for (double beta : {20.0, 27.0, 30.0, 45.0, 57.5, 70.0, 80.0, 88.0, 90.0}) {
        ZoneProperties q = p;
        q.orientation = static_cast<uint8_t>(dims);
        if (dims == 2) q.jangle = beta;
        if (dims == 3) q.jdip = beta, q.jdipdir = 30;
        q.finalize();
        Point pt{q, {-s3, -s3, 0, -s3, 0, 0}};
        const auto [axial, held, target] = confined(dims, s3);
        double strength = 0;
        for (int i = 0; i < 600; ++i) {
          pt.step({{axial, -1e-5}}, held, target);
          strength = std::max(strength, -at(pt.s, axial));
        }
        const double joint = jaeger(s3, 0.5e6, 25, beta);
        const double want = std::min(joint, matrix);
        (joint < matrix ? joint_governs : matrix_governs)++;
        qInfo("%dD beta %4.1f: strength %8.4f MPa, closed form %8.4f MPa (%s), error %.1e", dims,
              beta, strength / 1e6, want / 1e6, joint < matrix ? "joint" : "matrix",
              strength / want - 1);
        QVERIFY(std::abs(strength / want - 1) < 1e-6);
      }
      QVERIFY(joint_governs >= 5 && matrix_governs >= 3);
    }
  }

  // A stress beyond the joint's corner (tension above the cut-off with shear above the line's
  // strength there) goes back to the corner: sn the cut-off, tau the line's strength at it.
  void ubiquitousJointCornerReturn() {
    ZoneProperties p = base("ubiquitous-joint");
    p.friction = 40, p.cohesion = 50e6, p.tension = 50e6;
    p.jfriction = 30, p.jcohesion = 1e6, p.jtension = 0.5e6;
    p.orientation = 2, p.jangle = 0;  // the plane along x: sn = syy, tau = sxy
    p.finalize();
    ZoneStress s;
    uint8_t state = 0;
    double history = 0;
    StrainIncrement de;
    de.yy = 1e-3, de.xy = 1e-3;  // pulls the plane open and shears it hard
    p.impl->update(p, de, s, state, history);
    const double tau_p = 1e6 - 0.5e6 * std::tan(30 * M_PI / 180);
    qInfo("sn %.6g (cut-off 5e5), tau %.6g (corner %.6g)", s.yy, s.xy, tau_p);
    QVERIFY(std::abs(s.yy - 0.5e6) < 1e-6 * 0.5e6);
    QVERIFY(std::abs(std::abs(s.xy) - tau_p) < 1e-6 * tau_p);
    QVERIFY((state & kTensionNow) && (state & kShearNow));
  }

  // Uniaxial stress along, across and at 45 degrees to the plane of isotropy (oblique to the
  // axes): the strain tensor is the rotated compliance times the stress (to 1e-9), the axial
  // strain Lekhnitskii's 1/E(theta) in 3D and its plane-strain counterpart in 2D, where the
  // out-of-plane stress is nu12 s1 + nu13 s3 (s1 along the plane, s3 across it).
  void transverselyIsotropicCompliance() {
    const double s0 = -10e6;
    // 3D: the plane dipping 60 degrees toward 120.
    {
      const ZoneProperties p = transverse(3, 60, 120);
      const double d = 60 * kDeg, a = 120 * kDeg;
      const Eigen::Vector3d n(std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d));
      const Eigen::Vector3d strike(std::cos(a), -std::sin(a), 0), dip = n.cross(strike);
      Eigen::Matrix3d r;
      r.row(0) = strike, r.row(1) = dip, r.row(2) = n;
      for (double theta : {90.0, 0.0, 45.0}) {
        const Eigen::Vector3d u =
            std::sin(theta * kDeg) * strike + std::cos(theta * kDeg) * n;  // load direction
        const Eigen::Matrix3d sigma = s0 * u * u.transpose();
        Point pt{p, {}};
        const StrainIncrement e =
            pt.step({}, {XX, YY, XY, ZZ, YZ, XZ},
                    {sigma(0, 0), sigma(1, 1), sigma(0, 1), sigma(2, 2), sigma(1, 2), sigma(0, 2)});
        const Eigen::Matrix3d got{{e.xx, e.xy, e.xz}, {e.xy, e.yy, e.yz}, {e.xz, e.yz, e.zz}};
        // Closed form: local stress, local compliance, strain back in x, y, z.
        const Eigen::Matrix3d sl = r * sigma * r.transpose();
        Eigen::Matrix<double, 6, 1> sv;
        sv << sl(0, 0), sl(1, 1), sl(2, 2), sl(1, 2), sl(0, 2), sl(0, 1);
        const Eigen::Matrix<double, 6, 1> ev = local_compliance() * sv;
        const Eigen::Matrix3d el{{ev[0], ev[5] / 2, ev[4] / 2},
                                 {ev[5] / 2, ev[1], ev[3] / 2},
                                 {ev[4] / 2, ev[3] / 2, ev[2]}};
        const Eigen::Matrix3d want = r.transpose() * el * r;
        const double err = (got - want).cwiseAbs().maxCoeff() / want.cwiseAbs().maxCoeff();
        const double axial = u.dot(got * u), closed = s0 / directional_modulus(theta);
        qInfo("3D theta %4.1f: axial strain %.6e (Lekhnitskii %.6e), tensor error %.1e", theta,
              axial, closed, err);
        QVERIFY(err < 1e-9);
        QVERIFY(std::abs(axial / closed - 1) < 1e-9);
      }
    }
    // 2D plane strain: the plane at 30 degrees from x.
    {
      const ZoneProperties p = transverse(2, 30);
      for (double theta : {90.0, 0.0, 45.0}) {
        // theta from the normal, which is at 120 degrees from x.
        const double w = (120 - theta) * kDeg;
        const Eigen::Vector2d u(std::cos(w), std::sin(w));
        const Eigen::Matrix2d sigma = s0 * u * u.transpose();
        Point pt{p, {}};
        const StrainIncrement e =
            pt.step({}, {XX, YY, XY}, {sigma(0, 0), sigma(1, 1), sigma(0, 1)});
        const Eigen::Matrix2d got{{e.xx, e.xy}, {e.xy, e.yy}};
        const double axial = u.dot(got * u), closed = s0 / plane_strain_modulus(theta);
        // The out-of-plane stress: nu12 (along the plane) + nu13 (across it), locally.
        const Eigen::Vector2d along(std::cos(30 * kDeg), std::sin(30 * kDeg));
        const Eigen::Vector2d normal(-along.y(), along.x());
        const double zz = kNu12 * along.dot(sigma * along) + kNu13 * normal.dot(sigma * normal);
        qInfo(
            "2D theta %4.1f: axial strain %.6e (plane strain closed form %.6e), szz %.4f MPa "
            "(%.4f)",
            theta, axial, closed, pt.s.zz / 1e6, zz / 1e6);
        QVERIFY(std::abs(axial / closed - 1) < 1e-9);
        QVERIFY(std::abs(pt.s.zz - zz) < 1e-9 * std::abs(s0));
        // The same from the in-plane stress alone (what insitu sets).
        const ZoneStress in_plane{sigma(0, 0), sigma(1, 1), sigma(0, 1)};
        QVERIFY(std::abs(plane_strain_zz(p, in_plane) - zz) < 1e-9 * std::abs(s0));
        QVERIFY(std::abs(pt.s.xx - sigma(0, 0)) < 1e-6 * std::abs(s0));
      }
    }
  }

  // The time step's moduli bound the material: no strain is stiffer in it than in the
  // isotropic material of its K and G (e . C . e <= e . C_iso . e for random strains).
  void transverselyIsotropicStepIsSafe() {
    const ZoneProperties p = transverse(3, 35, 200);
    Eigen::Matrix<double, 6, 6> d, iso = Eigen::Matrix<double, 6, 6>::Zero();
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) d(i, j) = p.stiffness[static_cast<size_t>(6 * i + j)];
    const double lambda = p.bulk - 2 * p.shear / 3;
    iso.topLeftCorner<3, 3>().setConstant(lambda);
    for (int i = 0; i < 3; ++i) iso(i, i) += 2 * p.shear, iso(3 + i, 3 + i) = p.shear;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(iso - d);
    qInfo("K %.3e G %.3e; smallest eigenvalue of C_iso - C %.3e", p.bulk, p.shear,
          eig.eigenvalues().minCoeff());
    QVERIFY(eig.eigenvalues().minCoeff() > -1e-6 * p.bulk);
    // And the P-wave modulus is no more than twice the stiffest direction's: not needlessly slow.
    double stiffest = 0;
    for (int i = 0; i < 3; ++i) stiffest = std::max(stiffest, d(i, i));
    QVERIFY(p.bulk + 4 * p.shear / 3 < 2 * stiffest);
  }

  // The same in 3D: a unit cube on rollers (x, y, z = 0) under a uniaxial boundary stress on
  // its top, the plane of isotropy horizontal (load across it) or vertical with its normal
  // along x (load along it): strains from the corner's displacements against the compliance,
  // within 1%.
  void transverselyIsotropicCube() {
    const double s = -10e6;
    for (bool across : {true, false}) {
      ScriptRun r;
      r.run(std::string("dimension 3\ntolerance 0.01\n"
                        "material define ti density=2500 model=transversely-isotropic E1=20e9 "
                        "E3=5e9 nu12=0.2 nu13=0.25 G13=3e9 ") +
            (across ? "jdip=0 jdipdir=0" : "jdip=90 jdipdir=90") +
            "\nblock box 0,0,0 1,1,1 material=ti\nzone generate edge=0.3\n"
            "boundary fix=x x=-0.001,0.001\nboundary fix=y y=-0.001,0.001\n"
            "boundary fix=z z=-0.001,0.001\nboundary stress=0,0,-10e6,0,0,0 z=0.95,1.05\n"
            "history xdisp at=1,1,1 label=ux\nhistory ydisp at=1,1,1 label=uy\n"
            "history zdisp at=1,1,1 label=uz\nsolve ratio=1e-7 cycles=200000\n");
      const double exx = last(r.model(), "ux"), eyy = last(r.model(), "uy");
      const double ezz = last(r.model(), "uz");
      // Across: ezz = s / E3, exx = eyy = -nu13 s / E1. Along (normal x): ezz = s / E1,
      // eyy = -nu12 s / E1, exx = -nu13 s / E1.
      const double want_zz = across ? s / kE3 : s / kE1;
      const double want_yy = across ? -kNu13 * s / kE1 : -kNu12 * s / kE1;
      const double want_xx = -kNu13 * s / kE1;
      qInfo("%s: ezz %.5e (closed form %.5e), eyy %.5e (%.5e), exx %.5e (%.5e)",
            across ? "across" : "along", ezz, want_zz, eyy, want_yy, exx, want_xx);
      QVERIFY(std::abs(ezz / want_zz - 1) < 0.01);
      QVERIFY(std::abs(eyy / want_yy - 1) < 0.01);
      QVERIFY(std::abs(exx / want_xx - 1) < 0.01);
    }
  }

  // Script runs of a 1 x 2 m zoned sample (plane strain): rollers at its foot, a lateral
  // boundary stress of 2 MPa and an axial one raised by parts (each solved) to 2% below or above
  // the closed-form strength (Jaeger's for a joint at 57.5 degrees to the axis, the matrix's for
  // one at 20). Below, the run converges (ratio 1e-6) with the top's settlement within 2% of the
  // elastic one; above, it does not: it diverges, or stops at the cycle limit with every zone
  // yielding and the top moved more than 3 times as far. (Loaded at once, the transient's
  // overshoot slips the joint early, and with psi_j = 0 that slip need not arrest.)
  void ubiquitousSamplesFailAtTheirStrength() {
    const std::string model =
        "model=ubiquitous-joint friction=40 cohesion=5e6 tension=5e6 "
        "jfriction=25 jcohesion=0.5e6 jangle=";
    const double g = 4e9, k = 10e9 / 1.5, nu = 0.25;
    for (double beta : {57.5, 20.0}) {
      const double strength = std::min(jaeger(2e6, 0.5e6, 25, beta), coulomb(2e6, 5e6, 40));
      for (double f : {0.98, 1.02}) {
        ScriptRun r;
        bool diverged = false;
        try {
          // Loaded by parts, each solved, so that the transients stay below the strength.
          std::string run = sample(model + std::to_string(beta), 0);
          for (double part : {0.5, 0.3, 0.1, 0.05, 0.03, f - 0.98})
            if (part > 0) run += axial_stress(part * strength) + "solve ratio=1e-6 cycles=20000\n";
          r.run(run);
        } catch (const ScriptError& e) {
          QVERIFY2(std::string(e.what()).find("diverged") != std::string::npos, e.what());
          diverged = true;
        }
        // Plane strain, uniform stress: eyy = ((1 - nu^2) syy - nu (1 + nu) sxx) / E.
        const double e = 9 * k * g / (3 * k + g);
        const double elastic = 2 * ((1 - nu * nu) * f * strength - nu * (1 + nu) * 2e6) / e;
        if (diverged) {
          qInfo("beta %.1f at %.2f of %.4f MPa: the run diverged", beta, f, strength / 1e6);
          QVERIFY(f > 1);
          continue;
        }
        const Continuum& z = r.model().continuum;
        size_t yielding = 0;
        for (uint8_t st : z.state) yielding += (st & kShearNow) != 0;
        const double uy = -last(r.model(), "uy");
        qInfo(
            "beta %.1f at %.2f of %.4f MPa: ratio %.1e, %zu of %zu zones yielding, top "
            "settles %.4e m (elastic %.4e)",
            beta, f, strength / 1e6, r.model().ratio, yielding, z.zone_count(), uy, elastic);
        if (f < 1) {
          QVERIFY(r.model().ratio < 1e-6);
          QVERIFY(std::abs(uy / elastic - 1) < 0.02);
        } else {
          QVERIFY(r.model().ratio > 1e-6);
          QCOMPARE(yielding, z.zone_count());
          QVERIFY(uy > 3 * elastic);
        }
      }
    }
  }

  // The same sample of strain-softening rock loaded 2% above its peak: after 300 cycles its
  // zones have yielded and carry plastic shear strain, which the VTK output shows and a state
  // file keeps.
  void softeningSampleKeepsItsPlasticStrain() {
    ScriptRun r;
    r.run(sample("model=strain-softening friction=35 cohesion=2e6 tension=1e6 "
                 "ctable=0,2e6,0.01,0.5e6 ftable=0,35,0.01,30",
                 1.02 * coulomb(2e6, 2e6, 35)) +
          "step 300\nvtk\nsave s.state\n");
    const std::vector<double>& plastic = r.model().continuum.plastic;
    const auto strained =
        std::count_if(plastic.begin(), plastic.end(), [](double e) { return e > 0; });
    qInfo("%td of %zu zones carry plastic strain, the most %.3e", strained, plastic.size(),
          *std::max_element(plastic.begin(), plastic.end()));
    QVERIFY(strained > 0);
    ScriptRun back;
    back.run("restore " + r.path("s.state"));
    QVERIFY(back.model().continuum.plastic == plastic);
    QFile vtk(QString::fromStdString(r.path("vtk/zones_0000.vtp")));
    QVERIFY(vtk.open(QIODevice::ReadOnly));
    QVERIFY(vtk.readAll().contains("Name=\"plastic_strain\""));
    // 3D, quadratic zones: kept at the integration points, the zone's their mean.
    ScriptRun r3;
    r3.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2600 E=10e9 nu=0.25 "
        "model=strain-softening friction=35 cohesion=2e6 tension=1e6 "
        "ctable=0,2e6,0.01,0.5e6 ftable=0,35,0.01,30\n"
        "block box 0,0,0 1,1,2 material=rock\nzone generate edge=0.5 order=2\n"
        "boundary fix=z z=-0.001,0.001\nboundary fix=x x=-0.001,0.001\n"
        "boundary fix=y y=-0.001,0.001\n"
        "boundary stress=0,0,-25e6,0,0,0 z=1.95,2.05\nstep 300\nsave s3.state\n");
    const Continuum3& c3 = r3.model().continuum3;
    QVERIFY(c3.quadratic(0) && c3.gp_plastic.size() == c3.zone_count());
    double most = 0;
    for (size_t z = 0; z < c3.zone_count(); ++z) {
      const auto& g = c3.gp_plastic[z];
      QCOMPARE(c3.plastic[z], g[0] / 4 + g[1] / 4 + g[2] / 4 + g[3] / 4);
      most = std::max(most, c3.plastic[z]);
    }
    qInfo("3D quadratic: the most plastic strain %.3e", most);
    QVERIFY(most > 0);
    ScriptRun back3;
    back3.run("restore " + r3.path("s3.state"));
    QVERIFY(back3.model().continuum3.gp_plastic == c3.gp_plastic);
  }

  // A zoned block under a uniaxial boundary stress (rollers left and bottom, plane strain):
  // the strains measured from the corner's displacements follow the plane-strain compliance
  // across (jangle=0) and along (jangle=90) the plane of isotropy, within 0.5%.
  void transverselyIsotropicBlock() {
    for (double angle : {0.0, 90.0}) {
      ScriptRun r;
      r.run(
          "round 0.01\n"
          "material define ti density=2500 model=transversely-isotropic E1=20e9 E3=5e9 "
          "nu12=0.2 nu13=0.25 G13=3e9 jangle=" +
          std::to_string(angle) +
          "\n"
          "block 0,0 2,0 2,2 0,2 material=ti\n"
          "zone generate edge=0.4\n"
          "boundary fix=x x=-0.001,0.001\nboundary fix=y y=-0.001,0.001\n"
          "boundary stress=0,-10e6,0 y=1.999,2.001\n"
          "history xdisp at=1.999,1.999 label=ux\nhistory ydisp at=1.999,1.999 label=uy\n"
          "solve ratio=1e-7 cycles=200000\n");
      const double exx = last(r.model(), "ux") / 2, eyy = last(r.model(), "uy") / 2;
      // Plane-strain compliances in the plane's axes: across is S'33, along S'11, coupling S'13.
      const double s11 = (1 - kNu12 * kNu12) / kE1, s33 = 1 / kE3 - kNu13 * kNu13 / kE1;
      const double s13 = -kNu13 * (1 + kNu12) / kE1;
      const double want_yy = -10e6 * (angle == 0 ? s33 : s11), want_xx = -10e6 * s13;
      qInfo("jangle %.0f: eyy %.5e (closed form %.5e), exx %.5e (%.5e)", angle, eyy, want_yy, exx,
            want_xx);
      QVERIFY(std::abs(eyy / want_yy - 1) < 0.005);
      QVERIFY(std::abs(exx / want_xx - 1) < 0.005);
    }
  }
};

TESSERA_TEST_MAIN(TestZoneModels)
#include "test_zone_models.moc"
