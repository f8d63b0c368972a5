// Dynamics of the contact springs with damping off: a block bouncing on its base oscillates at
// sqrt(k/m); two blocks colliding stay in contact for pi sqrt(m_eff/k). The contact springs sit
// at the rounded corners' arc centres, so a face of width w carries k = kn (w - 2d).
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/core/step.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
const char* kSetup =
    "round 0.005\n"
    "material define rock density=2500\n"
    "joint define j kn=1e10 ks=1e10 friction=30\n"
    "joint assign j\n"
    "damping none\n";
}  // namespace

class TestDynamics : public QObject {
  Q_OBJECT
 private slots:
  // Stiff joints and soft ones (1e7 Pa/m: the block then sits 2.5 mm deep in its joint).
  void bouncesAtTheSpringFrequency_data() {
    QTest::addColumn<double>("kn");
    QTest::newRow("kn 1e10") << 1e10;
    QTest::newRow("kn 1e7") << 1e7;
  }
  void bouncesAtTheSpringFrequency() {
    QFETCH(double, kn);
    ScriptRun r;
    r.run(std::string(kSetup) + "joint define j kn=" + std::to_string(kn) +
          " ks=" + std::to_string(kn) + " friction=30\n" +
          "block -2,-1 3,-1 3,0 -2,0 group=base material=rock\nfix group=base\n"
          "block 0,0 1,0 1,1 0,1 material=rock\n"
          "gravity 0 -9.81\ntimestep auto safety=0.1\n");
    Model& m = r.model();
    // Times at which the vertical velocity turns from upward to downward (the top of a bounce).
    std::vector<double> tops;
    double prev = 0.0;
    while (tops.size() < 6 && m.cycle < 100000) {
      r.run("step 1");
      const double vy = m.blocks.vy[1];
      if (prev > 0.0 && vy <= 0.0) tops.push_back(m.time - m.dt * vy / (vy - prev));
      prev = vy;
    }
    QVERIFY(tops.size() == 6);
    const double period = (tops.back() - tops.front()) / 5.0;
    const double k = kn * (1.0 - 2 * 0.005), mass = 2500.0;
    const double expected = 2 * M_PI * std::sqrt(mass / k);
    qInfo("period %.6e s, closed form %.6e s", period, expected);
    QVERIFY(std::abs(period - expected) < 0.01 * expected);
  }
  // A base moved at a prescribed velocity carries a block bonded to it; when the velocity is
  // changed between steps, the joint's shear displacement stays the relative motion the blocks
  // made (once, the changed velocity fed the next increment before the block moved by it, and
  // the joint was V dt out of step with the geometry after every change).
  void prescribedVelocityChangesKeepJointsInStep() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "joint define glue kn=1e9 ks=1e9 friction=40 cohesion=1e8 tension=1e8\n"
          "joint assign glue\n"
          "block -2,-1 3,-1 3,0 -2,0 group=base material=rock\nfix group=base\n"
          "block 0,0 1,0 1,1 0,1 material=rock\nfix block=2 rotation\ngravity 0 -9.81\nstep 10\n");
    Model& m = r.model();
    // The joint's shear displacement against the relative motion of the blocks (normals point
    // to the owner, block 2, whose shear is its motion along -x). At the end of a cycle the
    // joints have seen every move but the last (the next cycle's law takes it), so the blocks
    // are compared where they were one step back: x - dt v.
    const auto back = [&](size_t b) { return m.blocks.x[b] - m.dt * m.blocks.vx[b]; };
    const double x1 = back(0), x2 = back(1);
    const auto mismatch = [&] {
      const double rel = (back(1) - x2) - (back(0) - x1);
      double worst = 0.0;
      for (size_t i = 0; i < m.contacts.size(); ++i)
        if (m.contacts.kind[i] != kLost)
          worst = std::max(worst, std::abs(m.contacts.shear_disp[i] + rel));
      return worst;
    };
    const double V = 0.1;
    r.run("velocity block=1 vx=0.1\nstep 300");
    const double during = mismatch();
    r.run("velocity block=1 vx=0.3\nstep 300");
    const double faster = mismatch();
    r.run("velocity block=1 vx=0\nstep 300");
    const double after = mismatch();
    qInfo("V dt = %.3g m; joint vs motion: %.3g, %.3g, %.3g m", V * m.dt, during, faster, after);
    QVERIFY(back(0) - x1 > 0.3 * 300 * m.dt);
    QVERIFY(during < 1e-3 * V * m.dt);
    QVERIFY(faster < 1e-3 * V * m.dt);
    QVERIFY(after < 1e-3 * V * m.dt);
  }

  void collisionLastsHalfAPeriod() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "block 0,0 1,0 1,1 0,1 material=rock\n"
          "block 1.001,0 2.001,0 2.001,1 1.001,1 material=rock\n"
          "velocity block=1 vx=1\nvelocity block=2 vx=-1\n"
          "timestep auto safety=0.002\n");
    Model& m = r.model();
    uint64_t touching = 0;
    bool was_touching = false, done = false;
    while (!done && m.cycle < 200000) {
      r.run("step 1");
      bool now = false;
      for (size_t i = 0; i < m.contacts.size(); ++i) now = now || m.contacts.fn[i] > 0.0;
      touching += now;
      done = was_touching && !now;
      was_touching = now;
    }
    QVERIFY(done);
    const double duration = static_cast<double>(touching) * m.dt;
    const double k = 1e10 * (1.0 - 2 * 0.005), m_eff = 2500.0 / 2;
    const double expected = M_PI * std::sqrt(m_eff / k);
    qInfo("contact lasted %.6e s, closed form %.6e s", duration, expected);
    QVERIFY(std::abs(duration - expected) < 0.02 * expected);
    // Equal masses, elastic: the velocities are exchanged.
    QVERIFY(std::abs(m.blocks.vx[0] + 1.0) < 0.02);
    QVERIFY(std::abs(m.blocks.vx[1] - 1.0) < 0.02);
  }
  // Contact damping: a block dropped at 1 m/s onto a held one, gravity and global damping off,
  // rebounds with the restitution of a linear spring and dashpot, e = exp(-pi zeta / sqrt(1 -
  // zeta^2)) (the dashpot acting while the springs overlap), for zeta = ndamping. 2D and 3D.
  void contactDampingGivesTheRestitution_data() {
    QTest::addColumn<bool>("three");
    QTest::addColumn<double>("zeta");
    for (bool three : {false, true})
      for (double zeta : {0.0, 0.1, 0.3})
        QTest::newRow(qPrintable(QString("%1 zeta %2").arg(three ? "3D" : "2D").arg(zeta)))
            << three << zeta;
  }
  void contactDampingGivesTheRestitution() {
    QFETCH(bool, three);
    QFETCH(double, zeta);
    const std::string joint =
        "material define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30 ndamping=" +
        std::to_string(zeta) + "\njoint assign j\ndamping none\n";
    ScriptRun r;
    if (three)
      r.run("dimension 3\ntolerance 0.005\n" + joint +
            "block box 0,0,-1 1,1,0 material=rock\nfix block=1\n"
            "block box 0,0,0.001 1,1,1.001 material=rock\nvelocity block=2 vz=-1\n");
    else
      r.run("round 0.005\n" + joint +
            "block 0,-1 1,-1 1,0 0,0 material=rock\nfix block=1\n"
            "block 0,0.001 1,0.001 1,1.001 0,1.001 material=rock\nvelocity block=2 vy=-1\n");
    r.run("timestep auto safety=0.02\n");
    Model& m = r.model();
    const auto vertical = [&] { return three ? m.blocks3.body[1].velocity.z() : m.blocks.vy[1]; };
    // The force the joint still carries.
    const auto carried = [&] {
      double f = 0.0;
      for (const Contact3& c : m.contacts3) f += c.force.norm();
      for (size_t i = 0; i < m.contacts.size(); ++i) f += m.contacts.force(i).norm();
      return f;
    };
    // Until the block has met the joint and left it again.
    bool touched = false;
    while (m.cycle < 200000 && !(touched && carried() == 0.0)) {
      r.run("step 1");
      touched = touched || carried() > 0.0;
    }
    QVERIFY(touched && carried() == 0.0);
    const double e = vertical(), expected = std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta));
    qInfo("rebound %.5f m/s, e = %.5f", e, expected);
    QVERIFY(std::abs(e - expected) < 0.02 * expected);
  }
  // Every damping mode comes to the same static answer, the elastic settlement mg / k.
  void dampingModesReachTheStaticSettlement_data() {
    QTest::addColumn<QString>("mode");
    QTest::newRow("local") << "local 0.8";
    QTest::newRow("adaptive global") << "global 0.5";
    QTest::newRow("kinetic") << "kinetic 0.2";
  }
  void dampingModesReachTheStaticSettlement() {
    QFETCH(QString, mode);
    ScriptRun r;
    r.run(std::string(kSetup) +
          "block -2,-1 3,-1 3,0 -2,0 group=base material=rock\nfix group=base\n"
          "block 0,0 1,0 1,1 0,1 material=rock\n"
          "gravity 0 -9.81\ndamping " +
          mode.toStdString() + "\nsolve ratio=1e-7 cycles=20000\n");
    const Model& m = r.model();
    const double settle = -(m.blocks.y[1] - m.blocks.y_ref[1]);
    const double expected = 2500 * 9.81 / (1e10 * (1.0 - 2 * 0.005));
    // At rest: kinetic energy a negligible part of the strain energy m g d / 2.
    const double strain = 0.5 * 2500 * 9.81 * expected;
    qInfo("%s: settled %.6e m in %llu cycles, closed form %.6e m; kinetic / strain energy %.2e",
          qPrintable(mode), settle, static_cast<unsigned long long>(m.cycle), expected,
          kinetic_energy(m) / strain);
    QVERIFY(m.ratio <= 1e-7);
    QVERIFY(std::abs(settle - expected) < 1e-3 * expected);
    QVERIFY(kinetic_energy(m) < 1e-6 * strain);
  }
  // Without damping the same block keeps bouncing: the damping above is what settled it.
  void undampedBlockDoesNotSettle() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "block -2,-1 3,-1 3,0 -2,0 group=base material=rock\nfix group=base\n"
          "block 0,0 1,0 1,1 0,1 material=rock\ngravity 0 -9.81\nstep 5000\n");
    QVERIFY(r.model().ratio > 1e-3);
  }
};

QTEST_APPLESS_MAIN(TestDynamics)
#include "test_dynamics.moc"
