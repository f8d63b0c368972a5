// Grouted cables: a cable pulled from rock against the closed-form pull-out solution (elastic
// grout, partly slipping grout, pull-out capacity) in 2D and 3D models (one mechanism, hosts of
// either dimension), pretension through a faceplate, and the cable kept through deletion, state
// files and bad input.
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/io/state_io.hpp"

using namespace tessera;
using tessera::test::num;
using tessera::test::ScriptRun;

namespace {
// A fixed rock block 4 m long (x from 0.5 to 4.5) and a free plate (x from 0 to 0.4, 1,000 kg
// per metre) 0.1 m from it; a cable tied to the plate at x = 0.4 runs through the gap and the
// whole rock, nodes every 0.1 m. EA = 1e8 N, kbond = 1e8 N/m/m: alpha = sqrt(kbond / EA) = 1/m,
// alpha L = 4. The plate's weight along -x pulls the cable out.
constexpr double kEA = 1e8, kBond = 1e8, kL = 4.0, kGap = 0.1;
std::string pulled(const std::string& load, const std::string& extra = "") {
  return "round 0.01\n"
         "material define rock density=2500\n"
         "joint define j kn=1e10 ks=1e10 friction=30\n"
         "joint assign j\n"
         "block 0.5,-1 4.5,-1 4.5,1 0.5,1 material=rock group=rock\n"
         "block 0,-0.5 0.4,-0.5 0.4,0.5 0,0.5 material=rock group=plate\n"
         "fix group=rock\n"
         "cable 0.4,0 4.5,0 segments=41 ea=1e8 kbond=1e8 sbond=2e4 head=on name=c" +
         extra + "\n" + load + "\n";
}
// The same in 3D: a rock box 2 m square in section, a plate 1 m square and 0.4 m thick (1,000
// kg), the cable along the x axis through both. (3D cable properties are per cable.)
std::string pulled3(const std::string& load) {
  return "dimension 3\ntolerance 0.01\n"
         "material define rock density=2500\n"
         "joint define j kn=1e10 ks=1e10 friction=30\n"
         "joint assign j\n"
         "block box 0.5,-1,-1 4.5,1,1 material=rock group=rock\n"
         "block box 0,-0.5,-0.5 0.4,0.5,0.5 material=rock group=plate\n"
         "fix group=rock\n"
         "cable 0.4,0,0 4.5,0,0 segments=41 ea=1e8 kbond=1e8 sbond=2e4 head=on name=c\n" +
         load + "\n";
}
// A pull-out run in 2D or 3D: the load in 2D words (gravity GX 0, vx=), written for the
// dimension; the cable's nodes and the plate's displacement along -x.
struct PullOut {
  ScriptRun r;
  int dim = 2;
  PullOut(int d, std::string load) : dim(d) {
    if (dim == 3)
      for (size_t at = load.find("gravity -10 0"); at != std::string::npos;
           at = load.find("gravity -10 0", at + 1))
        load.replace(at, 13, "gravity -10 0 0");
    r.run(dim == 3 ? pulled3(load) : pulled(load));
  }
  // The node arrays, whichever the dimension (the same fields in both).
  template <class F>
  void with_cables(F f) {
    if (dim == 3)
      f(r.model().cables3);
    else
      f(r.model().cables);
  }
  double plate_moved() {
    const Model& m = r.model();
    return dim == 3 ? m.blocks3.ref[1].x() - m.blocks3.body[1].position.x()
                    : m.blocks.x_ref[1] - m.blocks.x[1];
  }
};
void dimensions() {
  QTest::addColumn<int>("dim");
  QTest::newRow("2D") << 2;
  QTest::newRow("3D") << 3;
}
// The rock's cable nodes: the first at the rock face (x = 0.5), after the head and the gap.
constexpr uint32_t kFace = 1;

// The checks of each pull-out against its closed form, on the node arrays of either dimension.
template <class K_>
void check_elastic(const K_& K, double moved) {
  const double P = 1000.0 * 10.0, alpha = std::sqrt(kBond / kEA);
  qInfo("force across the gap %.6g N (load %.6g)", K.axial[0], P);
  QVERIFY(std::abs(K.axial[0] - P) < 1e-6 * P);
  const double slip = P / (kEA * alpha * std::tanh(alpha * kL));
  qInfo("slip at the rock face %.6g m (closed form %.6g)", K.slip[kFace], slip);
  QVERIFY(std::abs(K.slip[kFace] - slip) < 2e-3 * slip);
  double worst = 0.0;
  for (uint32_t i = kFace; i + 1 < K.size(); ++i) {
    // A segment's force at its middle.
    const double x = (i - kFace + 0.5) * 0.1;
    const double n = P * std::sinh(alpha * (kL - x)) / std::sinh(alpha * kL);
    worst = std::max(worst, std::abs(K.axial[i] - n) / P);
  }
  qInfo("largest error in the axial force along the cable: %.3g of the load", worst);
  QVERIFY(worst < 3e-3);
  // The plate moves by the slip and the stretch of the free length across the gap.
  QVERIFY(std::abs(moved - (slip + P * kGap / kEA)) < 2e-3 * moved);
}
template <class K_>
void check_slipping(const K_& K) {
  const double P = K.axial[0], s = 2e4, alpha = 1.0;
  QVERIFY(P > 4e4 && P < 7e4);  // well into slip, short of the capacity 8e4
  double lo = 0.0, hi = kL;     // bisection for a
  for (int k = 0; k < 100; ++k) {
    const double a = 0.5 * (lo + hi);
    (s * a + s / alpha * std::tanh(alpha * (kL - a)) < P ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  const double slip = s / kBond + (P * a - 0.5 * s * a * a) / kEA;
  int yielding = 0;
  for (uint32_t i = kFace; i < K.size(); ++i) yielding += K.slip_plastic[i] != 0.0;
  qInfo(
      "pulled with %.6g N: slipping length %.4g m (closed form %.4g), slip at the face %.6g m "
      "(closed form %.6g)",
      P, 0.1 * (yielding - 0.5), a, K.slip[kFace], slip);
  QVERIFY(std::abs(K.slip[kFace] - slip) < 5e-3 * slip);
  QVERIFY(std::abs(0.1 * (yielding - 0.5) - a) <= 0.1);
  QVERIFY(std::abs(K.bond[kFace] - s) < 1e-3 * s);
}
template <class K_>
void check_capacity(const K_& K) {
  qInfo("force at pull-out %.6g N (closed form %.6g)", K.axial[0], 2e4 * kL);
  QVERIFY(std::abs(K.axial[0] - 2e4 * kL) < 1e-3 * 2e4 * kL);
  for (uint32_t i = kFace; i < K.size(); ++i) QVERIFY(K.state[i] & kCableBondYield);
}
}  // namespace

class TestCables : public QObject {
  Q_OBJECT
 private slots:
  // Elastic grout (shear lag): N(x) = P sinh(alpha (L - x)) / sinh(alpha L) along the rock, and
  // the cable enters the rock with the slip P / (EA alpha tanh(alpha L)). The cable's segments
  // and grout springs every h = 0.1 m approximate it to about (alpha h)^2 / 12 = 0.1%.
  void elasticPullOut_data() { dimensions(); }
  void elasticPullOut() {
    QFETCH(int, dim);
    PullOut run(dim, "gravity -10 0\nsolve ratio=1e-9");
    run.with_cables([&](const auto& K) { check_elastic(K, run.plate_moved()); });
  }
  // Past the bond strength sbond the grout slips over a length a from the face: there
  // N = P - sbond x, beyond it the elastic solution with N(a) = (sbond / alpha) tanh(alpha
  // (L - a)). So P = sbond a + (sbond / alpha) tanh(alpha (L - a)), and the cable enters the
  // rock with slip sbond / kbond + (P a - sbond a^2 / 2) / EA. The plate is drawn out slowly
  // (a load applied at once would overshoot and slip the grout further than the static answer).
  void slippingGroutPullOut_data() { dimensions(); }
  void slippingGroutPullOut() {
    QFETCH(int, dim);
    PullOut run(dim,
                "fix group=plate\nvelocity group=plate vx=-0.02\nstep 2500\n"
                "velocity group=plate vx=0\nstep 1000");
    run.with_cables([&](const auto& K) { check_slipping(K); });
  }
  // Pulled past its capacity the cable slides out through grout slipping everywhere; held there,
  // the force across the gap settles at the bond strength times the bonded length, 8e4 N.
  void pullOutCapacity_data() { dimensions(); }
  void pullOutCapacity() {
    QFETCH(int, dim);
    PullOut run(dim,
                "fix group=plate\nvelocity group=plate vx=-0.1\nstep 3000\n"
                "velocity group=plate vx=0\nstep 2000");
    run.with_cables([&](const auto& K) { check_capacity(K); });
  }
  // 3D: a plate (2 x 1 x 0.4 m, 20 kN) hung 0.1 m below the rock on three vertical cables tied
  // to it off its centroid. Statics alone fixes the forces (vertical equilibrium and moments
  // about both horizontal axes): the cables must hand the plate their torques as well as their
  // pull, whatever their stiffness.
  // The plate rigid, or zoned (an elastic plate: its zones' corner nodes take each cable node's
  // grout force by their weights, and the forces are still those of statics).
  void threeCablesShareAHangingPlate_data() {
    QTest::addColumn<bool>("zoned");
    QTest::newRow("rigid") << false;
    QTest::newRow("zoned") << true;
  }
  void threeCablesShareAHangingPlate() {
    QFETCH(bool, zoned);
    ScriptRun r;
    const double xy[3][2] = {{-0.5, -0.3}, {0.7, -0.2}, {0.1, 0.35}};
    std::string script =
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2500 E=1e10 nu=0.25\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block box -2,-2,0 2,2,2 material=rock group=rock\n"
        "block box -1,-0.5,-0.5 1,0.5,-0.1 material=rock group=plate\nfix group=rock\n" +
        // (zoned: kinetic damping, which stops the plate's slow swing on the cables sooner)
        std::string(zoned ? "zone generate edge=0.6 group=plate\ntimestep scaled\n"
                            "damping kinetic\n"
                          : "");
    // Rigid: each cable tied to the plate's top. Zoned: grouted through the whole plate from its
    // underside (nodes every 0.1 m in its zones), so the grout hands the zones the weight.
    for (const auto& p : xy)
      script += "cable " + std::to_string(p[0]) + "," + std::to_string(p[1]) +
                (zoned ? ",-0.5 " : ",-0.1 ") + std::to_string(p[0]) + "," + std::to_string(p[1]) +
                ",2 ea=1e8 kbond=1e8 sbond=0 " +
                (zoned ? "segments=25\n" : "segments=21 head=on\n");
    r.run(script + "gravity 0 0 -10\nsolve ratio=" + (zoned ? "1e-6" : "1e-9"));
    const Cables3& K = r.model().cables3;
    QCOMPARE(K.cables.size(), size_t(3));
    Eigen::Matrix3d A;
    for (int k = 0; k < 3; ++k) A.col(k) = Eigen::Vector3d(1.0, xy[k][0], xy[k][1]);
    const Eigen::Vector3d T = A.inverse() * Eigen::Vector3d(2e4, 0.0, 0.0);
    for (int k = 0; k < 3; ++k) {
      // The segment across the gap, from the plate's top.
      const double f = K.axial[K.cables[static_cast<size_t>(k)].first + (zoned ? 4u : 0u)];
      qInfo("cable %d: %.6g N at the plate (statics %.6g N)", k + 1, f, T[k]);
      QVERIFY(std::abs(f - T[k]) < 1e-3 * 2e4);
    }
    // The plate hangs level to within the cables' unequal stretch.
    const Model& m = r.model();
    if (zoned) {
      QVERIFY(m.continuum3.zone_count() > 20);
      QVERIFY(K.host[0].node[0] >= 0 && K.bonded[0] > 0.0);
      return;
    }
    const double turned =
        2.0 *
        std::acos(std::min(1.0, std::abs(m.blocks3.body[1].orientation.dot(m.blocks3.ref_q[1]))));
    qInfo("plate turned %.3g rad", turned);
    QVERIFY(turned < 1e-3);
  }
  // The bond strength rising with confinement (FLAC's sfriction and perimeter): the rock zoned,
  // held at every node under an in-situ stress of 1 MPa all round, so each node's grout has the
  // strength sbond + 1e6 tan(30) perimeter per metre; pulled out, the force settles at that
  // times the bonded length, 3.1e5 N rather than the 8e4 N of sbond alone.
  void confinementRaisesTheBondStrength() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500 E=1e10 nu=0.25\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block 0.5,-1 4.5,-1 4.5,1 0.5,1 material=rock group=rock\n"
        "block 0,-0.5 0.4,-0.5 0.4,0.5 0,0.5 material=rock group=plate\n"
        "zone generate edge=0.5 group=rock\nboundary fix=xy x=0.45,4.55\n"
        "insitu stress=-1e6,-1e6,0 szz=-1e6\n"
        "cable 0.4,0 4.5,0 segments=41 ea=1e8 kbond=1e8 sbond=2e4 sfriction=30 perimeter=0.1 "
        "head=on name=c\n"
        "fix group=plate\nvelocity group=plate vx=-0.1\nstep 3000\n"
        "velocity group=plate vx=0\nstep 2000");
    const Cables& K = r.model().cables;
    const double capacity = (2e4 + 1e6 * std::tan(M_PI / 6) * 0.1) * kL;
    qInfo("force at pull-out %.6g N (closed form %.6g)", K.axial[0], capacity);
    QVERIFY(std::abs(K.axial[0] - capacity) < 1e-3 * capacity);
    // Every bonded node's grout at the confined strength.
    const double strength = capacity / kL;
    for (uint32_t i = kFace; i < K.size(); ++i)
      QVERIFY2(std::abs(K.bond[i] - strength) < 1e-6 * strength,
               qPrintable(QString("node %1: bond %2 N/m").arg(i).arg(K.bond[i])));
    // In a rigid block there is no confinement: sbond alone.
    ScriptRun rigid;
    rigid.run(
        pulled("fix group=plate\nvelocity group=plate vx=-0.1\nstep 3000\n"
               "velocity group=plate vx=0\nstep 2000",
               " sfriction=30 perimeter=0.1"));
    QVERIFY(std::abs(rigid.model().cables.axial[0] - 2e4 * kL) < 1e-3 * 2e4 * kL);
  }
  // A cable tensioned against its faceplate: the plate presses the rock with the pretension,
  // less what the cable gives back as it shortens, and the grout beyond the free length holds it.
  void pretensionHeldByTheGrout() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block 0.4,-1 4.4,-1 4.4,1 0.4,1 material=rock group=rock\n"
        "block 0,-0.5 0.4,-0.5 0.4,0.5 0,0.5 material=rock group=plate\n"
        "fix group=rock\n"
        "cable 0.2,0 4.4,0 segments=42 ea=1e8 kbond=1e8 sbond=1e5 head=on free=2.2 "
        "pretension=5e4 name=c\nsolve ratio=1e-9");
    const Model& m = r.model();
    const Cables& K = m.cables;
    // Shear lag in the bonded length Lb = 2 m, whose segments start at the pretension F0 and end
    // free: N'' = alpha^2 (N - F0), N(Lb) = 0, N(0) = F; its start draws in by N'(0) / kbond.
    // The free length Lf = 2.2 m shortens by that and by the joint's closure F / kj (kj = kn
    // times the 1 m plate): F = F0 - EA / Lf times both, whence
    // F = F0 (1 + (cosh - 1) / (Lf alpha sinh)) / (1 + 1 / (Lf alpha tanh) + EA / (Lf kj)).
    const double F0 = 5e4, kj = 1e10 * 1.0, Lf = 2.2, Lb = 2.0, alpha = 1.0;
    const double ch = std::cosh(alpha * Lb), sh = std::sinh(alpha * Lb);
    const double F = F0 * (1.0 + (ch - 1.0) / (Lf * alpha * sh)) /
                     (1.0 + ch / (Lf * alpha * sh) + kEA / (Lf * kj));
    double grout = 0.0;
    for (uint32_t i = 1; i < K.size(); ++i) grout += K.bond[i] * K.bonded[i];
    qInfo("cable force at the plate %.6g N (closed form %.6g), grout total %.6g N", K.axial[0], F,
          grout);
    QVERIFY(std::abs(K.axial[0] - F) < 2e-3 * F);
    QVERIFY(std::abs(grout - K.axial[0]) < 1e-4 * F);
    // Nodes every 0.1 m from x = 0.2: the grout starts at node 22, x = 2.4.
    for (uint32_t i = 0; i < 22; ++i) QCOMPARE(K.bonded[i], 0.0);
    QCOMPARE(K.bonded[22], 0.05);
  }
  // A block on a 30 degree slide held by a cable across the joint (tension cap 6000 N), on soft
  // joints: with friction cut by 1.30, beyond the limit tan 20 (W cos 30 + T sin 30) /
  // (W sin 30 - T cos 30) = 1.2485, block and cable nodes slide on together; the block alone is in
  // balance (its grout pulls it back), the nodes are not, and the ratio must say so (it counted
  // blocks only: 'solve' stopped at 1e-5 with the block sliding 1.75 mm/s, and 'solve fos'
  // gave 1.30 on these joints). At 1.2 the model stands.
  void creepingCableNodesAreNotSolved() {
    const std::string model =
        "dimension 3\ntolerance 0.005\nset c = cos(30)\nset s = sin(30)\n"
        "material define rock density=2500\njoint define j kn=1e8 ks=1e8 friction=20\n"
        "joint assign j\n"
        "block prism (-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s) z=-1,2 "
        "group=slab material=rock\n"
        "block prism 0,0 c,s (c-s),(s+c) (-s),c z=0,1 group=blk material=rock\nfix group=slab\n"
        "cable -0.117,0.25,0.5 1.383,0.25,0.5 segments=15 ea=1e8 kbond=1e9 sbond=0 tension=6000 "
        "name=cb\ntable ramp 0,0 1,1\ngravity 0 -9.81 0 table=ramp\nstep 2000\ntable stop\n"
        "solve ratio=1e-8\n";
    for (const double factor : {1.2, 1.3}) {
      ScriptRun r;
      r.run(model + "joint define j kn=1e8 ks=1e8 friction=(atan(tan(20)/" + num(factor) +
            "))\nsolve ratio=1e-5 cycles=20000\n");
      const Model& m = r.model();
      const double speed = m.blocks3.body[1].velocity.norm();
      qInfo("friction cut by %.2f: ratio %.3g, block at %.3g m/s", factor, m.ratio, speed);
      if (factor < 1.2485) {
        QVERIFY(m.ratio <= 1e-5);
        QVERIFY(speed < 1e-5);
      } else {
        QVERIFY(m.ratio > 1e-3);
        QVERIFY(speed > 1e-4);
      }
    }
  }
  // Support that carries nothing is solved: its nodes' forces are round-off, which is no
  // measure of balance (a liner ring and a cable pattern in fixed rock, and a cable cut by
  // excavation left in a free block, stayed at ratios 1-4 to the cycle limit).
  void unloadedSupportIsSolved() {
    const std::string rock =
        "round 0.01\nmaterial define rock density=2500\njoint define j kn=1e10 ks=1e10 "
        "friction=30\njoint assign j\nregion -5,-5 5,5 group=rock material=rock\n"
        "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\ndelete group=t\nfix all\n";
    const std::vector<std::string> support = {
        "liner joints=t e=25e9 nu=0.2 thickness=0.2 kn=1e10 ks=1e10 name=L\n",
        "cable pattern joints=t spacing=1 length=2 segments=4 ea=1e8 kbond=1e8 sbond=2e5\n"};
    for (const std::string& s : support) {
      ScriptRun r;
      r.run(rock + s + "solve ratio=1e-5 cycles=2000\n");
      QVERIFY2(r.model().ratio <= 1e-5, s.c_str());
      QVERIFY(r.model().cycle < 100);
    }
    // A pretensioned cable through three blocks; the middle one dug out leaves the cap free
    // (no gravity) with the cable's cut end in it, carrying nothing.
    ScriptRun r;
    r.run(
        "round 0.005\nmaterial define rock density=2500\njoint define j kn=1e10 ks=1e10 "
        "friction=30\njoint assign j\nblock 0,-2 4,-2 4,0 0,0 group=base material=rock\n"
        "block 1,0 3,0 3,1 1,1 group=top material=rock\n"
        "block 1,1 3,1 3,2 1,2 group=cap material=rock\nfix group=base\n"
        "cable 2,2 2,-1.8 segments=19 ea=1e8 kbond=1e8 sbond=2e5 pretension=1e5 free=1.5 "
        "head=on name=c\nsolve ratio=1e-8\ndelete group=top\nsolve ratio=1e-8 cycles=2000\n");
    QVERIFY(r.model().ratio <= 1e-8);
    QVERIFY(r.model().cycle < 10000);
  }
  // Deleting the rock a cable runs through cuts it; the rest carries on, and state files keep
  // it bit for bit.
  void deletionAndStateFiles() {
    ScriptRun r;
    r.run(pulled("gravity -10 0\nstep 200\nhistory cable_axial cable=c at=3,0"));
    Model& m = r.model();
    const std::string path = QDir::tempPath().toStdString() + "/tessera_cables.state";
    save_state(m, path);
    Model back = restore_state(path);
    QCOMPARE(back.cables.size(), m.cables.size());
    QCOMPARE(back.cables.axial, m.cables.axial);
    QCOMPARE(back.cables.cables[0].name, std::string("c"));
    std::remove(path.c_str());
    r.run("delete group=plate");
    QCOMPARE(r.model().cables.cables.size(), size_t(1));
    QCOMPARE(r.model().cables.size(), size_t(41));  // the head is gone with its plate
    QCOMPARE(r.model().cables.cables[0].head, uint8_t(0));
    QVERIFY(r.model().histories.series[0].element >= 0);
    r.run("step 10\ndelete group=rock");
    QCOMPARE(r.model().cables.size(), size_t(0));
  }
  // The same in 3D: state files keep the cable bit for bit, a history follows its node, and
  // deleting the plate takes the head with it.
  void deletionAndStateFiles3d() {
    ScriptRun r;
    r.run(pulled3("gravity -10 0 0\nstep 200\nhistory cable_axial cable=c at=3,0,0"));
    Model& m = r.model();
    const std::string path = QDir::tempPath().toStdString() + "/tessera_cables3.state";
    save_state(m, path);
    Model back = restore_state(path);
    QCOMPARE(back.cables3.size(), m.cables3.size());
    QCOMPARE(back.cables3.axial, m.cables3.axial);
    QCOMPARE(back.cables3.slip, m.cables3.slip);
    std::remove(path.c_str());
    QCOMPARE(m.histories.series[0].element, 26);  // the node at x = 3
    r.run("delete group=plate");
    QCOMPARE(r.model().cables3.size(), size_t(41));
    QCOMPARE(r.model().cables3.cables[0].head, uint8_t(0));
    QCOMPARE(r.model().histories.series[0].element, 25);
    r.run("step 10\ndelete group=rock");
    QCOMPARE(r.model().cables3.size(), size_t(0));
  }
  // Bad input names the cable and what is wrong; 3D models refuse what is 2D only and name a
  // node in the air by its three coordinates.
  void badCablesAreNamed_data() {
    QTest::addColumn<int>("dim");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("no segments") << 2 << "cable 1,0 4,0 ea=1e8 kbond=1e8 sbond=0"
                                 << "segments";
    QTest::newRow("no stiffness") << 2 << "cable 1,0 4,0 segments=3 kbond=1e8 sbond=0"
                                  << "ea";
    QTest::newRow("node in the air")
        << 2 << "cable 1,0 8,0 segments=7 ea=1e8 kbond=1e8 sbond=0 name=long"
        << "node 5 at (5, 0)";
    QTest::newRow("taken name") << 2 << "cable 1,0 4,0 segments=3 ea=1e8 kbond=1e8 sbond=0 name=c"
                                << "exists already";
    QTest::newRow("pretension above yield")
        << 2 << "cable 1,0 4,0 segments=3 ea=1e8 kbond=1e8 sbond=0 tension=1e4 pretension=2e4"
        << "pretension";
    QTest::newRow("sfriction without perimeter")
        << 2 << "cable 1,0 4,0 segments=3 ea=1e8 kbond=1e8 sbond=0 sfriction=30"
        << "needs perimeter=P";
    QTest::newRow("sfriction out of range")
        << 2 << "cable 1,0 4,0 segments=3 ea=1e8 kbond=1e8 sbond=0 sfriction=95 perimeter=0.1"
        << "from 0 to 90 degrees";
    QTest::newRow("3D pattern") << 3
                                << "cable pattern joints=j spacing=1 length=3 segments=3 ea=1e8 "
                                   "kbond=1e8 sbond=0"
                                << "place 3D cables one by one";
    QTest::newRow("3D row spacing") << 3
                                    << "cable 1,0,0 4,0,0 segments=3 ea=1e8 kbond=1e8 sbond=0 "
                                       "rowspacing=2"
                                    << "rowspacing= is for 2D";
    QTest::newRow("3D given 2D points") << 3 << "cable 1,0 4,0 segments=3 ea=1e8 kbond=1e8 sbond=0"
                                        << "x,y,z";
    QTest::newRow("3D node in the air")
        << 3 << "cable 1,0,0 8,0,0 segments=7 ea=1e8 kbond=1e8 sbond=0"
        << "node 5 at (5, 0, 0)";
  }
  void badCablesAreNamed() {
    QFETCH(int, dim);
    QFETCH(QString, line);
    QFETCH(QString, message);
    PullOut run(dim, "");
    QString error;
    try {
      run.r.run(line.toStdString());
    } catch (const std::exception& e) {
      error = e.what();
    }
    QVERIFY2(error.contains(message), qPrintable(error));
    // Nothing half placed.
    run.with_cables([](const auto& K) { QCOMPARE(K.cables.size(), size_t(1)); });
  }
};

QTEST_GUILESS_MAIN(TestCables)
#include "test_cables.moc"
