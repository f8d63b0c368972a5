// Contact geometry of rounded corners: a corner meets a face with its arc, not the arc's full
// circle. A flat corner (an opening's outline, 11.25 degrees a corner with 32 segments) is
// rounded with a radius of d / tan(5.6 deg) = 10 d, and its circle reaches 10 d past its block.
#include <QtTest>
#include <algorithm>
#include <cmath>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
// Two pieces of tunnel_jointed.tess (blocks 59 and 61, moved by -17,-20) that share an edge:
// block 1 has corners of the 32-sided opening 0.24 m from the shared edge's end.
const char* kPieces =
    "round 0.02\n"
    "material define rock density=2700\n"
    "joint define j kn=2e10 ks=1e10 friction=35\n"
    "joint assign j\n"
    "block 0,0 0.0259508,-0.2634826 1.3467708,0.2315475 0.6559285,1.8498973 0.5055912,1.6667107 "
    "0.2283614,1.1480503 0.0576442,0.5852710 material=rock\n"
    "block 0.6559285,1.8498973 1.3467708,0.2315475 4.0881480,1.2589881 3.2888609,2.9715497 "
    "3,3 2.4147290,2.9423558 1.8519497,2.7716386 1.3332893,2.4944088 0.8786797,2.1213203 "
    "material=rock\n";
}  // namespace

class TestContactGeometry : public QObject {
  Q_OBJECT
 private slots:
  void flatCornerDoesNotReachPastItsBlock() {
    ScriptRun r;
    r.run(std::string(kPieces) + "check\nstep 1\n");
    const Model& m = r.model();
    const Contacts& C = m.contacts;
    QVERIFY(C.size() > 0);
    double deepest = 0.0, largest = 0.0;
    for (size_t i = 0; i < C.size(); ++i)
      deepest = std::min(deepest, C.gap[i]), largest = std::max(largest, std::abs(C.fn[i]));
    qInfo("%zu contacts, deepest gap %.3g m, largest normal force %.3g N", C.size(), deepest,
          largest);
    // The blocks only touch along the shared edge: gaps are round-off, forces nothing
    // (before: corner 5 of block 1 at -0.104 m, 1.8e9 N).
    QVERIFY(deepest > -1e-9);
    QVERIFY(largest < 1.0);
  }
};

QTEST_APPLESS_MAIN(TestContactGeometry)
#include "test_contact_geometry.moc"
