// 3D block generation: exact plane cuts (volumes add up, no slivers through vertices, shared
// vertices bit-identical), joint sets, walls, and the script's messages for 3D mistakes.
#include <QtTest>
#include <cmath>
#include <map>
#include <numbers>

#include "support.hpp"
#include "tessera/generation/cutting3.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
double total_volume(const Model& m) {
  double v = 0.0;
  for (double x : m.blocks3.volume) v += x;
  return v;
}
std::string error_of(const std::string& script) {
  ScriptRun r;
  try {
    r.run(script);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return {};
}
const char* kHead = "dimension 3\ntolerance 0.01\nmaterial define rock density=2500\n";
}  // namespace

class TestGeneration3d : public QObject {
  Q_OBJECT
 private slots:
  void jointSetsCutARegionIntoPiecesThatAddUp() {
    ScriptRun r;
    r.run(std::string(kHead) +
          "region 0,0,0 10,8,6 material=rock\n"
          "jset dip=60,5 ddir=120,10 spacing=2,0.3 seed=3 name=J1\n"
          "jset dip=30 ddir=300 spacing=2.5 seed=4 name=J2\n");
    const Model& m = r.model();
    qInfo("%zu blocks", m.blocks3.size());
    QVERIFY(m.blocks3.size() > 20);
    QVERIFY(std::abs(total_volume(m) - 480.0) < 1e-9 * 480.0);
    // Every block convex and closed (solid_properties would have refused it) with its faces
    // tagged by the set that made them.
    int tagged = 0;
    for (int t : m.blocks3.face_tag) tagged += t >= 0;
    QVERIFY(tagged > 0);
  }

  // The same cuts at map coordinates (a northing of 4e6) as at the origin: the same blocks.
  // Their convexity was judged in world coordinates, within a tolerance of the block's size
  // only, and the cut was refused as "not convex" from a northing of 2e6.
  void mapCoordinatesCutAsAtTheOrigin() {
    const auto cut = [](const std::string& x, const std::string& y) {
      ScriptRun r;
      r.run(std::string(kHead) + "region " + x + "," + y + ",0 " + x + "+20," + y +
            "+20,20 material=rock\njset dip=60 ddir=30 spacing=2 origin=" + x + "," + y +
            ",0\njset dip=80 ddir=130 spacing=3 origin=" + x + "," + y + ",0\n");
      return std::make_pair(r.model().blocks3.size(), total_volume(r.model()));
    };
    const auto [n0, v0] = cut("0", "0");
    const auto [n1, v1] = cut("500000", "4000000");
    QCOMPARE(n1, n0);
    QVERIFY(std::abs(v0 - 8000.0) < 1e-9 * 8000.0 && std::abs(v1 - 8000.0) < 1e-6 * 8000.0);
  }

  void aCutThroughVerticesLeavesNoSliver() {
    // The diagonal plane x = y through a cube's vertical edges: two equal prisms, nothing else.
    ScriptRun r;
    r.run(std::string(kHead) +
          "region 0,0,0 1,1,1 material=rock\n"
          "crack dip=90 ddir=135 origin=0,0,0\n");
    const Model& m = r.model();
    QCOMPARE(m.blocks3.size(), size_t(2));
    QCOMPARE(m.blocks3.volume[0], 0.5);
    QCOMPARE(m.blocks3.volume[1], 0.5);
    // A plane along a face does not cut at all.
    ScriptRun along;
    along.run(std::string(kHead) +
              "region 0,0,0 1,1,1 material=rock\n"
              "crack dip=0 ddir=0 origin=0,0,1\n");
    QCOMPARE(along.model().blocks3.size(), size_t(1));
  }

  void neighboursShareBitIdenticalVertices() {
    ScriptRun r;
    r.run(std::string(kHead) +
          "region 0,0,0 3,3,3 material=rock\n"
          "crack dip=37 ddir=71 origin=1.1,1.3,1.7\n"
          "crack dip=81 ddir=203 origin=1.4,1.2,1.5\n");
    const Blocks3& B = r.model().blocks3;
    QCOMPARE(B.size(), size_t(4));
    // Each vertex made by a cut appears in at least two blocks, bit for bit.
    size_t shared = 0;
    for (size_t i = 0; i < B.world_vertex.size(); ++i)
      for (size_t j = i + 1; j < B.world_vertex.size(); ++j)
        shared += B.world_vertex[i] == B.world_vertex[j];
    QVERIFY(shared >= 8);
    QVERIFY(std::abs(total_volume(r.model()) - 27.0) < 1e-12 * 27.0);
  }

