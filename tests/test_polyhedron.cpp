// 3D blocks: mass properties of polyhedra against closed forms, and the free rotation of a
// rigid block: exact angular momentum, kinetic energy to 1e-6 over 1e5 steps, and the
// precession of a symmetric block at the rate of Euler's equations.
#include <QtTest>
#include <cmath>
#include <numbers>

#include "tessera/contact3d/rigid3d.hpp"

using namespace tessera;

class TestPolyhedron : public QObject {
  Q_OBJECT
 private slots:
  // A 1 x 2 x 3 box: V = 6, centroid at its middle, I = m (b^2 + c^2) / 12 on its axes.
  void boxProperties() {
    const SolidProperties s = solid_properties(box({1, 2, 3}, {2, 4, 6}));
    QVERIFY(std::abs(s.volume - 6.0) < 1e-12);
    QVERIFY((s.centroid - Vec3(1.5, 3, 4.5)).norm() < 1e-12);
    const Vec3 expect(6.0 * (4 + 9) / 12, 6.0 * (1 + 9) / 12, 6.0 * (1 + 4) / 12);
    QVERIFY((s.inertia.diagonal() - expect).norm() < 1e-11);
    QVERIFY((s.inertia - Mat3(expect.asDiagonal())).norm() < 1e-11);
  }

  // The unit corner tetrahedron: V = 1/6, centroid (1/4, 1/4, 1/4); about the centroid
  // Ixx = 1/80 and Ixy = 1/480 (from the canonical second moments 1/60 and 1/120).
  void tetrahedronProperties() {
    Polyhedron t;
    t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    t.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const SolidProperties s = solid_properties(t);
    QVERIFY(std::abs(s.volume - 1.0 / 6) < 1e-14);
    QVERIFY((s.centroid - Vec3(0.25, 0.25, 0.25)).norm() < 1e-14);
    QVERIFY(std::abs(s.inertia(0, 0) - 1.0 / 80) < 1e-14);
    QVERIFY(std::abs(s.inertia(0, 1) - 1.0 / 480) < 1e-14);
  }

  // Turned and moved, the same box has the turned tensor R I R^T and the moved centroid.
  void turnedBoxProperties() {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    Polyhedron p = box({0, 0, 0}, {1, 2, 3});
    const SolidProperties before = solid_properties(p);
    for (Vec3& v : p.vertices) v = r * v + Vec3(10, -5, 2);
    const SolidProperties after = solid_properties(p);
    QVERIFY(std::abs(after.volume - 6.0) < 1e-12);
    QVERIFY((after.centroid - (r * before.centroid + Vec3(10, -5, 2))).norm() < 1e-12);
    QVERIFY((after.inertia - r * before.inertia * r.transpose()).norm() < 1e-10);
    // Principal moments do not depend on the turn; the axes are a right-handed frame.
    QVERIFY((after.principal_moments - before.principal_moments).norm() < 1e-10);
    QVERIFY(std::abs(after.principal_axes.determinant() - 1.0) < 1e-12);
  }

  // A prism on a triangle: V = area x height.
  void prismProperties() {
    const SolidProperties s = solid_properties(prism({{0, 0}, {3, 0}, {0, 2}}, -1, 1.5));
    QVERIFY(std::abs(s.volume - 3.0 * 2.5) < 1e-12);
    QVERIFY((s.centroid - Vec3(1, 2.0 / 3, 0.25)).norm() < 1e-12);
  }

  // Open or inside-out surfaces are refused with the fault named.
  void badSurfacesAreRefused() {
    Polyhedron p = box({0, 0, 0}, {1, 1, 1});
    p.faces.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, solid_properties(p));
    Polyhedron q = box({0, 0, 0}, {1, 1, 1});
    for (auto& f : q.faces) std::reverse(f.begin(), f.end());
    try {
      solid_properties(q);
      QFAIL("an inside-out box was accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY(QString(e.what()).contains("inside out"));
    }
  }

