// Contact geometry of rounded corners: a corner meets a face with its arc, not the arc's full
// circle. A flat corner (an opening's outline, 11.25 degrees a corner with 32 segments) is
// rounded with a radius of d / tan(5.6 deg) = 10 d, and its circle reaches 10 d past its block.
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "support.hpp"
#include "tessera/contact2d/detection.hpp"
#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"

using namespace tessera;
using tessera::test::num;
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

// Eight unit squares on a fixed slab, 1 m apart (blocks 2-9); the second (block 3) hangs 0.5 m
// above the slab. Joint properties apply to contacts of groups slab and a only.
std::string row(const std::string& assign = "joint assign j\n") {
  std::string s =
      "round 0.005\nmaterial define rock density=2500\n"
      "joint define j kn=1e9 ks=1e9 friction=40\n"
      "block -1,-1 16,-1 16,0 -1,0 group=slab material=rock\nfix group=slab\n";
  for (int k = 0; k < 8; ++k) {
    const double x = 2.0 * k, y = k == 1 ? 0.5 : 0.0;
    s += "block " + std::to_string(x) + "," + std::to_string(y) + " " + std::to_string(x + 1) +
         "," + std::to_string(y) + " " + std::to_string(x + 1) + "," + std::to_string(y + 1) + " " +
         std::to_string(x) + "," + std::to_string(y + 1) + " group=" + (k == 1 ? "b" : "a") +
         " material=rock\n";
  }
  return s + assign;
}
using ContactKey = std::tuple<uint32_t, uint32_t, uint32_t, uint8_t>;
ContactKey key_of(const Contacts& C, size_t i) {
  return {C.a[i], C.corner[i], C.b[i], C.slot[i]};
}
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

  // Contacts are found at every gap below the tolerance, as the detection passes' spacing (a
  // block moving half the tolerance) assumes: two blocks closing from a gap just inside it, each
  // moving just under half of it, must already be in contact. (The corners were tested against
  // the other block grown by half the tolerance only: a square 0.6 tolerance above its base had
  // no contact, in 2D; 3D found it.)
  void contactsAreFoundWithinTheTolerance() {
    const std::string rock =
        "material define rock density=2500\njoint define j kn=1e9 ks=1e9 friction=40\n"
        "joint assign j\n";
    for (const double gap : {0.3, 0.6, 0.95, 1.05}) {
      for (const int dim : {2, 3}) {
        const std::string y = num(gap * 0.005), top = num(1 + gap * 0.005);
        const std::string blocks =
            dim == 2
                ? "round 0.005\n" + rock + "block -1,-1 2,-1 2,0 -1,0 material=rock\nblock 0," + y +
                      " 1," + y + " 1," + top + " 0," + top + " material=rock\ngravity 0 -9.81\n"
                : "dimension 3\ntolerance 0.005\n" + rock +
                      "block box -1,-1,-1 2,2,0 material=rock\nblock box 0,0," + y + " 1,1," + top +
                      " material=rock\ngravity 0 0 -9.81\n";
        ScriptRun r;
        r.run(blocks + "fix block=1\nstep 1\n");
        const size_t found = dim == 2 ? r.model().contacts.size() : r.model().contacts3.size();
        qInfo("%dD, gap %.2f of the tolerance: %zu contacts", dim, gap, found);
        QCOMPARE(found > 0, gap < 1.0);
      }
    }
  }

  // A detection pass carries each contact's history to the same contact (the same corner of the
  // same block against the same block) wherever it now stands in the store, as contacts before
  // it come and go; new contacts start without history; length is there again.
  void detectionCarriesHistoryByIdentity() {
    ScriptRun r;
    r.run(row() + "step 1\n");
    Model& m = r.model();
    Contacts& C = m.contacts;
    std::map<ContactKey, size_t> before;
    for (size_t i = 0; i < C.size(); ++i) {
      C.fn[i] = 1.0 + static_cast<double>(i), C.shear_disp[i] = 1e-3 * static_cast<double>(i);
      C.dilation[i] = 1e-6 * static_cast<double>(i), C.flags[i] |= kTouching;
      before[key_of(C, i)] = i;
    }
    QCOMPARE(C.size(), size_t{14});  // two corners of each square on the slab
    // Block 3 comes down onto the slab and blocks 6 and 7 lift off: the contacts of blocks 4 and
    // 5 move up the store by two, and those of blocks 8 and 9 down by two, each onto a place
    // another one leaves.
    m.blocks.y[2] -= 0.5, m.blocks.y[5] += 0.5, m.blocks.y[6] += 0.5;
    detect_contacts(m);
    size_t moved_up = 0, moved_down = 0, fresh = 0;
    for (size_t i = 0; i < C.size(); ++i) {
      const auto was = before.find(key_of(C, i));
      if (was == before.end()) {
        ++fresh;
        QCOMPARE(C.fn[i], 0.0);
        QCOMPARE(C.shear_disp[i], 0.0);
        QVERIFY(!(C.flags[i] & kTouching));
        continue;
      }
      const size_t o = was->second;
      QCOMPARE(C.fn[i], 1.0 + static_cast<double>(o));
      QCOMPARE(C.shear_disp[i], 1e-3 * static_cast<double>(o));
      QCOMPARE(C.dilation[i], 1e-6 * static_cast<double>(o));
      QVERIFY(C.flags[i] & kTouching);
      moved_up += i > o, moved_down += i < o;
    }
    QCOMPARE(C.size(), size_t{12});
    // Every contact of a block that stayed is still there, once.
    std::set<ContactKey> after;
    for (size_t i = 0; i < C.size(); ++i) after.insert(key_of(C, i));
    QCOMPARE(after.size(), C.size());
    for (const auto& [key, i] : before)
      if (std::get<0>(key) != 5 && std::get<0>(key) != 6) QVERIFY(after.count(key) == 1);
    QCOMPARE(fresh, size_t{2});
    QCOMPARE(moved_up, size_t{4});
    QCOMPARE(moved_down, size_t{4});
    QCOMPARE(C.length.size(), C.size());
    QCOMPARE(m.block_contact_begin.back(), static_cast<uint32_t>(2 * C.pair_count()));
  }

  // Where joint properties are assigned by group only, a pass that meets a contact none apply to
  // stops with a message naming the blocks and leaves the contacts as they were.
  void detectionFailsWithoutChangingTheContacts() {
    ScriptRun r;
    r.run(row("joint assign j groups=slab,a\n") + "step 1\n");
    Model& m = r.model();
    const Contacts C0 = m.contacts;
    QCOMPARE(C0.size(), size_t{14});
    m.blocks.y[2] -= 0.5;  // block 3, group b, onto the slab
    try {
      detect_contacts(m);
      QFAIL("a contact without joint properties was made");
    } catch (const ModelError& e) {
      QVERIFY(std::string(e.what()).find("block 3 (group b)") != std::string::npos);
    }
    const Contacts& C = m.contacts;
    QCOMPARE(C.size(), C0.size());
    QCOMPARE(C.length.size(), C0.size());
    for (size_t i = 0; i < C.size(); ++i) {
      QVERIFY(key_of(C, i) == key_of(C0, i));
      QCOMPARE(C.length[i], C0.length[i]);
      QCOMPARE(C.fn[i], C0.fn[i]);
    }
  }

  // The block sums gather each pair's force, moment and load as the interfaces stage summed
  // them (the second block's moment turned by the arm between the centroids): the same as
  // summing every contact's force, dashpot included, on each block directly. Three blocks in
  // running bond, pushed sideways, so that pairs carry shear and moment on both sides.
  void blockSumsAreTheContactForces() {
    ScriptRun r;
    r.run(
        "round 0.005\ngravity 0 -9.81\nmaterial define rock density=2500\n"
        "joint define j kn=1e9 ks=1e9 friction=30 ndamping=0.2 sdamping=0.2\njoint assign j\n"
        "block -1,-1 4,-1 4,0 -1,0 group=slab material=rock\nfix group=slab\n"
        "block 0,0 1,0 1,0.5 0,0.5 material=rock\nblock 1,0 2,0 2,0.5 1,0.5 material=rock\n"
        "block 0.5,0.5 1.5,0.5 1.5,1 0.5,1 material=rock\nload block=4 fx=3000\nstep 40\n");
    Model& m = r.model();
    const Blocks& B = m.blocks;
    const Contacts& C = m.contacts;
    // The positions the cycle's sums are taken about (integration moves the blocks after).
    const std::vector<double> x = B.x, y = B.y;
    r.run("step 1\n");
    QVERIFY(!C.damp_fn.empty());
    const Vec2 g = m.settings.gravity;
    int checked = 0;
    for (size_t b = 1; b < B.size(); ++b) {
      double fx = B.mass[b] * g.x() + B.load_fx[b], fy = B.mass[b] * g.y() + B.load_fy[b];
      double mz = B.load_m[b], applied = B.mass[b] * g.norm() + std::abs(B.load_fx[b]);
      for (size_t i = 0; i < C.size(); ++i) {
        if (C.a[i] != b && C.b[i] != b) continue;
        const Vec2 f = C.a[i] == b ? C.force(i) : Vec2(-C.force(i));
        fx += f.x(), fy += f.y();
        mz += (C.point[i].x() - x[b]) * f.y() - (C.point[i].y() - y[b]) * f.x();
        applied += std::abs(C.total_fn(i)) + std::abs(C.total_fs(i));
      }
      // Round-off of a handful of terms of the size of the load carried (moments over arms
      // under a metre).
      const double scale = 1e-9 * applied;
      QVERIFY2(std::abs(B.fx[b] - fx) <= scale, qPrintable(QString::number(B.fx[b] - fx)));
      QVERIFY2(std::abs(B.fy[b] - fy) <= scale, qPrintable(QString::number(B.fy[b] - fy)));
      QVERIFY2(std::abs(B.moment[b] - mz) <= scale, qPrintable(QString::number(B.moment[b] - mz)));
      QVERIFY(std::abs(B.applied[b] - applied) <= scale);
      qInfo("block %zu applied %g weight %g", b, applied, B.mass[b] * g.norm());
      checked += applied > B.mass[b] * g.norm() * 1.5;
    }
    QCOMPARE(checked, 3);  // every free block carries contact forces
  }
};

QTEST_APPLESS_MAIN(TestContactGeometry)
#include "test_contact_geometry.moc"
