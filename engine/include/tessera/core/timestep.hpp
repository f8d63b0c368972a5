// The time step (chapter 5.2.4), chosen here alone for 2D and 3D, rigid and deformable blocks:
// the user's fixed step, or the safety factor times the smallest stable step - of the rigid
// blocks on their joints (the dimension's back end), of the zones, and of the outline nodes on
// their joints - which under density scaling is the median of all of them instead.
#pragma once

namespace tessera {

struct Model;

// The stiffest joint's spring, max(kn, ks) over the property sets (Pa/m): the one stiffness
// every stable-step estimate uses.
double stiffest_joint(const Model& m);
// The stiffest joint's two springs together, max(kn + ks) (Pa/m), for an outline node of a
// deformable block: at a corner of its block, the normal spring of one edge's contact and the
// shear spring of the other's act along the same direction (deformable.cpp's node steps). A rigid
// block's perimeter bound needs only stiffest_joint: each face adds kn or ks along a direction.
double stiffest_joint_pair(const Model& m);
// The step the model cycles at.
double compute_timestep(const Model& m);
// Sets the step the model cycles at and, under density scaling (`timestep scaled`), the rigid
// blocks' scales (Model::block_scale) and the nodes' inertia: every degree of freedom whose own
// stable step is below the median takes the inertia that makes its own step the median.
void set_timestep(Model& m);

}  // namespace tessera
