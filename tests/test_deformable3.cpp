// Deformable 3D blocks in models built by script: tetrahedral zones touching rigid and
// deformable blocks through node-to-face sub-contacts, against closed-form answers.
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"
#include "tessera/io/state_io.hpp"

using namespace tessera;
using tessera::test::ScriptRun;
using tessera::test::state_hash;

namespace {
double last(const Model& m, const std::string& label) {
  const Histories& h = m.histories;
  return h.at(h.rows() - 1, static_cast<size_t>(h.find(label)));
}

// A rigid slab held fixed (block 1) and `blocks` zoned rock blocks 1 x 1 x h m stacked on it, of
// 4-node zones (edge 0.3) or 10-node ones (`quadratic`: edge 0.5).
std::string stack(int blocks, double h, double kn, const std::string& sides,
                  bool quadratic = false) {
  std::string s =
      "dimension 3\ntolerance 0.01\nmaterial define stone density=2500\n"
      "material define rock density=2000 E=1e9 nu=0.25\n"
      "joint define j kn=" +
      std::to_string(kn) + " ks=" + std::to_string(kn) +
      " friction=30\njoint assign j\n"
      "block box -1,-1,-1 2,2,0 group=base material=stone\nfix group=base\n";
  for (int k = 0; k < blocks; ++k)
    s += "block box 0,0," + std::to_string(k * h) + " 1,1," + std::to_string((k + 1) * h) +
         " group=rock material=rock\n";
  return s +
         (quadratic ? "zone generate edge=0.5 order=2 group=rock\n"
                    : "zone generate edge=0.3 group=rock\n") +
         sides + "gravity 0 0 -10\n";
}

// Rollers on the four sides of the stack (x and y held on the faces x, y = 0 and 1).
const char* kRollers =
    "boundary fix=x x=-0.001,0.001\nboundary fix=x x=0.999,1.001\n"
    "boundary fix=y y=-0.001,0.001\nboundary fix=y y=0.999,1.001\n";

// A zone's centroid in the x-z plane (initial or current positions) in polar form, with its
// radial and hoop stresses there (compression positive): the slab tests' holes run along y.
struct Polar3 {
  double r, theta, sr, st;
};
Polar3 zone_polar3(const Continuum3& c, size_t z, bool current) {
  Vec3 x = Vec3::Zero();
  for (uint32_t n : c.zones[z]) x += (current ? c.pos[n] : c.pos0[n]) / 4.0;
  const double th = std::atan2(x.z(), x.x()), cs = std::cos(th), sn = std::sin(th);
  const ZoneStress& s = c.stress[z];
  return {std::hypot(x.x(), x.z()), th, -(s.xx * cs * cs + s.zz * sn * sn + 2 * s.xz * sn * cs),
          -(s.xx * sn * sn + s.zz * cs * cs - 2 * s.xz * sn * cs)};
}

// Normal force of every sub-contact of the 3D contacts, summed.
double total_normal_force(const Model& m) {
  double sum = 0;
  for (const Contact3& c : m.contacts3)
    for (const SubContact& s : c.subs) sum += s.fn;
  return sum;
}
}  // namespace

class TestDeformable3 : public QObject {
  Q_OBJECT
  // Rows of 4-node and 10-node zones.
  static void orders() {
    QTest::addColumn<bool>("quadratic");
    QTest::newRow("4-node") << false;
    QTest::newRow("10-node") << true;
  }

 private slots:
  // A 4 m zoned column between rollers on a rigid base: the top settles rho g H^2 / (2M) in
  // the column plus the joint's closure rho g H / kn, within 1%; the base's sub-contacts carry
  // the column's weight within 0.1%. With 4-node and with 10-node zones (whose faces touch the
  // base at their mid-edge nodes: traction_shares).
  void columnOnARigidBase_data() { orders(); }
  void columnOnARigidBase() {
    QFETCH(bool, quadratic);
    ScriptRun r;
    r.run(stack(1, 4, 1e10, kRollers, quadratic) +
          "history zdisp at=0.5,0.5,3.999 label=top\n"
          "history zdisp at=0.5,0.5,0.001 label=bottom\nsolve ratio=1e-7 cycles=200000");
    const double k = 1e9 / (3 * (1 - 0.5)), g = 1e9 / 2.5, m = k + 4 * g / 3;
    const double column = 2000 * 10 * 16 / (2 * m), joint = 2000 * 10 * 4 / 1e10;
    const double top = -last(r.model(), "top"), bottom = -last(r.model(), "bottom");
    // The joint's mean closure over the column's foot.
    const Continuum3& c = r.model().continuum3;
    double foot = 0;
    int feet = 0;
    for (size_t n = 0; n < c.node_count(); ++n)
      if (c.pos0[n].z() < 1e-9) foot -= c.pos[n].z() - c.pos0[n].z(), ++feet;
    foot /= feet;
    qInfo(
        "top settlement %.5e m (closed form %.5e), joint closure %.4e m at the middle, %.4e m "
        "mean (%.4e)",
        top, column + joint, bottom, foot, joint);
    QVERIFY(std::abs(top / (column + joint) - 1) < 0.01);
    // 10-node zones' lumped weights (not the consistent body force) put the weight of the zones
    // at the foot a little unevenly on the joint (+1.1% on the mean, +2.2% at the middle).
    QVERIFY(std::abs(foot / joint - 1) < (quadratic ? 0.02 : 0.01));
    QVERIFY(std::abs(bottom / joint - 1) < (quadratic ? 0.04 : 0.02));
    // Rollers carry no vertical load: the base takes all the weight.
    const double weight = 2000 * 10 * 4;
    qInfo("base reaction %.6e N (weight %.6e)", total_normal_force(r.model()), weight);
    QVERIFY(std::abs(total_normal_force(r.model()) / weight - 1) < 1e-3);
  }

