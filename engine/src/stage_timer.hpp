// Times one stage of a cycle into the run's profile, if any (internal to the engine).
#pragma once

#include <chrono>

#include "tessera/solver.hpp"

namespace tessera {

// Times one stage into the profile, if any.
class StageTimer {
 public:
  explicit StageTimer(int stage) : stage_(stage), t0_(std::chrono::steady_clock::now()) {}
  ~StageTimer() {
    if (Profile* p = run_options().profile)
      p->seconds[static_cast<size_t>(stage_)] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  int stage_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace tessera
