// 3D rigid blocks against closed forms: a block sliding down an incline cut at an oblique dip
// direction, a block on a bonded joint oscillating at sqrt(k/m), a free block spinning about a
// non-principal axis, the limiting friction angle of a Hoek & Bray wedge, and 2D models
// extruded one block thick giving the 2D answers.
#include <QtTest>
#include <cmath>
#include <functional>

#include "support.hpp"
#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/generation/cutting3.hpp"

using namespace tessera;
using tessera::test::num;
using tessera::test::ScriptRun;
using tessera::test::wedge_limit_angle;
using tessera::test::wedge_script;

namespace {
constexpr double kDeg = M_PI / 180;

std::string pt(const Vec3& p) {
  return num(p.x()) + "," + num(p.y()) + "," + num(p.z());
}

// Downslope unit vector of a plane of dip and dip direction (degrees).
Vec3 dip_vector(double dip, double ddir) {
  return {std::cos(dip * kDeg) * std::sin(ddir * kDeg),
          std::cos(dip * kDeg) * std::cos(ddir * kDeg), -std::sin(dip * kDeg)};
}

// A 1 m cube cut out of a region resting on a slab, both bounded by a plane of dip psi towards
// ddir: every face of the block is oblique to the axes.
std::string oblique_incline(double psi, double ddir, double phi) {
  const Vec3 n = normal_from_dip(psi, ddir), d = dip_vector(psi, ddir), t = n.cross(d);
  std::string s =
      "dimension 3\ntolerance 0.005\nmaterial define rock density=2500\n"
      "joint define j kn=1e10 ks=1e10 friction=" +
      num(phi) +
      "\njoint assign j\n"
      "region -6,-6,-6 6,6,4 material=rock\n"
      "crack dip=" +
      num(psi) + " ddir=" + num(ddir) +
      " origin=0,0,0 name=slope\n"
      "group slab at=" +
      pt(-0.5 * n) + "\ngroup rest at=" + pt(0.5 * n) + "\nfix group=slab\n";
  // The block: four planes across the slope and one parallel to it, cutting the upper piece.
  const auto cut = [&](const Vec3& normal, const Vec3& through) {
    const double dip = std::acos(std::abs(normal.z())) / kDeg;
    const Vec3 up = normal.z() < 0 ? Vec3(-normal) : normal;
    double dd = std::atan2(up.x(), up.y()) / kDeg;
    if (std::hypot(up.x(), up.y()) < 1e-12) dd = 0;
    s += "crack dip=" + num(dip) + " ddir=" + num(dd) + " origin=" + pt(through) + " group=rest\n";
  };
  cut(n, n);
  cut(d, 0.5 * d), cut(d, -0.5 * d), cut(t, 0.5 * t), cut(t, -0.5 * t);
  s += "group block at=" + pt(0.5 * n) +
       "\ndelete group=rest\ngravity 0 0 -9.81\ndamping none\nhistory interval 1\n";
  return s;
}

// Fitted acceleration of block b along direction d over [t0, t1] of simulated time.
double acceleration_along(ScriptRun& r, size_t b, const Vec3& d, double t0, double t1) {
  Model& m = r.model();
  std::vector<double> t, v;
  while (m.time < t1) {
    r.run("step 20");
    if (m.time > t0) t.push_back(m.time), v.push_back(m.blocks3.body[b].velocity.dot(d));
  }
  return tessera::test::fitted_slope(t, v);
}

// Steps a model 50 cycles at a time until its tilt reaches 0.2 rad or `limit` seconds have
// passed; the time it got there.
double time_to_tilt(ScriptRun& r, const std::function<double()>& tilt, double limit) {
  while (tilt() < 0.2 && r.model().time < limit) r.run("step 50");
  return r.model().time;
}

}  // namespace

