// Liners: a lined circular tunnel in elastic ground against Einstein and Schwartz's closed form
// (thrust and moment, no-slip and full-slip interfaces), and liners through deletion, state
// files and bad input.
#include <QtTest>
#include <cmath>
#include <set>

#include "support.hpp"
#include "tessera/io/state_io.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
// A tunnel of radius 1 m in a 30 m square of elastic rock (E = 1 GPa, nu = 0.25) under
// vertical stress P = 1 MPa and horizontal K P, lined as it is excavated (the zones start at the
// in-situ stress; the opening's wall is unloaded at the first cycle with the liner in place).
// The rock's two pieces (the ring is split once) are glued by a stiff bonded joint.
std::string lined(double K, double thickness, double ks) {
  const std::string k = std::to_string(K), t = std::to_string(thickness);
  return "set p = 1e6\nround 0.01\ntimestep scaled\ndamping kinetic\n"
         "material define rock density=2500 E=1e9 nu=0.25\n"
         "joint define glue kn=1e13 ks=1e13 friction=45 cohesion=1e9 tension=1e9\n"
         "joint assign glue\nregion -15,-15 15,15 group=rock material=rock\n"
         "tunnel circle centre=0,0 radius=1 segments=48 name=t group=t\ndelete group=t\n"
         "zone generate edge=3 fine=0.15 near=0,0 radius=1.1 growth=0.3\n"
         "boundary fix=x x=-15.01,-14.99\nboundary fix=y y=-15.01,-14.99\n"
         "boundary stress=(-" +
         k +
         "*p),0,0 x=14.99,15.01\n"
         "boundary stress=0,(-p),0 y=14.99,15.01\n"
         "insitu stress=(-" +
         k +
         "*p),(-p),0\n"
         "liner joints=t e=2e10 nu=0.2 thickness=" +
         t + " kn=1e12 ks=" + std::to_string(ks) + "\nsolve ratio=1e-5 cycles=100000\n";
}
}  // namespace

