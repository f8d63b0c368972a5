// Bit-identical results: at 1 and 2 threads, and across save and restore.
#include <QtTest>

#include "support.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/io/state_io.hpp"

using namespace tessera;
using tessera::test::ScriptRun;
using tessera::test::state_hash;

namespace {
// A wall large enough that every parallel loop is split between threads.
const char* kWall =
    "round 0.02\n"
    "material define brick density=2600\n"
    "joint define mortar kn=1e10 ks=1e10 friction=35\n"
    "joint assign mortar\n"
    "block -1,-1 81,-1 81,0 -1,0 group=base material=brick\n"
    "fix group=base\n"
    "wall origin=0,0 brick=2,1 courses=30 bricks=40 material=brick group=wall\n"
    "gravity 0 -9.81\n";

const char* kWall3 =
    "dimension 3\ntolerance 0.01\nmaterial define brick density=2600\n"
    "joint define mortar kn=1e10 ks=1e10 friction=35\njoint assign mortar\n"
    "block box -1,-1,-1 41,1,0 group=base material=brick\nfix group=base\n"
    "wall brick=2,1,1 courses=12 bricks=20 material=brick\ngravity 0 0 -9.81\n";

uint64_t run_wall(int threads, int cycles) {
  set_thread_count(threads);
  ScriptRun r;
  r.run(std::string(kWall) + "step " + std::to_string(cycles));
  set_thread_count(1);
  return state_hash(r.model());
}
}  // namespace