class TestBlocks3d : public QObject {
  Q_OBJECT
 private slots:
  void obliqueInclineSlidesWithTheCoulombAcceleration() {
    const double psi = 30, ddir = 135, phi = 20;
    ScriptRun r;
    r.run(oblique_incline(psi, ddir, phi));
    Model& m = r.model();
    QCOMPARE(m.blocks3.size(), size_t(2));
    const size_t b = m.blocks3.group[0] == m.group_index("block", false) ? 0 : 1;
    QVERIFY(std::abs(m.blocks3.volume[b] - 1.0) < 1e-9);
    const double a = acceleration_along(r, b, dip_vector(psi, ddir), 0.2, 1.0);
    const double expected =
        9.81 * (std::sin(psi * kDeg) - std::cos(psi * kDeg) * std::tan(phi * kDeg));
    qInfo("acceleration %.5f, closed form %.5f", a, expected);
    QVERIFY(std::abs(a - expected) < 0.01 * expected);
    // Sliding straight down the dip, without turning.
    const Vec3 v = m.blocks3.body[b].velocity;
    QVERIFY(std::abs(v.dot(normal_from_dip(psi, ddir).cross(dip_vector(psi, ddir)))) <
            1e-3 * v.norm());
    QVERIFY(m.blocks3.body[b].angular_velocity().norm() < 1e-2);
  }