  // Two zoned cubes on the base: the joint between two deformable faces (both node sets, each
  // with half the area) is as stiff as the one against the rigid base, so each joint closes by
  // the weight above it over kn (soft joints, where the joints dominate), within 2%.
  void deformableOnDeformable_data() { orders(); }
  void deformableOnDeformable() {
    QFETCH(bool, quadratic);
    ScriptRun r;
    r.run(stack(2, 1, 1e8, kRollers, quadratic) +
          "history zdisp at=0.5,0.5,0.999 label=lower_top\n"
          "history zdisp at=0.5,0.5,1.001 label=upper_bottom\n"
          "history zdisp at=0.5,0.5,0.001 label=lower_bottom\nsolve ratio=1e-7 cycles=200000");
    const double k = 1e9 / (3 * (1 - 0.5)), g = 1e9 / 2.5, m = k + 4 * g / 3;
    // Closure of the upper joint: the upper cube's weight over kn.
    const double upper = -(last(r.model(), "upper_bottom") - last(r.model(), "lower_top"));
    const double lower = -last(r.model(), "lower_bottom");
    qInfo("upper joint closes %.5e m (%.5e), lower %.5e m (%.5e)", upper, 2000 * 10 / 1e8, lower,
          2 * 2000 * 10 / 1e8);
    QVERIFY(std::abs(upper / (2000 * 10 / 1e8) - 1) < 0.02);
    QVERIFY(std::abs(lower / (2 * 2000 * 10 / 1e8) - 1) < 0.02);
    // The column between: the lower cube shortens by the weight above plus half its own.
    const double shortening = last(r.model(), "lower_top") - last(r.model(), "lower_bottom");
    QVERIFY(std::abs(-shortening / (2000 * 10 * 1.5 / m) - 1) < 0.02);
  }

