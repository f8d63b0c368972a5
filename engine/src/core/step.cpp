// The one cycle of every model, 2D or 3D, top to bottom; run and solve control.
#include "tessera/core/step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/backend.hpp"
#include "core/stage_timer.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/timestep.hpp"
#include "tessera/zones/deformable.hpp"
#include "tessera/zones/zone_stage.hpp"

namespace tessera {

namespace {

// Convergence measures over the blocks that move under load, and the checks that the run has
// neither diverged nor drifted far enough to need a detection pass.
void measure_motion(Model& m, const BlockMotion& bm, const ZoneMotion& zm) {
  const size_t n = m.block_count();
  size_t free_blocks = 0, worst = 0;
  double max_ub = 0.0, max_drift = 0.0;
  for (size_t b = 0; b < n; ++b) {
    max_drift = std::max(max_drift, bm.drift[b]);
    if (!(bm.jump[b] <= bm.jump[worst])) worst = b;
    if (!bm.moves[b]) continue;
    ++free_blocks;
    max_ub = std::max(max_ub, bm.unbalanced[b]);
  }
  const double sum_applied = deterministic_sum(n, [&](size_t b) { return bm.applied[b]; });
  m.max_unbalanced = max_ub;
  m.mean_applied = free_blocks ? sum_applied / static_cast<double>(free_blocks) : 0.0;
  m.ratio = m.mean_applied > 0.0 ? max_ub / m.mean_applied : 0.0;
  if (zm.active) {
    max_drift = std::max(max_drift, zm.drift);
    m.ratio = free_blocks ? std::max(m.ratio, zm.ratio) : zm.ratio;
    if (!std::isfinite(zm.ratio)) max_drift = zm.ratio;
  }
  // Cable and liner nodes count as well: blocks at rest on creeping support are not solved.
  if (!m.cables.empty()) m.ratio = std::max(m.ratio, m.cables.balance.ratio(m.mean_applied));
  if (!m.cables3.empty()) m.ratio = std::max(m.ratio, m.cables3.balance.ratio(m.mean_applied));
  if (!m.liners.empty()) m.ratio = std::max(m.ratio, m.liners.balance.ratio(m.mean_applied));
  if (max_drift > 0.5 * m.tolerance()) m.detection_due = true;
  if (!std::isfinite(max_ub) || !std::isfinite(max_drift) || !(bm.jump[worst] < 0.1))
    throw_diverged(m, m.dim == 3 ? m.blocks3.id[worst] : m.blocks.id[worst]);
}

// Kinetic damping: once the kinetic energy of the whole model has passed a peak, every block and
// node stops where it is, and the motion starts again from rest under the unbalanced forces.
void kinetic_damping(Model& m) {
  const Backend& be = backend(m);
  const double e = be.motion_energy(m) + twice_node_energy(m);
  if (e < m.kinetic_last) {
    be.stop(m);
    stop_nodes(m);
    m.kinetic_last = 0.0;
  } else {
    m.kinetic_last = e;
  }
}

}  // namespace

void prepare(Model& m) {
  const Backend& be = backend(m);
  if (m.block_count() == 0) throw ModelError("the model has no blocks");
  be.prepare(m);
  if (m.dt_dirty || (!m.block_scale.empty() && m.block_scale.size() != m.block_count())) {
    set_timestep(m);
    m.dt_dirty = false;
  }
}

namespace {

// One cycle, leaving the 3D blocks' vertices behind their bodies where no contact read them.
void cycle(Model& m) {
  const Backend& be = backend(m);
  const RunOptions& run = m.options;
  BlockMotion motion;
  ZoneMotion zones;
  Damping damping;
  {
    StageTimer t(run, kStageDetect);
    if (m.detection_due) be.detect(m);
  }
  if (be.geometry) {
    StageTimer t(run, kStageContacts);
    be.geometry(m);
  }
  {
    StageTimer t(run, kStageInterfaces);
    be.joint_forces(m);
  }
  {
    StageTimer t(run, kStageMotion);
    // The resultants in a pass of their own when the damping needs their power first or the
    // back end cannot gather them block by block in the step (bit-identical either way).
    const bool servo = servo_due(m), apart = servo || !be.gathers_in_step(m);
    if (apart) be.resultants(m);
    const Power p = servo ? be.power(m) : Power{};
    damping = cycle_damping(m, p.power, p.kin2);
    be.integrate(m, damping, !apart, motion);
  }
  {
    StageTimer t(run, kStageZones);
    zones = zone_stage(m, damping);
    if (m.settings.damping == DampingMode::kKinetic) kinetic_damping(m);
  }
  measure_motion(m, motion, zones);
  if (run.validate) be.validate(m);
  m.time += m.dt;
  ++m.cycle;
  if (run.profile) ++run.profile->cycles;
  sample_histories(m);
}

// The caller after a run, however it ends, sees every vertex where its block is (a progress
// report, called every cycle by scripts, leaves that to what reads the vertices).
struct CatchUp {
  Model& m;
  ~CatchUp() { m.blocks3.catch_up(); }
};

}  // namespace

void step(Model& m) {
  const CatchUp after{m};
  cycle(m);
}

uint64_t run_cycles(Model& m, uint64_t n, const Progress& progress, uint64_t every) {
  const CatchUp after{m};
  prepare(m);
  for (uint64_t i = 0; i < n; ++i) {
    cycle(m);
    if (progress && every && (i + 1) % every == 0 && !progress(m)) return i + 1;
  }
  return n;
}

SolveResult solve(Model& m, double ratio, uint64_t max_cycles, const Progress& progress,
                  uint64_t every) {
  const CatchUp after{m};
  prepare(m);
  SolveResult r;
  while (r.cycles < max_cycles) {
    cycle(m);
    ++r.cycles;
    if (m.ratio <= ratio) {
      r.converged = true;
      break;
    }
    if (progress && every && r.cycles % every == 0 && !progress(m)) {
      r.stopped = true;
      break;
    }
  }
  return r;
}

double kinetic_energy(const Model& m) {
  return backend(m).kinetic_energy(m);
}

std::string find_overlap(const Model& m) {
  return backend(m).find_overlap(m);
}

void validate(const Model& m) {
  backend(m).validate(m);
}

void throw_overlap(const Model& m, size_t a, size_t b, double overlap, double limit,
                   const std::string& where, const std::string& what) {
  std::ostringstream msg;
  msg << "contact overlap too great at cycle " << m.cycle << ": " << m.block_label(a) << " and "
      << m.block_label(b) << " overlap by " << overlap << " m near " << where << " (more than "
      << limit << " m, an eighth of the smaller block's size; " << what
      << "): the joint's normal stiffness is too low for the load it carries, or the blocks were "
         "made overlapping";
  throw ModelError(msg.str());
}

void throw_diverged(const Model& m, int block_id) {
  throw ModelError("the run diverged at cycle " + std::to_string(m.cycle) + ": block " +
                   std::to_string(block_id) +
                   " moved more than a tenth of its size in one step (time step too large for "
                   "the joint stiffness, or blocks overlapping badly)");
}

}  // namespace tessera
