// The explicit cycle (chapter 5.2.3-5.2.4), one for 2D and 3D: detection when due, contact
// geometry, joint forces, block motion, deformable zones; then the checks, the clock and the
// histories. core/step.cpp reads top to bottom; the dimension's back end does what differs.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "tessera/core/model.hpp"

namespace tessera {

// An error in the model found while preparing or cycling (overlap, missing property, divergence).
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Makes the model ready to cycle: checks, time step, contact lists.
void prepare(Model& m);
// One cycle of the explicit scheme.
void step(Model& m);
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

double kinetic_energy(const Model& m);
// First pair of blocks that overlap beyond the contact tolerance, as a message; empty if none.
std::string find_overlap(const Model& m);
// Cross-reference checks of the block and contact arrays; throws std::logic_error naming what
// is inconsistent.
void validate(const Model& m);
// Overlaps beyond this share of the deepest plausible one (a quarter of the smaller block's
// size) stop the run, 2D and 3D: past it a corner would soon lose its feature and fall through.
constexpr double kOverlapLimit = 0.5;
// Stops the run on an overlap of blocks a and b beyond `limit`, as UDEC's "contact overlap too
// great" does: `where` is the place ("x=.., y=.."), `what` the features that touch.
[[noreturn]] void throw_overlap(const Model& m, size_t a, size_t b, double overlap, double limit,
                                const std::string& where, const std::string& what);
// Throws the ModelError of a run whose block moved more than a tenth of its size in a step.
[[noreturn]] void throw_diverged(const Model& m, int block_id);

}  // namespace tessera
