// The time step (chapter 5.2.4), chosen here alone for 2D and 3D, rigid and deformable blocks:
// the user's fixed step, or the safety factor times the smallest stable step - of the rigid
// blocks on their joints (the dimension's back end), of the zones, and of the outline nodes on
// their joints - which under density scaling is the nodes' median instead.
#pragma once

namespace tessera {

struct Model;

// The stiffest joint's spring, max(kn, ks) over the property sets (Pa/m): the one stiffness
// every stable-step estimate uses.
double stiffest_joint(const Model& m);
// The step the model cycles at.
double compute_timestep(const Model& m);

}  // namespace tessera
