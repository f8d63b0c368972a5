// Loads on rigid blocks ('load'), against closed forms: a block pushed along a rough floor
// accelerates at (F - mu W) / m and stays put below mu W (2D and 3D, soft and stiff joints); a
// pressed block's joint carries W + F; a moment ramped by a table spins a free block at
// M t^2 / (2 I); joined 3D pieces carry their loads at the body's centroid.
#include <QtTest>
#include <array>
#include <cmath>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
constexpr double kG = 9.81, kDeg = M_PI / 180;

// A 1 m cube (2500 kg) on a fixed slab 6 m long, friction 30 degrees.
std::string cube3d(double kn) {
  const std::string k = std::to_string(kn);
  return "dimension 3\ntolerance 0.001\nmaterial define rock density=2500\n"
         "joint define j kn=" +
         k + " ks=" + k +
         " friction=30\njoint assign j\n"
         "block box -1,-1,-1 5,2,0 group=base material=rock\nfix group=base\n"
         "block box 0,0,0 1,1,1 material=rock\ngravity 0 0 -9.81\n";
}

// Pushes block 2 along x with a load that rises over 0.2 s (a sudden one would set the block
// rocking on its joint, undamped, for the rest of the run), then fits its speed over 0.3-1.0 s:
// the acceleration.
template <class Speed>
double pushed_acceleration(ScriptRun& r, double push, Speed speed) {
  Model& m = r.model();
  const double t0 = m.time;
  r.run("table rise " + std::to_string(t0) + ",0 " + std::to_string(t0 + 0.2) +
        ",1\nload block=2 fx=" + std::to_string(push) + " table=rise");
  std::vector<double> t, v;
  while (m.time < t0 + 1.0) {
    r.run("step 20");
    if (m.time > t0 + 0.3) t.push_back(m.time), v.push_back(speed());
  }
  return tessera::test::fitted_slope(t, v);
}
}  // namespace

class TestLoads : public QObject {
  Q_OBJECT
 private slots:
  void pushedBlockSlidesAtTheCoulombAcceleration_data() {
    QTest::addColumn<int>("dim");
    QTest::addColumn<double>("kn");
    QTest::newRow("2D stiff joint") << 2 << 1e10;
    QTest::newRow("2D soft joint") << 2 << 1e8;
    QTest::newRow("3D stiff joint") << 3 << 1e10;
    QTest::newRow("3D soft joint") << 3 << 1e8;
  }
  // F = 2 mu W along x: a = (F - mu W) / m = mu g.
  void pushedBlockSlidesAtTheCoulombAcceleration() {
    QFETCH(int, dim);
    QFETCH(double, kn);
    const double mu = std::tan(30 * kDeg), mass = 2500.0;
    const double push = 2 * mu * mass * kG;
    ScriptRun r;
    Model& m = r.model();
    double a = 0.0;
    if (dim == 2) {
      r.run(tessera::test::incline_script(0, 30, 1, 1, kn) +
            "damping local 0.8\nsolve ratio=1e-7\ndamping none");
      a = pushed_acceleration(r, push, [&] { return m.blocks.vx[1]; });
      // Friction at the base, the push at the centroid: the joint's normal force shifts forward
      // by mu h / 2 (within the base: no tipping), which tilts the block on its two corner
      // springs (rotational stiffness kn b^3 / 4) by 2 mu W h / (kn b^3) = 2.8e4 / kn rad.
      qInfo("tilt %.3g rad, static %.3g", m.blocks.theta[1], 2.8e4 / kn);
      QVERIFY(std::abs(m.blocks.theta[1]) < 1e5 / kn);
    } else {
      r.run(cube3d(kn) + "damping local 0.8\nsolve ratio=1e-7\ndamping none");
      a = pushed_acceleration(r, push, [&] { return m.blocks3.body[1].velocity.x(); });
    }
    const double expected = mu * kG;
    qInfo("acceleration %.5f m/s2, closed form %.5f", a, expected);
    QVERIFY(std::abs(a - expected) < 0.01 * expected);
  }

