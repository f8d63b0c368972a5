// Bad input gets a message naming the file, the line and the object at fault.
#include <QtTest>
#include <cstring>
#include <fstream>
#include <iterator>

#include "support.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
const char* kBase =
    "round 0.01\n"
    "material define rock density=2600\n"
    "joint define j kn=1e9 ks=1e9 friction=30\n";

// The message of the ScriptError that running `text` raises, or "" if none.
std::string error_of(const std::string& text) {
  ScriptRun r;
  try {
    r.run(text);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return {};
}

bool has(const std::string& s, const std::string& part) {
  if (s.find(part) != std::string::npos) return true;
  qWarning("message was: %s", s.c_str());
  return false;
}
}  // namespace

class TestScriptErrors : public QObject {
  Q_OBJECT
 private slots:
  void unknownCommandSuggests() {
    const auto e = error_of("round 0.01\nstpe 10");
    QVERIFY(has(e, "test:2: unknown command 'stpe' (did you mean 'step'?)"));
  }
  void badDampingIsNamed() {
    QVERIFY(has(error_of("round 0.01\ndamping kinetik"),
                "test:2: 'kinetik' is not a damping mode (did you mean 'kinetic'?)"));
    QVERIFY(
        has(error_of("damping kinetic 1.5"), "test:1: kinetic damping's alpha must be in [0, 1)"));
    QVERIFY(has(error_of("damping kinetic 0.2 0.3"), "unexpected word '0.3'"));
  }
  void badBoltsAreNamed() {
    const std::string two = std::string(kBase) +
                            "block 0,0 2,0 2,1 0,1 material=rock\n"
                            "block 0,1 2,1 2,2 0,2 material=rock\n";
    QVERIFY(has(error_of(two + "bolt 5,5 6,6 ka=1e8 ks=1e7"),
                "test:6: bolt 'bolt1' from (5, 5) to (6, 6) crosses no block"));
    QVERIFY(has(error_of(two + "bolt 1,0.2 1,0.8 ka=1e8 ks=1e7 name=short"),
                "test:6: bolt 'short' from (1, 0.2) to (1, 0.8) lies in block 1 (group (none)) "
                "and crosses no joint"));
    QVERIFY(has(error_of(two + "bolt 1,0.5 1,1.5 ks=1e7"),
                "test:6: a bolt (its axial stiffness, N/m) needs ka="));
    QVERIFY(has(error_of(two + "bolt 1,0.5 1,1.5 ka=1e8 ks=1e7 tension=-1"),
                "yield forces and rupture displacement cannot be negative"));
    QVERIFY(has(error_of(two + "bolt 1,0.5 ka=1e8 ks=1e7"), "write 'bolt X,Y X,Y"));
    QVERIFY(has(error_of(two + "bolt 1,0.5 1,1.5 ka=1e8 ks=1e7 name=b\nbolt 1,0.5 1,1.5 ka=1e8 "
                               "ks=1e7 name=b"),
                "test:7: a bolt named 'b' exists already"));
    QVERIFY(has(error_of(two + "bolt pattern joints=tunnel spacing=1 length=3 ka=1 ks=1"),
                "no joint set, crack or opening is named 'tunnel'"));
    QVERIFY(has(error_of(two + "bolt 1,0.5 1,1.5 ka=1e8 ks=1e7\ncrack 0,0.5 2,0.5"),
                "test:7: cut and join blocks before placing bolts"));
    QVERIFY(has(error_of(two + "bolt 1,0.5 1,1.5 ka=1e8 ks=1e7\nhistory bolt_axial bolt=c"),
                "test:7: no bolt is named 'c'"));
    QVERIFY(has(error_of("dimension 3\nbolt 0,0 1,1 ka=1 ks=1"),
                "'bolt' is not available in 3D models yet"));
  }
  void badFactorOfSafetyIsNamed() {
    QVERIFY(has(error_of("solve fos joints=maybe"), "test:1: write joints=on or joints=off"));
    QVERIFY(has(error_of("solve fos cycles=1"), "the cycle limit of a trial must be"));
    QVERIFY(has(error_of("solve fos joints=off zones=off"), "no strength to reduce"));
    QVERIFY(has(error_of("solve fos now"), "unexpected word 'now'"));
    QVERIFY(has(error_of("solve fos exclude=rok"), "there is no group 'rok'"));
    QVERIFY(has(error_of("joint define j kn=1e9 ks=1e9 friction=30 rcohesion=5"),
                "rfriction and rcohesion belong to law=coulomb-residual"));
    QVERIFY(has(error_of("joint define j kn=1e9 ks=1e9 friction=30 law=coulomb-residual "
                         "rfriction=95"),
                "rfriction must be below 90 degrees"));
  }
  void planeOfTheWrongDimensionIsNamed() {
    QVERIFY(has(error_of("material define m density=2500 E=1e9 nu=0.2 model=ubiquitous-joint "
                         "friction=30 cohesion=1e6 jfriction=20 jdip=30 jdipdir=0"),
                "a 2D model's plane is jangle="));
  }
  void badNonlinearJointIsNamed() {
    QVERIFY(has(error_of("joint define j law=barton-bandis kn=1e9 ks=1e9 friction=28 jrc=10 "
                         "jcs=1e8"),
                "test:1: joint 'j' (law=barton-bandis) needs vm="));
    QVERIFY(has(error_of("joint define j law=barton-bandis kn=1e9 ks=1e9 friction=28 jrc=25 "
                         "jcs=1e8 vm=1e-3"),
                "jrc must be in [0, 20]"));
    QVERIFY(has(error_of("joint define j kn=1e9 ks=1e9 friction=28 jrc=10"),
                "belong to law=barton-bandis"));
    QVERIFY(has(error_of("joint define j law=cy kn=1e9 ks=1e9 friction=30 ifriction=40"),
                "roughness (m) must be positive"));
    QVERIFY(has(error_of("joint define j law=cy kn=1e9 ks=1e9 friction=30 en=1.2"),
                "en and es must be in [0, 1)"));
    QVERIFY(has(error_of("joint define j law=cy kn=1e9 ks=1e9 friction=30 cohesion=1e5"),
                "law=cy has no cohesion"));
    QVERIFY(has(error_of("joint define j kn=1e9 ks=1e9 friction=30 roughness=1e-3"),
                "belong to law=cy"));
  }
  void badTablesAreNamed() {
    const std::string two = std::string(kBase) + "block 0,0 1,0 1,1 0,1 material=rock\n";
    QVERIFY(
        has(error_of("table t 0,1 0,2"), "test:1: table 't': the times must increase (point 2)"));
    QVERIFY(has(error_of("table t 0,1 2"), "test:1: '2' is not a pair T,V"));
    QVERIFY(has(error_of(two + "table ramp 0,0 1,1\nfix block=1 table=ramp"),
                "test:6: table= goes with 'velocity', 'load',"));
    QVERIFY(has(error_of(two + "table ramp 0,0 1,1\nload block=1 fx=1 table=rmp"),
                "test:6: there is no table 'rmp' (did you mean 'ramp'?)"));
    // A file's bad line is named by the file and its line.
    ScriptRun r;
    { std::ofstream(r.path("motion.csv")) << "time,velocity\n0,0\n0.5,x\n"; }
    try {
      r.run("table shake " + r.path("motion.csv"));
      QFAIL("a bad table file was read");
    } catch (const ScriptError& e) {
      QVERIFY(has(e.what(), "motion.csv:3: write time,value"));
    }
  }
  void badLoadsAreNamed() {
    const std::string two = std::string(kBase) + "block 0,0 1,0 1,1 0,1 material=rock\n";
    QVERIFY(has(error_of(two + "load block=1"), "test:5: 'load' needs fx=, fy= (N/m)"));
    QVERIFY(has(error_of(two + "load block=1 fx=1 omega=2"), "test:5: 'omega' is not a keyword"));
    QVERIFY(has(error_of(two + "material define rock density=2600 E=1e9 nu=0.25\n"
                               "zone generate edge=0.5\nload block=1 fx=1"),
                "test:7: block 1 is deformable: load its nodes"));
  }
  // Messages an independent check found misleading: a missing kn= blamed a given ks= as not a
  // keyword; a bad elastic constant or strength suggested a model name; a bad K named the
  // material twice and said constants were missing; a second 'zone generate' did nothing and
  // said nothing; a one-number box range was "not a point".
  void misleadingMessagesAreStraight() {
    QVERIFY(has(error_of("joint define k ks=1e10 friction=30"), "test:1: joint 'k' needs kn="));
    QVERIFY(error_of("joint define k ks=1e10 friction=30").find("not a keyword") ==
            std::string::npos);
    const std::string mat = "material define rock density=2000 ";
    QVERIFY(has(error_of(mat + "E=-1e9 nu=0.25"),
                "test:1: material 'rock': Young's modulus must be positive"));
    QVERIFY(error_of(mat + "E=-1e9 nu=0.25").find("did you mean") == std::string::npos);
    const auto k = error_of(mat + "K=-1e9 G=1e9");
    QVERIFY(has(k, "material 'rock': elastic constants must be positive (bulk modulus K -1e+09"));
    QVERIFY(k.find("zone material") == std::string::npos);
    QVERIFY(has(error_of(mat + "E=1e9 nu=0.25 model=mohr-colomb"),
                "'mohr-colomb' is not a zone model (did you mean 'mohr-coulomb'?)"));
    const std::string zoned =
        "dimension 3\ntolerance 0.01\n" + mat +
        "E=1e9 nu=0.25\nblock box 0,0,0 1,1,1 material=rock\nzone generate edge=0.5\n";
    QVERIFY(has(error_of(zoned + "zone generate edge=0.3"),
                "test:6: block 1 is zoned already; a block is zoned once"));
    QVERIFY(has(error_of(zoned + "boundary fix=z x=0,1 y=0"),
                "test:6: 'y=0' is not a range: write y=Y0,Y1"));
    // A keyword of the other dimension is named as not one of this command's, with no
    // suggestion of itself.
    const auto vz = error_of(std::string(kBase) +
                             "material define z density=2000 E=1e9 nu=0.25\n"
                             "block 0,0 1,0 1,1 0,1 material=z\nzone generate edge=0.5\n"
                             "boundary vz=1 y=0.9,1.1");
    QVERIFY(has(vz, "'vz' is not a keyword of 'boundary'"));
    QVERIFY(vz.find("did you mean 'vz'") == std::string::npos);
  }
  void unknownKeywordSuggests() {
    const auto e = error_of("joint define j kn=1e9 ks=1e9 frction=30");
    QVERIFY(has(e, "test:1:"));
    QVERIFY(has(e, "'friction'"));
  }
  void badNumberIsNamed() {
    QVERIFY(has(error_of("gravity 0 -9.81x"), "cannot read the number '-9.81x'"));
    QVERIFY(has(error_of("set a = 2*b"), "'b' is not a defined variable"));
  }
  void degenerateBlockIsNamed() {
    const auto e = error_of(std::string(kBase) + "block 0,0 1,0 2,0 material=rock");
    QVERIFY(has(e, "test:4: block 1: the polygon has no area"));
    QVERIFY(has(error_of(std::string(kBase) + "block 0,0 1,1 1,0 0,1"), "cross"));
  }
  void missingMaterialIsNamed() {
    const auto e = error_of(std::string(kBase) + "joint assign j\nblock 0,0 1,0 1,1 0,1\nstep 1");
    QVERIFY(has(e, "test:6: block 1 has no mass"));
    QVERIFY(has(error_of(std::string(kBase) + "block 0,0 1,0 1,1 material=granit"),
                "there is no material 'granit'"));
  }
  void overlappingBlocksAreNamed() {
    const auto e = error_of(std::string(kBase) +
                            "joint assign j\nblock 0,0 1,0 1,1 0,1 material=rock\n"
                            "block 0.5,0.5 1.5,0.5 1.5,1.5 0.5,1.5 material=rock\nstep 1");
    QVERIFY(has(e, "test:7: error: blocks 1 and 2 overlap"));
  }
  void crossingBlocksAreNamed() {
    // A "+" of two bars: no vertex of either lies inside the other.
    const auto e = error_of(std::string(kBase) +
                            "joint assign j\nblock 0,1 3,1 3,2 0,2 material=rock\n"
                            "block 1,0 2,0 2,3 1,3 material=rock\nstep 1");
    QVERIFY(has(e, "test:7: error: blocks 1 and 2 overlap"));
  }
  void duplicateBlocksAreNamed() {
    // The same block twice: no vertex lies deeper than the other's edges and no edges cross.
    const auto e = error_of(std::string(kBase) +
                            "joint assign j\nblock 0,0 1,0 1,1 0,1 material=rock\n"
                            "block 0,0 1,0 1,1 0,1 material=rock\nstep 1");
    QVERIFY(has(e, "test:7: error: blocks 1 and 2 overlap"));
  }
  // Bad input of issue 13: each ends with file:line and a message, never a crash.
  void deepNestingIsRefused() {
    const std::string deep = "set x = " + std::string(50000, '(') + "1" + std::string(50000, ')');
    QVERIFY(has(error_of(deep), "test:1:"));
    QVERIFY(has(error_of(deep), "nests more than 200 levels"));
    QVERIFY(has(error_of("set y = " + std::string(20000, '-') + "1"), "nests more than"));
  }
  void folderCalledIsRefused() {
    ScriptRun r;
    QVERIFY(has(error_of("call " + r.dir.path().toStdString()), "is a folder, not a script file"));
  }
  void byteOrderMarkIsSkipped() {
    ScriptRun r;
    const std::string path = r.path("bom.tess");
    std::ofstream(path) << "\xEF\xBB\xBFround 0.01\nmaterial define rock density=2600\n";
    r.run("call " + path);
    QCOMPARE(r.model().settings.rounding, 0.01);
  }
  void pointOnAnOutlineSelectsItsBlock() {
    ScriptRun r;
    r.run(std::string(kBase) +
          "joint assign j\nblock 0,0 1,0 1,4 0,4 material=rock\n"
          "history ydisp at=0.5,4 label=top\n");
    QCOMPARE(r.model().histories.series.at(0).block, 0);
    QVERIFY(has(error_of(std::string(kBase) + "block 0,0 1,0 1,4 0,4 material=rock\n"
                                              "history ydisp at=0.5,4.5"),
                "no block contains the point 0.5,4.5"));
  }
  void singleZonedBlockNeedsNoJoints() {
    ScriptRun r;
    r.run(
        "round 0.01\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
        "block 0,0 1,0 1,2 0,2 material=rock\nzone generate edge=0.5\n"
        "boundary fix=y y=-0.01,0.01\ngravity 0 -10\nstep 20");
    QCOMPARE(r.model().cycle, uint64_t(20));
  }
  void warningsReachTheSummary() {
    ScriptRun r;
    r.run(std::string(kBase) +
          "joint assign j\nblock 0,-1 2,-1 2,0 0,0 material=rock\n"
          "fix block=1\nblock 0,0 1,0 1,1 0,1 material=rock\n"
          "gravity 0 -10\nhistory ratio\nsolve ratio=1e-12 cycles=10\n");
    QCOMPARE(r.interp->summary().warnings.size(), size_t(1));
    QVERIFY(has(r.interp->summary().warnings[0], "test:10: warning: solve stopped at the cycle"));
    // A history over a long run is announced before it starts (this model has no blocks, so
    // the run itself stops at once).
    ScriptRun h;
    try {
      h.run("history ratio\nhistory time\nhistory interval 1\nstep 100000000");
    } catch (const ScriptError&) {
    }
    QCOMPARE(h.interp->summary().warnings.size(), size_t(1));
    QVERIFY(has(h.interp->summary().warnings[0], "test:4: warning: the histories will reach"));
    QVERIFY(has(h.interp->summary().warnings[0], "history interval"));
    // A model at map coordinates (a northing of 4e6, where a coordinate rounds to 1e-9 m) is
    // told to move its origin, once; the same model at a local origin is not.
    const auto far = [](double y0) {
      ScriptRun f;
      f.run(std::string(kBase) + "joint assign j\nblock 0," + test::num(y0 - 1) + " 2," +
            test::num(y0 - 1) + " 2," + test::num(y0) + " 0," + test::num(y0) +
            " material=rock\nfix block=1\nblock 0," + test::num(y0) + " 1," + test::num(y0) +
            " 1," + test::num(y0 + 1) + " 0," + test::num(y0 + 1) +
            " material=rock\ngravity 0 -10\nstep 5\nstep 5\n");
      return f.interp->summary().warnings;
    };
    const std::vector<std::string> w = far(4e6);
    QCOMPARE(w.size(), size_t(1));
    QVERIFY(has(w[0], "test:9: warning: the model lies 4e+06 m from the origin"));
    QVERIFY(has(w[0], "local origin"));
    QVERIFY(far(10.0).empty());
  }
  void nonUtf8TitleStillWritesTheSummary() {
    ScriptRun r;
    r.run("title caf\xE9 \xFF\nround 0.01");
    r.interp->finish();
    std::ifstream in(r.path("summary.json"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    QVERIFY(has(text, "\"title\": \"caf\xEF\xBF\xBD \xEF\xBF\xBD\""));
  }
  void corruptedStateIsRefused() {
    ScriptRun r;
    r.run(
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2000\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n"
        "block box 0,0,-1 1,1,0 material=rock\nfix block=1\n"
        "block box 0,0,0 1,1,1 material=rock\ngravity 0 0 -10\nstep 5\nsave s.state");
    const std::string path = r.path("s.state");
    std::string bytes;
    {
      std::ifstream in(path, std::ios::binary);
      bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    // Every 4-byte word set to a huge index in turn (a sample of them): never a crash.
    size_t refused = 0, tried = 0;
    for (size_t at = 16; at + 4 < bytes.size(); at += 37) {
      std::string bad = bytes;
      const uint32_t huge = 0x7fffff00u;
      std::memcpy(bad.data() + at, &huge, 4);
      std::ofstream(r.path("bad.state"), std::ios::binary) << bad;
      const std::string e = error_of("restore " + r.path("bad.state") + "\nstep 3");
      ++tried;
      if (e.find("not a readable Tessera state file") != std::string::npos) ++refused;
    }
    qInfo("%zu of %zu corrupted files refused when read (the rest changed only values)", refused,
          tried);
    QVERIFY(refused > tried / 4);
    // Bytes after the end: not the file save wrote.
    std::ofstream(r.path("long.state"), std::ios::binary) << bytes << "junk";
    QVERIFY(error_of("restore " + r.path("long.state")).find("data after the end of the state") !=
            std::string::npos);
    // Another version (the word after the 8-byte magic): what to do about it.
    std::string other = bytes;
    other[8] = static_cast<char>(other[8] + 1);
    std::ofstream(r.path("other.state"), std::ios::binary) << other;
    const std::string e = error_of("restore " + r.path("other.state"));
    QVERIFY2(e.find("run the script that made it again") != std::string::npos, e.c_str());
  }
  void enclosingOpeningAddsNoArea() {
    ScriptRun r;
    r.run(std::string(kBase) +
          "region 0,0 10,10 material=rock\n"
          "tunnel circle centre=5,5 radius=20 segments=8 group=dig\n");
    const Blocks& B = r.model().blocks;
    double area = 0.0;
    for (size_t b = 0; b < B.size(); ++b) area += B.area[b];
    QVERIFY(std::abs(area - 100.0) < 1e-9);
    QCOMPARE(B.group[0], r.model().group_index("dig", false));
  }
  void missingJointAssignmentIsNamed() {
    const auto e = error_of(std::string(kBase) +
                            "block 0,0 1,0 1,1 0,1 material=rock group=a\n"
                            "block 0,1 1,1 1,2 0,2 material=rock group=b\nstep 1");
    QVERIFY(has(e,
                "no joint properties apply to the contact between block 1 (group a) and block 2 "
                "(group b)"));
  }
  void divergenceIsReported() {
    const auto e = error_of(std::string(kBase) +
                            "joint assign j\nblock 0,0 1,0 1,1 0,1 material=rock\n"
                            "block 0,1 1,1 1,2 0,2 material=rock\nfix block=1\ngravity 0 -10\n"
                            "damping none\ntimestep fixed 1\nstep 200");
    QVERIFY(has(e, "diverged"));
  }
  void cuttingNothingIsAnError() {
    QVERIFY(has(error_of("round 0.01\ncrack 0,0 1,1"), "test:2: there are no blocks to cut"));
    QVERIFY(has(error_of("round 0.01\nregion 0,0 1,1\njset angle=0 spacing=0.5 sideways"),
                "test:3: unexpected word 'sideways'"));
  }
  void emptySelectionIsAnError() {
    const auto e = error_of(std::string(kBase) + "block 0,0 1,0 1,1 0,1 material=rock\nfix x=5,6");
    QVERIFY(has(e, "test:5: no block matches the selection of 'fix'"));
  }
  void errorsInCalledFilesNameThatFile() {
    QTemporaryDir dir;
    const std::string inner = dir.path().toStdString() + "/inner.tess";
    const std::string outer = dir.path().toStdString() + "/outer.tess";
    std::ofstream(inner) << "round 0.01\n\nmaterial define rock densty=2600\n";
    std::ofstream(outer) << "; calls a file with a typo\ncall inner.tess\n";
    Interpreter interp(dir.path().toStdString(), [](const std::string&) {});
    try {
      interp.run_file(outer);
      QFAIL("no error raised");
    } catch (const ScriptError& e) {
      QCOMPARE(e.file(), inner);
      QCOMPARE(e.line(), 3);
      QVERIFY(has(e.message(), "'densty'"));
    }
  }
  void selfCallingFileIsStopped() {
    QTemporaryDir dir;
    const std::string loop = dir.path().toStdString() + "/loop.tess";
    std::ofstream(loop) << "call loop.tess\n";
    Interpreter interp(dir.path().toStdString(), [](const std::string&) {});
    try {
      interp.run_file(loop);
      QFAIL("no error raised");
    } catch (const ScriptError& e) {
      QVERIFY(has(e.what(), "nests more than 32 files deep"));
    }
    // The interpreter is usable afterwards, with its own folder stack intact.
    interp.execute("set a = 2");
    QCOMPARE(interp.variable("a"), 2.0);
  }
  void variablesReachEveryNumber() {
    ScriptRun r;
    r.run(std::string(kBase) + "set w = 2*5\nset h = w/10\nblock 0,0 w,0 w,h 0,h material=rock");
    QCOMPARE(r.model().blocks.area[0], 10.0);
  }
  // The figure command checks its request before handing it to the program's renderer.
  void figureRequestsAreChecked() {
    const std::string blk = std::string(kBase) + "block 0,0 1,0 1,1 0,1 material=rock\n";
    QVERIFY(has(error_of(blk + "figure a.jpg"), "test:5: 'a.jpg': a figure is written as .png"));
    QVERIFY(has(error_of(blk + "figure a.png colour=displacment"),
                "not something blocks are coloured by (did you mean 'displacement'?)"));
    QVERIFY(has(error_of(blk + "figure a.png contacts=stres"), "(did you mean 'stress'?)"));
    QVERIFY(has(error_of(blk + "figure a.png window=1,1,0,0"), "second corner"));
    QVERIFY(has(error_of(blk + "figure a.png size=4,4"), "between 16 and 16384"));
    QVERIFY(has(error_of(blk + "figure a.png"), "this run has no renderer"));
    // A cut is for 3D models, as five numbers, with a dip from 0 to 90 degrees.
    QVERIFY(has(error_of(blk + "figure a.png cut=90,0,0,0,0"), "test:5: cut= cuts 3D models"));
    const std::string box =
        "dimension 3\nmaterial define rock density=2500\nblock box 0,0,0 1,1,1 material=rock\n";
    QVERIFY(has(error_of(box + "figure a.png cut=90,0,0.5"), "test:4: write cut=DIP,DIPDIR,X,Y,Z"));
    QVERIFY(has(error_of(box + "figure a.png cut=120,0,0,0,0"), "between 0 and 90 degrees"));
    QVERIFY(has(error_of(box + "figure a.png cut=90,east,0,0,0"), "test:4:"));
    // With a renderer, it gets the request as written.
    ScriptRun r;
    FigureRequest got;
    r.interp->set_figure_sink([&](const FigureRequest& f, const Model&) { got = f; });
    r.run(blk +
          "figure out.svg size=640,480 colour=ydisp contacts=shear vectors=on magnify=50 "
          "window=-1,-1,2,2 title=\"Fig 1\"");
    QCOMPARE(got.width, 640);
    QCOMPARE(got.height, 480);
    QVERIFY(got.view.colour == ColourBy::kYDisp && got.view.contacts == ContactShow::kShear);
    QVERIFY(got.view.vectors && got.view.magnify == 50 && got.view.has_window);
    QCOMPARE(got.view.title, std::string("Fig 1"));
    QVERIFY(QString::fromStdString(got.path).endsWith("out.svg"));
  }
  // Deformable-block commands name what is missing or wrong.
  void deformableInputIsChecked() {
    const std::string blk = std::string(kBase) + "block 0,0 1,0 1,1 0,1 material=rock\n";
    QVERIFY(has(error_of(blk + "zone generate edge=0.2"),
                "test:5: block 1: its material has no elastic constants"));
    QVERIFY(has(error_of(blk + "zone generate"), "zone generate needs edge="));
    QVERIFY(has(error_of(blk + "boundary fix=x"), "there are no zones"));
    QVERIFY(has(error_of(blk + "insitu stress=0,-1e6,0"),
                "test:5: nothing takes the stress: there are no zones and no shut joints"));
    QVERIFY(has(error_of(std::string(kBase) + "material define soft density=2000 E=1e9"),
                "material 'soft' needs both E and nu"));
    QVERIFY(has(error_of(std::string(kBase) + "material define soft density=2000 E=1e9 nu=0.6"),
                "Poisson's ratio must be between -1 and 0.5"));
    QVERIFY(has(error_of(std::string(kBase) +
                         "material define soft density=2000 E=1e9 nu=0.2 model=mohr-colomb"),
                "(did you mean 'mohr-coulomb'?)"));
    const std::string soft = std::string(kBase) +
                             "material define soft density=2000 E=1e9 nu=0.2\n"
                             "block 0,0 1,0 1,1 0,1 material=soft\nzone generate edge=0.25\n";
    QVERIFY(has(error_of(soft + "boundary fix=z"), "write fix=x, fix=y or fix=xy"));
    QVERIFY(has(error_of(soft + "boundary fix=x x=5,6"), "no node lies in that box"));
    QVERIFY(has(error_of(soft + "zone null x=5,6 y=5,6"), "no zone has its centre in that box"));
    QVERIFY(has(error_of(soft + "crack -1,0.5 2,0.5"), "is deformable: cut blocks before"));
    QVERIFY(has(error_of(std::string(kBase) + "material define soft density=2000 E=1e9 nu=0.2\n"
                                              "block 0,0 1,0 1,1 0,1 material=soft\n"
                                              "zone generate edge=1e-4"),
                "test:6: block 1: zones of size"));
  }
  // The strain-softening, ubiquitous-joint and transversely isotropic models' input.
  void zoneModelInputIsChecked() {
    const std::string m = std::string(kBase) + "material define soft density=2000 ";
    const std::string ss = m + "E=1e9 nu=0.2 model=strain-softening friction=30 cohesion=1e6 ";
    QVERIFY(has(error_of(ss + "ctable=0,1e6,0.01"),
                "test:4: material 'soft': ctable needs pairs strain,value (3 numbers given)"));
    QVERIFY(has(error_of(ss + "ftable=0,30,0.02,25,0.01,20"),
                "test:4: material 'soft': ftable's plastic strains must "
                "increase"));
    QVERIFY(has(error_of(ss + "ctable=0,1e6,0.01,-5"), "ctable's values cannot be negative"));
    QVERIFY(has(error_of(ss + "ftable=0,30,0.01,95"), "ftable's angles must be below 90"));
    QVERIFY(has(error_of(m + "E=1e9 nu=0.2 ctable=0,1e6,0.01,0"),
                "ctable, ftable, dtable and ttable belong to model=strain-softening"));
    const std::string uj = m + "E=1e9 nu=0.2 model=ubiquitous-joint friction=30 cohesion=1e6 ";
    QVERIFY(has(error_of(uj + "jcohesion=1e5 jangle=30"),
                "test:4: material 'soft' (ubiquitous-joint) needs jfriction="));
    QVERIFY(has(error_of(uj + "jfriction=20"),
                "(ubiquitous-joint) needs its plane: jangle= (2D) or jdip= and jdipdir= (3D)"));
    QVERIFY(has(error_of(uj + "jfriction=20 jdip=30"), "needs both jdip= and jdipdir="));
    QVERIFY(has(error_of(uj + "jfriction=20 jangle=10 jdip=30 jdipdir=0"),
                "give jangle= (2D) or jdip= and jdipdir= (3D), not both"));
    QVERIFY(has(error_of(uj + "jfriction=20 jdilation=30 jangle=10"),
                "jdilation in [0, jfriction] degrees"));
    QVERIFY(has(error_of(m + "E=1e9 nu=0.2 jfriction=20"),
                "jfriction, jcohesion, jtension and jdilation belong to model=ubiquitous-joint"));
    const std::string ti = m + "model=transversely-isotropic ";
    QVERIFY(has(error_of(ti + "E1=2e9 E3=1e9 nu12=0.2 G13=1e9 jangle=0"),
                "test:4: material 'soft' (transversely-isotropic) needs nu13="));
    QVERIFY(has(error_of(ti + "E=1e9 nu=0.2 E1=2e9 E3=1e9 nu12=0.2 nu13=0.2 G13=1e9 jangle=0"),
                "takes E1, E3, nu12, nu13 and G13, not E and nu or K and G"));
    QVERIFY(has(error_of(ti + "E1=2e9 E3=1e9 nu12=0.2 nu13=0.2 G13=1e9"), "needs its plane"));
    QVERIFY(has(error_of(ti + "E1=1e9 E3=10e9 nu12=0.2 nu13=0.5 G13=1e9 jangle=0"),
                "make no stable material"));
  }
  // With rollback on, a failing command leaves the model as it was before it.
  void rollbackKeepsTheModel() {
    ScriptRun r;
    r.interp->set_rollback(true);
    r.run(std::string(kBase) +
          "joint assign j\nblock 0,0 4,0 4,1 0,1 material=rock\n"
          "fix block=1\nblock 0,1 1,1 1,2 0,2 material=rock\n"
          "gravity 0 -10\nstep 20");
    const auto before = tessera::test::state_hash(r.model());
    const uint64_t cycle = r.model().cycle;
    QVERIFY(has(error_of_in(r, "timestep fixed 1\nstep 100"), "diverged"));
    QCOMPARE(r.model().cycle, cycle);
    QCOMPARE(tessera::test::state_hash(r.model()), before);
    QVERIFY(has(error_of_in(r, "block 5,5 6,5 material=rock"), "test:"));
    QCOMPARE(r.model().blocks.size(), size_t(2));
  }

 private:
  static std::string error_of_in(ScriptRun& r, const std::string& text) {
    try {
      r.run(text);
    } catch (const ScriptError& e) {
      return e.what();
    }
    return {};
  }
};

QTEST_APPLESS_MAIN(TestScriptErrors)
#include "test_script_errors.moc"
