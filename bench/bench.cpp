// tessera-bench: cycles a named scene and prints one JSON line of figures.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>

#include "kernel.hpp"
#include "tessera/contact2d/detection.hpp"
#include "tessera/contact3d/detection3.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"
#include "tessera/generation/generators.hpp"
#include "tessera/generation/generators3.hpp"
#include "tessera/zones/continuum.hpp"
#include "tessera/zones/zoning.hpp"
#include "tessera/zones/zoning3.hpp"

using namespace tessera;

namespace {

// Brick (density 2600) and mortar joints (kn = ks = 1e10, friction 0.6) for every contact.
void add_brick_and_mortar(Model& m) {
  m.materials.push_back({"brick", 2600.0, {}});
  JointProperties j;
  j.name = "mortar", j.kn = 1e10, j.ks = 1e10, j.friction = std::atan(0.6) * 180 / M_PI;
  j.finalize();
  m.joints.push_back(j);
  m.joint_table.push_back({-1, -1, 0});
}

// A running-bond wall of 2.0 x 1.0 m bricks on a fixed base (density 2600, friction 0.6,
// kn 1e10), settling under gravity with local damping.
Model wall_scene(int cols, int rows) {
  Model m;
  m.settings.rounding = 0.01;
  m.settings.gravity = Vec2(0, -9.81);
  add_brick_and_mortar(m);
  const double width = 2.0 * cols;
  m.blocks.add({{-1, -1}, {width + 1, -1}, {width + 1, 0}, {-1, 0}}, m.settings.rounding, 2600, -1,
               0);
  m.blocks.fixity[0] = kFixAll;
  WallSpec w;
  w.brick_length = 2.0, w.brick_height = 1.0, w.courses = rows, w.bricks = cols, w.material = 0;
  add_running_bond_wall(m, w);
  return m;
}

// The same wall in 3D, one brick (1.0 m) thick: 2.0 x 1.0 x 1.0 m bricks, courses along x
// stacked in z, on a fixed base.
Model wall3d_scene(int cols, int rows) {
  Model m;
  m.dim = 3;
  m.settings.contact_tolerance = 0.01;
  m.settings.gravity3 = Vec3(0, 0, -9.81);
  add_brick_and_mortar(m);
  add_block3(m, box(Vec3(-1, -1, -1), Vec3(2.0 * cols + 1, 2, 0)), -1, 0);
  m.blocks3.fixity[0] = kFix3All;
  WallSpec3 w;
  w.length = 2.0, w.height = 1.0, w.width = 1.0, w.courses = rows, w.bricks = cols, w.material = 0;
  add_wall3(m, w);
  return m;
}

// A block's centroid height (y in 2D, z in 3D).
double height(const Model& m, size_t b) {
  return m.dim == 3 ? m.blocks3.body[b].position.z() : m.blocks.y[b];
}

// The blocks of the wall's top course (centroids within half a course of the highest).
std::vector<size_t> top_course(const Model& m) {
  double highest = -1e300;
  for (size_t b = 0; b < m.block_count(); ++b) highest = std::max(highest, height(m, b));
  std::vector<size_t> top;
  for (size_t b = 0; b < m.block_count(); ++b)
    if (height(m, b) > highest - 0.5) top.push_back(b);
  return top;
}

double mean_height(const Model& m, const std::vector<size_t>& blocks) {
  double sum = 0.0;
  for (size_t b : blocks) sum += height(m, b);
  return sum / static_cast<double>(blocks.size());
}

// Elastic rock (density 2500, E 10 GPa, nu 0.25) settling under gravity on rollers: the zone
// kernel alone (no contacts). zones2d: a 20 x 40 m plane-strain panel of triangles; column3d:
// a 4 x 4 x 16 m column of tetrahedra. `edge` is the zone size.
template <int D>
void rollers_and_rock(ContinuumT<D>& c) {
  ZoneProperties p;
  p.name = "rock", p.density = 2500;
  elastic_from_young(10e9, 0.25, p.bulk, p.shear);
  p.finalize();
  c.materials.push_back(p);
  for (auto& z : c.material) z = 0;
  lump_masses(c);
  for (size_t n = 0; n < c.node_count(); ++n)
    for (int k = 0; k < D; ++k)
      if (c.pos0[n][k] < 1e-9) c.fixity[n] |= node_fix_bit(k);
  c.gravity[D - 1] = -9.81;
  c.dt = critical_timestep(c);
}

template <int D>
int run_zones(ContinuumT<D>& c, const std::string& scene, double edge, uint64_t cycles,
              double mesh_seconds) {
  rollers_and_rock(c);
  const auto t0 = std::chrono::steady_clock::now();
  for (uint64_t i = 0; i < cycles; ++i) continuum_cycle(c);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double per_cycle = seconds / static_cast<double>(std::max<uint64_t>(cycles, 1));
  std::cout << fmt::format(
                   "{{\"scene\": \"{}\", \"edge\": {}, \"zones\": {}, \"nodes\": {}, "
                   "\"mesh_seconds\": {:.3f}, \"cycles\": {}, \"seconds\": {:.4f}, "
                   "\"ms_per_cycle\": {:.4f}, \"zone_updates_per_s\": {:.4g}, \"ratio\": {:.3e}}}",
                   scene, edge, c.zone_count(), c.node_count(), mesh_seconds, cycles, seconds,
                   1e3 * per_cycle, static_cast<double>(c.zone_count()) / per_cycle, c.ratio)
            << std::endl;
  return 0;
}

int zone_scene(const std::string& scene, double edge, uint64_t cycles, int order) {
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  if (scene == "zones2d") {
    if (edge <= 0) edge = 0.2;
    Continuum c;
    add_mesh(c, zone_polygon({{0, 0}, {20, 0}, {20, 40}, {0, 40}}, edge), 0);
    return run_zones(c, scene, edge, cycles, since());
  }
  if (edge <= 0) edge = 0.36;
  Continuum3 c;
  ZoneMesh3 mesh = zone_pieces({box(Vec3::Zero(), Vec3(4, 4, 16))}, edge);
  if (order == 2) make_quadratic(mesh);
  add_mesh(c, mesh, 0);
  return run_zones(c, order == 2 ? scene + "-order2" : scene, edge, cycles, since());
}

}  // namespace

