// In-situ stress (chapter 5.2.1, initial conditions): a field set in the zones of deformable
// blocks and on the joints between blocks, so that a model starts in equilibrium.
#pragma once

#include <cstddef>

#include "tessera/core/model.hpp"
#include "tessera/zones/zone_model.hpp"

namespace tessera {

// Uniform stress `base` plus `gradient` times (v - v0), v the height (y in 2D, z in 3D);
// tension positive, Pa.
struct StressField {
  ZoneStress base, gradient;
  double y0 = 0.0;
  ZoneStress at(double v) const;
};

// Gives every shut contact (gap within a thousandth of the contact tolerance) the traction of
// the field at its point: a joint closure sigma_n / kn (from the drawn gap; any earlier force is
// replaced), taken up as the normal force at the next cycle, and the shear stress, made a force
// with that cycle's contact length. Joints in tension across their normal are left unloaded.
// Detects contacts first if due. Returns the number of contacts loaded. In 3D each shut
// sub-contact is loaded the same way, its shear force the shear traction times its area.
size_t preload_contacts(Model& m, const StressField& field);

}  // namespace tessera
