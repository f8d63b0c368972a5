// Bolts across joints (local reinforcement): a block on a frictionless joint held only by a bolt,
// against the closed form of the bolt's two springs and their yield forces.
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/io/state_io.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
// A 2 x 1 m block (density 2500: 5,000 kg per metre) on a fixed base along y = 0, frictionless
// joint kn = ks = 1e10, and a bolt from inside the base across the joint into the block.
std::string bolted(const std::string& bolt, const std::string& extra = "") {
  return "round 0.005\n"
         "material define rock density=2500\n"
         "joint define smooth kn=1e10 ks=1e10 friction=0\n"
         "joint assign smooth\n"
         "block 0,-1 4,-1 4,0 0,0 group=base material=rock\n"
         "block 1,0 3,0 3,1 1,1 group=top material=rock\n"
         "fix group=base\n" +
         extra + bolt + "\n";
}
constexpr double kMass = 5000.0;
constexpr double kDeg = M_PI / 180.0;
}  // namespace

class TestReinforcement : public QObject {
  Q_OBJECT
 private slots:
  // A sideways load m gx on a frictionless joint is held by the bolt's shear spring alone:
  // slip u = m gx / ks and the shear force m gx.
  void shearSpringHoldsSideLoad() {
    ScriptRun r;
    // Bolted after the block has settled on the joint, then loaded sideways.
    r.run(bolted("bolt 2,-0.5 2,0.8 ka=1e8 ks=1e7 name=b", "gravity 0 -9.81\nsolve ratio=1e-7\n") +
          "gravity 0.5 -9.81\nsolve ratio=1e-7");
    const Model& m = r.model();
    const Reinforcement& R = m.support;
    QCOMPARE(R.size(), size_t(1));
    const double load = kMass * 0.5, slip = m.blocks.x[1] - m.blocks.x_ref[1];
    qInfo("shear force %.6g N (load %.6g), slip %.6g m (closed form %.6g)", R.shear[0], load, slip,
          load / 1e7);
    QVERIFY(std::abs(-R.shear[0] - load) < 1e-4 * load);
    QVERIFY(std::abs(slip - load / 1e7) < 0.01 * load / 1e7);
    QVERIFY(std::abs(R.axial[0]) < 1e-3 * load);
  }
  // Gravity reversed: the block hangs from the bolt, which carries its weight in tension and
  // stretches by m g / ka; with a rupture displacement below that, it breaks and lets go.
  void axialSpringCarriesTheWeight() {
    ScriptRun r;
    r.run(bolted("bolt 2,-0.5 2,0.8 ka=1e8 ks=1e7 name=b") + "gravity 0 9.81\nsolve ratio=1e-7");
    const Model& m = r.model();
    const double w = kMass * 9.81, open = m.blocks.y[1] - m.blocks.y_ref[1];
    qInfo("axial force %.6g N (weight %.6g), opening %.6g m (closed form %.6g)", m.support.axial[0],
          w, open, w / 1e8);
    QVERIFY(std::abs(m.support.axial[0] - w) < 1e-4 * w);
    QVERIFY(std::abs(open - w / 1e8) < 0.01 * w / 1e8);
    QVERIFY(std::abs(m.support.ua[0] - w / 1e8) < 0.01 * w / 1e8);

    ScriptRun broken;
    broken.run(bolted("bolt 2,-0.5 2,0.8 ka=1e8 ks=1e7 rupture=2e-4 name=b") +
               "gravity 0 9.81\nstep 3000");
    const Model& mb = broken.model();
    QVERIFY(mb.support.state[0] & kBoltBroken);
    QCOMPARE(mb.support.axial[0], 0.0);
    QVERIFY(mb.blocks.vy[1] > 0.1);  // falling upwards, free
  }
  // A bolt at 60 degrees to a joint sheared at a steady rate: with slip u along the joint and
  // opening v across it, the springs stretch ua = u cos + v sin and shear us = v cos - u sin,
  // and the force resisting slip is ka ua cos - ks us sin until the axial spring yields at T,
  // the shear spring at S (the springs' closed form). Soft joints let the bolt pull the block
  // down into the joint (v < 0); stiff ones hardly.
  void inclinedBoltAgainstSlip_data() {
    QTest::addColumn<double>("kn");
    QTest::newRow("stiff joint 1e10") << 1e10;
    QTest::newRow("soft joint 1e8") << 1e8;
  }
  void inclinedBoltAgainstSlip() {
    QFETCH(double, kn);
    const double ka = 2e7, ks = 4e6, T = 4000.0, S = 3000.0, a = 60 * kDeg;
    const double c = std::cos(a), s = std::sin(a);
    ScriptRun r;
    r.run(bolted("bolt 2-0.5*cos(60),-0.5*sin(60) 2+0.5*cos(60),0.5*sin(60) ka=2e7 ks=4e6 "
                 "tension=4000 shear=3000 name=b",
                 "joint define smooth kn=" + std::to_string(kn) + " ks=" + std::to_string(kn) +
                     " friction=0\ngravity 0 -9.81\nsolve ratio=1e-7\n") +
          "fix group=top x rotation\nvelocity group=top vx=0.005\ndamping none");
    Model& m = r.model();
    // Joints and bolts move by the velocities of the step before (read before they are
    // integrated): a cycle's springs see the block where it was one step earlier.
    const double x0 = m.blocks.x[1], y0 = m.blocks.y[1];
    double worst = 0.0, sink = 0.0;
    int samples = 0;
    bool axial_yield = false, shear_yield = false;
    // About 100 samples over 2 mm of slip (0.4 s).
    const std::string every = "step " + std::to_string(1 + static_cast<int>(0.004 / m.dt));
    while (m.blocks.x[1] - x0 < 2e-3) {
      r.run(every);
      const double u = m.blocks.x[1] - m.dt * m.blocks.vx[1] - x0;
      const double v = m.blocks.y[1] - m.dt * m.blocks.vy[1] - y0;
      const double fa = std::min(ka * (u * c + v * s), T);
      const double fs = std::clamp(ks * (v * c - u * s), -S, S);
      const double expect = fa * c - fs * s;
      // The bolt's pull on the block along the joint, against the slip.
      const double f = m.support.axial[0] * c - m.support.shear[0] * s;
      worst = std::max(worst, std::abs(f - expect) / expect);
      sink = std::min(sink, v);
      ++samples;
      axial_yield |= (m.support.state[0] & kBoltAxialYield) != 0;
      shear_yield |= (m.support.state[0] & kBoltShearYield) != 0;
    }
    qInfo("%d samples over 2 mm of slip, block pulled %.3g mm into the joint: largest error %.3g%%",
          samples, -1e3 * sink, 100 * worst);
    QVERIFY(samples > 80);
    QVERIFY(axial_yield && shear_yield);
    QVERIFY(worst < 1e-4);
  }
  // A deformable block hanging from a bolt: the zones carry the weight to the bolt.
  void deformableBlockHangsFromTheBolt() {
    ScriptRun r;
    r.run(bolted("bolt 2,-0.5 2,0.8 ka=1e8 ks=1e7 name=b",
                 "material define rock density=2500 E=1e9 nu=0.25\nzone generate edge=0.25 "
                 "group=top\n") +
          "gravity 0 9.81\nsolve ratio=1e-6");
    const double w = kMass * 9.81;
    qInfo("axial force %.6g N (weight %.6g)", r.model().support.axial[0], w);
    QVERIFY(r.model().support.side_b[0].node[0] >= 0);
    QVERIFY(std::abs(r.model().support.axial[0] - w) < 1e-3 * w);
  }
  // Crossings follow the blocks through excavation and through a state file.
  void boltsFollowDeletionAndStateFiles() {
    ScriptRun r;
    r.run(bolted("bolt 2,-0.5 2,2.5 ka=1e8 ks=1e7 name=b",
                 "block 1,1 3,1 3,2 1,2 group=cap material=rock\n") +
          "gravity 0 -9.81\nhistory bolt_axial bolt=b at=2,1\nstep 200");
    QCOMPARE(r.model().support.size(), size_t(2));
    save_state(r.model(), r.path("s.tes"));
    const Model back = restore_state(r.path("s.tes"));
    QCOMPARE(back.support.size(), size_t(2));
    QCOMPARE(back.support.axial, r.model().support.axial);
    QCOMPARE(back.support.bolts[0].name, std::string("b"));
    // The history was at the upper crossing (y = 1), which goes with the cap.
    r.run("delete group=cap\nstep 20");
    QCOMPARE(r.model().support.size(), size_t(1));
    QCOMPARE(r.model().histories.series[0].element, -1);
    QVERIFY(std::isnan(r.model().histories.values.back()));
    r.run("delete group=top");
    QCOMPARE(r.model().support.bolts.size(), size_t(0));
  }
  // A pattern around an excavated circular opening in bedded rock: radial bolts on the arc,
  // every crossing anchored in rock on both sides.
  void patternAroundAnOpening() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2600\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block -10,-10 10,-10 10,10 -10,10 material=rock\n"
        "jset angle=20 spacing=1.5\n"
        "tunnel circle centre=0,0 radius=3 name=tunnel group=tunnel\n"
        "delete group=tunnel\n"
        "bolt pattern joints=tunnel spacing=1 length=4 angles=0,180 ka=1e8 ks=1e7 "
        "tension=2e5 name=roof");
    const Reinforcement& R = r.model().support;
    QVERIFY(R.bolts.size() >= 8);
    QVERIFY(R.size() >= R.bolts.size());
    for (size_t e = 0; e < R.size(); ++e) {
      const Vec2 p = anchor_position(r.model(), R.side_a[e]);
      QVERIFY(p.y() > -0.2);                      // on the upper half
      QVERIFY(p.norm() > 2.9 && p.norm() < 7.1);  // between the wall and the bolt's end
      QVERIFY(R.side_a[e].block != R.side_b[e].block);
    }
    // Bolts NAME-k and NAME-(k+1) start one spacing apart along the wall (a chord of the
    // polygonal wall: a little less), whichever way each wall edge's outline runs.
    for (size_t i = 0; i + 1 < R.bolts.size(); ++i) {
      const auto number = [](const std::string& n) {
        return std::stoi(n.substr(n.rfind('-') + 1));
      };
      if (number(R.bolts[i + 1].name) != number(R.bolts[i].name) + 1) continue;
      const double gap = (anchor_position(r.model(), R.bolts[i + 1].end0) -
                          anchor_position(r.model(), R.bolts[i].end0))
                             .norm();
      QVERIFY2(gap > 0.95 && gap < 1.0 + 1e-9, qPrintable(QString::number(gap)));
    }
  }
};

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  TestReinforcement t;
  return tessera::test::run_tests(t, argc, argv);
}

#include "test_reinforcement.moc"
