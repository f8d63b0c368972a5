// The mechanics of zoned (deformable) material: nodes carrying the motion, uniform-strain
// simplices carrying the stress (§5.2.1, §5.2.3, §5.3.1), stepped with central differences.
// One kernel for both dimensions: triangles in 2D (plane strain), tetrahedra in 3D.
//
// This is the deformable-block kernel on its own: nodes, zones, boundary conditions, in-situ
// stress, damping and the time step, verified against closed-form solutions (Kirsch's hole, an
// elastic column, a P-wave, a Mohr-Coulomb plastic zone; in 3D a uniaxial cube, a confined
// column and a triaxial test). Deformable blocks in the model and their contacts with other
// blocks are built on it (see docs/ARCHITECTURE.md).
//
// Layout: structure of arrays. Nodes: position, initial position, velocity, force, lumped mass,
// fixity; zones: D + 1 node indices (counter-clockwise triangles, positive-volume tetrahedra),
// stress (tension positive), plastic state, the model's history and material. A node's mass is the
// density times the measure of its median-dual cell (1/(D+1) of each zone around it), the
// barycentric counterpart of the chapter's Voronoi cell.
//
// Quadratic zones (3D, the chapter's 10-node option, §5.3.1): a tetrahedron with a node at the
// middle of each edge and the quadratic displacement field of those ten nodes, its stress and
// state kept at four integration points (Gauss, exact for the quadratic strain energy) with
// the zone's `stress` their mean and `state` their union. The edges stay straight (the corners
// map the shape, subparametric); masses are lumped in proportion to the consistent mass
// matrix's diagonal (1/36 of the zone's mass at each corner, 4/27 at each mid-edge node; the
// row sums would put negative mass at the corners). No mixed discretization: a quadratic
// zone's strain varies inside it, which is what the averaging stands in for.
//
// Nodal mixed discretization (Detournay & Dzik 2006, as in FLAC3D and 3DEC): uniform-strain
// simplices lock under plastic flow (too few of their modes deform at constant volume), so each
// cycle the volumetric part of a zone's strain increment is replaced by the mean over its nodes
// of the volume-weighted nodal averages, keeping the zone's own deviatoric part. Under dilatant
// flow the isotropic part of each yielding zone's plastic stress correction is averaged the
// same way (else it is a zone-by-zone pressure the averaged strain cannot relieve, which grows
// without bound); isochoric flow (psi = 0) makes no such correction.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tessera/core/geometry.hpp"
#include "tessera/zones/zone_model.hpp"
#include "tessera/zones/zoning.hpp"
#include "tessera/zones/zoning3.hpp"

