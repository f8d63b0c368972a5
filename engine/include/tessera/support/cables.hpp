// Grouted cables (UDEC's and 3DEC's cable elements), one mechanism for 2D and 3D models.
//
// A cable is a chain of nodes joined by axial segments (stiffness EA over the segment's length,
// yield forces in tension and compression, no bending). Each node sits at a point of its host
// rock (a rigid block, or a zone of a deformable one) and may slide along the cable's axis
// against the grout: a spring of stiffness kbond per metre of cable, capped at the bond strength
// sbond per metre (perfectly plastic). Across the axis a node follows its host. A cable's head
// may be tied to its host (a faceplate): it moves with the rock and hands it the whole force.
//
// Each node has inertia only along the axis. In static runs (any damping but `none`) that
// inertia is scaled so that the cables never set the time step, as structural elements are in
// other explicit codes; with `damping none` the nodes keep the steel's mass and may shorten it.
//
// The node arrays are one template on the dimension: a 2D cable's hosts are Anchor2 (rigid
// blocks and zones), a 3D cable's Anchor3 (rigid blocks).
#pragma once

#include <string>
#include <vector>

#include "tessera/support/anchor3.hpp"
#include "tessera/support/node_balance.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

// A cable's properties (2D: per metre out of the plane, the user's values over the row spacing).
struct CableProperties {
  double ea = 0.0;                          // axial stiffness E A, N
  double tension = 0.0, compression = 0.0;  // segment yield forces, N (0: none)
  double kbond = 0.0;                       // grout shear stiffness, N/m per m of cable
  double sbond = 0.0;                       // grout bond strength, N per m of cable (0: none)
  double pretension = 0.0;                  // axial force when installed, N
  double mass = 0.0;  // steel per metre of cable, kg/m (0: steel of the section EA implies)
  // The bond strength's rise with confinement (FLAC's sfriction and perimeter): tan of the
  // grout's friction angle (0: none) and the grout's perimeter, m, so that the strength per
  // metre is sbond + confinement * tan * perimeter.
  double bond_friction = 0.0, perimeter = 0.0;
};

struct Cable {
  std::string name;
  CableProperties props;
  uint32_t first = 0, count = 0;  // nodes [first, first + count)
  uint8_t head = 0;               // 1: the first node is tied to its host
};

// Node states.
enum CableState : uint8_t { kCableBondYield = 1, kCableYield = 2 };

template <int D>
struct CableHost;
template <>
struct CableHost<2> {
  using type = Anchor2;
};
template <>
struct CableHost<3> {
  using type = Anchor3;
};

template <int D>
struct CablesT {
  using V = Eigen::Matrix<double, D, 1>;
  using Host = typename CableHost<D>::type;
  std::vector<Cable> cables;
  // Per node: its cable, its host point, bonded length (half of each neighbouring segment that
  // lies in rock; 0 within the free length), slip of the host past the node along the axis
  // (total and plastic), the node's velocity along the axis and its inertia, the grout force per
  // metre (on the node, along +axis), state bits.
  std::vector<uint32_t> cable;
  std::vector<Host> host;
  std::vector<double> bonded, slip, slip_plastic, vel, inertia, bond;
  std::vector<uint8_t> state;
  // Per node, the segment to the next node of the same cable (unused at a cable's last node):
  // rest length, plastic elongation and axial force (tension positive).
  std::vector<double> rest, plastic, axial;
  // The cycle's results: node positions, axes and the force each node hands its host.
  std::vector<V> pos, axis, host_force;
  // Per node, the zone that hosts it (a cache for the confinement, found again when stale).
  std::vector<int32_t> zone;
  // The free nodes' balance along their axes in the last cycle (the model's ratio counts it).
  NodeBalance balance;

  size_t size() const { return cable.size(); }
  bool empty() const { return cables.empty(); }
  // Appends a cable with nodes at `hosts`; returns its index.
  size_t add(Cable c, const std::vector<Host>& hosts, const std::vector<double>& bonded);
};
using Cables = CablesT<2>;
using Cables3 = CablesT<3>;

// The cycle: node axes, positions and forces from the hosts' motion, the nodes' axial motion,
// and each node's force on its host (added by add_reinforcement_forces and _to_nodes in 2D,
// add_cable_forces3 in 3D). The model's cables of its dimension.
void update_cables(Model& m, double alpha);
// The inertia each node takes for the step dt (static runs), or the steel's (dynamic runs).
void scale_cable_nodes(Model& m, double dt);
// The stiffness node i adds to its host: its grout, or a tied head's segment.
template <int D>
double cable_host_stiffness(const CablesT<D>& K, size_t i);
// Each node's own stable step with the steel's mass (which sets the model's step in dynamic runs,
// and in static ones only when no block or zone moves).
std::vector<double> cable_node_steps(const Model& m);

// After blocks are deleted (see remap_reinforcement): nodes in excavated rock go, and a cable
// goes on as its runs of nodes left in rock.
void remap_cables(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map);
void remap_cables3(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map);
// 3D: each node's pull on its rigid host (force and torque about the body's centroid; nodes in
// zones: add_cable_forces_to_nodes3), and the grout stiffness each body carries (time step).
void add_cable_forces3(Model& m);
std::vector<double> cable_stiffness3(const Model& m);

// Places a cable from p0 to p1 in `segments` segments; every node must lie in a block. `free`:
// the length from p0 left unbonded; `head`: the node at p0 tied to its block.
size_t install_cable(Model& m, const std::string& name, Vec2 p0, Vec2 p1, int segments,
                     const CableProperties& props, double free, bool head);
size_t install_cable3(Model& m, const std::string& name, const Vec3& p0, const Vec3& p1,
                      int segments, const CableProperties& props, double free, bool head);

}  // namespace tessera
