// The Coulomb joint law: stiffness, slip, bond failure in tension and shear, residual strength,
// dilation.
#include <QtTest>
#include <cmath>

#include "tessera/contact2d/contacts.hpp"
#include "tessera/core/joint_law.hpp"

using namespace tessera;

namespace {
JointProperties joint(double friction, double cohesion = 0, double tension = 0, double dilation = 0,
                      double limit = 0) {
  JointProperties j;
  j.kn = 1e9, j.ks = 5e8, j.friction = friction, j.cohesion = cohesion, j.tension = tension;
  j.dilation = dilation, j.dilation_limit = limit;
  j.finalize();
  return j;
}
}  // namespace

class TestJointLaw : public QObject {
  Q_OBJECT
 private slots:
  void elasticBelowTheLimit() {
    const auto j = joint(30);
    JointState s;
    j.impl->update(j, 1.0, 1e-4, 1e-6, s);  // sigma_n = 1e5, tau = -500
    QCOMPARE(s.fn, 1e5);
    QCOMPARE(s.fs, -500.0);
    QVERIFY(!(s.flags & kSlipping) && (s.flags & kTouching));
  }
  void slipsAtTheCoulombLimit() {
    const auto j = joint(30);
    JointState s;
    j.impl->update(j, 1.0, 1e-4, 1e-3, s);
    QVERIFY(std::abs(s.fs + 1e5 * std::tan(M_PI / 6)) < 1e-6);
    QVERIFY(s.flags & kSlipping);
  }
  void openContactCarriesNothing() {
    const auto j = joint(30);
    JointState s;
    s.fs = 50;
    s.un_prev = 1e-6;
    j.impl->update(j, 1.0, -1e-5, 0, s);
    QCOMPARE(s.fn, 0.0);
    QCOMPARE(s.fs, 0.0);
    QVERIFY(!(s.flags & kTouching));
  }
  void bondHoldsTensionThenBreaksForGood() {
    const auto j = joint(30, 0, 2e4);
    JointState s;
    s.flags = kBonded;
    j.impl->update(j, 1.0, -1e-5, 0, s);  // sigma_n = -1e4, inside the strength
    QCOMPARE(s.fn, -1e4);
    QVERIFY(s.flags & kBonded);
    j.impl->update(j, 1.0, -3e-5, 0, s);  // -3e4 beyond the strength
    QCOMPARE(s.fn, 0.0);
    QVERIFY(!(s.flags & kBonded) && (s.flags & kBroken));
    j.impl->update(j, 1.0, -1e-5, 0, s);  // no tension any more
    QCOMPARE(s.fn, 0.0);
  }
  void cohesionIsLostOnShearFailure() {
    const auto j = joint(30, 1e5);
    JointState s;
    s.flags = kBonded;
    j.impl->update(j, 1.0, 1e-4, 1e-4, s);  // trial tau = -5e4 < c + sigma tan(phi)
    QCOMPARE(s.fs, -5e4);
    j.impl->update(j, 1.0, 1e-4, 1e-3, s);  // trial -5.5e5 beyond 1e5 + 5.77e4
    QVERIFY(!(s.flags & kBonded));
    QVERIFY(std::abs(s.fs + 1e5 * std::tan(M_PI / 6)) < 1e-6);
  }
  // coulomb-residual: the peak (cohesion 1e5, friction 30) until the bond fails in shear, then
  // the residual strength (cohesion 2e4, friction 20) at every later slip - not friction alone.
  void residualStrengthAfterShearFailure() {
    auto j = joint(30, 1e5);
    j.law = "coulomb-residual", j.residual_friction = 20, j.residual_cohesion = 2e4;
    j.finalize();
    JointState s;
    s.flags = kBonded;
    j.impl->update(j, 1.0, 1e-4, 1e-3, s);  // trial -5e5 beyond the peak 1e5 + 5.77e4
    QVERIFY((s.flags & kBroken) && (s.flags & kSlipping));
    const double residual = 2e4 + 1e5 * std::tan(20 * M_PI / 180);
    QVERIFY(std::abs(s.fs + residual) < 1e-6);
    j.impl->update(j, 1.0, 1e-4, 1e-3, s);  // slips on at the residual strength
    QVERIFY(std::abs(s.fs + residual) < 1e-6);
    // Without residual values the law is plain coulomb: friction only after failure.
    auto plain = joint(30, 1e5);
    plain.law = "coulomb-residual";
    plain.finalize();
    JointState t;
    t.flags = kBonded;
    plain.impl->update(plain, 1.0, 1e-4, 1e-3, t);
    QVERIFY(std::abs(t.fs + 1e5 * std::tan(M_PI / 6)) < 1e-6);
  }
  void dilationWhileSlippingUpToTheLimit() {
    const auto j = joint(30, 0, 0, 10, 2e-3);
    JointState s;
    for (int i = 0; i < 10; ++i) j.impl->update(j, 1.0, 1e-4, 1e-3, s);
    // Slips every call; dilation grows only while the shear displacement is under 2 mm (first
    // call).
    QVERIFY(std::abs(s.dilation - 1e-3 * std::tan(10 * M_PI / 180)) < 1e-12);
    QVERIFY(std::abs(s.fn - 1e9 * (1e-4 + s.dilation)) < 1e-3);
  }
  void unknownLawIsRejected() {
    JointProperties j;
    j.law = "nonsense";
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, j.finalize());
  }
};

QTEST_APPLESS_MAIN(TestJointLaw)
#include "test_joint_law.moc"