namespace tessera {

// A node's fixity bit for axis k (x, y, z): kFixX, kFixY of blocks.hpp in 2D.
constexpr uint8_t node_fix_bit(int k) {
  return static_cast<uint8_t>(1u << k);
}

// Work arrays of a cycle, kept with the model (not shared between models): the size of the
// forces meeting at each node (for the unbalanced-force ratio), and per zone the strain
// increment, volume, volumetric increment, isotropic plastic correction and their nodal
// averages, with per-node sums and weights; which zones the linear passes take (solid 4-node).
struct ZoneScratch {
  std::vector<uint8_t> linear;
  std::vector<double> scale;
  std::vector<StrainIncrement> de;
  std::vector<Spin> spin;
  std::vector<double> volume, ev, ev_mixed, dp, dp_mixed, node_sum, node_weight;
};

template <int D>
struct ContinuumT {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Zone = std::array<uint32_t, D + 1>;
  // Nodes.
  std::vector<Vec> pos, pos0, vel, force, applied;  // applied: constant loads (tractions)
  std::vector<double> mass;                         // lumped mass: gravity and reported quantities
  std::vector<double> inertia;  // mass in the motion: the lumped mass, or more under scaling
  std::vector<uint8_t> fixity;  // node_fix_bit(k) for each held axis
  std::vector<Vec> fixed_vel;
  // Zones.
  std::vector<Zone> zones;
  std::vector<ZoneStress> stress;
  std::vector<uint8_t> state;
  std::vector<double> plastic;  // the model's history: strain-softening's plastic shear strain
  std::vector<uint32_t> material;
  std::vector<ZoneProperties> materials;
  // Loading and stepping.
  Vec gravity = Vec::Zero();
  double local_damping = 0.8;  // UDEC's local damping; 0 for dynamic runs
  double dt = 0.0, time = 0.0;
  uint64_t cycle = 0;
  double ratio = 1.0;       // largest unbalanced force over the mean applied force
  bool nodal_mixed = true;  // nodal mixed discretization (false: plain uniform-strain zones)
  // Quadratic zones (3D only): empty when there are none, else per zone its mid-edge nodes in
  // VTK's order (edges 01, 12, 20, 03, 13, 23; kNoMid for a 4-node zone) and its integration
  // points' stresses, states and histories (the zone's `plastic` their mean).
  std::vector<std::array<uint32_t, 6>> mid;
  std::vector<std::array<ZoneStress, 4>> gp_stress;
  std::vector<std::array<uint8_t, 4>> gp_state;
  std::vector<std::array<double, 4>> gp_plastic;
  std::vector<uint8_t> edge_node;  // per node: 1 at the middle of a quadratic zone's edge
  ZoneScratch scratch;