  // A zoned cube sliding down a 30 degree slope (gravity tilted) on a joint of 20 degrees'
  // friction, undamped: the mean acceleration of its corners is g (sin 30 - cos 30 tan 20)
  // within 1% (fitted over the second half of the run, after the first contact's rebound).
  void slidesAtTheCoulombAcceleration() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2500 E=1e9 nu=0.25\n"
        "joint define j kn=1e10 ks=1e10 friction=20\njoint assign j\n"
        "block box -1,-1,-1 6,2,0 material=rock group=base\nfix group=base\n"
        "block box 0,0,0 1,1,1 material=rock group=top\nzone generate edge=0.34 group=top\n"
        "damping none\ngravity (10*sin(30)) 0 (-10*cos(30))\n"
        "history xvel block=2 label=v\nhistory interval 10\nstep 4000");
    const Histories& h = r.model().histories;
    std::vector<double> t, v;
    for (size_t i = h.rows() / 2; i < h.rows(); ++i)
      t.push_back(static_cast<double>(h.cycles[i]) * r.model().dt), v.push_back(h.at(i, 0));
    const double a = tessera::test::fitted_slope(t, v);
    const double coulomb = 10 * (std::sin(M_PI / 6) - std::cos(M_PI / 6) * std::tan(M_PI / 9));
    qInfo("acceleration %.5f m/s2 (Coulomb %.5f)", a, coulomb);
    QVERIFY(std::abs(a / coulomb - 1) < 0.01);
  }

  // Boundary stress on a zoned cube's top face and rollers elsewhere: uniaxial strain, the top
  // moving sigma H / M.
  void boundaryStressOnSurfaceTriangles() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
        "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.3\n" +
        std::string(kRollers) +
        "boundary fix=z z=-0.001,0.001\nboundary stress=0,0,-1e6,0,0,0 z=0.999,1.001\n"
        "history zdisp at=0.5,0.5,1 label=top\nhistory szz at=0.5,0.5,0.5\n"
        "history sxx at=0.5,0.5,0.5\nhistory sigma1 at=0.5,0.5,0.5\n"
        "history sigma3 at=0.5,0.5,0.5\nsolve ratio=1e-7 cycles=100000");
    const double m = 1e9 * 0.75 / (1.25 * 0.5);
    qInfo("top %.6e m (%.6e)", last(r.model(), "top"), -1e6 / m);
    QVERIFY(std::abs(last(r.model(), "top") / (-1e6 / m) - 1) < 0.005);
    // The zone histories: szz the applied stress, sxx = syy = nu / (1 - nu) szz (rollers).
    qInfo("szz %.5e sxx %.5e sigma1 %.5e sigma3 %.5e Pa", last(r.model(), "szz"),
          last(r.model(), "sxx"), last(r.model(), "sigma1"), last(r.model(), "sigma3"));
    QVERIFY(std::abs(last(r.model(), "szz") / -1e6 - 1) < 0.005);
    QVERIFY(std::abs(last(r.model(), "sxx") / (-1e6 / 3) - 1) < 0.01);
    QVERIFY(std::abs(last(r.model(), "sigma1") / last(r.model(), "szz") - 1) < 1e-6);
    QVERIFY(std::abs(last(r.model(), "sigma3") / (-1e6 / 3) - 1) < 0.01);
  }

  // A cube cut by a joint dipping 30 degrees, under the in-situ stress sxx = syy = -5, szz = -10
  // MPa held by the matching boundary stresses: with `insitu` on zones and joints the model
  // starts in equilibrium (it moves under 2% of what the same loads do from zero), and the
  // joint carries the field's traction (normal 8.75, shear 2.165 MPa) within 3%. 4-node and
  // 10-node zones both move 0.4% of that (10-node ones 1.8% when a node's force on the other face
  // went to that triangle's corners too, not the consistent mid-edge loads). Solved under kinetic
  // damping: the same answers within 0.5% in three quarters of the time.
  void insituStressInJoints_data() { orders(); }
  void insituStressInJoints() {
    QFETCH(bool, quadratic);
    const auto run = [&](bool insitu, ScriptRun& r) {
      r.run(
          "dimension 3\ntolerance 0.01\nmaterial define rock density=2500 E=10e9 nu=0.25\n"
          "joint define stiff kn=1e11 ks=1e11 friction=40 cohesion=1e12 tension=1e12\n"
          "joint assign stiff\nblock box 0,0,0 6,6,6 material=rock\n"
          "crack dip=30 ddir=90 origin=3,3,3 name=j\nzone generate edge=1.5" +
          std::string(quadratic ? " order=2\n" : "\n") +
          "boundary fix=x x=-0.001,0.001\nboundary fix=y y=-0.001,0.001\n"
          "boundary fix=z z=-0.001,0.001\n"
          "boundary stress=-5e6,-5e6,-10e6,0,0,0 x=5.999,6.001\n"
          "boundary stress=-5e6,-5e6,-10e6,0,0,0 y=5.999,6.001\n"
          "boundary stress=-5e6,-5e6,-10e6,0,0,0 z=5.999,6.001\n" +
          std::string(insitu ? "insitu stress=-5e6,-5e6,-10e6,0,0,0\n" : "") +
          "damping kinetic\nhistory zdisp at=5.99,5.99,5.99 label=uz\n"
          "solve ratio=1e-6 cycles=100000");
    };
    ScriptRun loaded, preloaded;
    run(false, loaded);
    run(true, preloaded);
    const double full = last(loaded.model(), "uz"), start = last(preloaded.model(), "uz");
    qInfo("top corner moves %.4e m loaded from zero, %.4e m from the in-situ state", full, start);
    QVERIFY(full < -1e-3);
    QVERIFY(std::abs(start) < 0.02 * std::abs(full));
    double fn = 0, fs = 0, area = 0;
    for (const Contact3& c : preloaded.model().contacts3)
      for (const SubContact& s : c.subs) fn += s.fn, fs += s.shear(), area += s.area;
    qInfo("joint tractions: normal %.4e, shear %.4e Pa over %.3f m2", fn / area, fs / area, area);
    QVERIFY(std::abs(area / (36 / std::cos(M_PI / 6)) - 1) < 1e-4);
    QVERIFY(std::abs(fn / area / 8.75e6 - 1) < 0.03);
    QVERIFY(std::abs(fs / area / 2.165e6 - 1) < 0.03);
  }

  // Density scaling (`timestep scaled`) in 3D: the same settlement within 0.1%, at a larger
  // step and in fewer cycles.
  void scaledTimestepSameStaticAnswer_data() { orders(); }
  void scaledTimestepSameStaticAnswer() {
    QFETCH(bool, quadratic);
    const std::string tail =
        "history zdisp at=0.5,0.5,3.999 label=top\nsolve ratio=1e-7 cycles=200000";
    ScriptRun plain, scaled;
    plain.run(stack(1, 4, 1e10, kRollers, quadratic) + tail);
    scaled.run(stack(1, 4, 1e10, kRollers, quadratic) + "timestep scaled\n" + tail);
    const double a = last(plain.model(), "top"), b = last(scaled.model(), "top");
    qInfo("settlement %.6e (auto, dt %.3e, %llu cycles) and %.6e m (scaled, dt %.3e, %llu)", a,
          plain.model().dt, (unsigned long long)plain.model().cycle, b, scaled.model().dt,
          (unsigned long long)scaled.model().cycle);
    QVERIFY(std::abs(b / a - 1) < 1e-3);
    QVERIFY(scaled.model().dt > 1.2 * plain.model().dt);
    QVERIFY(scaled.model().cycle < plain.model().cycle);
  }

  // A cantilever 10 x 1 x 1 m (E = 1 GPa, nu = 0.25) clamped at x = 0 under a uniform shear
  // traction on its free end, P = 10 kN, zoned by the script's 'zone generate': the end's mean
  // deflection against Timoshenko's beam, P L^3 / 3EI + P L / (kappa G A), Cowper's kappa =
  // 10 (1 + nu) / (12 + 11 nu) for a rectangle (shear adds 0.7%). 10-node zones come within 2%
  // on the coarse mesh (edge 1 m: one or two zones through the depth; -0.7%, what is left is
  // the clamped root and the end's uniform traction, not the zoning: the finer mesh gives the
  // same); 4-node zones lock in bending (a third too stiff on the coarse mesh, a sixth on the
  // fine one) and close in as they get smaller.
  void cantileverOfLinearAndQuadraticZones() {
    const double len = 10, e = 1e9, nu = 0.25, g = e / (2 * (1 + nu)), load = 1e4;
    const double inertia = 1.0 / 12, kappa = 10 * (1 + nu) / (12 + 11 * nu);
    const double beam = load * len * len * len / (3 * e * inertia) + load * len / (kappa * g);
    const auto deflection = [&](int order, double edge) {
      ScriptRun r;
      r.run(
          "dimension 3\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
          "block box 0,0,0 10,1,1 material=rock\nzone generate edge=" +
          std::to_string(edge) + " order=" + std::to_string(order) +
          "\nboundary fix=xyz x=-0.001,0.001\n"
          "boundary stress=0,0,0,0,0,-1e4 x=9.999,10.001\ntimestep scaled\n"
          "solve ratio=1e-5 cycles=300000");
      const Model& m = r.model();
      const Continuum3& c = m.continuum3;
      double sum = 0;
      int count = 0;
      for (size_t n = 0; n < c.node_count(); ++n)
        if (c.pos0[n].x() > len - 1e-9) sum += c.pos[n].z() - c.pos0[n].z(), ++count;
      const double d = -sum / count;
      qInfo(
          "%d-node, edge %.2f m: %zu zones, %llu cycles, deflection %.5g m (beam %.5g m, %+.2f%%)",
          order == 2 ? 10 : 4, edge, c.zone_count(), static_cast<unsigned long long>(m.cycle), d,
          beam, 100 * (d / beam - 1));
      return m.ratio <= 1e-5 ? d : 0.0;
    };
    const double quad_coarse = deflection(2, 1.0), quad_fine = deflection(2, 0.7);
    QVERIFY2(std::abs(quad_coarse / beam - 1) < 0.02, "10-node, coarse");
    QVERIFY2(std::abs(quad_fine / beam - 1) < 0.02, "10-node, fine");
    const double lin_coarse = deflection(1, 1.0), lin_fine = deflection(1, 0.5);
    QVERIFY(lin_coarse > 0 && lin_fine > lin_coarse && lin_fine < beam);
    // Converging: the finer mesh's error well under the coarser's.
    QVERIFY(beam - lin_fine < 0.7 * (beam - lin_coarse));
  }

  // Saved mid-run and restored, a 3D deformable model continues bit for bit; one thread or
  // two give the same bits.
  void restoresAndRepeatsBitForBit_data() { orders(); }
  void restoresAndRepeatsBitForBit() {
    QFETCH(bool, quadratic);
    uint64_t hash[2] = {};
    for (int t = 1; t <= 2; ++t) {
      set_thread_count(t);
      ScriptRun r;
      r.run(stack(2, 1, 1e9, kRollers, quadratic) + "step 300");
      const std::string path = r.path("mid.state");
      save_state(r.model(), path);
      run_cycles(r.model(), 300);
      Model back = restore_state(path);
      run_cycles(back, 300);
      QCOMPARE(state_hash(back), state_hash(r.model()));
      hash[t - 1] = state_hash(r.model());
    }
    set_thread_count(1);
    QCOMPARE(hash[0], hash[1]);
  }

  // A node sub-contact's node, side and triangle live in its contact's `nodes`: one per node
  // sub-contact where a zoned block touches, none where two rigid blocks do.
  void nodeLinksOnlyWhereADeformableBlockTouches() {
    ScriptRun r;
    r.run(stack(2, 1, 1e9, kRollers) + "block box 1.5,0,0 2,0.5,0.5 material=stone\nstep 20");
    const Model& m = r.model();
    size_t rigid = 0, soft = 0;
    for (const Contact3& c : m.contacts3) {
      const bool zoned = m.blocks3.deformable[c.a] || m.blocks3.deformable[c.b];
      if (c.subs.empty()) continue;
      (zoned ? soft : rigid)++;
      QCOMPARE(c.nodes.size(), zoned ? c.subs.size() : size_t(0));
      for (size_t k = 0; k < c.subs.size(); ++k)
        QCOMPARE(c.subs[k].link, zoned ? static_cast<int32_t>(k) : -1);
    }
    QVERIFY(rigid >= 1);
    QVERIFY(soft >= 2);
  }

  // Excavating one of two stacked cubes removes its nodes and zones; the other keeps its own.
  void deletingADeformableBlock_data() { orders(); }
  void deletingADeformableBlock() {
    QFETCH(bool, quadratic);
    ScriptRun r;
    r.run(stack(2, 1, 1e9, kRollers, quadratic) + "step 100\ndelete block=3\nstep 100");
    const Model& m = r.model();
    QCOMPARE(m.blocks3.size(), size_t(2));
    const Blocks3& B = m.blocks3;
    QCOMPARE(B.node_begin[1], 0u);
    QCOMPARE(size_t(B.node_end[1]), m.continuum3.node_count());
    for (const Vec3& p : m.continuum3.pos) QVERIFY(p.z() < 1.01);
  }

  // `fix` and `free` act on a deformable block's nodes, and zoning a fixed block holds them as
  // the block was held: under gravity it stays put, freed it falls, fixed and stopped it stays.
  void fixHoldsADeformableBlocksNodes() {
    ScriptRun r;
    r.run(
        "dimension 3\nmaterial define rock density=2500 E=10e9 nu=0.25\n"
        "block box 0,0,0 1,1,1 material=rock\nfix all\nzone generate edge=0.5\n"
        "gravity 0 0 -10\ndamping none\nstep 100");
    const Continuum3& c = r.model().continuum3;
    const auto lowest = [&] {
      double z = 1e300;
      for (const Vec3& p : c.pos) z = std::min(z, p.z());
      return z;
    };
    QVERIFY(r.log.find("nodes of 1 fixed block(s) are held") != std::string::npos);
    QCOMPARE(lowest(), 0.0);
    r.run("free all\nstep 1000");
    // Free fall: g t^2 / 2 over the 1,000 steps (to the step's first-order start).
    const double fallen = lowest(), t = 1000 * r.model().dt;
    qInfo("fell %.4g m in %.4g s (free fall %.4g m)", fallen, t, -5.0 * t * t);
    QVERIFY(std::abs(fallen + 5.0 * t * t) < 0.01 * 5.0 * t * t);
    r.run("fix all\nvelocity all vz=0\nstep 10");
    const double stopped = lowest();
    r.run("step 100");
    qInfo("fell %.3g m, then held", fallen);
    QCOMPARE(lowest(), stopped);
  }

  // A zoned cube under sxx = -1 MPa turned rigidly through 90 degrees about z, its nodes driven
  // along the chords of the turn: the stress turns with it (syy = -1 MPa, sxx = sxy = 0), for
  // 4- and 10-node zones. The stress was not turned at all (an independent check: sxx -0.874,
  // syy +0.126 MPa after the turn), and the strain taken on the shape at the end of each step
  // read the turn as a stretch of the angle times the step's turn (0.126 MPa of isotropic
  // stress here): it is taken halfway along the step now.
  void stressTurnsWithTheZone() {
    for (const int order : {1, 2}) {
      ScriptRun r;
      r.run(
          "dimension 3\ntolerance 0.01\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
          "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5 order=" +
          std::to_string(order) +
          "\ngravity 0 0 0\ndamping none\ntimestep fixed 1e-4\n"
          "insitu stress=-1e6,0,0,0,0,0\n");
      Model& m = r.model();
      Continuum3& c = m.continuum3;
      const Vec3 centre(0.5, 0.5, 0.5);
      const double turn = 1e-4;  // radians a step
      const int steps = static_cast<int>(std::lround(0.5 * M_PI / turn));
      std::vector<Vec3> start = c.pos;
      for (int i = 1; i <= steps; ++i) {
        const Eigen::Matrix3d rot = Eigen::AngleAxisd(turn * i, Vec3::UnitZ()).toRotationMatrix();
        for (size_t n = 0; n < c.node_count(); ++n) {
          c.fixity[n] = 7;
          c.fixed_vel[n] = (centre + rot * (start[n] - centre) - c.pos[n]) / 1e-4;
        }
        run_cycles(m, 1);
      }
      double sxx = 0, syy = 0, sxy = 0, mean = 0;
      const auto zones = static_cast<double>(c.zone_count());
      for (size_t z = 0; z < c.zone_count(); ++z) {
        const ZoneStress& s = c.stress[z];  // (a 10-node zone's: its points' mean)
        sxx += s.xx / zones, syy += s.yy / zones, sxy += s.xy / zones;
      }
      mean = 0.5 * (sxx + syy) + 0.5e6;  // the in-plane isotropic part beyond the turned stress
      qInfo("order %d: after 90 degrees sxx %.4g, syy %.4g, sxy %.4g MPa (isotropic part %.3g)",
            order, sxx / 1e6, syy / 1e6, sxy / 1e6, mean / 1e6);
      QVERIFY(std::abs((syy - sxx) + 1e6) < 1e-3 * 1e6);
      QVERIFY(std::abs(sxy) < 1e-3 * 1e6);
      QVERIFY(std::abs(mean) < 1e-6 * 1e6);
    }
  }

  // `boundary vz=` drives the top's nodes down and leaves them free across (a smooth platen):
  // an elastic cube on rollers, pressed 0.1 mm, spreads across at nu times its axial strain,
  // top as well as bottom. (`boundary velocity=0,0,-v`, all three axes, held the top from
  // spreading; an independent check's triaxial test read 20% over Mohr-Coulomb's strength.)
  void boundaryVelocityOfOneAxis() {
    ScriptRun r;
    r.run(
        "dimension 3\nmaterial define rock density=2500 E=10e9 nu=0.25\n"
        "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5\ngravity 0 0 0\n"
        "boundary fix=z z=-0.01,0.01\nboundary fix=x x=-0.01,0.01\nboundary fix=y y=-0.01,0.01\n"
        "boundary vz=-1e-3 z=0.99,1.01\nstep 1000\n");
    const Model& m = r.model();
    const Continuum3& c = m.continuum3;
    size_t top = 0;
    for (size_t n = 0; n < c.node_count(); ++n)
      if (c.pos0[n].z() > 0.99) {
        // (Those on the rollers at x = 0 or y = 0 keep them.)
        const bool roller = c.pos0[n].x() < 0.01 || c.pos0[n].y() < 0.01;
        if (!roller) QCOMPARE(int(c.fixity[n]), int(node_fix_bit(2)));
        QCOMPARE(c.fixed_vel[n].z(), -1e-3);
        ++top;
      }
    QVERIFY(top > 4);
    // Held still at 1000 steps' travel, then settled.
    r.run("boundary vz=0 z=0.99,1.01\nsolve ratio=1e-7 cycles=20000\n");
    double pressed = 0.0, spread_top = 0.0, spread_bottom = 0.0;
    for (size_t n = 0; n < c.node_count(); ++n) {
      const Vec3 d = c.pos[n] - c.pos0[n];
      if (c.pos0[n].z() > 0.99) pressed = -d.z();
      if (c.pos0[n].x() > 0.99 && c.pos0[n].z() > 0.99) spread_top = d.x();
      if (c.pos0[n].x() > 0.99 && c.pos0[n].z() < 0.01) spread_bottom = d.x();
    }
    qInfo("pressed %.4g mm: spread %.4g mm at the top, %.4g mm at the bottom (nu e: %.4g)",
          pressed * 1e3, spread_top * 1e3, spread_bottom * 1e3, 0.25 * pressed * 1e3);
    QVERIFY(pressed > 1e-5);
    QVERIFY(std::abs(spread_top / (0.25 * pressed) - 1) < 1e-3);
    QVERIFY(std::abs(spread_bottom / (0.25 * pressed) - 1) < 1e-3);
  }

  // CGAL's mesher can leave a flat zone on a block's surface (four nodes on one face). The
  // Salencon slab zoned at 0.2 a had one on the opening's wall (19,073 zones, smallest dihedral
  // angle 0.000 degrees): its nodes had no stable step, froze under density scaling, and the
  // plastic radius came out 41% short. Such caps are dropped, and the slivers exuded (18,658
  // zones, 3 under 5 degrees, the smallest 2.5; unexuded 97, the smallest 1.04): every zone
  // has volume and together they fill the slab exactly.
  void flatZonesOnTheSurfaceAreDropped() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500 K=3.9e9 G=2.8e9\n"
        "block box 0,0,0 6,0.5,6 material=rock\n"
        "tunnel circle centre=0,0,0 axis=0,1,0 radius=1 length=0.5 segments=48 group=hole "
        "join\nzone generate edge=1.2 fine=0.2 near=0,0.25,0 radius=1.9 growth=0.35");
    const Continuum3& c = r.model().continuum3;
    double volume = 0, flattest = 1e300;
    for (size_t z = 0; z < c.zone_count(); ++z) {
      const auto& t = c.zones[z];
      double longest = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          longest = std::max(longest, (c.pos[t[i]] - c.pos[t[j]]).norm());
      const double v = zone_volume(c, z);
      volume += v, flattest = std::min(flattest, 6 * v / (longest * longest * longest));
    }
    qInfo("%zu zones, volume %.12g (slab 18), flattest 6V/L^3 %.3g", c.zone_count(), volume,
          flattest);
    QVERIFY(flattest > 1e-4);
    QVERIFY(std::abs(volume - 18) < 1e-9 * 18);
    // The slivers left (under 5 degrees) are counted in a warning with the worst one's place.
    QVERIFY2(r.log.find("zones have a dihedral angle under 5 degrees (the smallest near ") !=
                 std::string::npos,
             r.log.c_str());
  }

  // Two boxes joined into one body and zoned as one mesh, each its own material: no joint
  // between them (no contact, their nodes shared), so the column between rollers settles as a
  // continuous one, rho g (6 / M1 + 2 / M2) at the top for 2 m of each on a stiff base, within
  // 1% (with the base joint's closure); and excavating the body removes every node.
  void joinedBodyIsOneMesh() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define stone density=2500\n"
        "material define lower density=2000 E=1e9 nu=0.25\n"
        "material define upper density=2000 E=2e9 nu=0.25\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block box -1,-1,-1 2,2,0 group=base material=stone\nfix group=base\n"
        "block box 0,0,0 1,1,2 group=rock material=lower\n"
        "block box 0,0,2 1,1,4 group=rock material=upper\njoin group=rock\n"
        "zone generate edge=0.3 group=rock\n" +
        std::string(kRollers) +
        "gravity 0 0 -10\nhistory zdisp at=0.5,0.5,3.999 label=top\n"
        "solve ratio=1e-7 cycles=200000");
    const Model& m = r.model();
    const double m1 = 1e9 * 0.75 / (1.25 * 0.5), m2 = 2 * m1;
    const double expect = 2000 * 10 * (6 / m1 + 2 / m2) + 2000 * 10 * 4 / 1e10;
    qInfo("top settles %.5e m (continuous column %.5e)", -last(m, "top"), expect);
    QVERIFY(std::abs(-last(m, "top") / expect - 1) < 0.01);
    // One mesh: both pieces share its nodes; contacts only with the base.
    const Blocks3& B = m.blocks3;
    QCOMPARE(B.node_begin[1], B.node_begin[2]);
    QCOMPARE(B.node_end[1], B.node_end[2]);
    QCOMPARE(B.zone_end[1], B.zone_begin[2]);
    for (const Contact3& c : m.contacts3) QVERIFY(c.a == 0 || c.b == 0);
    QCOMPARE(m.continuum3.material[B.zone_begin[1]], uint32_t(B.material[1] + 1));
    QCOMPARE(m.continuum3.material[B.zone_begin[2]], uint32_t(B.material[2] + 1));
    r.run("delete group=rock\nstep 10");
    QCOMPARE(r.model().continuum3.node_count(), size_t(0));
    QCOMPARE(r.model().blocks3.size(), size_t(1));
  }

  // Kirsch's hole in 3D, the way a user builds it: a quarter slab held in plane strain (y held on
  // both faces), a 48-sided circular tunnel of radius a = 1 m cut through it with `join` (the
  // rock one body, one mesh: no fictitious joints), the in-situ stress sxx = -5, szz = -10 MPa
  // in the zones and as tractions on the far faces 12 a away, excavated and solved. Against
  // Kirsch (compression positive, p = 5 along x, q = 10 along z, theta from x): the hoop stress
  // of the zones at the wall (averaged over 9-degree sectors, relative to its peak 3q - p) and
  // both stresses at r = 2a (relative to the hoop stress there) within 5%, the wall's radial
  // displacement within 3% of 2 q a / 4G. The far boundary at 12a, not infinity, makes about 1%
  // of that: the displacement the farther boundary of the 2D test (20a) gets within 1%.
  void kirschHoleInAJoinedSlab() {
    const double a = 1, sv = 10e6, sh = 5e6, nu = 0.25, e = 1e10, g = e / (2 * (1 + nu));
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500 E=1e10 nu=0.25\n"
        "joint define j kn=1e11 ks=1e11 friction=40\njoint assign j\n"
        "block box 0,0,0 12,0.5,12 material=rock\n"
        "tunnel circle centre=0,0,0 axis=0,1,0 radius=1 length=0.5 segments=48 group=hole "
        "join\nzone generate edge=1.2 fine=0.14 near=0,0.25,0 radius=1.1 growth=0.35\n"
        "boundary fix=x x=-0.001,0.001\nboundary fix=z z=-0.001,0.001\n"
        "boundary fix=y y=-0.001,0.001\nboundary fix=y y=0.499,0.501\n"
        "boundary stress=-5e6,0,0,0,0,0 x=11.999,12.001\n"
        "boundary stress=0,0,-10e6,0,0,0 z=11.999,12.001\n"
        "insitu stress=-5e6,-3.75e6,-10e6,0,0,0\ndelete group=hole\ntimestep scaled\n"
        "solve ratio=1e-5 cycles=60000");
    const Model& m = r.model();
    QVERIFY(m.ratio <= 1e-5);
    const Continuum3& c = m.continuum3;
    // Kirsch in the x-z plane.
    const double p = sh, q = sv;
    auto kirsch = [&](double rr, double th, double& sr, double& st) {
      const double u = a * a / (rr * rr), c2 = std::cos(2 * th);
      sr = 0.5 * (p + q) * (1 - u) + 0.5 * (p - q) * (1 - 4 * u + 3 * u * u) * c2;
      st = 0.5 * (p + q) * (1 + u) - 0.5 * (p - q) * (1 + 3 * u * u) * c2;
    };
    std::array<double, 10> wall{}, ring_t{}, ring_r{}, ref{};
    std::array<int, 10> nwall{}, nring{};
    for (size_t z = 0; z < c.zone_count(); ++z) {
      if (!c.materials[c.material[z]].impl->solid()) continue;
      const Polar3 p3 = zone_polar3(c, z, false);
      const double rr = p3.r, th = p3.theta, sr = p3.sr, st = p3.st;
      const auto bin = std::min<size_t>(9, static_cast<size_t>(th / (0.5 * M_PI) * 10));
      double kr, kt;
      kirsch(rr, th, kr, kt);
      if (rr < a + 0.08) {
        wall[bin] += (st - kt) / (3 * sv - sh), ++nwall[bin];
      } else if (std::abs(rr - 2 * a) < 0.12) {
        ring_t[bin] += st - kt, ring_r[bin] += sr - kr, ref[bin] += kt, ++nring[bin];
      }
    }
    double worst_wall = 0, worst_2a = 0;
    for (size_t b = 0; b < 10; ++b) {
      QVERIFY(nwall[b] > 5 && nring[b] > 5);
      worst_wall = std::max(worst_wall, std::abs(wall[b] / nwall[b]));
      worst_2a = std::max({worst_2a, std::abs(ring_t[b] / ref[b]), std::abs(ring_r[b] / ref[b])});
    }
    // The wall's radial displacement, plane strain: -(q a / 4G)[(1+K) - (1-K)(3-4 nu) cos 2 theta].
    const double k = p / q;
    double worst_u = 0;
    int on_wall = 0;
    for (size_t n = 0; n < c.node_count(); ++n) {
      const Vec3 x0 = c.pos0[n];
      const double rr = std::hypot(x0.x(), x0.z());
      if (std::abs(rr - a) > 1e-6) continue;
      const Vec3 radial = Vec3(x0.x(), 0, x0.z()) / rr;
      const double ur = (c.pos[n] - x0).dot(radial), th = std::atan2(x0.z(), x0.x());
      const double expect =
          -(q * a / (4 * g)) * ((1 + k) - (1 - k) * (3 - 4 * nu) * std::cos(2 * th));
      worst_u = std::max(worst_u, std::abs(ur - expect) / (q * a / (4 * g) * 2)), ++on_wall;
    }
    qInfo(
        "%zu zones, %llu cycles; worst errors: hoop at wall %.2f%%, at 2a %.2f%%, wall "
        "displacement %.2f%% (%d nodes)",
        c.zone_count(), static_cast<unsigned long long>(m.cycle), 100 * worst_wall, 100 * worst_2a,
        100 * worst_u, on_wall);
    QVERIFY(on_wall > 50);
    QVERIFY(worst_wall < 0.05);
    QVERIFY(worst_2a < 0.05);
    QVERIFY(worst_u < 0.03);
  }

  // Salencon's hole in 3D: a joined slab as in the Kirsch test, in Mohr-Coulomb rock under a
  // hydrostatic p0 = 30 MPa (FLAC's problem, as test_continuum's 2D one: c = 3.45 MPa, phi =
  // 30, psi = 0, G = 2.8 GPa, K = 3.9 GPa, a = 1 m), zones of 0.1 a out to 1.9 a, the far faces
  // at b = 6 a. Against Salencon (1969) with that boundary: the plastic zone reaches the radius
  // where the plastic stresses meet the elastic ring (1.774 a; 1.735 a with b infinite), each
  // 9-degree sector's outermost yielding zone within 5% of it (0.8%), and inside it the zones'
  // sigma_r and sigma_theta, averaged over rings 0.1 a wide on the current shape, within 5% of
  // c cot phi ((r/a)^(Kp-1) - 1) and c cot phi (Kp (r/a)^(Kp-1) - 1) (3.1% next to the wall,
  // 1.3% further out). Solved to a ratio of 1e-4: 1e-5 changes the radius by 0.05% and takes
  // half as long again.
  void salenconHoleInAJoinedSlab() { salencon(0.1, 0.05); }

  // The same zoned at 0.2 a, where CGAL's mesher leaves 97 zones under 5 degrees: unexuded, the
  // plastic radius was 39% short in some sectors (and at 0.14 a, 30%). Exuded, 3 are left and
  // the radius is within 0.6%; sigma_r is held to 8% (+5.9% at worst), as these zones are twice
  // as wide as the rings next to the free wall where it vanishes.
  void salenconHoleCoarselyZoned() { salencon(0.2, 0.08); }

 private:
  void salencon(double fine, double sr_tolerance) {
    const double a = 1, p0 = 30e6, coh = 3.45e6, phi = 30 * M_PI / 180;
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500 K=3.9e9 G=2.8e9 "
        "model=mohr-coulomb friction=30 cohesion=3.45e6 tension=1e9 dilation=0\n"
        "joint define j kn=1e11 ks=1e11 friction=40\njoint assign j\n"
        "block box 0,0,0 6,0.5,6 material=rock\n"
        "tunnel circle centre=0,0,0 axis=0,1,0 radius=1 length=0.5 segments=48 group=hole "
        "join\nzone generate edge=1.2 fine=" +
        std::to_string(fine) +
        " near=0,0.25,0 radius=1.9 growth=0.35\n"
        "boundary fix=x x=-0.001,0.001\nboundary fix=z z=-0.001,0.001\n"
        "boundary fix=y y=-0.001,0.001\nboundary fix=y y=0.499,0.501\n"
        "boundary stress=-30e6,0,0,0,0,0 x=5.999,6.001\n"
        "boundary stress=0,0,-30e6,0,0,0 z=5.999,6.001\n"
        "insitu stress=-30e6,-30e6,-30e6,0,0,0\ndelete group=hole\ntimestep scaled\n"
        "solve ratio=1e-4 cycles=100000");
    const Model& m = r.model();
    const Continuum3& c = m.continuum3;
    const double sphi = std::sin(phi), kp = (1 + sphi) / (1 - sphi), ccot = coh / std::tan(phi);
    const double infinite = std::pow(2 * (p0 + ccot) / ((kp + 1) * ccot), 1 / (kp - 1));
    // With p0 on a boundary at b = 6a (the elastic ring a thick cylinder, Lame's A - B/r^2 with
    // sigma_r(b) = p0), the plastic zone reaches further: the radius where the plastic
    // stresses meet the ring, by bisection (1.774 a; 1.735 a for b infinite).
    const auto ring_mismatch = [&](double rp) {
      const double sr = ccot * (std::pow(rp, kp - 1) - 1),
                   st = ccot * (kp * std::pow(rp, kp - 1) - 1);
      return 0.5 * (sr + st) - 0.5 * (st - sr) * rp * rp / 36.0 - p0;
    };
    double lo = 1, hi = 5;
    for (int i = 0; i < 100; ++i) (ring_mismatch(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
    const double extent = 0.5 * (lo + hi);
    // The wall's radius now (the x-z plane).
    double wall = 0;
    int on_wall = 0;
    for (size_t n = 0; n < c.node_count(); ++n)
      if (std::abs(std::hypot(c.pos0[n].x(), c.pos0[n].z()) - a) < 1e-6)
        wall += std::hypot(c.pos[n].x(), c.pos[n].z()), ++on_wall;
    wall /= std::max(on_wall, 1);
    std::array<double, 10> reach{};
    constexpr int kRings = 6;
    std::array<double, kRings> sr{}, st{}, sr_x{}, st_x{};
    std::array<int, kRings> count{};
    for (size_t z = 0; z < c.zone_count(); ++z) {
      if (!c.materials[c.material[z]].impl->solid()) continue;
      const Polar3 p3 = zone_polar3(c, z, true);
      const double rr = p3.r / wall, th = p3.theta, srad = p3.sr, shoop = p3.st;
      const double fs =
          kp * std::min(srad, shoop) - std::max(srad, shoop) + 2 * coh * std::sqrt(kp);
      if (fs <= 0.005 * p0) {
        const auto bin = std::min<size_t>(9, static_cast<size_t>(th / (0.5 * M_PI) * 10));
        reach[bin] = std::max(reach[bin], rr);
      }
      const int ring = static_cast<int>(std::floor((rr - 1.05) / 0.1));
      if (ring < 0 || ring >= kRings) continue;
      const double q = std::pow(rr, kp - 1);
      sr[ring] += srad, st[ring] += shoop, ++count[ring];
      sr_x[ring] += ccot * (q - 1), st_x[ring] += ccot * (kp * q - 1);
    }
    double mean = 0, worst = 0;
    for (double x : reach) mean += x / 10, worst = std::max(worst, std::abs(x / extent - 1));
    qInfo(
        "%zu zones, %llu cycles, ratio %.2e; wall moved %.4f a; plastic radius %.3f a "
        "(sectors within %.1f%%), Salencon %.3f a (b infinite: %.3f a)",
        c.zone_count(), static_cast<unsigned long long>(m.cycle), m.ratio, 1 - wall / a, mean,
        100 * worst, extent, infinite);
    double worst_r = 0, worst_t = 0;
    for (int k = 0; k < kRings; ++k) {
      QVERIFY(count[k] > 20);
      const double er = sr[k] / sr_x[k] - 1, et = st[k] / st_x[k] - 1;
      qInfo("  r %.2f-%.2f a (%3d zones): sigma_r %+5.1f%%, sigma_theta %+5.1f%%", 1.05 + 0.1 * k,
            1.15 + 0.1 * k, count[k], 100 * er, 100 * et);
      worst_r = std::max(worst_r, std::abs(er)), worst_t = std::max(worst_t, std::abs(et));
    }
    QVERIFY(m.ratio <= 1e-4);
    QVERIFY(worst < 0.05);
    QVERIFY(worst_r < sr_tolerance && worst_t < 0.05);
  }

 private slots:

  // An extruded 2D jointed model: a 2 x 2 m zoned rock square on a rigid base, rollers on its
  // sides, cut through its centre by a joint dipping 30 degrees and loaded on top by 1 MPa, in
  // 2D (plane strain) and as its 3D extrusion (0.5 m thick, y held on both faces). The joint
  // either stays elastic (45 degrees' friction, stiff) or slips (15 degrees against the 19 the
  // load would need, soft: kn = E / 1 m) until the rollers and the rock hold it. The 3D model
  // gives the 2D answer: the top's settlement and the slip across the joint (the upper side's
  // x displacement less the lower side's, at the centre) within 3% of the 2D ones.
  void extrudedJointedModelGivesThe2DAnswer_data() {
    QTest::addColumn<double>("friction");
    QTest::addColumn<double>("kn");
    QTest::newRow("elastic") << 45.0 << 1e9;
    QTest::newRow("slipping") << 15.0 << 1e9;
  }
  void extrudedJointedModelGivesThe2DAnswer() {
    QFETCH(double, friction);
    QFETCH(double, kn);
    const std::string common =
        "material define stone density=2500\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
        "joint define j kn=" +
        std::to_string(kn) + " ks=" + std::to_string(kn) + " friction=" + std::to_string(friction) +
        "\njoint assign j\n";
    ScriptRun flat;
    flat.run("round 0.01\n" + common +
             "block -1,-1 3,-1 3,0 -1,0 group=base material=stone\nfix group=base\n"
             "block 0,0 2,0 2,2 0,2 group=rock material=rock\n"
             "crack -0.1,(1-1.1*tan(30)) 2.1,(1+1.1*tan(30)) group=rock\n"
             "zone generate edge=0.1 group=rock\n"
             "boundary fix=x x=-0.001,0.001\nboundary fix=x x=1.999,2.001\n"
             "boundary stress=0,-1e6,0 y=1.999,2.001\n"
             "history ydisp at=1,1.999 label=top\nsolve ratio=1e-6 cycles=200000");
    ScriptRun solid;
    solid.run("dimension 3\ntolerance 0.01\n" + common +
              "block box -1,-1,-1 3,1.5,0 group=base material=stone\nfix group=base\n"
              "block box 0,0,0 2,0.5,2 group=rock material=rock\n"
              "crack dip=30 ddir=270 origin=1,0.25,1 group=rock\n"
              "zone generate edge=0.15 group=rock\n"
              "boundary fix=x x=-0.001,0.001\nboundary fix=x x=1.999,2.001\n"
              "boundary fix=y y=-0.001,0.001\nboundary fix=y y=0.499,0.501\n"
              "boundary stress=0,0,-1e6,0,0,0 z=1.999,2.001\n"
              "history zdisp at=1,0.25,1.999 label=top\nsolve ratio=1e-6 cycles=200000");
    const Model &a = flat.model(), &b = solid.model();
    const double top2 = last(a, "top"), top3 = last(b, "top");
    // Slip: the shear displacement of the joint's contacts (not the base's, block 1), their
    // mean weighted by length in 2D and by area in 3D.
    double slip2 = 0, length = 0, slip3 = 0, area = 0;
    const Contacts& C = a.contacts;
    for (size_t i = 0; i < C.a.size(); ++i)
      if (C.a[i] != 0 && C.b[i] != 0)
        slip2 += C.length[i] * std::abs(C.shear_disp[i]), length += C.length[i];
    for (const Contact3& c : b.contacts3)
      if (c.a != 0 && c.b != 0)
        for (const SubContact& sub : c.subs)
          slip3 += sub.area * sub.shear_travel(), area += sub.area;
    slip2 /= length, slip3 /= area;
    qInfo("%zu triangles, %zu tetrahedra; %llu and %llu cycles; joint %.4f m long, %.4f m2",
          a.continuum.zone_count(), b.continuum3.zone_count(),
          static_cast<unsigned long long>(a.cycle), static_cast<unsigned long long>(b.cycle),
          length, area);
    qInfo("top settles %.5e m in 2D, %.5e m in 3D; mean slip %.4e m in 2D, %.4e m in 3D", -top2,
          -top3, slip2, slip3);
    // Contacts cover the joint (2 / cos 30 long; both sides' nodes in 3D, each half the area).
    QVERIFY(std::abs(length / (2 / std::cos(M_PI / 6)) - 1) < 0.02);
    QVERIFY(top2 < 0 && slip2 > 0);
    QVERIFY(std::abs(top3 / top2 - 1) < 0.03);
    QVERIFY(std::abs(slip3 / slip2 - 1) < 0.03);
  }

  // Bad input names the line and the block.
  void badInputIsNamed() {
    const auto fails = [](const std::string& text, const char* expect) {
      ScriptRun r;
      try {
        r.run(text);
      } catch (const ScriptError& e) {
        qInfo("%s", e.what());
        return std::string(e.what()).find(expect) != std::string::npos;
      }
      return false;
    };
    const std::string cube =
        "dimension 3\ntolerance 0.01\nmaterial define stone density=2000\n"
        "material define rock density=2000 E=1e9 nu=0.25\n";
    QVERIFY(fails(cube + "block box 0,0,0 1,1,1 material=stone\nzone generate edge=0.5",
                  "block 1: its material has no elastic constants"));
    QVERIFY(fails(cube + "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5 order=3",
                  "write order=1 (4-node zones) or order=2 (10-node tetrahedra, 3D)"));
    QVERIFY(
        fails("round 0.01\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
              "block 0,0 1,0 1,1 0,1 material=rock\nzone generate edge=0.5 order=2",
              "order=2 (10-node tetrahedra) is for 3D models"));
    QVERIFY(fails(cube + "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5\n"
                         "boundary stress=1,2,3",
                  "SXX,SYY,SZZ,SXY,SYZ,SXZ"));
    QVERIFY(fails(cube + "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5\n"
                         "boundary fix=z z=5,6",
                  "no node lies in that box"));
    QVERIFY(fails(cube + "block box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5\n"
                         "jset dip=30 ddir=0 spacing=0.5",
                  "is deformable: cut blocks before"));
    // A jointed tunnel whose cuts meet at shallow angles made CGAL's mesher fail in block 20
    // ("... is already inserted on surface") when single blocks were meshed from their surface;
    // meshed as bodies of one piece, like joined ones, it zones. (Such a failure names the block
    // and clears away the dump CGAL writes into the working directory.)
    {
      ScriptRun r;
      r.run(
          "dimension 3\ntolerance 0.01\nmaterial define rock density=2700 E=10e9 "
          "nu=0.25\njoint define j kn=2e10 ks=1e10 friction=32\njoint assign j\n"
          "region 0,0,-10.5 10.5,18,10.5 group=rock material=rock\n"
          "jset dip=0 ddir=0 spacing=12 origin=0,0,6 name=bedding\n"
          "jset dip=90 ddir=0 spacing=4.5 origin=0,0,0 name=cross\n"
          "tunnel circle centre=0,0,0 axis=0,1,0 radius=3 length=9 rounds=3 segments=16 "
          "name=tunnel group=tunnel join\n"
          "zone generate edge=4 fine=0.8 near=0,4.5,0 radius=4 growth=0.4");
      QVERIFY(r.model().continuum3.zone_count() > 10000);
    }
    QVERIFY(!QFile::exists("dump-bug.mesh") && !QFile::exists("dump-bug.binary.cgal"));
  }

  // A tunnel through a jointed block whose mesh CGAL's sliver exuder could not finish: it went
  // round in circles for hours, deaf to Ctrl+C. It is given up after a budget of cells (the
  // plain mesh kept), and the zoning ends: here refused with the flat zone the plain mesh has,
  // named by block.
  void exudationGoingRoundInCirclesIsGivenUp() {
    ScriptRun r;
    try {
      r.run(
          "dimension 3\ntolerance 0.01\nmaterial define rock density=2500 E=10e9 nu=0.25\n"
          "joint define j kn=1e10 ks=1e10 friction=40\njoint assign j\n"
          "region 0,0,0 10,4,10 material=rock\njset dip=60 ddir=90 spacing=3 origin=0,0,0\n"
          "tunnel circle centre=5,0,5 axis=0,1,0 radius=2 length=4 segments=16 group=tun join\n"
          "zone generate edge=1.2");
      QVERIFY(r.model().continuum3.zone_count() > 0);
    } catch (const ScriptError& e) {
      qInfo("%s", e.what());
      QVERIFY(std::string(e.what()).find("block 4: the mesher left a flat zone") !=
              std::string::npos);
    }
  }
};

TESSERA_TEST_MAIN(TestDeformable3)
#include "test_deformable3.moc"