// FNV-1a over the bytes of the blocks' positions and velocities and the contacts' forces: two
// runs of a scene that print the same hash ended bit for bit the same (a change of the cycle
// that should not change its arithmetic is checked by it).
uint64_t state_hash(const Model& m) {
  uint64_t h = 1469598103934665603ull;
  const auto mix = [&](const auto& values) {
    const auto* p = reinterpret_cast<const unsigned char*>(values.data());
    for (size_t i = 0; i < values.size() * sizeof(values[0]); ++i)
      h = (h ^ p[i]) * 1099511628211ull;
  };
  if (m.dim == 3) {
    for (size_t b = 0; b < m.blocks3.body.size(); ++b) {
      const RigidBody3& body = m.blocks3.body[b];
      mix(std::array<double, 6>{body.position.x(), body.position.y(), body.position.z(),
                                body.velocity.x(), body.velocity.y(), body.velocity.z()});
    }
    for (const Contact3& c : m.contacts3)
      for (const SubContact& s : c.subs) mix(std::array<double, 1>{s.fn});
  } else {
    const Blocks& B = m.blocks;
    for (const auto* v : {&B.x, &B.y, &B.theta, &B.vx, &B.vy, &B.omega}) mix(*v);
    mix(m.contacts.fn), mix(m.contacts.fs);
  }
  return h;
}

