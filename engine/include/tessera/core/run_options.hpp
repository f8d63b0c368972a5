// How a model runs, apart from its state: validation after each cycle and the stage profile.
// Each model carries its own (Model::options), so two models in one process never share them.
#pragma once

#include <array>
#include <cstdint>

namespace tessera {

// Stages of one cycle, each timed into the profile (3D contacts move their planes in the
// interfaces stage, contact by contact: its contacts stage takes no time).
enum Stage : int {
  kStageDetect,
  kStageContacts,
  kStageInterfaces,
  kStageMotion,
  kStageZones,
  kStageCount
};
const char* stage_name(int stage);

struct Profile {
  std::array<double, kStageCount> seconds{};
  uint64_t cycles = 0;
};

struct RunOptions {
  bool validate = false;  // cross-reference checks after each cycle
  Profile* profile = nullptr;
};
// Validation on in builds configured with TESSERA_VALIDATE (the dev and asan presets).
RunOptions default_run_options();

}  // namespace tessera