  static constexpr uint32_t kNoMid = 0xffffffffu;
  size_t node_count() const { return pos.size(); }
  size_t zone_count() const { return zones.size(); }
  bool quadratic(size_t z) const { return !mid.empty() && mid[z][0] != kNoMid; }
  // Calls f(node) for each node of zone z: its corners, then its mid-edge nodes if any.
  template <typename F>
  void for_zone_nodes(size_t z, F&& f) const {
    for (uint32_t n : zones[z]) f(n);
    if (quadratic(z))
      for (uint32_t n : mid[z]) f(n);
  }
};
using Continuum = ContinuumT<2>;   // triangles, plane strain
using Continuum3 = ContinuumT<3>;  // tetrahedra

// Appends a zone mesh as free nodes and zones of one material; returns the first new node.
uint32_t add_mesh(Continuum& c, const ZoneMesh& mesh, uint32_t material);
uint32_t add_mesh(Continuum3& c, const ZoneMesh3& mesh, uint32_t material);
// Makes a tetrahedral mesh quadratic: a node at the middle of every edge (one per edge, shared
// by the zones around it), listed in `mesh.mid` per zone in VTK's order; surface flags follow.
void make_quadratic(ZoneMesh3& mesh);
// How a force, traction or area on a surface triangle t is shared among its nodes, given the
// weights l it would have on a plain triangle: on a piece of a quadratic zone's face (a node
// with `edge_node` set) kept to its mid-edge nodes and renormalised (in equal parts if l has
// none there); elsewhere l. For a uniform traction on the four pieces of a face this is the
// consistent load of a 6-node triangle: none at the corners, a third at each mid-edge node.
inline Vec3 mid_edge_weights(const std::array<uint32_t, 3>& t, Vec3 l,
                             const std::vector<uint8_t>& edge_node) {
  if (edge_node.empty() || !(edge_node[t[0]] | edge_node[t[1]] | edge_node[t[2]])) return l;
  for (int i = 0; i < 3; ++i)
    if (!edge_node[t[i]]) l[i] = 0.0;
  if (!(l.sum() > 0.0))
    for (int i = 0; i < 3; ++i) l[i] = edge_node[t[i]];
  return l / l.sum();
}
// A traction's shares: a third to each node, or on a quadratic face as mid_edge_weights.
inline Vec3 traction_shares(const std::array<uint32_t, 3>& t,
                            const std::vector<uint8_t>& edge_node) {
  return mid_edge_weights(t, Vec3::Constant(1.0 / 3.0), edge_node);
}
// Sets zone z's stress (and, for a quadratic zone, its integration points') and state.
void set_zone_stress(Continuum3& c, size_t z, const ZoneStress& s, uint8_t state);
void set_zone_stress(Continuum& c, size_t z, const ZoneStress& s, uint8_t state);
// Lumped nodal masses from the zones' densities and volumes (after meshes and material changes).
template <int D>
void lump_masses(ContinuumT<D>& c);
// A zone's stable step: its height over the P-wave speed (1e300 for a null zone); a quadratic
// zone's, Gershgorin's bound for the zone alone at its worst node (quadratic_zones.hpp).
template <int D>
double zone_timestep(const ContinuumT<D>& c, size_t z);
// Each node's stable step from its zones (1e300 for a node with none): the smallest of its
// 4-node (3-node) zones' steps; where quadratic zones meet, Gershgorin's bound on the assembled
// mesh, 2 sqrt(M / R): the node's mass over the sum of its zones' largest stiffness row sums.
template <int D>
std::vector<double> node_steps(const ContinuumT<D>& c);
// Stable time step times `safety`: the smallest of the nodes' steps.
template <int D>
double critical_timestep(const ContinuumT<D>& c, double safety = 0.5);
// Stress in every zone: uniform `s0`, plus `gradient` times the height of the zone's centroid
// above `v0` (y in 2D, z in 3D; e.g. for gravity).
template <int D>
void initialize_stress(ContinuumT<D>& c, const ZoneStress& s0, const ZoneStress& gradient = {},
                       double v0 = 0.0);
// Loads from a boundary stress (tension positive) on the outline edges whose two nodes pass
// `on_edge`: each edge's traction sigma . n times its length, half to each node.
template <typename Pred>
void apply_boundary_stress(Continuum& c, const ZoneMesh& mesh, uint32_t first_node,
                           const ZoneStress& s, Pred on_edge);
// The same on the surface triangles of a tetrahedral mesh whose three nodes pass `on_face`:
// each triangle's traction times its area, a third to each node.
template <typename Pred>
void apply_boundary_stress(Continuum3& c, const ZoneMesh3& mesh, uint32_t first_node,
                           const ZoneStress& s, Pred on_face);
// Small strain of a zone from its nodes' displacements on the initial shape.
template <int D>
StrainIncrement total_strain(const ContinuumT<D>& c, size_t z);
inline void zone_strain(const Continuum& c, size_t z, double& exx, double& eyy, double& exy) {
  const StrainIncrement e = total_strain(c, z);
  exx = e.xx, eyy = e.yy, exy = e.xy;
}
// Most and least compressive principal stresses (tension positive: s1 <= s3).
void principal_stresses(const ZoneStress& s, double& s1, double& s3);
// Area of a triangle, volume of a tetrahedron, in its current shape.
template <int D>
double zone_volume(const ContinuumT<D>& c, size_t z);
inline double zone_area(const Continuum& c, size_t z) {
  return zone_volume(c, z);
}
// One cycle: zone stresses from the strain increments, nodal forces, damping, motion.
template <int D>
void continuum_cycle(ContinuumT<D>& c);
// The two halves of a cycle, for models that add contact forces in between: nodal forces from
// loads and zones, then damping and motion (sets the ratio; returns the largest node move).
template <int D>
void zone_forces(ContinuumT<D>& c);
// Adds an outside force (a contact's) to a node between the two halves.
template <int D>
void add_node_force(ContinuumT<D>& c, size_t n, const typename ContinuumT<D>::Vec& f);
template <int D>
double move_nodes(ContinuumT<D>& c);

// Boundary edges of a mesh (node pairs with the domain on their left), in mesh node numbers.
std::vector<std::array<uint32_t, 2>> boundary_edges(const ZoneMesh& mesh);
// Boundary triangles of a tetrahedral mesh (counter-clockwise seen from outside), in mesh node
// numbers, in the order of the tetrahedra; a quadratic mesh's are each split into four at the
// mid-edge nodes (the corner triangles, then the middle one), as contacts and pictures use them.
std::vector<std::array<uint32_t, 3>> boundary_faces(const ZoneMesh3& mesh);

// The nodal mixed discretization's average of a zone field over simplices of N nodes (3:
// triangles, 4: tetrahedra): at each node the volume-weighted mean of its zones' `value`, then
// out[z] = the mean of z's nodes' values. Zones of zero volume (null zones) take no part and
// keep their own value. Sums run in zone order (deterministic); `node_sum` and `node_weight`
// are scratch of at least `node_count` entries.
template <size_t N>
void nodal_average(std::span<const std::array<uint32_t, N>> zones, std::span<const double> volume,
                   std::span<const double> value, size_t node_count, std::span<double> node_sum,
                   std::span<double> node_weight, std::span<double> out) {
  std::fill_n(node_sum.begin(), node_count, 0.0);
  std::fill_n(node_weight.begin(), node_count, 0.0);
  // Scatter: each zone's volume times its value, and its volume, to its nodes.
  for (size_t z = 0; z < zones.size(); ++z) {
    if (!(volume[z] > 0)) continue;
    for (uint32_t n : zones[z]) node_sum[n] += volume[z] * value[z], node_weight[n] += volume[z];
  }
  // Nodes: the volume-weighted mean of the zones around each.
  for (size_t n = 0; n < node_count; ++n)
    if (node_weight[n] > 0) node_sum[n] /= node_weight[n];
  // Gather: each zone takes the plain mean of its nodes' averages.
  for (size_t z = 0; z < zones.size(); ++z) {
    if (!(volume[z] > 0)) {
      out[z] = value[z];
      continue;
    }
    double sum = 0;
    for (uint32_t n : zones[z]) sum += node_sum[n];
    out[z] = sum / static_cast<double>(N);
  }
}

template <typename Pred>
void apply_boundary_stress(Continuum& c, const ZoneMesh& mesh, uint32_t first_node,
                           const ZoneStress& s, Pred on_edge) {
  for (const auto& e : boundary_edges(mesh)) {
    const uint32_t a = first_node + e[0], b = first_node + e[1];
    if (!on_edge(c.pos[a], c.pos[b])) continue;
    // Outward normal times length: the edge turned clockwise (domain on the left).
    const Vec2 d = c.pos[b] - c.pos[a];
    const Vec2 nl(d.y(), -d.x());
    const Vec2 t(s.xx * nl.x() + s.xy * nl.y(), s.xy * nl.x() + s.yy * nl.y());
    c.applied[a] += 0.5 * t, c.applied[b] += 0.5 * t;
  }
}

template <typename Pred>
void apply_boundary_stress(Continuum3& c, const ZoneMesh3& mesh, uint32_t first_node,
                           const ZoneStress& s, Pred on_face) {
  for (const auto& f : boundary_faces(mesh)) {
    const uint32_t a = first_node + f[0], b = first_node + f[1], d = first_node + f[2];
    if (!on_face(c.pos[a], c.pos[b], c.pos[d])) continue;
    // Outward normal times area, then the traction sigma . n, a third to each corner.
    const Vec3 n = 0.5 * (c.pos[b] - c.pos[a]).cross(c.pos[d] - c.pos[a]);
    const Vec3 t(s.xx * n.x() + s.xy * n.y() + s.xz * n.z(),
                 s.xy * n.x() + s.yy * n.y() + s.yz * n.z(),
                 s.xz * n.x() + s.yz * n.y() + s.zz * n.z());
    const Vec3 share = traction_shares({a, b, d}, c.edge_node);
    c.applied[a] += share[0] * t, c.applied[b] += share[1] * t, c.applied[d] += share[2] * t;
  }
}

}  // namespace tessera
