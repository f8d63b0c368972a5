// Plug-in laws (`model load`): the example plug-in's joint law registers and runs in 2D and 3D,
// and what cannot be loaded is named.
#include <QtTest>
#include <cmath>

#include "support.hpp"
#include "tessera/plugin.hpp"

using namespace tessera;
using tessera::test::ScriptRun;

namespace {
// A 1 m block on a frictionless plane at 30 degrees, on joints of the given law.
std::string incline(bool three, const std::string& law) {
  const std::string common =
      "model load " TESSERA_PLUGIN_FILE
      "\nset psi = 30\nset c = cos(psi)\nset s = sin(psi)\n"
      "material define rock density=2500\njoint define j kn=1e9 ks=1e9 friction=0 law=" +
      law + "\njoint assign j\ndamping none\n";
  const std::string slab = "(-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s)";
  const std::string block = "0,0 c,s (c-s),(s+c) (-s),c";
  if (three)
    return "dimension 3\ntolerance 0.005\n" + common + "block prism " + slab +
           " z=-1,2 group=slab material=rock\nblock prism " + block +
           " z=0,1 material=rock\nfix group=slab\ngravity 0 -9.81 0\nstep 3000\n";
  return "round 0.005\n" + common + "block " + slab + " group=slab material=rock\nblock " + block +
         " material=rock\nfix group=slab\ngravity 0 -9.81\nstep 3000\n";
}
}  // namespace

class TestPlugins : public QObject {
  Q_OBJECT
 private slots:
  // Undamped, on the plug-in's elastic joint the block stays where it is (its shear springs hold
  // it: it rocks on its springs about its static offset W / (k A) = 2.5e-5 m); on a frictionless
  // coulomb joint it slides
  // away at g sin(psi).
  void exampleLawHoldsWhereCoulombSlides_data() {
    QTest::addColumn<bool>("three");
    QTest::newRow("2D") << false;
    QTest::newRow("3D") << true;
  }
  void exampleLawHoldsWhereCoulombSlides() {
    QFETCH(bool, three);
    ScriptRun elastic, coulomb;
    elastic.run(incline(three, "elastic-joint"));
    coulomb.run(incline(three, "coulomb"));
    const auto moved = [&](Model& m) {
      return three
                 ? (m.blocks3.body[1].position - m.blocks3.ref[1]).norm()
                 : std::hypot(m.blocks.x[1] - m.blocks.x_ref[1], m.blocks.y[1] - m.blocks.y_ref[1]);
    };
    const double held = moved(elastic.model()), slid = moved(coulomb.model());
    qInfo("moved %.3e m on the elastic joint, %.3e m on the frictionless one", held, slid);
    QVERIFY(held < 1e-4);
    const double free = 0.5 * 9.81 * 0.5 * std::pow(coulomb.model().time, 2);
    QVERIFY(std::abs(slid - free) < 0.02 * free);
    // Loaded by the first run in the program; the later ones find it loaded already.
    QVERIFY(elastic.log.find("model load: ") != std::string::npos);
    QVERIFY(std::find(joint_law_names().begin(), joint_law_names().end(), "elastic-joint") !=
            joint_law_names().end());
  }
  // The plug-in's zone model is the built-in elastic one written again: a zoned square under
  // boundary stresses, 2D and 3D, gives the same state bit for bit.
  void exampleZoneModelMatchesTheBuiltIn_data() {
    QTest::addColumn<bool>("three");
    QTest::newRow("2D") << false;
    QTest::newRow("3D") << true;
  }
  void exampleZoneModelMatchesTheBuiltIn() {
    QFETCH(bool, three);
    const auto square = [&](const std::string& model) {
      const std::string rock = "model load " TESSERA_PLUGIN_FILE
                               "\nmaterial define rock density=2500 E=10e9 nu=0.25 model=" +
                               model + "\n";
      if (three)
        return "dimension 3\ntolerance 0.01\n" + rock +
               "block box 0,0,0 4,4,4 material=rock\nzone generate edge=1\n"
               "boundary fix=z z=-0.001,0.001\nboundary stress=0,0,-1e6,0,0,0 z=3.999,4.001\n"
               "step 300\n";
      return "round 0.01\n" + rock +
             "block 0,0 4,0 4,4 0,4 material=rock\nzone generate edge=0.5\n"
             "boundary fix=y y=-0.001,0.001\nboundary stress=0,-1e6,0 y=3.999,4.001\nstep 300\n";
    };
    ScriptRun built_in, plugin;
    built_in.run(square("elastic"));
    plugin.run(square("plugin-elastic"));
    const Model& m = plugin.model();
    QVERIFY(three ? m.continuum3.zone_count() > 0 : m.continuum.zone_count() > 0);
    QCOMPARE(tessera::test::state_hash(m), tessera::test::state_hash(built_in.model()));
    // The load reached the zones: the vertical stress of the first zone is compressive.
    const double vertical = three ? m.continuum3.stress[0].zz : m.continuum.stress[0].yy;
    qInfo("first zone's vertical stress %.4g Pa", vertical);
    QVERIFY(vertical < -1e4);
  }
  // Loading twice registers nothing more; a missing file and a library that is no plug-in are
  // named; an unknown law suggests the loaded one.
  void badPluginsAreNamed() {
    ScriptRun r;
    r.run("model load " TESSERA_PLUGIN_FILE "\nmodel load " TESSERA_PLUGIN_FILE "\n");
    QVERIFY(r.log.find("is loaded already") != std::string::npos);
    const auto error_of = [](const std::string& text) {
      ScriptRun s;
      try {
        s.run(text);
      } catch (const std::exception& e) {
        return std::string(e.what());
      }
      return std::string();
    };
    const std::string missing = error_of("model load no_such_plugin.so");
    qInfo("%s", missing.c_str());
    QVERIFY(missing.find("no_such_plugin.so: cannot load the plug-in") != std::string::npos);
    QVERIFY(error_of("model unload x.so").find("write 'model load FILE.so'") != std::string::npos);
    const std::string unknown =
        error_of("joint define j kn=1e9 ks=1e9 friction=0 law=elastic-joints");
    QVERIFY(unknown.find("did you mean 'elastic-joint'") != std::string::npos);
  }
};

QTEST_APPLESS_MAIN(TestPlugins)
#include "test_plugins.moc"
