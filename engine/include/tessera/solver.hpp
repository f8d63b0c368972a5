// The explicit cycle (chapter 5.2.3-5.2.4): contacts, joint law, resultants, damping, motion.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "tessera/model.hpp"

namespace tessera {

// Stages of one cycle, each timed into the profile.
enum Stage : int { kStageDetect, kStageContacts, kStageInterfaces, kStageMotion, kStageCount };
const char* stage_name(int stage);

struct Profile {
  std::array<double, kStageCount> seconds{};
  uint64_t cycles = 0;
};

// An error in the model found while preparing or cycling (overlap, missing property, divergence).
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Engine options that are not part of the model's state.
struct RunOptions {
  bool validate = false;  // cross-reference checks after each stage
  Profile* profile = nullptr;
};
RunOptions& run_options();

// Critical time step times the safety factor (or the user's fixed step).
double compute_timestep(const Model& m);
// Makes the model ready to cycle: time step, contact detection, overlap check.
void prepare(Model& m);
// One cycle of the explicit scheme.
void cycle(Model& m);
// The first stage of a cycle alone: each contact's feature, gap, normal and point from the
// current positions.
void update_contact_geometry(Model& m);
// Contact detection pass: broad phase, corner search, merge with existing contacts.
void detect_contacts(Model& m);
// Rebuilds the per-block contact lists from the contact array.
void build_adjacency(Model& m);
// First pair of blocks that overlap beyond the contact tolerance, as a message; empty if none.
std::string find_overlap(const Model& m);
// Cross-reference checks; throws std::logic_error naming what is inconsistent.
void validate(const Model& m);
double kinetic_energy(const Model& m);
// Throws the ModelError of a run whose block moved more than a tenth of its size in a step.
[[noreturn]] void throw_diverged(const Model& m, int block_id);
// Adaptive global damping (Cundall 1982): the viscosity that absorbs the chosen share of the
// power of the unbalanced forces, from that power and twice the kinetic energy, changed by at
// most a factor 1.25 each time (2D and 3D cycles, every 10 cycles).
void servo_global_damping(Model& m, double power, double kin2);

// Runs n cycles; `progress` is called every `every` cycles and may return false to stop.
using Progress = std::function<bool(const Model&)>;
uint64_t run_cycles(Model& m, uint64_t n, const Progress& progress = {}, uint64_t every = 0);
// Cycles until the unbalanced-force ratio is below `ratio` or `max_cycles` have run.
struct SolveResult {
  uint64_t cycles = 0;
  bool converged = false;
  bool stopped = false;
};
SolveResult solve(Model& m, double ratio, uint64_t max_cycles, const Progress& progress = {},
                  uint64_t every = 0);

}  // namespace tessera
