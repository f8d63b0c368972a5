// What the one cycle (step.cpp) asks of a dimension: contact detection and geometry, the joint
// forces, and rigid-body motion with 3 (2D) or 6 (3D) degrees of freedom. Internal to the engine.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tessera/core/damping.hpp"
#include "tessera/core/model.hpp"

namespace tessera {

// What integration leaves per block for the core's convergence and divergence checks.
struct BlockMotion {
  std::vector<double> unbalanced;  // norm of the unbalanced force (translation)
  std::vector<double> drift;       // largest displacement of a point since the last detection
  std::vector<double> jump;        // step's displacement as a share of the block's size
  std::vector<double> applied;     // load carried, if the block moves under load (else 0)
  std::vector<uint8_t> moves;      // whether it moves under load (counts in the ratio)
  void reset(size_t n) {
    unbalanced.assign(n, 0.0), drift.assign(n, 0.0), jump.assign(n, 0.0);
    applied.assign(n, 0.0), moves.assign(n, 0);
  }
};

// The lowest index any thread flagged: the first offender, the same at every thread count (the
// contact a run stops on for too great an overlap, 2D and 3D).
class FirstFlagged {
 public:
  void flag(uint32_t i) {
    uint32_t seen = index_.load(std::memory_order_relaxed);
    while (i < seen && !index_.compare_exchange_weak(seen, i)) {
    }
  }
  bool any() const { return index_.load() != kNone; }
  uint32_t index() const { return index_.load(); }

 private:
  static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::atomic<uint32_t> index_{kNone};
};

// Power of the unbalanced forces and twice the kinetic energy over free degrees of freedom
// (adaptive global damping).
struct Power {
  double power = 0.0, kin2 = 0.0;
};

struct Backend {
  // Checks and caches before cycling (the block store's own; the core does the rest).
  void (*prepare)(Model& m);
  // Detection pass: broad phase, contact search, merge with the contacts that persist.
  void (*detect)(Model& m);
  // Contact geometry from the current positions (2D corners and features); null in 3D, where
  // joint_forces moves each contact's common plane and sub-contacts just before its joint law.
  void (*geometry)(Model& m);
  // Joint law at every contact (2D: shares of joint length first), giving contact forces.
  void (*joint_forces)(Model& m);
  // Each block's resultant force and moment and the load it carries, in a pass of their own.
  void (*resultants)(Model& m);
  // Whether each block's resultant may be gathered in its own step instead (integrate with
  // `gather`), which spares a pass over the blocks: no block takes forces from another (a
  // concave body's pieces, cables and bolts), and the sums read nothing the step moves.
  bool (*gathers_in_step)(const Model& m);
  Power (*power)(const Model& m);
  // Twice the kinetic energy of the rigid blocks' motion (with the density-scaled inertia).
  double (*motion_energy)(const Model& m);
  // Sets every rigid block's velocity and spin to zero (kinetic damping; held blocks take
  // their prescribed velocities again when they move).
  void (*stop)(Model& m);
  // Damping and central-difference integration of every rigid block (each block's resultant
  // first, if `gather`).
  void (*integrate)(Model& m, const Damping& d, bool gather, BlockMotion& out);
  // Each block's own stable step on joints of stiffness k (Pa/m), in translation and in rotation
  // (infinity where it does not move that way).
  std::vector<std::array<double, 2>> (*block_steps)(const Model& m, double k);
  double (*kinetic_energy)(const Model& m);
  std::string (*find_overlap)(const Model& m);
  void (*validate)(const Model& m);
};

const Backend& backend2d();
const Backend& backend3d();
inline const Backend& backend(const Model& m) {
  return m.dim == 3 ? backend3d() : backend2d();
}

}  // namespace tessera
