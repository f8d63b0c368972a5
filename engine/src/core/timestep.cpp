// The time step of every model: fixed, or the safety factor times the smallest stable step, or
// under density scaling the median one with the blocks and nodes below it given more inertia.
#include "tessera/core/timestep.hpp"

#include <algorithm>
#include <cmath>

#include "backend.hpp"
#include "tessera/support/cables.hpp"
#include "tessera/support/liners.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

double stiffest_joint(const Model& m) {
  double k = 0.0;
  for (const JointProperties& j : m.joints) k = std::max({k, j.kn_max, j.ks_max});
  return k;
}

double stiffest_joint_pair(const Model& m) {
  double k = 0.0;
  for (const JointProperties& j : m.joints) k = std::max(k, j.kn_max + j.ks_max);
  return k;
}

namespace {

// Every degree of freedom's own stable step: the rigid blocks' translation and rotation, and the
// nodes of deformable blocks.
struct OwnSteps {
  std::vector<std::array<double, 2>> block;
  std::vector<double> node, cable;  // cable: cable and liner nodes
};

OwnSteps own_steps(const Model& m) {
  std::vector<double> support = cable_node_steps(m);
  for (double d : liner_node_steps(m)) support.push_back(d);
  return {backend(m).block_steps(m, stiffest_joint(m)), node_timesteps(m), support};
}

// The step before the safety factor: the smallest of the own steps, or under density scaling
// their median (1e300 if nothing moves).
double base_step(const Model& m, const OwnSteps& s) {
  std::vector<double> all;
  all.reserve(2 * s.block.size() + s.node.size());
  for (const auto& b : s.block)
    for (double d : b)
      if (d < 1e300) all.push_back(d);
  for (double d : s.node)
    if (d < 1e300) all.push_back(d);
  // Cable nodes take scaled inertia in static runs, unless nothing else moves.
  if (m.settings.damping == DampingMode::kNone || all.empty())
    for (double d : s.cable)
      if (d < 1e300) all.push_back(d);
  if (all.empty()) return 1e300;
  if (!m.settings.dt_scaled) return *std::min_element(all.begin(), all.end());
  const auto mid = all.begin() + static_cast<long>(all.size() / 2);
  std::nth_element(all.begin(), mid, all.end());
  return *mid;
}

double safe_step(const Model& m, double base) {
  if (m.settings.dt_fixed > 0.0) return m.settings.dt_fixed;
  if (!std::isfinite(base) || base >= 1e299) return 1e-3;
  return m.settings.dt_safety * base;
}

template <int D>
void scale_nodes(ContinuumT<D>& c, const std::vector<double>& steps, double target) {
  for (size_t n = 0; n < steps.size(); ++n)
    if (steps[n] < target) c.inertia[n] = c.mass[n] * (target / steps[n]) * (target / steps[n]);
}

}  // namespace

double compute_timestep(const Model& m) {
  return safe_step(m, m.settings.dt_fixed > 0.0 ? 0.0 : base_step(m, own_steps(m)));
}

void set_timestep(Model& m) {
  const OwnSteps s = own_steps(m);
  const double target = base_step(m, s);
  m.dt = safe_step(m, target);
  scale_cable_nodes(m, m.dt);
  scale_liner_nodes(m, m.dt);
  m.continuum.inertia = m.continuum.mass;
  m.continuum3.inertia = m.continuum3.mass;
  m.block_scale.clear();
  if (!m.settings.dt_scaled) return;
  // Each degree of freedom whose own step is below the target takes the inertia that makes its
  // own step the target; gravity keeps the real mass.
  m.block_scale.resize(s.block.size());
  for (size_t b = 0; b < s.block.size(); ++b)
    for (int k = 0; k < 2; ++k) {
      const double own = s.block[b][static_cast<size_t>(k)];
      m.block_scale[b][static_cast<size_t>(k)] =
          own < target ? (target / own) * (target / own) : 1.0;
    }
  if (m.dim == 3)
    scale_nodes(m.continuum3, s.node, target);
  else
    scale_nodes(m.continuum, s.node, target);
}

}  // namespace tessera