  void persistenceLeavesSomeBlocksWhole() {
    ScriptRun full, part;
    const std::string region = std::string(kHead) +
                               "region 0,0,0 10,10,10 material=rock\n"
                               "jset dip=90 ddir=90 spacing=1 seed=1\n";
    full.run(region + "jset dip=0 ddir=0 spacing=1 seed=2\n");
    part.run(region + "jset dip=0 ddir=0 spacing=1 persistence=0.5 seed=2\n");
    qInfo("blocks: persistent %zu, persistence 0.5: %zu", full.model().blocks3.size(),
          part.model().blocks3.size());
    QCOMPARE(full.model().blocks3.size(), size_t(100));
    QVERIFY(part.model().blocks3.size() > 20 && part.model().blocks3.size() < 90);
    QVERIFY(std::abs(total_volume(part.model()) - 1000.0) < 1e-9);
  }

  void aFiniteJointCutsOnlyBlocksInsideItsDisc() {
    // Ten 1 x 1 x 2 m slabs side by side; a level disc of radius 2.2 about (2.5, 0.5) at mid
    // height holds the sections of the slabs from x = 1 to 4 (farthest corner 1.58 m away) but
    // not those from 0 to 1 or 4 to 5 (2.55 m): three slabs are halved, the rest stay whole.
    ScriptRun r;
    r.run(std::string(kHead) +
          "region 0,0,0 10,1,2 material=rock\n"
          "jset dip=90 ddir=90 spacing=1 seed=1\n"
          "crack dip=0 ddir=0 origin=2.5,0.5,1 radius=2.2 name=disc\n");
    const Blocks3& B = r.model().blocks3;
    QCOMPARE(B.size(), size_t(13));
    size_t halves = 0;
    for (size_t b = 0; b < B.size(); ++b)
      if (B.volume[b] < 1.5) {
        ++halves;
        QVERIFY(B.body[b].position.x() > 1.0 && B.body[b].position.x() < 4.0);
      }
    QCOMPARE(halves, size_t(6));
    QVERIFY(std::abs(total_volume(r.model()) - 20.0) < 1e-9);
  }

  void wallHasRunningBondAndTaggedJoints() {
    ScriptRun r;
    r.run(std::string(kHead) + "wall brick=0.4,0.2,0.2 courses=4 bricks=5 material=rock\n");
    const Model& m = r.model();
    QCOMPARE(m.blocks3.size(), size_t(5 + 6 + 5 + 6));
    QVERIFY(std::abs(total_volume(m) - 4 * 5 * 0.4 * 0.2 * 0.2) < 1e-12);
  }

  void aTunnelCutsItsOpeningExactlyInRounds() {
    // A 16-sided circle of radius 2 along y through a 10 m cube, 6 m long in 3 rounds.
    ScriptRun r;
    r.run(std::string(kHead) +
          "region -5,0,-5 5,10,5 material=rock\n"
          "tunnel circle centre=0,0,0 axis=0,1,0 radius=2 length=6 rounds=3 segments=16 "
          "name=T group=dig\n");
    Model& m = r.model();
    const Blocks3& B = m.blocks3;
    // 16 sectors of rock along the opening and 16 beyond its end, 3 rounds, the rock ahead.
    QCOMPARE(B.size(), size_t(16 + 16 + 3 + 1));
    QVERIFY(std::abs(total_volume(m) - 1000.0) < 1e-9 * 1000.0);
    const double section = 0.5 * 16 * 4.0 * std::sin(2 * std::numbers::pi / 16);
    for (int round = 1; round <= 3; ++round) {
      const int g = m.group_index("dig_" + std::to_string(round), false);
      QVERIFY(g >= 0);
      double v = 0.0;
      for (size_t b = 0; b < B.size(); ++b) {
        if (B.group[b] != g) continue;
        v += B.volume[b];
        // Inside the walls and within its round.
        for (uint32_t k = B.vert_begin[b]; k < B.vert_begin[b + 1]; ++k) {
          const Vec3& x = B.world_vertex[k];
          QVERIFY(std::hypot(x.x(), x.z()) < 2.0 + 1e-9);
          QVERIFY(x.y() > 2.0 * (round - 1) - 1e-9 && x.y() < 2.0 * round + 1e-9);
        }
      }
      QVERIFY2(std::abs(v - 2.0 * section) < 1e-9 * v, std::to_string(v).c_str());
    }
    // The walls carry the opening's joint name; the other new faces are 'split'.
    int walls = 0, splits = 0;
    for (int t : B.face_tag) {
      walls += t >= 0 && m.joint_tags[static_cast<size_t>(t)] == "T";
      splits += t >= 0 && m.joint_tags[static_cast<size_t>(t)] == "split";
    }
    QCOMPARE(walls, 16 + 3 * 16);  // each rock sector's wall, and each round's 16
    QVERIFY(splits >= 2 * 16);
  }

