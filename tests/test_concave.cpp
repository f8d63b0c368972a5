// Concave blocks: an L-shaped block standing on a base, and a block resting in the notch of a
// fixed L: both come to rest with contact forces that balance the weight.
#include <QtTest>
#include <cmath>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
const char* kSetup =
    "round 0.01\n"
    "material define rock density=2500\n"
    "joint define j kn=1e10 ks=1e10 friction=30\n"
    "joint assign j\n"
    "gravity 0 -9.81\n";

// Vertical force the contacts put on block b.
double contact_lift(const Model& m, size_t b) {
  double fy = 0.0;
  for (size_t i = 0; i < m.contacts.size(); ++i) {
    if (m.contacts.a[i] == b) fy += m.contacts.force(i).y();
    if (m.contacts.b[i] == b) fy -= m.contacts.force(i).y();
  }
  return fy;
}
}  // namespace

class TestConcave : public QObject {
  Q_OBJECT
 private slots:
  void lShapedBlockStandsOnItsFoot() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "block -1,-1 4,-1 4,0 -1,0 group=base material=rock\nfix group=base\n"
          "block 0,0 2,0 2,1 1,1 1,2 0,2 material=rock\n"
          "solve ratio=1e-7\n");
    const Model& m = r.model();
    QCOMPARE(m.blocks.area[1], 3.0);
    QVERIFY(!m.blocks.all_convex[1]);
    const double weight = m.blocks.mass[1] * 9.81;
    QVERIFY(std::abs(contact_lift(m, 1) - weight) < 1e-6 * weight);
    // Resting on its 2 m foot: small, uniform-ish settlement, no tipping.
    QVERIFY(std::abs(m.blocks.theta[1]) < 1e-5);
    QVERIFY(std::abs(m.blocks.y[1] - m.blocks.y_ref[1]) < 1e-5);
  }
  void blockRestsInTheNotchOfAnL() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "block 0,0 3,0 3,1 1,1 1,3 0,3 group=base material=rock\nfix group=base\n"
          "block 1,1 2,1 2,2 1,2 material=rock\n"
          "gravity -0.5 -9.81\n"  // pushed against the notch's wall, pressed on its floor
          "solve ratio=1e-7\n");
    const Model& m = r.model();
    const double weight = m.blocks.mass[1] * 9.81;
    QVERIFY(m.ratio <= 1e-7);
    QVERIFY(std::abs(contact_lift(m, 1) - weight) < 1e-6 * weight);
    // Stayed in the notch: moved less than a micrometre-scale elastic amount.
    QVERIFY(std::hypot(m.blocks.x[1] - m.blocks.x_ref[1], m.blocks.y[1] - m.blocks.y_ref[1]) <
            1e-5);
  }
};

QTEST_APPLESS_MAIN(TestConcave)
#include "test_concave.moc"
