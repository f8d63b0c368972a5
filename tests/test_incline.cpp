// A block on an inclined plane (damping off): it slides with a = g (sin psi - cos psi tan phi)
// when psi > phi, and stays put when phi > psi.
#include <QtTest>
#include <cmath>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
std::string incline(double psi, double phi) {
  return tessera::test::incline_script(psi, phi) + "damping none\n";
}
constexpr double kDeg = M_PI / 180;
}  // namespace

class TestIncline : public QObject {
  Q_OBJECT
 private slots:
  void slidesWithTheCoulombAcceleration_data() {
    QTest::addColumn<double>("psi");
    QTest::addColumn<double>("phi");
    QTest::newRow("psi 30 phi 20") << 30.0 << 20.0;
    QTest::newRow("psi 40 phi 25") << 40.0 << 25.0;
  }
  void slidesWithTheCoulombAcceleration() {
    QFETCH(double, psi);
    QFETCH(double, phi);
    ScriptRun r;
    r.run(incline(psi, phi));
    Model& m = r.model();
    const double c = std::cos(psi * kDeg), s = std::sin(psi * kDeg);
    // Speed along the slope sampled over 0.2-1.0 s; the fitted slope is the acceleration.
    std::vector<double> t, v;
    while (m.time < 1.0) {
      r.run("step 20");
      if (m.time > 0.2)
        t.push_back(m.time), v.push_back(-(m.blocks.vx[1] * c + m.blocks.vy[1] * s));
    }
    const double a = tessera::test::fitted_slope(t, v);
    const double expected = 9.81 * (s - c * std::tan(phi * kDeg));
    qInfo("acceleration %.5f, closed form %.5f", a, expected);
    QVERIFY(std::abs(a - expected) < 0.01 * expected);
    // Still resting on the slope: no rotation.
    QVERIFY(std::abs(m.blocks.theta[1]) < 1e-3);
  }
  void staysWhenFrictionExceedsTheSlope() {
    // Settle under gravity first (damped), then watch one undamped second: no creep.
    ScriptRun r;
    r.run(incline(30, 40) + "damping local 0.8\nsolve ratio=1e-7\ndamping none");
    Model& m = r.model();
    const double c = std::cos(30 * kDeg), s = std::sin(30 * kDeg);
    auto along = [&] { return m.blocks.x[1] * c + m.blocks.y[1] * s; };
    const double start = along(), t0 = m.time;
    while (m.time < t0 + 1.0) r.run("step 100");
    qInfo("displacement along the slope over 1 s undamped: %.3g m", along() - start);
    QVERIFY(std::abs(along() - start) < 1e-6);
    QVERIFY(std::hypot(m.blocks.vx[1], m.blocks.vy[1]) < 1e-4);
  }
  // What a script reads of the model: `slipping` counts the contacts at their shear strength
  // (both corners of the sliding block; none while friction holds it, the same in the
  // `slipping` history), and blockat() numbers the block holding a point.
  void slippingAndBlockAtReadTheModel() {
    for (const auto& [phi, expected] : {std::pair{20.0, 2.0}, std::pair{40.0, 0.0}}) {
      ScriptRun r;
      r.run(incline(30, phi) + "history slipping\n" +
            (expected > 0 ? "step 300\n" : "damping local 0.8\nsolve ratio=1e-7\n") +
            "set n = slipping\n"
            "set top = blockat(0.5*c-0.5*s, 0.5*s+0.5*c)\nset base = blockat(0, -0.5)");
      qInfo("friction %g: %g contacts slipping", phi, r.interp->variable("n"));
      QCOMPARE(r.interp->variable("n"), expected);
      QCOMPARE(r.model().histories.values.back(), expected);
      QCOMPARE(r.interp->variable("top"), 2.0);
      QCOMPARE(r.interp->variable("base"), 1.0);
    }
    ScriptRun r;
    r.run(incline(30, 40));
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, r.run("set k = blockat(50, 50)"));
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, r.run("set k = blockat(0)"));
  }
  // Block numbers are kept when others are deleted (as messages, the window's selection and VTK
  // show them): `block=`, per-block values and blockat() use them, not the order in memory.
  void blockNumbersOutliveDeletion() {
    ScriptRun r;
    r.run(incline(30, 40) + "block 3,3 4,3 4,4 3,4 material=rock\ndelete block=1");
    QCOMPARE(r.model().blocks.size(), size_t(2));
    r.run("set b = blockat(3.5,3.5)\nset y = ypos(3)\nfix block=3");
    QCOMPARE(r.interp->variable("b"), 3.0);
    QCOMPARE(r.interp->variable("y"), r.model().blocks.y[1]);
    QCOMPARE(r.model().blocks.fixity[1], uint8_t(kFixAll));
    QCOMPARE(r.model().blocks.fixity[0], uint8_t(0));
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, r.run("fix block=1"));
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, r.run("set k = xdisp(1)"));
  }
  // A cohesive joint with no tensile strength keeps its bond from the first cycle (a block set
  // exactly on another has a round-off gap, which is not tension), and its cohesion holds the
  // block until W sin(psi) = c L. Friction zero: the two base contacts then share the shear
  // equally and fail together, whatever the normal forces; L = 1 - 2d (springs at arc centres).
  // The slope is raised in steps of 0.25 degrees, settled at each (a sudden load would overshoot
  // the static shear), and the block must start to slide within a step of the limit.
  void cohesionWithoutTensileStrengthHoldsUntilItsLimit() {
    const double c = 1e4, d = 0.005, W = 2500 * 9.81;
    const double limit = std::asin(c * (1 - 2 * d) / W) / kDeg;
    ScriptRun r;
    r.run(
        "round 0.005\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=0 cohesion=1e4 tension=0\njoint assign j\n"
        "block -2,-1 3,-1 3,0 -2,0 material=rock\nfix block=1\n"
        "block 0,0 1,0 1,1 0,1 material=rock\ngravity 0 -9.81\nstep 1\n");
    Model& m = r.model();
    int bonded = 0;
    for (size_t i = 0; i < m.contacts.size(); ++i) bonded += (m.contacts.flags[i] & kBonded) != 0;
    QCOMPARE(bonded, 2);
    double slid_at = 0.0;
    for (double psi = 5.0; psi < 40.0 && slid_at == 0.0; psi += 0.25) {
      r.run("gravity " + std::to_string(9.81 * std::sin(psi * kDeg)) + " " +
            std::to_string(-9.81 * std::cos(psi * kDeg)) + "\nsolve ratio=1e-5 cycles=5000");
      if (m.blocks.x[1] - 0.5 > 1e-3) slid_at = psi;
    }
    qInfo("slid at psi %.2f degrees; W sin(psi) = c L at %.2f", slid_at, limit);
    QVERIFY(slid_at > limit - 0.25 && slid_at < limit + 0.5);
  }
  // Only joints shut when the model is made are bonded: a block 2 mm above its base (within the
  // contact tolerance of 5 mm) is not glued across the gap; one set on it is.
  void onlyShutJointsAreBonded() {
    for (const double gap : {0.0, 0.002}) {
      ScriptRun r;
      const std::string y0 = std::to_string(gap), y1 = std::to_string(gap + 1);
      r.run(
          "round 0.005\nmaterial define rock density=2500\n"
          "joint define j kn=1e10 ks=1e10 friction=30 cohesion=1e6 tension=1e6\njoint assign j\n"
          "block -2,-1 3,-1 3,0 -2,0 material=rock\nfix block=1\n"
          "block 0," +
          y0 + " 1," + y0 + " 1," + y1 + " 0," + y1 + " material=rock\ndamping none\nstep 200");
      const Model& m = r.model();
      int bonded = 0;
      for (size_t i = 0; i < m.contacts.size(); ++i) bonded += (m.contacts.flags[i] & kBonded) != 0;
      qInfo("gap %.3f m: %d bonded contacts, block moved %.3g m", gap, bonded,
            m.blocks.y[1] - (gap + 0.5));
      QCOMPARE(bonded, gap > 0 ? 0 : 2);
      // Without gravity nothing moves it: no force across the open gap.
      QVERIFY(std::abs(m.blocks.y[1] - (gap + 0.5)) < 1e-12);
    }
  }

  // A block near its friction limit on a two-spring base: W sin(psi) h/2 tilts the normal
  // forces to the toe (N/2 + T h/2s) and heel (N/2 - T h/2s); equal shear shares would put the
  // heel 6.5 times over its limit at psi 40, phi 40.1, so it slips while gravity comes on and
  // the toe carries the rest, within 0.4% of its own limit. Settled, it stands undamped.
  void nearLimitBlockStandsOnUnequalContacts_data() {
    QTest::addColumn<double>("kn");
    QTest::newRow("kn 1e9") << 1e9;
    QTest::newRow("kn 1e7") << 1e7;
  }
  void nearLimitBlockStandsOnUnequalContacts() {
    QFETCH(double, kn);
    const double psi = 40, phi = 40.1, d = 0.005, g = 9.81, W = 2500 * g;
    const double N = W * std::cos(psi * kDeg), T = W * std::sin(psi * kDeg), s = 1 - 2 * d;
    const double mu = std::tan(phi * kDeg);
    ScriptRun r;
    r.run("round 0.005\nmaterial define rock density=2500\njoint define j kn=" +
          std::to_string(kn) + " ks=" + std::to_string(kn) + " friction=" + std::to_string(phi) +
          "\njoint assign j\nblock -2,-1 3,-1 3,0 -2,0 material=rock\nfix block=1\n"
          "block 0,0 1,0 1,1 0,1 material=rock\ngravity " +
          std::to_string(-g * std::sin(psi * kDeg)) + " " +
          std::to_string(-g * std::cos(psi * kDeg)) + "\ndamping local\nsolve ratio=1e-6\n");
    Model& m = r.model();
    const Contacts& C = m.contacts;
    QCOMPARE(C.size(), size_t(2));
    const size_t toe = C.point[0].x() < C.point[1].x() ? 0 : 1, heel = 1 - toe;
    QVERIFY(std::abs(C.fn[toe] - (N / 2 + T * 0.5 / s)) < 5e-3 * N);
    QVERIFY(std::abs(C.fn[heel] - (N / 2 - T * 0.5 / s)) < 5e-3 * N);
    QVERIFY(std::abs(std::abs(C.fs[toe] + C.fs[heel]) - T) < 1e-4 * T);
    for (size_t i : {toe, heel}) {
      QVERIFY(std::abs(C.length[i] - s / 2) < 1e-5);
      QVERIFY(std::abs(C.fs[i]) <= mu * C.fn[i] * (1 + 1e-9));
      // The incremental normal force has not drifted from kn L overlap (5.6e-5 at kn 1e7, where
      // the block turns 3.3 mrad and the heel's arc rolls).
      QVERIFY(std::abs(C.fn[i] - kn * C.length[i] * -C.gap[i]) < 1e-4 * C.fn[i]);
    }
    QVERIFY(std::abs(C.fs[toe]) > 0.99 * mu * C.fn[toe]);
    QVERIFY(std::abs(C.fs[heel]) < 0.25 * T / 2);
    const double x0 = m.blocks.x[1],
                 settle_bound = 20 * 2 * mu * g * std::cos(psi * kDeg) * 2500 / (kn * s);
    qInfo("kn %.0e: toe %.1f N (%.2f%% of its limit), heel %.1f N, settle slip %.3g m", kn,
          C.fn[toe], 100 * std::abs(C.fs[toe]) / (mu * C.fn[toe]), C.fn[heel], x0 - 0.5);
    QVERIFY(std::abs(x0 - 0.5) < settle_bound);
    r.run("damping none\nstep 20000");
    QVERIFY(std::abs(m.blocks.x[1] - x0) < 0.01 * T / (kn * s));
  }
};

QTEST_APPLESS_MAIN(TestIncline)
#include "test_incline.moc"
