// Damping of one cycle, the same in 2D and 3D.
#include "tessera/core/damping.hpp"

#include <algorithm>

#include "tessera/core/model.hpp"

namespace tessera {

bool servo_due(const Model& m) {
  return m.settings.damping == DampingMode::kAdaptiveGlobal && m.cycle % 10 == 0;
}

Damping cycle_damping(Model& m, double power, double kin2) {
  const Settings& s = m.settings;
  // The viscosity that absorbs the chosen share of the unbalanced forces' power, changed by at
  // most a factor 1.25 at a time.
  if (servo_due(m) && kin2 > 0.0) {
    const double target = s.global_ratio * power / kin2;
    m.global_c =
        m.global_c <= 0.0 ? target : std::clamp(target, m.global_c / 1.25, m.global_c * 1.25);
  }
  Damping d;
  d.alpha = s.damping == DampingMode::kLocal     ? s.local_alpha
            : s.damping == DampingMode::kKinetic ? s.kinetic_alpha
                                                 : 0.0;
  d.viscosity = s.damping == DampingMode::kAdaptiveGlobal ? m.global_c : 0.0;
  return d;
}

}  // namespace tessera