  // A block sliding from one base block onto the next (their top faces level, gravity tilted
  // 30 degrees): the joint it crosses changes nothing, it slides on at g (sin a - tan phi cos a).
  // Its contact with the next block was made on a vertical plane (the front face nearing the
  // joint) and kept it as they overlapped: the block sank into the base until the run stopped.
  void blockSlidesAcrossAJointInItsBase() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2000\n"
        "joint define j kn=1e10 ks=1e10 friction=20\njoint assign j\n"
        "block box -3,-2,-1 1.5,2,0 material=rock\nblock box 1.5,-2,-1 10,2,0 material=rock\n"
        "fix block=1,2\nblock box -1,-1,0 1,1,1 material=rock\n"
        "gravity (9.81*sin(30)) 0 (-9.81*cos(30))\ndamping none\ntimestep fixed 1e-5\n"
        "step 100000\n");
    const Model& m = r.model();
    const double a = 9.81 * (std::sin(30 * kDeg) - std::tan(20 * kDeg) * std::cos(30 * kDeg));
    const Vec3 moved = m.blocks3.body[2].position - Vec3(0, 0, 0.5);
    qInfo("slid %.6f m in 1 s, closed form %.6f", moved.x(), 0.5 * a);
    // Past the joint at 0.5 m, and over it as on one block (the time steps' error is 1e-5).
    QVERIFY(std::abs(moved.x() / (0.5 * a) - 1.0) < 1e-4);
    QVERIFY(std::abs(moved.z()) < 1e-5);
  }

  void obliqueInclineHoldsWhenFrictionExceedsTheSlope() {
    ScriptRun r;
    r.run(oblique_incline(30, 135, 40) + "damping local\nsolve ratio=1e-6\ndamping none");
    Model& m = r.model();
    const size_t b = m.blocks3.group[0] == m.group_index("block", false) ? 0 : 1;
    const Vec3 start = m.blocks3.body[b].position;
    const double t0 = m.time;
    while (m.time < t0 + 0.5) r.run("step 100");
    const double moved = (m.blocks3.body[b].position - start).norm();
    qInfo("moved %.3g m in 0.5 s undamped", moved);
    QVERIFY(moved < 1e-5);
  }

  void blockOnBondedJointOscillatesAtSqrtKOverM() {
    // 1 m cube (2500 kg) on a 1 m^2 bonded joint, kn = 1e9 Pa/m: omega = sqrt(kn A / m).
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.001\nmaterial define rock density=2500\n"
        "joint define glue kn=1e9 ks=1e9 friction=30 cohesion=1e7 tension=1e7\njoint assign glue\n"
        "block box -1,-1,-1 2,2,0 group=base material=rock\nfix group=base\n"
        "block box 0,0,0 1,1,1 material=rock\n"
        "damping none\ntimestep auto safety=0.05\nvelocity block=2 vz=-0.001\n");
    Model& m = r.model();
    // Upward zero crossings of the vertical displacement give the period.
    std::vector<double> crossings;
    double prev = 0.0;
    while (crossings.size() < 11) {
      r.run("step 1");
      const double z = m.blocks3.body[1].position.z() - m.blocks3.ref[1].z();
      if (prev < 0.0 && z >= 0.0) crossings.push_back(m.time - m.dt * z / (z - prev));
      prev = z;
    }
    const double period = (crossings.back() - crossings.front()) / 10.0;
    const double expected = 2 * M_PI / std::sqrt(1e9 * 1.0 / 2500.0);
    qInfo("period %.6g s, closed form %.6g s", period, expected);
    QVERIFY(std::abs(period - expected) < 0.01 * expected);
  }

  void freeBlockKeepsEnergyAndMomentum() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.001\nmaterial define rock density=2500\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n"
        "block box 0,0,0 1,2,3 material=rock\ndamping none\n");
    Model& m = r.model();
    RigidBody3& b = m.blocks3.body[0];
    b.momentum = Vec3(300, -200, 500);  // about no principal axis
    r.run("step 1");
    const double e0 = b.kinetic_energy();
    const Vec3 l0 = b.momentum;
    r.run("step 100000");
    const double de = std::abs(b.kinetic_energy() - e0) / e0;
    const double dl = (b.momentum - l0).norm() / l0.norm();
    qInfo("after 1e5 cycles: energy %.3g, momentum %.3g (relative change)", de, dl);
    QVERIFY(de < 1e-6);
    QVERIFY(dl < 1e-6);
    // The shape stays rigid: the cached world vertices keep their distances.
    const Blocks3& B = m.blocks3;
    double diagonal = 0.0;
    for (const Vec3& p : B.world_vertex)
      for (const Vec3& q : B.world_vertex) diagonal = std::max(diagonal, (p - q).norm());
    QVERIFY(std::abs(diagonal - std::sqrt(14.0)) < 1e-9);
  }

  void wedgeStartsToSlideAtTheHoekBrayFrictionAngle() {
    // Planes A and B through a point 6 m below the crest of a vertical face (normal -y).
    const double dip_a = 50, dd_a = 140, dip_b = 55, dd_b = 230;
    const double limit =
        wedge_limit_angle(normal_from_dip(dip_a, dd_a), normal_from_dip(dip_b, dd_b));
    qInfo("Hoek-Bray limit friction angle %.3f degrees", limit);
    const auto slides = [&](double phi) {
      ScriptRun r;
      r.run(wedge_script(phi, dip_a, dd_a, dip_b, dd_b) + "damping none\n");
      Model& m = r.model();
      const size_t w = static_cast<size_t>(
          std::find(m.blocks3.group.begin(), m.blocks3.group.end(), m.group_index("wedge", false)) -
          m.blocks3.group.begin());
      const Vec3 start = m.blocks3.body[w].position;
      while (m.time < 1.0) r.run("step 200");
      const double moved = (m.blocks3.body[w].position - start).norm();
      qInfo("phi %.3f: wedge moved %.3g m in 1 s", phi, moved);
      return moved > 1e-3;
    };
    double lo = limit - 4.0, hi = limit + 4.0;
    QVERIFY(slides(lo));
    QVERIFY(!slides(hi));
    while (hi - lo > 0.25) {
      const double mid = 0.5 * (lo + hi);
      (slides(mid) ? lo : hi) = mid;
    }
    qInfo("model limit angle in [%.3f, %.3f]", lo, hi);
    QVERIFY(std::abs(0.5 * (lo + hi) - limit) < 0.5);
  }

  void extrudedInclineGivesThe2dAnswer() {
    // The 2D block-on-incline model and the same section extruded 1 m along z.
    const std::string section =
        "set psi = 30\nset phi = 20\nset c = cos(psi)\nset s = sin(psi)\n"
        "material define rock density=2500\njoint define j kn=1e10 ks=1e10 friction=phi\n"
        "joint assign j\ndamping none\n";
    const std::string slab = "(-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s)";
    const std::string block = "0,0 c,s (c-s),(s+c) (-s),c";
    ScriptRun r2, r3;
    r2.run(section + "round 0.005\nblock " + slab + " group=slab material=rock\nblock " + block +
           " material=rock\nfix group=slab\ngravity 0 -9.81\nstep 5000");
    r3.run("dimension 3\ntolerance 0.005\n" + section + "block prism " + slab +
           " z=-1,2 group=slab material=rock\nblock prism " + block +
           " z=0,1 material=rock\nfix group=slab\ngravity 0 -9.81 0\nstep 5000");
    const Model &m2 = r2.model(), &m3 = r3.model();
    const double v2 = std::hypot(m2.blocks.vx[1], m2.blocks.vy[1]) / m2.time;
    const double v3 = m3.blocks3.body[1].velocity.norm() / m3.time;
    qInfo("mean acceleration 2D %.5f, 3D %.5f", v2, v3);
    QVERIFY(std::abs(v3 - v2) < 0.02 * v2);
    QVERIFY(std::abs(m3.blocks3.body[1].velocity.z()) < 1e-9);
  }

  void extrudedToppleAndStandMatch2d() {
    // A slender block on a 30 degree slope with friction enough not to slide topples (b/h =
    // 0.33 < tan 30); a squat one (b/h = 0.8) stands, in 2D and extruded. A toppling block's
    // tilt grows from round-off, so the models are compared by the time to tilt 0.2 rad.
    for (const double b : {0.4, 0.96}) {
      const double h = 1.2;
      const std::string pre =
          "set psi = 30\nset b = " + num(b) + "\nset h = " + num(h) +
          "\nset c = cos(psi)\nset s = sin(psi)\n"
          "material define rock density=2500\n"
          "joint define j kn=1e10 ks=1e10 friction=45\njoint assign j\ndamping none\n";
      const std::string slab = "(-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s)";
      const std::string block = "0,0 b*c,b*s (b*c-h*s),(b*s+h*c) (-h*s),h*c";
      ScriptRun r2, r3;
      r2.run(pre + "round 0.005\nblock " + slab + " group=slab material=rock\nblock " + block +
             " material=rock\nfix group=slab\ngravity 0 -9.81");
      r3.run("dimension 3\ntolerance 0.005\n" + pre + "block prism " + slab +
             " z=-1,2 group=slab material=rock\nblock prism " + block +
             " z=0,1 material=rock\nfix group=slab\ngravity 0 -9.81 0");
      const auto tilt2 = [&] { return std::abs(r2.model().blocks.theta[1]); };
      const auto tilt3 = [&] {
        return history_value(r3.model(), {HistoryQuantity::kRotation, 1, -1, ""});
      };
      const double t2 = time_to_tilt(r2, tilt2, 2.0), t3 = time_to_tilt(r3, tilt3, 2.0);
      qInfo("b/h %.2f: tilt 2D %.4f rad at %.3f s, 3D %.4f rad at %.3f s", b / h, tilt2(), t2,
            tilt3(), t3);
      if (b / h < std::tan(30 * kDeg)) {
        // Rigid rotation about the toe: I_toe theta'' = m g r sin(alpha0 + theta), alpha0 the
        // initial angle of the centroid past the vertical through the toe.
        const double r = 0.5 * std::hypot(b, h),
                     lever = 0.5 * b * std::cos(30 * kDeg) - 0.5 * h * std::sin(30 * kDeg);
        const double rate = 9.81 * r / ((b * b + h * h) / 12.0 + r * r);
        double th = 0.0, w = 0.0, t = 0.0;
        for (const double dt = 1e-5; th < 0.2; t += dt)
          w += rate * std::sin(std::asin(-lever / r) + th) * dt, th += w * dt;
        qInfo("closed form: 0.2 rad at %.3f s", t);
        QVERIFY(t2 < 2.0 && t3 < 2.0);
        QVERIFY(std::abs(t3 - t2) < 0.05 * t2);
        QVERIFY(std::abs(t3 - t) < 0.05 * t);
      } else {
        // Standing, undamped: gravity switched on at once overshoots to twice the static
        // moment, which lifts the heel (N/2 - 2 T h/2s < 0 here), and with no damping the block
        // goes on rocking by a few milliradians, far from the toppling block's 0.2 rad.
        QVERIFY(tilt2() < 1e-2);
        QVERIFY(tilt3() < 1e-2);
      }
    }
  }

  // 'timestep fixed DT' sets the step of 2D and 3D models alike (3D once ignored it).
  void fixedTimestepIsUsedIn2dAnd3d() {
    const std::string law =
        "material define rock density=2500\njoint define j kn=1e10 ks=1e10 friction=30\n"
        "joint assign j\n";
    ScriptRun r3;
    r3.run(
        "dimension 3\ntolerance 0.01\ngravity 0 0 -9.81\n" + law +
        "block box 0,0,-1 1,1,0 material=rock\nfix block=1\nblock box 0,0,0 1,1,1 material=rock\n"
        "timestep fixed 1e-6\nstep 10");
    QCOMPARE(r3.model().dt, 1e-6);
    QVERIFY(std::abs(r3.model().time - 1e-5) < 1e-18);
    ScriptRun r2;
    r2.run(
        "round 0.01\ngravity 0 -9.81\n" + law +
        "block 0,-1 1,-1 1,0 0,0 material=rock\nfix block=1\nblock 0,0 1,0 1,1 0,1 material=rock\n"
        "timestep fixed 1e-6\nstep 10");
    QCOMPARE(r2.model().dt, 1e-6);
    // Back to automatic: the stable step of these stiffnesses is far larger.
    r3.run("timestep auto\nstep 1");
    QVERIFY(r3.model().dt > 1e-5);
  }

  void joinedBlocksMoveAsOneConcaveBody() {
    // An L: a foot and an arm joined. Mass, centroid and principal moments are the L prism's.
    const std::string l_block =
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=45\njoint assign j\ndamping none\n"
        "block prism -1,-1 3,-1 3,0 -1,0 z=-1,2 group=base material=rock\nfix group=base\n"
        "block prism 0,0 0.4,0 0.4,1.2 0,1.2 z=0,1 material=rock\n"
        "block prism 0.4,0.9 ARM,0.9 ARM,1.2 0.4,1.2 z=0,1 material=rock\n"
        "join block=2,3\ngravity 0 -9.81 0\n";
    const auto with_arm = [&](double arm) {
      std::string t = l_block;
      for (size_t k; (k = t.find("ARM")) != std::string::npos;) t.replace(k, 3, num(arm));
      return t;
    };
    ScriptRun r3;
    r3.run(with_arm(1.4));
    const Blocks3& B = r3.model().blocks3;
    QCOMPARE(B.master[2], 1);
    const SolidProperties l = solid_properties(
        prism({{0, 0}, {0.4, 0}, {0.4, 0.9}, {1.4, 0.9}, {1.4, 1.2}, {0, 1.2}}, 0, 1));
    QVERIFY(std::abs(B.body[1].mass - 2500 * l.volume) < 1e-9 * B.body[1].mass);
    QVERIFY((B.body[1].position - l.centroid).norm() < 1e-12);
    QVERIFY((B.body[1].principal - 2500 * l.principal_moments).norm() <
            1e-9 * B.body[1].principal.norm());
    // Its centroid (x = 0.47) is beyond the foot (x = 0.4): it topples as the 2D concave block
    // does; with a shorter arm (centroid at x = 0.28) both stand.
    for (const double arm : {1.4, 0.8}) {
      ScriptRun r2, r3b;
      r2.run(
          "round 0.005\nmaterial define rock density=2500\n"
          "joint define j kn=1e10 ks=1e10 friction=45\njoint assign j\ndamping none\n"
          "block -1,-1 3,-1 3,0 -1,0 group=base material=rock\nfix group=base\n"
          "block 0,0 0.4,0 0.4,0.9 " +
          num(arm) + ",0.9 " + num(arm) + ",1.2 0,1.2 material=rock\ngravity 0 -9.81\n");
      r3b.run(with_arm(arm));
      const auto tilt2 = [&] { return std::abs(r2.model().blocks.theta[1]); };
      const auto tilt3 = [&] {
        return history_value(r3b.model(), {HistoryQuantity::kRotation, 2, -1, ""});
      };
      const double t2 = time_to_tilt(r2, tilt2, 1.5), t3 = time_to_tilt(r3b, tilt3, 1.5);
      qInfo("arm to x = %.1f: tilt 2D %.4f rad at %.3f s, 3D %.4f rad at %.3f s", arm, tilt2(), t2,
            tilt3(), t3);
      if (arm > 1.0) {
        QVERIFY(t2 < 1.5 && t3 < 1.5);
        QVERIFY(std::abs(t3 - t2) < 0.05 * t2);
        // The arm piece went round with the foot: both pieces' vertices keep their distances.
        const Blocks3& J = r3b.model().blocks3;
        QVERIFY(
            std::abs((J.world_vertex[J.vert_begin[1]] - J.world_vertex[J.vert_begin[2]]).norm() -
                     (J.local_vertex[J.vert_begin[1]] - J.local_vertex[J.vert_begin[2]]).norm()) <
            1e-9);
      } else {
        // Standing, undamped: gravity switched on at once overshoots to twice the static
        // moment, which lifts the heel (N/2 - 2 T h/2s < 0 here), and with no damping the block
        // goes on rocking by a few milliradians, far from the toppling block's 0.2 rad.
        QVERIFY(tilt2() < 1e-2);
        QVERIFY(tilt3() < 1e-2);
      }
    }
  }

  // A trapezoid prism resting on a base: its weight acts over its footprint's centroid, so the
  // corner sub-contacts' areas must put a uniform pressure's resultant there, and it settles
  // level with every corner at the same stress (the fan about the corners' mean put the resultant
  // 0.028 m off and tilted it by 2.9e-5 rad on soft joints).
  void trapezoidSettlesLevel() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2600\n"
        "joint define j kn=1e8 ks=1e8 friction=30\njoint assign j\n"
        "block box -3,-3,-1 5,3,0 group=base material=rock\nfix group=base\n"
        "block prism 0,0 2,0 1.5,1 0.5,1 z=0,1 material=rock\ngravity 0 0 -9.81\n"
        "solve ratio=1e-7\n");
    const Model& m = r.model();
    QCOMPARE(m.contacts3.size(), size_t(1));
    const Contact3& c = m.contacts3[0];
    QCOMPARE(c.subs.size(), size_t(4));
    double area = 0.0;
    Vec3 first = Vec3::Zero();
    for (const SubContact& s : c.subs) {
      area += s.area, first += s.area * world_point(m.blocks3, c, s);
      QVERIFY2(std::abs(s.fn / s.area - 2600 * 9.81) < 1e-4 * 2600 * 9.81,
               std::to_string(s.fn / s.area).c_str());
    }
    QVERIFY(std::abs(area - 1.5) < 1e-12);
    // The footprint's centroid: x = 1, y = h (a + 2 b) / 3 (a + b) = 4/9 (a = 2 at y = 0, b = 1).
    QVERIFY((first / area - Vec3(1.0, 4.0 / 9.0, 0.0)).head<2>().norm() < 1e-6);
    const double tilt = history_value(m, {HistoryQuantity::kRotation, 1, -1, ""});
    QVERIFY2(tilt < 1e-8, std::to_string(tilt).c_str());
  }

  // 'reset displacement': displacements count from the reset, for 2D and 3D blocks, rigid and
  // zoned, and grow again from zero when the load changes.
  void resetDisplacementCountsFromNow_data() {
    QTest::addColumn<QString>("model");
    QTest::addColumn<int>("quantity");
    const std::string joint = "joint define j kn=1e8 ks=1e8 friction=30\njoint assign j\n";
    const std::string rock3 =
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2600 E=1e9 nu=0.25\n" + joint +
        "block box -1,-1,-1 2,2,0 group=base material=rock\nfix group=base\n"
        "block box 0,0,0 1,1,1 material=rock group=top\n";
    QTest::newRow("2D rigid") << QString::fromStdString(
                                     "round 0.01\nmaterial define rock density=2600\n" + joint +
                                     "block -1,-1 2,-1 2,0 -1,0 group=base material=rock\n"
                                     "fix group=base\nblock 0,0 1,0 1,1 0,1 material=rock\n"
                                     "gravity 0 -9.81\n")
                              << int(HistoryQuantity::kYDisp);
    QTest::newRow("3D rigid") << QString::fromStdString(rock3 + "gravity 0 0 -9.81\n")
                              << int(HistoryQuantity::kZDisp);
    QTest::newRow("3D zoned") << QString::fromStdString(rock3 +
                                                        "zone generate edge=0.5 group=top\n"
                                                        "gravity 0 0 -9.81\n")
                              << int(HistoryQuantity::kZDisp);
  }
  void resetDisplacementCountsFromNow() {
    QFETCH(QString, model);
    QFETCH(int, quantity);
    const HistorySeries disp{static_cast<HistoryQuantity>(quantity), 1, -1, ""};
    const bool three = model.startsWith("dimension 3");
    ScriptRun r;
    r.run(model.toStdString() + "solve ratio=1e-5\n");
    const double settled = history_value(r.model(), disp);
    QVERIFY2(settled < -1e-5, std::to_string(settled).c_str());
    r.run("reset displacement\n");
    QCOMPARE(history_value(r.model(), disp), 0.0);
    // Twice the weight: the block sinks again, from zero.
    r.run(three ? "gravity 0 0 -19.62\nstep 50\n" : "gravity 0 -19.62\nstep 50\n");
    const double more = history_value(r.model(), disp);
    QVERIFY2(more < -1e-7 && more > 2 * settled, std::to_string(more).c_str());
  }

  void angularVelocitySpinsABlock() {
    // A free box spun about its long (principal) axis keeps turning at that rate; one held whole
    // turns at its prescribed rate; one with only its rotation fixed refuses.
    const std::string box =
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2500\n"
        "block box 0,0,0 1,2,3 material=rock\ngravity 0 0 0\ntimestep fixed 1e-3\n"
        "damping none\n";
    ScriptRun free, held, part;
    free.run(box + "velocity block=1 wz=0.5 vx=0.1\n");
    const Blocks3& B = free.model().blocks3;
    QVERIFY((B.body[0].angular_velocity() - Vec3(0, 0, 0.5)).norm() < 1e-12);
    QCOMPARE(B.body[0].velocity.x(), 0.1);
    const Vec3 momentum = B.body[0].momentum;
    free.run("step 1000\n");
    const HistorySeries turn{HistoryQuantity::kRotation, 0, -1, ""};
    QVERIFY(std::abs(history_value(free.model(), turn) - 0.5) < 1e-9);
    QVERIFY((B.body[0].momentum - momentum).norm() < 1e-12 * momentum.norm());
    QVERIFY(std::abs(B.body[0].position.x() - 0.5 - 0.1) < 1e-12);
    held.run(box + "fix block=1\nvelocity block=1 wz=0.2\nstep 1000\n");
    QVERIFY(std::abs(history_value(held.model(), turn) - 0.2) < 1e-9);
    part.run(box + "fix block=1 rotation\n");
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, part.run("velocity block=1 wz=0.2\n"));
  }

  void aPieceActsOnItsWholeBody() {
    // An L of two joined pieces: 'fix', 'free' and 'velocity' of either piece act on the body
    // (they did nothing through the slave piece), and a piece takes no other material.
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500\n"
        "material define light density=1000\n"
        "joint define j kn=1e10 ks=1e10 friction=45\njoint assign j\n"
        "block prism 0,0 0.4,0 0.4,1.2 0,1.2 z=0,1 material=rock\n"
        "block prism 0.4,0.9 1.4,0.9 1.4,1.2 0.4,1.2 z=0,1 material=rock\n"
        "join block=1,2\ngravity 0 -9.81 0\nfix block=2\nstep 20\n");
    const Blocks3& B = r.model().blocks3;
    QCOMPARE(B.master[1], 0);
    QCOMPARE(B.fixity[0], uint8_t(kFix3All));
    QCOMPARE(B.body[0].position, B.ref[0]);
    r.run("free block=2\nvelocity block=2 vx=1\n");
    QCOMPARE(B.fixity[0], uint8_t(0));
    QCOMPARE(B.fixity[1], uint8_t(0));
    QCOMPARE(B.body[0].velocity.x(), 1.0);
    r.run("step 20\n");
    QVERIFY(B.body[0].position.y() < B.ref[0].y() - 1e-6);
    QVERIFY_THROWS_EXCEPTION(tessera::ScriptError, r.run("material assign light block=2\n"));
    r.run("material assign rock block=1,2\n");
    QCOMPARE(B.body[0].mass, 2500 * (0.4 * 1.2 + 1.0 * 0.3));
  }

  void joinedBodyIsRemovedWhole() {
    // An L of two joined pieces on a base: 'delete' of one piece takes the body whole, and
    // removing one piece alone (master or slave) is refused with the model unchanged.
    const std::string l_block =
        "dimension 3\ntolerance 0.005\nmaterial define rock density=2500\n"
        "block prism -1,-1 3,-1 3,0 -1,0 z=-1,2 group=base material=rock\n"
        "block prism 0,0 0.4,0 0.4,1.2 0,1.2 z=0,1 material=rock\n"
        "block prism 0.4,0.9 1.4,0.9 1.4,1.2 0.4,1.2 z=0,1 material=rock\n"
        "join block=2,3\n";
    for (const std::vector<uint8_t>& doomed : {std::vector<uint8_t>{0, 1, 0}, {0, 0, 1}}) {
      ScriptRun r;
      r.run(l_block);
      Blocks3& B = r.model().blocks3;
      const Vec3 centre = B.body[1].position;
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, B.remove(doomed));
      QCOMPARE(B.size(), size_t(3));
      QCOMPARE(B.master[2], 1);
      QVERIFY(B.body[1].position == centre);
    }
    ScriptRun r;
    r.run(l_block + "delete block=3\n");
    QCOMPARE(r.model().blocks3.size(), size_t(1));
    QCOMPARE(r.model().blocks3.id[0], 1);
  }
};

QTEST_APPLESS_MAIN(TestBlocks3d)
#include "test_blocks3d.moc"