class TestDeterminism : public QObject {
  Q_OBJECT
 private slots:
  // A 3D wall settling: sub-contacts and block motion the same at 1 and 2 threads.
  void wall3dSameAtOneAndTwoThreads() {
    const std::string wall = kWall3;
    const auto run = [&](int threads, int cycles) {
      set_thread_count(threads);
      ScriptRun r;
      r.run(wall + "step " + std::to_string(cycles));
      set_thread_count(1);
      return state_hash(r.model());
    };
    const uint64_t one = run(1, 150);
    QCOMPARE(run(2, 150), one);
    QVERIFY(one != run(1, 1));
    // Save part way, restore, go on: the same state bit for bit.
    ScriptRun straight, first, second;
    straight.run(wall + "step 100");
    first.run(wall + "step 60\nsave half3.sav\nstep 40");
    QCOMPARE(state_hash(first.model()), state_hash(straight.model()));
    second.run("restore " + first.path("half3.sav") + "\nstep 40");
    QCOMPARE(second.model().dim, uint8_t(3));
    QCOMPARE(state_hash(second.model()), state_hash(straight.model()));
  }
  // Each block's resultant gathered in its own step (no joined pieces, no cables) or in a pass of
  // their own (here because a joined body, held apart from the wall, is in the model): the
  // wall's blocks move the same, bit for bit.
  void wall3dForcesGatheredInTheStepAsApart() {
    const std::string steps = "step 150\n";
    ScriptRun fused, apart;
    fused.run(std::string(kWall3) + steps);
    apart.run(std::string(kWall3) +
              "block box 60,-1,0 61,1,1 material=brick\nblock box 61,-1,0 62,1,1 material=brick\n"
              "join block=248,249\nfix block=248\n" +
              steps);
    const Blocks3 &F = fused.model().blocks3, &A = apart.model().blocks3;
    QCOMPARE(F.size(), size_t(247));
    QCOMPARE(A.master[248], 247);
    for (size_t b = 0; b < F.size(); ++b) {
      QVERIFY(F.body[b].position == A.body[b].position);
      QVERIFY(F.body[b].orientation.coeffs() == A.body[b].orientation.coeffs());
      QVERIFY(F.body[b].velocity == A.body[b].velocity);
      QVERIFY(F.body[b].momentum == A.body[b].momentum);
    }
    QVERIFY(F.body[246].position != F.ref[246]);
  }
  // Density scaling and kinetic damping (the blocks' scales and the last kinetic energy are part
  // of the state): the same at 1 and 2 threads and across save and restore, in 2D and 3D.
  void kineticScaledRunsAreReproducible_data() {
    QTest::addColumn<QString>("wall");
    QTest::newRow("2D") << QString(kWall);
    QTest::newRow("3D") << QString(kWall3);
  }
  void kineticScaledRunsAreReproducible() {
    QFETCH(QString, wall);
    const std::string model = wall.toStdString() + "timestep scaled\ndamping kinetic\n";
    const auto run = [&](int threads, const std::string& steps) {
      set_thread_count(threads);
      auto r = std::make_unique<ScriptRun>();
      r->run(model + steps);
      set_thread_count(1);
      return r;
    };
    // The first cycle that stops the model: the save falls just before it, so that a restore
    // that lost the last kinetic energy would not stop there.
    ScriptRun probe;
    probe.run(model);
    int stop = 0;
    for (int c = 1; c <= 150 && !stop; ++c) {
      probe.run("step 1");
      if (c > 1 && probe.model().kinetic_last == 0.0) stop = c;
    }
    QVERIFY(stop > 1);
    const std::string before = std::to_string(stop - 1), after = std::to_string(151 - stop);
    const auto straight = run(1, "step 150");
    QVERIFY(!straight->model().block_scale.empty());
    QCOMPARE(state_hash(run(2, "step 150")->model()), state_hash(straight->model()));
    const auto first = run(1, "step " + before + "\nsave half.sav\nstep " + after);
    QCOMPARE(state_hash(first->model()), state_hash(straight->model()));
    const auto second = run(1, "restore " + first->path("half.sav") + "\nstep " + after);
    QCOMPARE(state_hash(second->model()), state_hash(straight->model()));
  }
  void sameAtOneAndTwoThreads() {
    const uint64_t one = run_wall(1, 120), two = run_wall(2, 120);
    QCOMPARE(two, one);
    // The state did change: the hash is not of an idle model.
    QVERIFY(one != run_wall(1, 1));
  }
  void restoreThenStepMatchesSteppingOn() {
    ScriptRun straight;
    straight.run(std::string(kWall) + "step 100");
    ScriptRun first;
    first.run(std::string(kWall) + "step 60\nsave half.sav\nstep 40");
    QCOMPARE(state_hash(first.model()), state_hash(straight.model()));
    ScriptRun second;
    second.run("restore " + first.path("half.sav") + "\nstep 40");
    QCOMPARE(state_hash(second.model()), state_hash(straight.model()));
    QCOMPARE(second.model().cycle, uint64_t(100));
  }
  // Deformable blocks on a rigid base: the same at 1 and 2 threads, and across save/restore.
  void deformableBlocksAreReproducible() {
    const std::string model =
        "round 0.01\nmaterial define stone density=2500\n"
        "material define rock density=2000 E=1e9 nu=0.25 model=mohr-coulomb friction=30 "
        "cohesion=1e4 tension=1e3\n"
        "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
        "block 0,0 4,0 4,1 0,1 group=base material=stone\nfix group=base\n"
        "block 0,1 2,1 2,3 0,3 group=soft material=rock\n"
        "block 2,1 4,1 4,2.5 2,2.5 group=soft material=rock\n"
        "zone generate edge=0.3 group=soft\ngravity 0 -10\n";
    auto run = [&](int threads, const std::string& steps) {
      set_thread_count(threads);
      auto r = std::make_unique<ScriptRun>();
      r->run(model + steps);
      set_thread_count(1);
      return r;
    };
    const auto one = run(1, "step 300"), two = run(2, "step 300");
    QVERIFY(one->model().continuum.zone_count() > 50);
    QCOMPARE(state_hash(two->model()), state_hash(one->model()));
    const auto first = run(1, "step 120\nsave half.sav\nstep 180");
    QCOMPARE(state_hash(first->model()), state_hash(one->model()));
    ScriptRun second;
    second.run("restore " + first->path("half.sav") + "\nstep 180");
    QCOMPARE(state_hash(second.model()), state_hash(one->model()));
    // The blocks did settle onto the base.
    QVERIFY(one->model().continuum.pos[0].y() != one->model().continuum.pos0[0].y());
  }
  void corruptStateFileIsRefused() {
    ScriptRun r;
    const std::string bad = r.path("bad.sav");
    std::FILE* f = std::fopen(bad.c_str(), "wb");
    std::fputs("TESSERA2 not really", f);
    std::fclose(f);
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, restore_state(bad));
  }
};

QTEST_APPLESS_MAIN(TestDeterminism)
#include "test_determinism.moc"
