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
    // psi = 30 degrees: tan(psi) = 0.577; b/h = 1 stands, b/h = 0.25 topples; tan(20) = 0.364.
    QTest::newRow("stable") << 40.0 << 1.0 << 1.0 << false << false;
    QTest::newRow("slides") << 20.0 << 1.0 << 1.0 << true << false;
    QTest::newRow("topples") << 40.0 << 0.5 << 2.0 << false << true;
    QTest::newRow("slides and topples") << 20.0 << 0.4 << 2.0 << true << true;
  }
  void endsInTheRightRegime() {
    QFETCH(double, phi);
    QFETCH(double, b);
    QFETCH(double, h);
    QFETCH(bool, slides);
    QFETCH(bool, topples);
    const double psi = 30 * M_PI / 180;
    ScriptRun r;
    r.run(tessera::test::incline_script(30, phi, b, h) + "damping local 0.8");
    Model& m = r.model();
    const Vec2 down(-std::cos(psi), -std::sin(psi));
    const uint32_t toe = m.blocks.vert_begin[1];
    const Vec2 toe0 = m.blocks.world_vertex[toe];
    // Run 4 s, or until the block has clearly tipped over (20 degrees).
    while (m.time < 4.0 && std::abs(m.blocks.theta[1]) < 0.35) r.run("step 200");
    const double rotation = m.blocks.theta[1];
    const double toe_slide = (m.blocks.world_vertex[toe] - toe0).dot(down);
    qInfo("t = %.2f s: rotation %.4f rad, toe slid %.4f m", m.time, rotation, toe_slide);
    QCOMPARE(toe_slide > 0.01, slides);
    QCOMPARE(rotation > 0.1, topples);
    // The regimes that do not move stay well inside the thresholds.
    if (!slides) QVERIFY(std::abs(toe_slide) < 2e-3);
    if (!topples) QVERIFY(std::abs(rotation) < 0.01);
  }
};

QTEST_APPLESS_MAIN(TestToppling)
#include "test_toppling.moc"
