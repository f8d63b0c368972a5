// Random script lines never crash the interpreter: each either works or raises a ScriptError
// with a file:line message, and the interpreter stays usable after it.
#include <QtTest>
#include <random>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
const std::vector<std::string> kWords{"round",
                                      "block",
                                      "region",
                                      "crack",
                                      "jset",
                                      "tunnel",
                                      "voronoi",
                                      "arch",
                                      "wall",
                                      "join",
                                      "delete",
                                      "check",
                                      "material",
                                      "joint",
                                      "define",
                                      "assign",
                                      "group",
                                      "fix",
                                      "free",
                                      "velocity",
                                      "gravity",
                                      "damping",
                                      "timestep",
                                      "step",
                                      "solve",
                                      "history",
                                      "vtk",
                                      "set",
                                      "print",
                                      "local",
                                      "global",
                                      "none",
                                      "auto",
                                      "fixed",
                                      "circle",
                                      "horseshoe",
                                      "rectangle",
                                      "polygon",
                                      "all",
                                      "x",
                                      "y",
                                      "rotation",
                                      "interval",
                                      "extend",
                                      "proceed",
                                      "=",
                                      "rock",
                                      "j",
                                      "base",
                                      "0",
                                      "1",
                                      "-1",
                                      "0.5",
                                      "2",
                                      "1e9",
                                      "1e30",
                                      "-1e30",
                                      "nan",
                                      "(",
                                      ")",
                                      "0,0",
                                      "1,0",
                                      "1,1",
                                      "0,1",
                                      "2,2",
                                      "1,2",
                                      "-1,-1",
                                      "3,0",
                                      "0,3",
                                      "5",
                                      "1,",
                                      ",1",
                                      "a",
                                      "pi",
                                      "2*pi",
                                      "1/0",
                                      "sqrt(-1)",
                                      "density=2500",
                                      "kn=1e9",
                                      "ks=1e9",
                                      "friction=30",
                                      "friction=95",
                                      "group=base",
                                      "material=rock",
                                      "block=1",
                                      "block=99",
                                      "at=0.5,0.5",
                                      "at=9,9",
                                      "x=0,1",
                                      "y=-1,2",
                                      "circle=0,0,1",
                                      "polygon=(0,0 1,0 1,1)",
                                      "joints=jset1",
                                      "smaller=1",
                                      "angle=30",
                                      "spacing=0.3",
                                      "spacing=0",
                                      "trace=0.5",
                                      "gap=0.1",
                                      "seed=3",
                                      "size=0.4",
                                      "size=0",
                                      "centre=0.5,0.5",
                                      "radius=0.2",
                                      "radius=0",
                                      "segments=2",
                                      "width=0.3",
                                      "height=0.4",
                                      "thickness=0.1",
                                      "voussoirs=5",
                                      "voussoirs=0",
                                      "brick=0.5,0.25",
                                      "courses=2",
                                      "bricks=2",
                                      "courses=0",
                                      "ratio=1e-3",
                                      "cycles=50",
                                      "vx=1",
                                      "vy=0",
                                      "omega=1",
                                      "label=h",
                                      "name=n",
                                      "safety=0.5",
                                      "safety=2",
                                      "origin=0,0",
                                      "abutment=0.2",
                                      "half_angle=60"};
// A valid start, so that later lines reach deeper code.
const char* kStart =
    "round 0.01\nmaterial define rock density=2500\njoint define j kn=1e9 ks=1e9 friction=30\n"
    "joint assign j\nregion 0,0 2,2 group=base material=rock\ngravity 0 -9.81";

// Runs one line: it works, or it is refused with a message that names the file and line.
void attempt(ScriptRun& r, const std::string& text, int line, int& ok, int& errors) {
  try {
    r.interp->execute(text, "fuzz", line);
    ++ok;
  } catch (const ScriptError& e) {
    ++errors;
    QVERIFY2(std::string(e.what()).rfind("fuzz:", 0) == 0, e.what());
  }
}
}  // namespace

class TestScriptFuzz : public QObject {
  Q_OBJECT
 private slots:
  void randomLinesNeverCrash() {
    std::mt19937 rng(20261122);
    int errors = 0, ok = 0;
    for (int model = 0; model < 40; ++model) {
      ScriptRun r;
      r.run(kStart);
      for (int line = 0; line < 60; ++line) {
        // A command, then a few words (drawn from the first 25 words of the list, the commands and
        // their verbs).
        std::string text = kWords[rng() % 25] + " ";
        const int n = static_cast<int>(rng() % 5);
        for (int w = 0; w < n; ++w) text += kWords[rng() % kWords.size()] + " ";
        attempt(r, text, line + 1, ok, errors);
      }
      // Still usable.
      r.interp->execute("set z = 1 + 1", "fuzz", 99);
      QCOMPARE(r.interp->variable("z"), 2.0);
    }
    qInfo("%d lines ran, %d were refused with a message", ok, errors);
    QVERIFY(ok > 0 && errors > 0);
  }
  // Meaningful commands with numbers drawn from a set that includes zero, negatives and huge
  // values: generation, cutting, excavation and cycling in random order.
  void randomModelsNeverCrash() {
    const std::vector<std::string> templates{
        "step N",
        "jset angle=A spacing=S seed=N",
        "crack P P",
        "crack P P P",
        "tunnel circle centre=P radius=S",
        "tunnel rectangle P P",
        "voronoi size=S seed=N",
        "delete at=P",
        "fix at=P",
        "velocity at=P vx=A",
        "solve ratio=R cycles=N",
        "join all",
        "region P P material=rock",
        "block P P P material=rock",
        "history xdisp at=P",
        "check",
        "arch centre=P radius=S thickness=S voussoirs=N material=rock",
        "wall origin=P brick=S,S courses=N bricks=N material=rock",
        "group g x=A,A",
        "free all",
        "gravity A A",
        "damping global",
        "damping none",
        "timestep auto safety=S",
        "delete smaller=S",
        "join x=A,A"};
    const std::vector<std::string> numbers{"-1",  "0", "0.05", "0.3", "0.5", "1",
                                           "1.5", "2", "3",    "1e9", "-1e9"};
    std::mt19937 rng(7);
    auto pick = [&](const std::vector<std::string>& v) { return v[rng() % v.size()]; };
    int errors = 0, ok = 0;
    for (int model = 0; model < 25; ++model) {
      ScriptRun r;
      r.run(kStart);
      for (int line = 0; line < 25; ++line) {
        std::string text;
        for (char c : pick(templates)) {
          if (c == 'N')
            text += std::to_string(rng() % 40);
          else if (c == 'P')
            text += pick(numbers) + "," + pick(numbers);
          else if (c == 'A' || c == 'S' || c == 'R')
            text += pick(numbers);
          else
            text += c;
        }
        attempt(r, text, line + 1, ok, errors);
      }
    }
    qInfo("%d commands ran, %d were refused with a message", ok, errors);
    QVERIFY(ok > 100 && errors > 10);
  }
};

QTEST_APPLESS_MAIN(TestScriptFuzz)
#include "test_script_fuzz.moc"
