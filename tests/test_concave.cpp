// Concave blocks: an L-shaped block standing on a base, and a block resting in the notch of a
// fixed L: both come to rest with contact forces that balance the weight. A block standing on
// two feet, and a region cut in two by a tunnel: the joint's length is shared only where the
// joint runs, never across the gap between the feet or the opening.
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/contact2d/interfaces.hpp"

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

// Whether every contact's drawn stretch lies within one of the x ranges (to `slack`).
bool stretches_within(const Model& m, const std::vector<std::pair<double, double>>& ranges,
                      double slack) {
  const std::vector<ContactStretch> st = contact_stretches(m);
  for (size_t i = 0; i < st.size(); ++i) {
    if (m.contacts.kind[i] == kLost) continue;
    const double lo = std::min(st[i].from.x(), st[i].to.x());
    const double hi = std::max(st[i].from.x(), st[i].to.x());
    bool inside = false;
    for (const auto& [x0, x1] : ranges) inside |= lo >= x0 - slack && hi <= x1 + slack;
    if (!inside) return false;
  }
  return true;
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
  // A 4 m block standing on two 1 m feet (an arch's springings, a table): the joint is the feet,
  // 2 m, so it settles W / (2 kn), on soft joints and stiff. The gap between the feet shared as
  // joint (as it was) halved the settlement.
  void blockOnTwoFeetSettlesOnTheFeet() {
    for (const double kn : {1e8, 1e11}) {
      ScriptRun r;
      r.run("round 0.001\nmaterial define rock density=2500\njoint define j kn=" + test::num(kn) +
            " ks=" + test::num(kn) +
            " friction=30\njoint assign j\ngravity 0 -9.81\n"
            "block -1,-1 5,-1 5,0 -1,0 group=base material=rock\nfix group=base\n"
            "block 0,0 1,0 1,1 3,1 3,0 4,0 4,2 0,2 material=rock\n"
            "solve ratio=1e-8\n");
      const Model& m = r.model();
      QVERIFY(!m.blocks.all_convex[1]);
      const double weight = m.blocks.mass[1] * 9.81;
      // The feet less the rounded corners' insets (0.001 m at each of four corners).
      QVERIFY(std::abs(test::joint_size(m) - 1.996) < 1e-9);
      const double settle = m.blocks.y_ref[1] - m.blocks.y[1];
      QVERIFY2(std::abs(settle / (weight / (2.0 * kn)) - 1.0) < 5e-3,
               std::to_string(settle).c_str());
      QVERIFY(std::abs(m.blocks.theta[1]) < 1e-9);
      QVERIFY(stretches_within(m, {{0.0, 1.0}, {3.0, 4.0}}, 1e-9));
    }
  }
  // A region cut by a circular tunnel through its middle: its two halves meet on either side of
  // the opening, 4 m less the opening's chord each side. Those joints are shared along their
  // own length, and drawn there; nothing spans the opening.
  void nothingSpansTheOpening() {
    ScriptRun r;
    r.run(std::string(kSetup) +
          "region -5,-5 5,5 group=rock material=rock\n"
          "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\n"
          "delete group=t\nfix at=0,-4\nstep 20\n");
    const Model& m = r.model();
    QCOMPARE(m.blocks.size(), size_t(2));
    // The halves meet along y = -sin(15 deg) / 2, through the middle of the 24-gon's chords at
    // |x| = (1 + cos 15 deg) / 2; rounding insets each joint's ends by 0.01.
    const double edge = 0.5 * (1.0 + std::cos(15.0 * M_PI / 180.0)), round = 0.01;
    const double joint = 2.0 * (5.0 - edge - 2.0 * round);
    QVERIFY2(std::abs(test::joint_size(m) - joint) < 1e-6,
             std::to_string(test::joint_size(m)).c_str());
    QVERIFY(stretches_within(m, {{-5.0, -edge}, {edge, 5.0}}, 1e-9));
  }
};

QTEST_APPLESS_MAIN(TestConcave)
#include "test_concave.moc"
