// A block on an incline in each regime of Wyllie & Mah's chart: sliding when psi > phi,
// toppling when b/h < tan(psi); stable, slides, topples, or slides and topples. A block that is
// already sliding topples only when b/h < tan(phi) as well (the friction at its toe is then the
// only restoring moment; Bray & Goodman 1981), so the last case is chosen inside that corner.
#include <QtTest>
#include <cmath>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

class TestToppling : public QObject {
  Q_OBJECT
 private slots:
  void endsInTheRightRegime_data() {
    QTest::addColumn<double>("phi");
    QTest::addColumn<double>("b");
    QTest::addColumn<double>("h");
    QTest::addColumn<bool>("slides");
    QTest::addColumn<bool>("topples");
    QTest::addColumn<double>("kn");
    // psi = 30 degrees: tan(psi) = 0.577; b/h = 1 stands, b/h = 0.25 topples; tan(20) = 0.364.
    // Stiff joints (1e10 Pa/m) and soft ones (1e7 Pa/m, common in rock models). On soft joints
    // the slender block of the last case tips over (1.3 s) before it has slid measurably.
    for (const double kn : {1e10, 1e7}) {
      const std::string k = kn > 1e8 ? ", stiff joints" : ", soft joints";
      QTest::newRow(("stable" + k).c_str()) << 40.0 << 1.0 << 1.0 << false << false << kn;
      QTest::newRow(("slides" + k).c_str()) << 20.0 << 1.0 << 1.0 << true << false << kn;
      QTest::newRow(("topples" + k).c_str()) << 40.0 << 0.5 << 2.0 << false << true << kn;
    }
    QTest::newRow("slides and topples, stiff joints") << 20.0 << 0.4 << 2.0 << true << true << 1e10;
  }
  void endsInTheRightRegime() {
    QFETCH(double, phi);
    QFETCH(double, b);
    QFETCH(double, h);
    QFETCH(bool, slides);
    QFETCH(bool, topples);
    QFETCH(double, kn);
    const double psi = 30 * M_PI / 180;
    ScriptRun r;
    r.run(tessera::test::incline_script(30, phi, b, h, kn) + "damping local 0.8");
    Model& m = r.model();
    const Vec2 down(-std::cos(psi), -std::sin(psi));
    const uint32_t toe = m.blocks.vert_begin[1];
    const Vec2 toe0 = m.blocks.world_vertex[toe];
    // Run 4 s, or until the block has clearly tipped over (20 degrees).
    while (m.time < 4.0 && std::abs(m.blocks.theta[1]) < 0.35) r.run("step 50");
    const double rotation = m.blocks.theta[1];
    const double toe_slide = (m.blocks.world_vertex[toe] - toe0).dot(down);
    qInfo("t = %.2f s: rotation %.4f rad, toe slid %.4f m", m.time, rotation, toe_slide);
    QCOMPARE(rotation > 0.1, topples);
    // On soft joints a toppling block's toe sinks into its joint and its arc rolls: about a
    // centimetre of travel without slip by 20 degrees, against metres when it slides.
    const double slid = kn > 1e8 ? 0.01 : 0.1, still = kn > 1e8 ? 2e-3 : 0.02;
    QCOMPARE(toe_slide > slid, slides);
    if (!slides) QVERIFY(std::abs(toe_slide) < still);
    if (!topples) QVERIFY(std::abs(rotation) < 0.01);
  }

  // A tall block toppling on soft joints (kn = 1e7 Pa/m): once the heel lifts, the toe is alone
  // on its joint line. It stands for the wedge of the corner cut by the slab's surface, so its
  // depth stays that of a rigid wedge on a spring bed: F = kn s o / 2 with the wedge's extent
  // s = o (cot t + tan t) at tilt t, o = sqrt(2 F / (kn (cot t + tan t))). (The arc's chord
  // alone, at most 2d, let the toe sink 2.3 m by 1.5 s and 104 m by 6.2 s.)
  void softToeStaysWithinItsWedgeDepth() {
    const double kn = 1e7, W = 2000 * 9.81 * 10 * 25, g = 9.81, tilt = 30 * M_PI / 180;
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2000\n"
        "joint define soft kn=1e7 ks=1e7 friction=40\njoint assign soft\n"
        "block -60,-5 20,-5 20,0 -60,0 material=rock\nfix block=1\n"
        "block 0,0 10,0 10,25 0,25 material=rock\n"
        "gravity " +
        std::to_string(-g * std::sin(tilt)) + " " + std::to_string(-g * std::cos(tilt)) +
        "\ndamping none\n");
    Model& m = r.model();
    const uint32_t toe = m.blocks.vert_begin[1];
    double worst = 0.0, deepest = 0.0;
    while (m.time < 8.0 && m.blocks.theta[1] < 1.2) {
      r.run("step 100");
      const double t = m.blocks.theta[1], depth = -m.blocks.world_vertex[toe].y();
      deepest = std::max(deepest, depth);
      if (t < 0.02) continue;
      // The deepest a wedge carrying one and a half times the block's weight would go.
      const double bound = std::sqrt(2 * 1.5 * W / (kn * (1 / std::tan(t) + std::tan(t))));
      worst = std::max(worst, depth / bound);
    }
    qInfo("t = %.2f s, tilt %.3f rad: deepest toe %.3f m, worst depth / wedge bound %.3f", m.time,
          m.blocks.theta[1], deepest, worst);
    QVERIFY(m.blocks.theta[1] >= 1.2);  // it toppled
    QVERIFY(worst > 0.3 && worst < 1.0);
    QVERIFY(deepest < 1.0);
  }

  // A block pushed far into its joint stops the run with a message naming both blocks
  // (UDEC's "contact overlap too great"), rather than falling through its base.
  void overlapTooGreatStopsTheRun() {
    ScriptRun r;
    try {
      r.run(
          "round 0.01\nmaterial define rock density=2000\n"
          "joint define soft kn=1e5 ks=1e5 friction=40\njoint assign soft\n"
          "block -5,-5 5,-5 5,0 -5,0 material=rock group=slab\nfix block=1\n"
          "block 0,0 1,0 1,1 0,1 material=rock group=cube\ngravity 0 -10\nstep 20000");
      QFAIL("the run went on");
    } catch (const ScriptError& e) {
      const std::string msg = e.what();
      qInfo("%s", msg.c_str());
      QVERIFY(msg.find("test:9: contact overlap too great") != std::string::npos);
      QVERIFY(msg.find("block 2 (group cube) and block 1 (group slab)") != std::string::npos);
    }
  }
};

QTEST_APPLESS_MAIN(TestToppling)
#include "test_toppling.moc"