  void joinedTunnelRockIsOneBodyPerBlock() {
    // With 'join', the rock each block keeps around the opening is one body: a jointed region
    // of two blocks (a joint plane across the opening's axis) gives two rock bodies, each of
    // 16 sectors and the rock past the end, and the rounds stay blocks of their own.
    ScriptRun r;
    r.run(std::string(kHead) +
          "region -5,0,-5 5,10,5 material=rock\ncrack dip=90 ddir=0 origin=0,3,0 name=J\n"
          "tunnel circle centre=0,0,0 axis=0,1,0 radius=2 length=6 rounds=3 segments=16 "
          "group=dig join\n");
    const Blocks3& B = r.model().blocks3;
    std::map<int32_t, int> pieces;
    for (size_t b = 0; b < B.size(); ++b) ++pieces[B.master[b]];
    std::vector<int> sizes;
    for (const auto& [master, n] : pieces) sizes.push_back(n);
    std::sort(sizes.begin(), sizes.end());
    // Rounds: 1 + 2 pieces (round 2 crosses the joint), the two rock bodies: 16 and 16 + 16 + 1.
    QCOMPARE(sizes, (std::vector<int>{1, 1, 1, 1, 16, 33}));
    QVERIFY(std::abs(total_volume(r.model()) - 1000.0) < 1e-9 * 1000.0);
    // Without a density the rock cannot be joined: refused before anything is cut.
    QVERIFY(error_of(std::string(kHead) + "region 0,0,0 4,4,4\n"
                                          "tunnel circle centre=2,0,2 axis=0,1,0 radius=1 "
                                          "length=4 join\n")
                .find("has no density") != std::string::npos);
  }

  void aTunnelThroughJointedRockAddsUpAndRuns() {
    // A horseshoe along a skewed axis through jointed rock: volumes add up, no blocks overlap,
    // and the rounds can be excavated one after another.
    ScriptRun r;
    r.run(std::string(kHead) +
          "joint define j kn=1e10 ks=1e10 friction=40 cohesion=1e6 tension=1e6\njoint assign j\n"
          "region -6,0,-6 6,12,6 material=rock\n"
          "jset dip=70 ddir=30 spacing=3 origin=0.3,0.2,0.1 name=J1\n"
          "tunnel horseshoe centre=0.5,1,-2 axis=0.1,1,0 width=4 height=4 length=9 rounds=3 "
          "group=dig\n"
          "delete group=dig_1\nstep 20\ndelete group=dig_2\nstep 20\n");
    const Model& m = r.model();
    QCOMPARE(m.cycle, uint64_t(40));
    const double section = 4.0 * 2.0 + 0.5 * 12 * 4.0 * std::sin(std::numbers::pi / 12);
    // Two rounds of 3 m along the axis excavated.
    const double opened = 1728.0 - total_volume(m);
    QVERIFY2(std::abs(opened - 2 * 3.0 * section) < 1e-6, std::to_string(opened).c_str());
  }

  void mistakesInThreeDimensionsAreNamed() {
    QVERIFY(error_of(std::string(kHead) + "region 0,0,0 1,1,1\ntunnel circle centre=0,0 "
                                          "axis=0,1,0 radius=1 length=1\n")
                .find("3D point") != std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "region 0,0,0 1,1,1\ntunnel circle centre=0,0,0 "
                                          "radius=1 length=1\n")
                .find("axis") != std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "region 0,0,0 1,1,1\ntunnel polygon 0,0 1,0 1,1\n")
                .find("circle or horseshoe") != std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "region 0,0,0 1,1,1\ntunnel circle centre=5,5,5 "
                                          "axis=0,0,1 radius=1 length=1\n")
                .find("reaches no block") != std::string::npos);
    QVERIFY(error_of("block 0,0 1,0 1,1\ndimension 3\n").find("before the first block") !=
            std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "block box 0,0,0 1,0,1\n").find("no volume") !=
            std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "block box 0,0 1,1\n").find("3D point") !=
            std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "round 0.01\n").find("tolerance") != std::string::npos);
    QVERIFY(error_of(std::string(kHead) + "crack dip=30 ddir=0\n").find("origin") !=
            std::string::npos);
    // Overlapping blocks are refused before the first cycle, naming both.
    const std::string e = error_of(std::string(kHead) +
                                   "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n"
                                   "block box 0,0,0 1,1,1 material=rock\n"
                                   "block box 0.5,0,0 1.5,1,1 material=rock\nstep 1\n");
    QVERIFY2(e.find("blocks 1 and 2 overlap") != std::string::npos, e.c_str());
    // A contact with no joint properties names both blocks.
    const std::string j = error_of(std::string(kHead) +
                                   "joint define j kn=1e9 ks=1e9 friction=30\n"
                                   "block box 0,0,-1 1,1,0 material=rock group=base\n"
                                   "block box 0,0,0 1,1,1 material=rock\nstep 1\n");
    QVERIFY2(j.find("no joint properties") != std::string::npos, j.c_str());
  }
};

QTEST_APPLESS_MAIN(TestGeneration3d)
#include "test_generation3d.moc"