class TestLiners : public QObject {
  Q_OBJECT
 private slots:
  // Einstein and Schwartz (1979), compressibility C = E R (1 - nus^2) / (Es A (1 - nu^2)) and
  // flexibility F = E R^3 (1 - nus^2) / (Es I (1 - nu^2)); a0 = C F (1 - nu) / (C + F + C F
  // (1 - nu)), a2 = (F + 6)(1 - nu) / (2 F (1 - nu) + 6 (5 - 6 nu)). Hydrostatic (K = 1):
  // thrust P R (1 - a0) all round, no moment, slip or not. Full slip: thrust P R (1/2 (1 + K)
  // (1 - a0) + 1/2 (1 - K)(1 - 2 a2) cos 2 theta) and moment P R^2 1/2 (1 - K)(1 - 2 a2)
  // cos 2 theta, theta from the springline. The far boundary at 15 R and 48 wall segments put
  // the answers within about 1%: thrust within 1.5% of P R, moment within 3% of its peak.
  void einsteinSchwartz_data() {
    QTest::addColumn<double>("K");
    QTest::addColumn<double>("thickness");
    QTest::addColumn<double>("ks");
    QTest::newRow("hydrostatic-no-slip") << 1.0 << 0.1 << 1e12;
    QTest::newRow("K0.5-full-slip") << 0.5 << 0.3 << 0.0;
  }
  void einsteinSchwartz() {
    QFETCH(double, K);
    QFETCH(double, thickness);
    QFETCH(double, ks);
    ScriptRun r;
    r.run(lined(K, thickness, ks));
    const Liners& L = r.model().liners;
    QCOMPARE(L.liners.size(), size_t(1));
    QVERIFY(L.liners[0].closed);
    const double E = 1e9, nu = 0.25, Es = 2e10, nus = 0.2, R = 1.0, P = 1e6;
    const double A = thickness, I = thickness * thickness * thickness / 12.0;
    const double C = E * R * (1 - nus * nus) / (Es * A * (1 - nu * nu));
    const double F = E * R * R * R * (1 - nus * nus) / (Es * I * (1 - nu * nu));
    const double a0 = C * F * (1 - nu) / (C + F + C * F * (1 - nu));
    const double a2 = (F + 6) * (1 - nu) / (2 * F * (1 - nu) + 6 * (5 - 6 * nu));
    double worst_t = 0.0, worst_m = 0.0, peak_m = 0.5 * (1 - K) * (1 - 2 * a2) * P * R * R;
    for (size_t i = 0; i < L.size(); ++i) {
      const double c2 = std::cos(2.0 * std::atan2(L.pos0[i].y(), L.pos0[i].x()));
      const double T = P * R * (0.5 * (1 + K) * (1 - a0) + 0.5 * (1 - K) * (1 - 2 * a2) * c2);
      const double M = peak_m * c2;
      worst_t = std::max(worst_t, std::abs(liner_thrust(L, i) - T) / (P * R));
      worst_m = std::max(worst_m, std::abs(liner_moment(L, i) - M));
    }
    qInfo(
        "C %.3g F %.3g: thrust within %.3g of P R (closed form at the crown %.6g N/m); moment "
        "within %.3g N m/m of the closed form (peak %.4g)",
        C, F, worst_t, P * R * (0.5 * (1 + K) * (1 - a0) - 0.5 * (1 - K) * (1 - 2 * a2)), worst_m,
        peak_m);
    QVERIFY(worst_t < 0.015);
    if (K == 1.0)
      QVERIFY(worst_m < 0.005 * P * R * R);
    else
      QVERIFY(worst_m < 0.03 * peak_m);
  }
  // A liner on part of a wall is an open chain with the angles asked; deleting its rock takes
  // it away; state files keep it.
  void openLinerDeletionAndState() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "region -5,-5 5,5 group=rock material=rock\njset angle=0 spacing=3 origin=0,1.5\n"
        "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\ndelete group=t\n"
        "fix all\nliner joints=t angles=0,180 ea=1e9 ei=1e6 kn=1e10 ks=1e10 name=crown\n"
        "history liner_thrust liner=crown at=0,1\nstep 10");
    const Liners& L = r.model().liners;
    QCOMPARE(L.liners.size(), size_t(1));
    QVERIFY(!L.liners[0].closed);
    for (size_t i = 0; i < L.size(); ++i) QVERIFY(L.pos0[i].y() > -1e-9);
    QCOMPARE(L.size(), size_t(13));  // 12 segments of the upper half
    const std::string path = QDir::tempPath().toStdString() + "/tessera_liners.state";
    save_state(r.model(), path);
    const Model back = restore_state(path);
    std::remove(path.c_str());
    QCOMPARE(back.liners.size(), L.size());
    QCOMPARE(back.liners.pos0[3].y(), L.pos0[3].y());
    r.run("delete at=0,1.2");  // the rock over the crown
    QCOMPARE(r.model().liners.size(), size_t(0));
    QCOMPARE(r.model().histories.series[0].element, -1);
  }
  // spacing= puts nodes between the wall's vertices, at most that far apart, each on the rock
  // of its edge: the 24-gon's half has 12 edges of 0.261 m, each split in three.
  void spacingPutsNodesBetweenTheVertices() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "region -5,-5 5,5 group=rock material=rock\n"
        "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\ndelete group=t\n"
        "fix all\nliner joints=t angles=0,180 ea=1e9 ei=1e6 kn=1e10 ks=1e10 spacing=0.1 "
        "name=crown\nstep 10");
    const Liners& L = r.model().liners;
    QCOMPARE(L.size(), size_t(37));
    const double edge = 2.0 * std::sin(7.5 * M_PI / 180.0);
    double length = 0.0;
    for (size_t i = 0; i < L.size(); ++i) {
      length += L.length[i];
      const double rad = L.pos0[i].norm();
      QVERIFY(rad <= 1.0 + 1e-9 && rad >= std::cos(7.5 * M_PI / 180.0) - 1e-9);
      if (i > 0) QVERIFY(std::abs((L.pos0[i] - L.pos0[i - 1]).norm() - edge / 3.0) < 1e-9);
    }
    QVERIFY(std::abs(length - 12.0 * edge) < 1e-9);
    ScriptRun bad;
    try {
      bad.run(
          "round 0.01\nmaterial define rock density=2500\n"
          "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
          "region -5,-5 5,5 group=rock material=rock\n"
          "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\ndelete group=t\n"
          "liner joints=t ea=1e9 ei=1e6 kn=1e10 ks=1e10 spacing=0");
      QFAIL("spacing=0 was taken");
    } catch (const ScriptError& e) {
      QVERIFY(std::string(e.what()).find("node spacing must be positive") != std::string::npos);
    }
  }
  // Rock settled before it is dug: blocks have moved along the joint the wall crosses, so the
  // wall's ends on either side are microns apart. The liner goes in (it was refused: "the wall
  // is broken between its edges", found by an independent check), as a closed ring on the
  // rock of both sides.
  void linedAfterTheRockHasSettled() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "region -5,-5 5,5 group=rock material=rock\ncrack -5,0.3 5,1.3 name=J\n"
        "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\nfix at=0,-3\n"
        "gravity 0 -9.81\nstep 100\ndelete group=t\n"
        "liner joints=t ea=1e9 ei=1e6 kn=1e10 ks=1e10 name=L\nstep 10\n");
    const Liners& L = r.model().liners;
    QCOMPARE(L.liners.size(), size_t(1));
    QVERIFY(L.liners[0].closed);
    std::set<int32_t> hosts;
    for (size_t i = 0; i < L.size(); ++i) hosts.insert(L.host[i].block);
    QVERIFY(hosts.size() >= 2);
  }
  void badLinersAreNamed_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("no opening") << "liner joints=nothing ea=1e9 ei=1e6 kn=1e10 ks=0"
                                << "nothing";
    QTest::newRow("no stiffness") << "liner joints=t kn=1e10 ks=0"
                                  << "ea";
    QTest::newRow("no interface") << "liner joints=t ea=1e9 ei=1e6"
                                  << "kn";
    QTest::newRow("not excavated") << "liner joints=s ea=1e9 ei=1e6 kn=1e10 ks=0"
                                   << "excavated";
  }
  void badLinersAreNamed() {
    QFETCH(QString, line);
    QFETCH(QString, message);
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2500\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "region -5,-5 5,5 group=rock material=rock\n"
        "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t\ndelete group=t\n"
        "tunnel circle centre=3,3 radius=0.5 segments=12 name=s group=s\n");
    QString error;
    try {
      r.run(line.toStdString());
    } catch (const std::exception& e) {
      error = e.what();
    }
    QVERIFY2(error.contains(message), qPrintable(error));
    QCOMPARE(r.model().liners.liners.size(), size_t(0));
  }
};

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  TestLiners t;
  return tessera::test::run_tests(t, argc, argv);
}

#include "test_liners.moc"