  // A 1 x 2 x 3 m granite block spinning about a non-principal axis, no damping, 1e5 steps:
  // angular momentum kept to round-off, kinetic energy to 1e-6 relative.
  void freeSpinKeepsEnergyAndMomentum() {
    RigidBody3 b = make_body(solid_properties(box({0, 0, 0}, {1, 2, 3})), 2700);
    b.momentum = b.orientation * Vec3(3000, 8000, 5000);  // about all three axes
    const Vec3 l0 = b.momentum;
    const double e0 = b.kinetic_energy(), dt = 1e-4;
    qInfo("angular speed %.3f rad/s, %.1e rad per step", b.angular_velocity().norm(),
          b.angular_velocity().norm() * dt);
    double worst = 0;
    for (int n = 0; n < 100000; ++n) {
      step_body(b, Vec3::Zero(), Vec3::Zero(), dt);
      worst = std::max(worst, std::abs(b.kinetic_energy() / e0 - 1));
    }
    qInfo("largest energy error %.2e, momentum error %.2e", worst,
          (b.momentum - l0).norm() / l0.norm());
    QVERIFY(worst < 1e-6);
    QVERIFY((b.momentum - l0).norm() < 1e-12 * l0.norm());
    QVERIFY(std::abs(b.orientation.norm() - 1.0) < 1e-12);
  }

  // An orientation given off unit length (a script's, a file's) is back at it after one step;
  // a step's own round-off is taken out by the cheaper Newton step and stays out.
  void stepBringsOrientationToUnitLength() {
    RigidBody3 b = make_body(solid_properties(box({0, 0, 0}, {1, 2, 3})), 2700);
    b.momentum = b.orientation * Vec3(3000, 8000, 5000);
    b.orientation.coeffs() *= 1.5;
    step_body(b, Vec3::Zero(), Vec3::Zero(), 1e-4);
    QVERIFY(std::abs(b.orientation.norm() - 1.0) < 1e-15);
    for (int n = 0; n < 1000; ++n) step_body(b, Vec3::Zero(), Vec3::Zero(), 1e-4);
    QVERIFY(std::abs(b.orientation.norm() - 1.0) < 1e-15);
  }

  // A square-based block (I1 = I2 = I, I3 about its long axis): torque-free, the angular
  // velocity turns about the axis of symmetry in the body at Omega = w3 (I3 - I) / I
  // (Euler's equations); the angle turned in 2 s within 1e-4 of that.
  void symmetricBlockPrecesses() {
    RigidBody3 b = make_body(solid_properties(box({0, 0, 0}, {1, 1, 3})), 2700);
    // The axis of symmetry: the principal moment unlike the other two.
    int axis = 0;
    for (int k = 0; k < 3; ++k)
      if (std::abs(b.principal[k] - b.principal[(k + 1) % 3]) > 1e-6 * b.principal[k] &&
          std::abs(b.principal[k] - b.principal[(k + 2) % 3]) > 1e-6 * b.principal[k])
        axis = k;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    Vec3 w_body = Vec3::Zero();
    w_body[axis] = 2.0, w_body[u] = 0.5;
    b.momentum = b.orientation * w_body.cwiseProduct(b.principal);
    const double rate = w_body[axis] * (b.principal[axis] - b.principal[u]) / b.principal[u];
    const double dt = 1e-4;
    double turned = 0, last = 0;
    for (int n = 0; n < 20000; ++n) {
      step_body(b, Vec3::Zero(), Vec3::Zero(), dt);
      const Vec3 w = (b.orientation.conjugate() * b.momentum).cwiseQuotient(b.principal);
      const double a = std::atan2(w[v], w[u]);
      double d = a - last;
      if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
      if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
      turned += d, last = a;
    }
    // Euler: w_u' = -Omega w_v, w_v' = Omega w_u, so (w_u, w_v) turns at Omega (negative here:
    // the long axis has the smaller moment).
    qInfo("turned %.6f rad in 2 s; Euler: %.6f rad", turned, rate * 2.0);
    QVERIFY(std::abs(turned / (rate * 2.0) - 1) < 1e-4);
  }
};

QTEST_APPLESS_MAIN(TestPolyhedron)
#include "test_polyhedron.moc"
