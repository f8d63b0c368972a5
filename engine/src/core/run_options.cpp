// Stage names and the build's default run options.
#include "tessera/core/run_options.hpp"

namespace tessera {

const char* stage_name(int stage) {
  static const char* const names[] = {"detect", "contacts", "interfaces", "motion", "zones"};
  return names[stage];
}

RunOptions default_run_options() {
  return RunOptions{TESSERA_VALIDATE_DEFAULT != 0, nullptr};
}

}  // namespace tessera
