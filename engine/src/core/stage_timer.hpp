// Times one stage of a cycle into the run's profile, if any (internal to the engine).
#pragma once

#include <chrono>

#include "tessera/core/run_options.hpp"

namespace tessera {

class StageTimer {
 public:
  StageTimer(const RunOptions& run, int stage) : profile_(run.profile), stage_(stage) {
    if (profile_) t0_ = std::chrono::steady_clock::now();
  }
  ~StageTimer() {
    if (profile_)
      profile_->seconds[static_cast<size_t>(stage_)] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  Profile* profile_;
  int stage_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace tessera