  // F = 0.8 mu W: friction holds it (no creep over one undamped second).
  void blockBelowTheFrictionLimitStays_data() {
    QTest::addColumn<int>("dim");
    QTest::newRow("2D") << 2;
    QTest::newRow("3D") << 3;
  }
  void blockBelowTheFrictionLimitStays() {
    QFETCH(int, dim);
    const double push = 0.8 * std::tan(30 * kDeg) * 2500.0 * kG;
    ScriptRun r;
    Model& m = r.model();
    const std::string load = "load block=2 fx=" + std::to_string(push) + "\n";
    r.run((dim == 2 ? tessera::test::incline_script(0, 30) : cube3d(1e10)) + load +
          "damping local 0.8\nsolve ratio=1e-7\ndamping none");
    const auto x = [&] { return dim == 2 ? m.blocks.x[1] : m.blocks3.body[1].position.x(); };
    const double start = x(), t0 = m.time;
    while (m.time < t0 + 1.0) r.run("step 100");
    qInfo("moved %.3g m over 1 s undamped", x() - start);
    QVERIFY(std::abs(x() - start) < 1e-6);
  }

  // A block pressed down by F: its joint carries W + F (N/m in 2D, N in 3D).
  void pressedBlockJointCarriesWeightPlusLoad_data() {
    QTest::addColumn<int>("dim");
    QTest::newRow("2D") << 2;
    QTest::newRow("3D") << 3;
  }
  void pressedBlockJointCarriesWeightPlusLoad() {
    QFETCH(int, dim);
    const double press = 1e5, weight = 2500.0 * kG;
    ScriptRun r;
    const std::string load = dim == 2 ? "load block=2 fy=-1e5\n" : "load block=2 fz=-1e5\n";
    r.run((dim == 2 ? tessera::test::incline_script(0, 30) : cube3d(1e10)) + load +
          "solve ratio=1e-8");
    const Model& m = r.model();
    double carried = 0.0;
    if (dim == 2)
      for (size_t i = 0; i < m.contacts.size(); ++i) carried += std::abs(m.contacts.force(i).y());
    else
      for (const Contact3& c : m.contacts3) carried += std::abs(c.force.z());
    qInfo("joint carries %.2f N, W + F = %.2f N", carried, weight + press);
    QVERIFY(std::abs(carried - (weight + press)) < 1e-4 * (weight + press));
  }

  // A free square (2D) or cube (3D), no gravity: the moment M ramped over 1 s by a table spins
  // it at omega = M t^2 / (2 I), I = m a^2 / 6 for both.
  void tableRampedMomentSpinsAFreeBlock_data() {
    QTest::addColumn<int>("dim");
    QTest::newRow("2D") << 2;
    QTest::newRow("3D") << 3;
  }
  void tableRampedMomentSpinsAFreeBlock() {
    QFETCH(int, dim);
    ScriptRun r;
    const std::string common =
        "material define rock density=2500\njoint define j kn=1e9 ks=1e9 friction=30\n"
        "joint assign j\ndamping none\ntimestep fixed 1e-4\ntable ramp 0,0 1,1\n";
    if (dim == 2)
      r.run("round 0.01\n" + common + "block 0,0 1,0 1,1 0,1 material=rock\n" +
            "load block=1 moment=1000 table=ramp\nstep 10000");
    else
      r.run("dimension 3\ntolerance 0.001\n" + common + "block box 0,0,0 1,1,1 material=rock\n" +
            "load block=1 mz=1000 table=ramp\nstep 10000");
    const Model& m = r.model();
    const double omega = dim == 2 ? m.blocks.omega[0] : m.blocks3.omega[0].z();
    const double inertia = 2500.0 / 6.0, t = m.time;
    const double expected = 1000.0 * t * t / (2 * inertia);
    qInfo("t %.4f s: omega %.6f rad/s, closed form %.6f", t, omega, expected);
    // The table is read once a cycle (a step of 1e-4 s in 1 s: 1e-4 of the answer).
    QVERIFY(std::abs(omega - expected) < 1e-3 * expected);
    if (dim == 3) QVERIFY(m.blocks3.omega[0].head<2>().norm() < 1e-9 * expected);
  }

