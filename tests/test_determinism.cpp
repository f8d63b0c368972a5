// Bit-identical results: at 1 and 2 threads, and across save and restore.
#include <QtTest>

#include "support.hpp"
#include "tessera/parallel.hpp"
#include "tessera/state_io.hpp"

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