int main(int argc, char** argv) {
  CLI::App app{"Tessera benchmarks"};
  std::string scene = "wall";
  int cols = 100, rows = 50, threads = 1, order = 1;
  uint64_t cycles = 1000;
  double ratio = 0.0;
  double edge = 0.0;
  app.add_option("--scene", scene, "Scene to run")
      ->check(CLI::IsMember({"wall", "wall3d", "zones2d", "column3d"}));
  app.add_option("--edge", edge, "Zone size of zones2d and column3d (default 0.2 and 0.36 m)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--order", order, "column3d: 1 (4-node zones, default) or 2 (10-node)")
      ->check(CLI::IsMember({1, 2}));
  app.add_option("--cols", cols, "Bricks per course")->check(CLI::PositiveNumber);
  app.add_option("--rows", rows, "Courses")->check(CLI::PositiveNumber);
  app.add_option("--cycles", cycles, "Cycles to run");
  app.add_option("--solve", ratio, "Instead of --cycles, solve to this unbalanced-force ratio");
  app.add_option("--threads", threads, "Worker threads")->check(CLI::PositiveNumber);
  bool kernel = false, scaled = false;
  uint64_t trace = 0, warmup = 0;
  std::string damping = "local";
  double alpha = -1.0;
  app.add_option("--trace", trace,
                 "--solve: print the cycle, the ratio and the top course's settlement every N "
                 "cycles to stderr");
  app.add_option("--warmup", warmup,
                 "Cycles run before the timed ones (through solve(), so that a profiler toggled "
                 "on run_cycles sees only the timed cycles): to time a settled model");
  app.add_option("--damping", damping, "local (alpha 0.8) or kinetic (alpha 0.2)")
      ->check(CLI::IsMember({"local", "kinetic"}));
  app.add_option("--alpha", alpha, "The damping's alpha instead of its default")
      ->check(CLI::Range(0.0, 0.999));
  app.add_flag("--scaled", scaled,
               "Density scaling of the blocks (the script's 'timestep scaled'), for --solve");
  app.add_flag("--kernel", kernel,
               "wall: also run the speed-of-light kernel (bench/kernel.hpp) on the same blocks and "
               "contacts for as many cycles, and report Tessera's time as a ratio to it");
  CLI11_PARSE(app, argc, argv);

  set_thread_count(threads);
  if (scene == "zones2d" || scene == "column3d") return zone_scene(scene, edge, cycles, order);
  Model m = scene == "wall3d" ? wall3d_scene(cols, rows) : wall_scene(cols, rows);
  Profile profile;
  m.options.profile = &profile;
  m.options.validate = false;
  m.settings.dt_scaled = scaled;
  if (damping == "kinetic") m.settings.damping = DampingMode::kKinetic;
  if (alpha >= 0.0) m.settings.local_alpha = m.settings.kinetic_alpha = alpha;
  prepare(m);
  const std::vector<size_t> top = top_course(m);
  const double top_before = mean_height(m, top);
  if (m.dim == 3)
    detect_contacts3(m);
  else
    detect_contacts(m);
  if (warmup) solve(m, 0.0, warmup);
  profile = Profile{};
  const auto t0 = std::chrono::steady_clock::now();
  uint64_t ran = 0;
  bool converged = false;
  if (ratio > 0.0) {
    const Progress show = [&](const Model& mm) {
      std::cerr << mm.cycle << " " << mm.ratio << " " << top_before - mean_height(mm, top) << "\n";
      return true;
    };
    const SolveResult r = solve(m, ratio, 10'000'000, trace ? show : Progress{}, trace);
    ran = r.cycles, converged = r.converged;
  } else {
    ran = run_cycles(m, cycles);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double per_cycle = seconds / static_cast<double>(std::max<uint64_t>(ran, 1));
  // The kernel on the model as it stands after the run (its contacts and lengths).
  std::string versus;
  if (kernel && m.dim == 2) {
    const bench::KernelResult k = bench::run_kernel(m, std::max<uint64_t>(ran, 1));
    versus = fmt::format(
        ", \"kernel_ms_per_cycle\": {:.4f}, \"ratio_to_kernel\": {:.2f}, "
        "\"kernel_top_y\": {:.4f}",
        k.ms_per_cycle, 1e3 * per_cycle / k.ms_per_cycle, k.top_y);
  }
  // Contacts: block pairs (2D corner contacts); in 3D also the sub-contacts updated per cycle.
  size_t contacts = m.dim == 3 ? m.contacts3.size() : m.contacts.size(), updates = contacts;
  if (m.dim == 3) {
    updates = 0;
    for (const Contact3& c : m.contacts3) updates += c.subs.size();
  }
  std::string stages;
  for (int s = 0; s < kStageCount; ++s)
    stages += fmt::format("{}\"{}_ms\": {:.4f}", s ? ", " : "", stage_name(s),
                          1e3 * profile.seconds[static_cast<size_t>(s)] /
                              static_cast<double>(std::max<uint64_t>(ran, 1)));
  std::cout
      << fmt::format(
             "{{\"scene\": \"{}\", \"cols\": {}, \"rows\": {}, \"threads\": {}, \"blocks\": {}, "
             "\"contacts\": {}, \"sub_contacts\": {}, \"cycles\": {}, \"seconds\": {:.4f}, "
             "\"ms_per_cycle\": {:.4f}, \"cycles_per_s\": {:.1f}, \"contact_updates_per_s\": "
             "{:.4g}, \"ratio\": {:.3e}, "
             "\"converged\": {}, \"damping\": \"{}\", \"scaled\": {}, \"top_settlement_m\": "
             "{:.6e}, \"dt\": {:.4e}, "
             "\"detection_passes\": {}, \"state_hash\": \"{:016x}\", \"stages\": {{{}}}{}}}",
             scene, cols, rows, threads, m.block_count(), contacts, m.dim == 3 ? updates : 0, ran,
             seconds, 1e3 * per_cycle, 1.0 / per_cycle, static_cast<double>(updates) / per_cycle,
             m.ratio, converged ? "true" : "false", damping, scaled ? "true" : "false",
             top_before - mean_height(m, top), m.dt, m.detection_passes, state_hash(m), stages,
             versus)
      << std::endl;
  return 0;
}
