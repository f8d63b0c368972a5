// The time step of every model: fixed, or the safety factor times the smallest stable step.
#include "tessera/core/timestep.hpp"

#include <algorithm>
#include <cmath>

#include "backend.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

double stiffest_joint(const Model& m) {
  double k = 0.0;
  for (const JointProperties& j : m.joints) k = std::max({k, j.kn, j.ks});
  return k;
}

double stiffest_joint_pair(const Model& m) {
  double k = 0.0;
  for (const JointProperties& j : m.joints) k = std::max(k, j.kn + j.ks);
  return k;
}

double compute_timestep(const Model& m) {
  if (m.settings.dt_fixed > 0.0) return m.settings.dt_fixed;
  double dt = backend(m).timestep(m, stiffest_joint(m));
  dt = std::min(dt, deformable_timestep(m));
  if (!std::isfinite(dt) || dt >= 1e299) return 1e-3;
  return m.settings.dt_safety * dt;
}

}  // namespace tessera
