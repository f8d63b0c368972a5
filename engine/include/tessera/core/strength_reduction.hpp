// Factor of safety by strength reduction, as UDEC and 3DEC apply it: the joints' cohesion,
// tan(friction) and tensile strength, and the zones' (Mohr-Coulomb, Drucker-Prager), divided by a
// trial factor F; each trial solved from the same initial state; F bracketed, then bisected.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

struct FosOptions {
  bool joints = true, zones = true;  // which strengths are reduced
  // Groups whose zones, and the joints that touch them, keep their full strength.
  std::vector<int> exclude;
  double ratio = 1e-5;       // a trial stands once the ratio falls to this
  uint64_t cycles = 20000;   // ... within this many cycles
  double precision = 0.01;   // bisection stops when the bracket is this narrow
  double max_factor = 64.0;  // brackets searched within [1 / max, max]
};

// One trial: the factor, whether the model stood, and what decided it.
struct FosTrial {
  double factor = 0.0;
  bool stands = false;
  uint64_t cycles = 0;
  double ratio = 0.0;
  // The largest displacement of a block centroid or node from the initial state, half way
  // through the trial and at its end.
  double moved_half = 0.0, moved_end = 0.0;
  std::string stopped;  // a trial that ended on a run error (overlap, divergence): its message
};

struct FosResult {
  // The largest factor that stood, within `precision` of the smallest that failed; when no
  // factor failed up to max_factor (or none stood down to 1 / max_factor) the bound itself.
  double factor = 0.0;
  bool bracketed = false;
  std::vector<FosTrial> trials;
  // The model at the end of the smallest failing trial: the mechanism.
  std::optional<Model> mechanism;
};

// Divides the strengths of the joints and/or the zones by `factor` (cohesion, tension, and
// friction through its tangent; stiffness and dilation stay). With groups to exclude, reduced
// copies of the joint sets and zone materials are added beside the originals, which the
// contacts touching those groups and the zones of their blocks keep.
void reduce_strength(Model& m, double factor, bool joints, bool zones,
                     const std::vector<int>& exclude = {});

// One trial from `initial` at `factor`. The failure criterion: no equilibrium (ratio) within the
// cycle limit and the largest displacement still growing (at the end more than 10% above its
// value half way); a trial that stops on a run error has failed. `progress` may stop it (then
// `stopped` says so and the trial counts as failed).
FosTrial strength_trial(const Model& initial, double factor, const FosOptions& o, Model& out,
                        const Progress& progress = {});

// The factor of safety of `initial` (left unchanged). `progress` is called between cycles; when
// it returns false the search ends with what it has (bracketed false).
FosResult factor_of_safety(const Model& initial, const FosOptions& o, const Progress& progress = {},
                           const std::function<void(const FosTrial&)>& each = {});

}  // namespace tessera