  // Two 1 m cubes joined after one of them was loaded sideways: the body of 2 m x 1 m x 1 m
  // moves at F t / m and turns at (0.5 F) t / Izz (the load kept where it acts).
  void joinedPiecesKeepTheirLoadWhereItActs() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.001\nmaterial define rock density=2500\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\ndamping none\n"
        "timestep fixed 1e-4\nblock box 0,0,0 1,1,1 material=rock\n"
        "block box 1,0,0 2,1,1 material=rock\nload block=2 fy=1000\njoin block=1,2\nstep 1000");
    const Model& m = r.model();
    const double mass = 5000.0, izz = mass * (4.0 + 1.0) / 12.0, t = m.time;
    const RigidBody3& body = m.blocks3.body[0];
    qInfo("vy %.6f (closed form %.6f), omega_z %.6f (%.6f)", body.velocity.y(), 1000 * t / mass,
          m.blocks3.omega[0].z(), 500 * t / izz);
    QVERIFY(std::abs(body.velocity.y() - 1000 * t / mass) < 1e-3 * 1000 * t / mass);
    QVERIFY(std::abs(m.blocks3.omega[0].z() - 500 * t / izz) < 2e-3 * 500 * t / izz);
  }

  // A cut or join keeps the loads of the blocks it leaves whole (2D rebuilds every block), and
  // a state file keeps loads (2D and 3D).
  void loadsSurviveCutsOfOtherBlocksAndStateFiles() {
    ScriptRun r;
    r.run(tessera::test::incline_script(0, 30) +
          "block 2,0 3,0 3,1 2,1 material=rock\nblock 3,0 4,0 4,1 3,1 material=rock\n"
          "load block=2 fx=5 fy=-6 moment=7\njoin block=3,4\n"
          "crack 1.5,0.5 4.5,0.5\njset angle=90 spacing=10 origin=-7.5,0");
    const auto sums = [&] {
      const Blocks& B = r.model().blocks;
      double fx = 0, fy = 0, mz = 0;
      for (size_t b = 0; b < B.size(); ++b)
        fx += B.load_fx[b], fy += B.load_fy[b], mz += B.load_m[b];
      return std::array<double, 3>{fx, fy, mz};
    };
    QVERIFY(r.model().blocks.size() > 5);  // the cuts were made
    QCOMPARE(sums(), (std::array<double, 3>{5.0, -6.0, 7.0}));
    r.run("save " + r.path("s.state") + "\nload all fx=0 fy=0 moment=0\nrestore " +
          r.path("s.state"));
    QCOMPARE(sums(), (std::array<double, 3>{5.0, -6.0, 7.0}));
    ScriptRun r3;
    r3.run(cube3d(1e10) + "load block=2 fz=-3 mx=2\nsave " + r3.path("s3.state") +
           "\nload block=2 fz=0 mx=0\nrestore " + r3.path("s3.state"));
    QCOMPARE(r3.model().blocks3.load_force[1].z(), -3.0);
    QCOMPARE(r3.model().blocks3.load_moment[1].x(), 2.0);
    // A 3D cut through the loaded cube is refused, the model as it was.
    try {
      r3.run("jset dip=90 ddir=90 spacing=10 origin=0.5,0,0");
      QFAIL("a loaded 3D block was cut");
    } catch (const ScriptError& e) {
      QVERIFY(std::string(e.what()).find("block 2 carries a load") != std::string::npos);
    }
    QCOMPARE(r3.model().blocks3.size(), size_t(2));
  }

  // What the command refuses, naming the block, and what it leaves as it was.
  void refusesWhatItCannotLoad() {
    ScriptRun r;
    r.run(tessera::test::incline_script(0, 30));
    QVERIFY_THROWS_EXCEPTION(ScriptError, r.run("load block=2"));
    QVERIFY_THROWS_EXCEPTION(ScriptError, r.run("load block=2 fz=1"));
    QVERIFY_THROWS_EXCEPTION(ScriptError, r.run("load block=9 fx=1"));
    QVERIFY_THROWS_EXCEPTION(ScriptError, r.run("load block=2 fx=1 table=none"));
    r.run("load block=2 fx=5 moment=2\nload block=2 fy=-3");
    QCOMPARE(r.model().blocks.load_fx[1], 5.0);  // components not given stay
    QCOMPARE(r.model().blocks.load_fy[1], -3.0);
    QCOMPARE(r.model().blocks.load_m[1], 2.0);
    try {
      r.run("jset angle=90 spacing=0.5 origin=0.25,0");
      QFAIL("a loaded block was cut");
    } catch (const ScriptError& e) {
      qInfo("%s", e.what());
      QVERIFY(std::string(e.what()).find("block 2 carries a load") != std::string::npos);
    }
  }
};

QTEST_GUILESS_MAIN(TestLoads)
#include "test_loads.moc"
