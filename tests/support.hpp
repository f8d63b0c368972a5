// Helpers shared by the tests: running script text in a temporary folder, hashing state.
#pragma once

#include <QCoreApplication>
#include <QObject>
#include <QTemporaryDir>
#include <cstdint>
#include <memory>
#include <string>

#include "tessera/script/script.hpp"
#include "tessera/zones/continuum.hpp"

namespace tessera::test {

// An interpreter writing into its own temporary folder, with progress lines silenced.
struct ScriptRun {
  QTemporaryDir dir;
  std::unique_ptr<Interpreter> interp;
  std::string log;  // every line the interpreter logged
  ScriptRun();
  // Runs lines of script text (newline separated); throws ScriptError like a file would.
  void run(const std::string& text);
  Model& model() { return interp->model(); }
  std::string path(const std::string& name) const;
};

// A b x h block resting on a fixed slab, both turned by psi degrees (the geometry, not gravity,
// is inclined); friction phi degrees, joint stiffnesses kn = ks; block 2 is the free block, its
// vertex 0 the downslope toe.
std::string incline_script(double psi, double phi, double b = 1.0, double h = 1.0,
                           double kn = 1e10);

// FNV-1a hash of the dynamic state (positions, velocities, contact stresses), bit for bit.
uint64_t state_hash(const Model& m);

// A number as script text, to every digit a double holds.
std::string num(double v);

// The zone tests' rock: density 2000, E = 1 GPa, nu = 0.25, of the given zone model.
inline ZoneProperties zone_rock(const std::string& model = "elastic") {
  ZoneProperties p;
  p.name = "rock";
  p.model = model;
  p.density = 2000;
  elastic_from_young(1e9, 0.25, p.bulk, p.shear);
  return p;
}

// Steps a zone mesh at its critical step until the unbalanced-force ratio drops below `ratio`;
// returns the cycles run.
template <int D>
uint64_t solve_zones(ContinuumT<D>& c, double ratio, uint64_t max_cycles) {
  c.dt = critical_timestep(c);
  for (uint64_t i = 0; i < max_cycles; ++i) {
    continuum_cycle(c);
    if (i > 100 && c.ratio < ratio) return i;
  }
  return max_cycles;
}

// The joints' total size in touch: contact lengths in 2D, sub-contact areas in 3D.
double joint_size(const Model& m);

// A tetrahedral wedge in a vertical face (normal -y): a 24 x 14 x 14 m region cut by joints A
// and B (dip, dip direction in degrees) through a point 6 m below the crest, friction phi,
// kn = ks = 1e10; everything fixed but the wedge (group wedge), gravity on.
std::string wedge_script(double phi, double dip_a, double dd_a, double dip_b, double dd_b);

// The friction angle (degrees) at which a wedge on planes of unit normals na and nb is at the
// limit (Hoek and Bray): the weight balanced by normal reactions on both planes and a force T
// along their intersection; sliding starts when T exceeds (N_A + N_B) tan phi.
double wedge_limit_angle(const Eigen::Vector3d& na, const Eigen::Vector3d& nb);

// Slope of the least-squares line through (x, y) samples.
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y);

// Runs a Qt Test object like QTest::qExec, and also takes `--skip F1,F2`: every test function
// but those (the rest of a program whose slow functions ctest runs as entries of their own, so
// that two cores share them; tests/CMakeLists.txt, SHARDS).
int run_tests(QObject& test, int argc, char** argv);

}  // namespace tessera::test

// A test program's main that understands `--skip` (see run_tests).
#define TESSERA_TEST_MAIN(TestClass)                   \
  int main(int argc, char** argv) {                    \
    QCoreApplication app(argc, argv);                  \
    TestClass test;                                    \
    return tessera::test::run_tests(test, argc, argv); \
  }
