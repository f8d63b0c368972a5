// Liners of 2D models: beam elements along the wall of an opening, joined to the rock by an
// interface (UDEC's and FLAC's structural liner).
//
// Nodes sit on the wall with two translations and a rotation each; elements between them are
// Euler-Bernoulli beams (E A, E I; small displacements in the element's placed frame) whose
// axial force and end moments are capped (perfectly plastic, hinges at the ends). Each node is
// tied to the rock point it was placed on by an interface: a normal spring (kn per metre of
// wall, pushing only while the liner presses the rock unless it has a tensile strength) and a
// shear spring (ks per metre, capped at cohesion plus friction times the pressure).
//
// Inertia as cables': in static runs what keeps the step the blocks set; with `damping none`
// the lining's mass.
#pragma once

#include <string>
#include <vector>

#include "tessera/support/node_balance.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

// A liner's properties, per metre out of the plane.
struct LinerProperties {
  double ea = 0.0, ei = 0.0;              // axial (N) and bending (N m2) stiffness
  double thrust = 0.0, moment = 0.0;      // axial (N) and moment (N m) capacity (0: none)
  double kn = 0.0, ks = 0.0;              // interface stiffness, Pa/m (per metre of wall)
  double tension = 0.0;                   // interface tensile strength, Pa (0: none)
  double cohesion = 0.0, friction = 0.0;  // interface shear strength: Pa, degrees (0, 0: none)
  double mass = 0.0;                      // lining per metre of wall, kg/m (dynamic runs)
};

struct Liner {
  std::string name;
  LinerProperties props;
  uint32_t first = 0, count = 0;  // nodes [first, first + count)
  uint8_t closed = 0;             // 1: a ring, the last node joined to the first
};

// Node states: the interface slipping or open, an element end (the one starting at the node)
// at its moment capacity, or the element at its thrust capacity.
enum LinerState : uint8_t {
  kLinerSlip = 1,
  kLinerOpen = 2,
  kLinerHinge = 4,
  kLinerThrustYield = 8
};

struct Liners {
  std::vector<Liner> liners;
  // Per node: its liner, host point in the rock, placed position, wall normal (into the rock)
  // and interface length; displacement, rotation and their rates; inertias; the interface's
  // shear force (incremental); forces on the node and the node's force on the rock; state.
  std::vector<uint32_t> liner;
  std::vector<Anchor2> host;
  std::vector<Vec2> pos0, normal, disp, vel, force, host_force;
  std::vector<double> length, rot, spin, mass, inertia, shear, pressure, moment_sum;
  std::vector<uint8_t> state;
  // Per element (from node i to the next of its liner; unused at an open liner's last node):
  // axial force, end moments (on the element, anticlockwise), shear, plastic parts.
  std::vector<double> axial, m_start, m_end, v_shear, plastic_axial, hinge_start, hinge_end;
  // The free nodes' balance in the last cycle (the model's ratio counts it).
  NodeBalance balance;

  size_t size() const { return liner.size(); }
  bool empty() const { return liners.empty(); }
  // The node after i on its liner, or -1 at an open liner's end.
  int64_t next(size_t i) const;
  size_t add(Liner l, const std::vector<Anchor2>& hosts, const std::vector<Vec2>& at,
             const std::vector<Vec2>& normals, const std::vector<double>& lengths);
};

// The cycle: element and interface forces from the nodes' and hosts' motion, the nodes' motion,
// and their reactions on the rock (added by add_reinforcement_forces and _to_nodes).
void update_liners(Model& m, double alpha);
// Node inertias for the step dt (static), or the lining's mass (dynamic).
void scale_liner_nodes(Model& m, double dt);
std::vector<double> liner_node_steps(const Model& m);
// The stiffness node i's interface adds to its host.
double liner_host_stiffness(const Model& m, size_t i);
// At node i: the thrust (compression positive, the mean of its elements') and the bending
// moment (positive when it puts the liner's rock-side face in tension, as Einstein and Schwartz
// count it: at the springline of a ring squeezed from above).
double liner_thrust(const Liners& L, size_t i);
double liner_moment(const Liners& L, size_t i);
// Where node i is now.
inline Vec2 liner_position(const Liners& L, size_t i) {
  return L.pos0[i] + L.disp[i];
}

// Lines the wall of the excavated opening `tag` between angles a0 and a1 (degrees about its
// centre; the whole wall, a closed ring, when they span 360): a node at every wall vertex, and
// with `spacing` more between them, at most that far apart.
size_t install_liner(Model& m, const std::string& name, int tag, double a0, double a1,
                     const LinerProperties& props, double spacing = 0.0);
// After blocks are deleted: a liner whose rock is gone goes.
void remap_liners(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map);

}  // namespace tessera
