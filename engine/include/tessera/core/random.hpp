// A seeded random stream that gives the same numbers on every machine and compiler.
//
// std::normal_distribution and friends are not specified bit for bit, so the draws are made
// here from the raw 64-bit output of std::mt19937_64, which is.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tessera {

class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Normal by Box-Muller (one value per call; the pair's second is dropped for simplicity).
  double normal(double mean, double sd) {
    if (sd <= 0.0) return mean;
    const double u1 = 1.0 - uniform(), u2 = uniform();
    return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace tessera
