// Uniform-strain triangles and tetrahedra with nodal mixed discretization, and nodal central
// differences: one kernel, templated on the dimension.
#include "tessera/zones/continuum.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "quadratic_zones.hpp"

namespace tessera {

namespace {
// D! : the measure of a simplex is |det| / D!.
template <int D>
constexpr double kFactorial = D == 2 ? 2.0 : 6.0;

template <int D>
using VecD = typename ContinuumT<D>::Vec;

// A zone's shape-function gradients on `pos`, each times D! times its measure: in 2D the edge
// opposite each node turned outward, in 3D the rows of the Jacobian's adjugate.
// (p: the zone's corners in zone order.)
template <int D>
[[gnu::always_inline]] inline std::array<VecD<D>, D + 1> corner_gradients(
    const std::array<VecD<D>, D + 1>& p) {
  std::array<VecD<D>, D + 1> g;
  if constexpr (D == 2) {
    for (int k = 0; k < 3; ++k) {
      const Vec2& pj = p[(k + 1) % 3];
      const Vec2& pk = p[(k + 2) % 3];
      g[k] = Vec2(pj.y() - pk.y(), pk.x() - pj.x());
    }
  } else {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    g[1] = e2.cross(e3), g[2] = e3.cross(e1), g[3] = e1.cross(e2);
    g[0] = -(g[1] + g[2] + g[3]);
  }
  return g;
}
template <int D>
[[gnu::always_inline]] inline std::array<VecD<D>, D + 1> gradients(
    const std::vector<VecD<D>>& pos, const typename ContinuumT<D>::Zone& t) {
  std::array<VecD<D>, D + 1> p;
  for (int k = 0; k <= D; ++k) p[k] = pos[t[k]];
  return corner_gradients<D>(p);
}

// The measure (area, volume) of a zone with corners in `pos`.
template <int D>
[[gnu::always_inline]] inline double measure(const std::vector<VecD<D>>& pos,
                                             const typename ContinuumT<D>::Zone& t) {
  if constexpr (D == 2)
    return 0.5 * cross(pos[t[1]] - pos[t[0]], pos[t[2]] - pos[t[0]]);
  else
    return (pos[t[1]] - pos[t[0]]).cross(pos[t[2]] - pos[t[0]]).dot(pos[t[3]] - pos[t[0]]) / 6.0;
}

// The symmetric part of sum_k u_k g_k^T times `f`, as a strain (tensor shears), and its
// antisymmetric part, the spin.
template <int D>
[[gnu::always_inline]] inline StrainIncrement symmetric_gradient(
    const std::array<VecD<D>, D + 1>& u, const std::array<VecD<D>, D + 1>& g, double f,
    Spin& spin) {
  Eigen::Matrix<double, D, D> l = Eigen::Matrix<double, D, D>::Zero();
  for (int k = 0; k <= D; ++k)
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) l(i, j) += u[k][i] * g[k][j];
  StrainIncrement e{l(0, 0) * f, l(1, 1) * f, 0.5 * (l(0, 1) + l(1, 0)) * f};
  spin.xy = 0.5 * (l(0, 1) - l(1, 0)) * f;
  if constexpr (D == 3) {
    e.zz = l(2, 2) * f, e.yz = 0.5 * (l(1, 2) + l(2, 1)) * f;
    e.xz = 0.5 * (l(0, 2) + l(2, 0)) * f;
    spin.yz = 0.5 * (l(1, 2) - l(2, 1)) * f, spin.xz = 0.5 * (l(0, 2) - l(2, 0)) * f;
  }
  return e;
}

template <int D>
double trace(const StrainIncrement& e) {
  return D == 2 ? e.xx + e.yy : e.xx + e.yy + e.zz;
}
template <int D>
double trace(const ZoneStress& s) {
  return D == 2 ? s.xx + s.yy : s.xx + s.yy + s.zz;
}

// The zone's own values of `v` (node velocities or displacements) gathered in zone order.
template <int D>
[[gnu::always_inline]] inline std::array<VecD<D>, D + 1> gather(
    const std::vector<VecD<D>>& v, const typename ContinuumT<D>::Zone& t,
    const std::vector<VecD<D>>* minus = nullptr) {
  std::array<VecD<D>, D + 1> out;
  for (int k = 0; k <= D; ++k) {
    out[k] = v[t[k]];
    if (minus) out[k] -= (*minus)[t[k]];
  }
  return out;
}
}  // namespace

uint32_t add_mesh(Continuum& c, const ZoneMesh& mesh, uint32_t material) {
  const auto first = static_cast<uint32_t>(c.pos.size());
  for (const Vec2& p : mesh.nodes) {
    c.pos.push_back(p), c.pos0.push_back(p);
    c.vel.emplace_back(0, 0), c.force.emplace_back(0, 0), c.applied.emplace_back(0, 0);
    c.mass.push_back(0), c.inertia.push_back(0), c.fixity.push_back(0);
    c.fixed_vel.emplace_back(0, 0);
  }
  for (const auto& t : mesh.triangles) {
    c.zones.push_back({first + t[0], first + t[1], first + t[2]});
    c.stress.emplace_back(), c.state.push_back(0), c.plastic.push_back(0);
    c.material.push_back(material);
  }
  return first;
}

uint32_t add_mesh(Continuum3& c, const ZoneMesh3& mesh, uint32_t material) {
  const auto first = static_cast<uint32_t>(c.pos.size());
  for (const Vec3& p : mesh.nodes) {
    c.pos.push_back(p), c.pos0.push_back(p);
    c.vel.push_back(Vec3::Zero()), c.force.push_back(Vec3::Zero());
    c.applied.push_back(Vec3::Zero()), c.fixed_vel.push_back(Vec3::Zero());
    c.mass.push_back(0), c.inertia.push_back(0), c.fixity.push_back(0);
  }
  const size_t before = c.zones.size();
  for (const auto& t : mesh.tets) {
    c.zones.push_back({first + t[0], first + t[1], first + t[2], first + t[3]});
    c.stress.emplace_back(), c.state.push_back(0), c.plastic.push_back(0);
    c.material.push_back(material);
  }
  // Quadratic zones: their mid-edge nodes (and every zone an entry once any zone has them).
  if (!mesh.mid.empty() || !c.mid.empty()) {
    std::array<uint32_t, 6> none;
    none.fill(Continuum3::kNoMid);
    c.mid.resize(before, none);
    for (size_t z = 0; z < mesh.tets.size(); ++z) {
      std::array<uint32_t, 6> m = none;
      if (!mesh.mid.empty())
        for (int k = 0; k < 6; ++k) m[k] = first + mesh.mid[z][k];
      c.mid.push_back(m);
    }
    c.gp_stress.resize(c.zones.size()), c.gp_state.resize(c.zones.size());
    c.gp_plastic.resize(c.zones.size());
    c.edge_node.resize(c.node_count(), 0);
    for (const auto& m : mesh.mid)
      for (uint32_t n : m) c.edge_node[first + n] = 1;
  }
  return first;
}

void set_zone_stress(Continuum3& c, size_t z, const ZoneStress& s, uint8_t state) {
  c.stress[z] = s, c.state[z] = state;
  if (c.quadratic(z)) c.gp_stress[z].fill(s), c.gp_state[z].fill(state);
}

void set_zone_stress(Continuum& c, size_t z, const ZoneStress& s, uint8_t state) {
  c.stress[z] = s, c.state[z] = state;
}

template <int D>
StrainIncrement total_strain(const ContinuumT<D>& c, size_t z) {
  if constexpr (D == 3)
    if (c.quadratic(z)) return quadratic_total_strain(c, z);
  const auto& t = c.zones[z];
  const double scaled = kFactorial<D> * measure<D>(c.pos0, t);
  Spin turned;  // (not reported)
  StrainIncrement e =
      symmetric_gradient<D>(gather<D>(c.pos, t, &c.pos0), gradients<D>(c.pos0, t), 1.0, turned);
  e.xx /= scaled, e.yy /= scaled, e.xy /= scaled, e.zz /= scaled, e.yz /= scaled, e.xz /= scaled;
  return e;
}

void principal_stresses(const ZoneStress& s, double& s1, double& s3) {
  if (s.yz != 0 || s.xz != 0) {
    const Principal p = principal_3d(s);
    s1 = p.s[0], s3 = p.s[2];
    return;
  }
  double a = 0, b = 0, angle = 0;
  principal_2d(s, a, b, angle);
  s1 = std::min(a, s.zz), s3 = std::max(b, s.zz);
}

template <int D>
double zone_volume(const ContinuumT<D>& c, size_t z) {
  return measure<D>(c.pos, c.zones[z]);
}

template <int D>
void lump_masses(ContinuumT<D>& c) {
  std::fill(c.mass.begin(), c.mass.end(), 0.0);
  for (size_t z = 0; z < c.zones.size(); ++z) {
    const ZoneProperties& p = c.materials[c.material[z]];
    if (!p.impl->solid()) continue;
    const double m = p.density * zone_volume(c, z);
    if constexpr (D == 3)
      if (c.quadratic(z)) {
        for (uint32_t n : c.zones[z]) c.mass[n] += kCornerMass * m;
        for (uint32_t n : c.mid[z]) c.mass[n] += kMidMass * m;
        continue;
      }
    for (uint32_t n : c.zones[z]) c.mass[n] += m / (D + 1.0);
  }
  c.inertia = c.mass;
}

template <int D>
double zone_timestep(const ContinuumT<D>& c, size_t z) {
  const ZoneProperties& p = c.materials[c.material[z]];
  if (!p.impl->solid()) return 1e300;
  if constexpr (D == 3)
    if (c.quadratic(z)) return quadratic_zone_step(c, z);
  const auto& t = c.zones[z];
  // The smallest height: D times the measure over the largest facet (edge, face).
  double largest = 0;
  if constexpr (D == 2) {
    for (int k = 0; k < 3; ++k)
      largest = std::max(largest, (c.pos[t[(k + 1) % 3]] - c.pos[t[k]]).norm());
  } else {
    for (int k = 0; k < 4; ++k) {
      const Vec3& a = c.pos[t[(k + 1) % 4]];
      const Vec3& b = c.pos[t[(k + 2) % 4]];
      const Vec3& d = c.pos[t[(k + 3) % 4]];
      largest = std::max(largest, 0.5 * (b - a).cross(d - a).norm());
    }
  }
  const double height = D * zone_volume(c, z) / largest;
  return height / std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.density);
}

template <int D>
std::vector<double> node_steps(const ContinuumT<D>& c) {
  std::vector<double> dt(c.node_count(), 1e300), rows;
  for (size_t z = 0; z < c.zone_count(); ++z) {
    if constexpr (D == 3)
      if (c.quadratic(z)) {
        // Summed at the nodes: Gershgorin's bound on the assembled mesh (a zone's own bound is
        // ruled by its worst shape; in a CGAL mesh it is three times too short).
        if (rows.empty()) rows.assign(c.node_count(), 0.0);
        const std::array<double, 10> r = quadratic_row_sums(c, z);
        const std::array<uint32_t, 10> nodes = quadratic_nodes(c, z);
        for (int k = 0; k < 10; ++k) rows[nodes[k]] += r[k];
        continue;
      }
    const double s = zone_timestep(c, z);
    for (uint32_t n : c.zones[z]) dt[n] = std::min(dt[n], s);
  }
  for (size_t n = 0; n < rows.size(); ++n)
    if (rows[n] > 0 && c.mass[n] > 0) dt[n] = std::min(dt[n], 2.0 * std::sqrt(c.mass[n] / rows[n]));
  return dt;
}

template <int D>
double critical_timestep(const ContinuumT<D>& c, double safety) {
  const std::vector<double> steps = node_steps(c);
  const double dt = steps.empty() ? 1e300 : *std::min_element(steps.begin(), steps.end());
  return safety * dt;
}

template <int D>
void initialize_stress(ContinuumT<D>& c, const ZoneStress& s0, const ZoneStress& g, double v0) {
  for (size_t z = 0; z < c.zones.size(); ++z) {
    if (!c.materials[c.material[z]].impl->solid()) continue;
    const auto& t = c.zones[z];
    const auto at = [&](double height) {
      const double dv = height - v0;
      return ZoneStress{s0.xx + g.xx * dv, s0.yy + g.yy * dv, s0.xy + g.xy * dv,
                        s0.zz + g.zz * dv, s0.yz + g.yz * dv, s0.xz + g.xz * dv};
    };
    double h = 0;
    for (uint32_t n : t) h += c.pos[n][D - 1];
    c.stress[z] = at(h / (D + 1.0));
    // A quadratic zone's integration points each at their own height.
    if constexpr (D == 3)
      if (c.quadratic(z))
        for (int p = 0; p < 4; ++p) {
          double hp = 0;
          for (int k = 0; k < 4; ++k) hp += gauss_coordinate(p, k) * c.pos[t[k]].z();
          c.gp_stress[z][p] = at(hp);
        }
  }
}

std::vector<std::array<uint32_t, 2>> boundary_edges(const ZoneMesh& mesh) {
  // An edge used by one triangle only is on the outline; it runs with the domain on its left.
  std::map<std::pair<uint32_t, uint32_t>, int> count;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<uint32_t, 2>> out;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      if (count[{std::min(a, b), std::max(a, b)}] == 1) out.push_back({a, b});
    }
  return out;
}

std::vector<std::array<uint32_t, 3>> boundary_faces(const ZoneMesh3& mesh) {
  // A face used by one tetrahedron only is on the surface (listed facing out, in zone order).
  const OpenFaces open = open_faces(mesh);
  // A quadratic zone's mid-edge node between two of its corners.
  const auto mid = [&](size_t z, int i, int j) {
    for (int e = 0; e < 6; ++e)
      if ((kTetEdge[e][0] == i && kTetEdge[e][1] == j) ||
          (kTetEdge[e][0] == j && kTetEdge[e][1] == i))
        return mesh.mid[z][e];
    return 0u;
  };
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t z = 0; z < mesh.tets.size(); ++z) {
    const auto& t = mesh.tets[z];
    for (int k = 0; k < 4; ++k) {
      const int* f = kTetFace[k];
      const std::array<uint32_t, 3> face{t[f[0]], t[f[1]], t[f[2]]};
      if (!open.count(face_key(mesh, z, k))) continue;
      if (mesh.mid.empty()) {
        out.push_back(face);
        continue;
      }
      // Four plane triangles: one at each corner, then the middle one.
      const uint32_t m01 = mid(z, f[0], f[1]), m12 = mid(z, f[1], f[2]), m20 = mid(z, f[2], f[0]);
      out.push_back({face[0], m01, m20}), out.push_back({m01, face[1], m12});
      out.push_back({m20, m12, face[2]}), out.push_back({m01, m12, m20});
    }
  }
  return out;
}

template <int D>
void continuum_cycle(ContinuumT<D>& c) {
  zone_forces(c);
  move_nodes(c);
}

template <int D>
void zone_forces(ContinuumT<D>& c) {
  const size_t nn = c.pos.size(), nz = c.zones.size();
  ZoneScratch& w = c.scratch;
  w.scale.assign(nn, 0.0);
  for (size_t n = 0; n < nn; ++n) {
    c.force[n] = c.applied[n] + c.mass[n] * c.gravity;
    w.scale[n] = c.applied[n].norm() + c.mass[n] * c.gravity.norm();
  }
  w.de.resize(nz), w.spin.resize(nz), w.volume.resize(nz), w.ev.resize(nz), w.ev_mixed.resize(nz);
  w.dp.resize(nz), w.dp_mixed.resize(nz), w.node_sum.resize(nn), w.node_weight.resize(nn);
  w.linear.assign(nz, 0);
  // Zones: strain increment from the nodal velocities (uniform gradient of the linear field).
  for (size_t z = 0; z < nz; ++z) {
    const ZoneProperties& p = c.materials[c.material[z]];
    if (!p.impl->solid()) {
      w.volume[z] = 0, w.ev[z] = 0;
      continue;
    }
    // A quadratic zone's whole stage at its integration points (no mixed discretization: zero
    // volume keeps it out of the averages).
    if constexpr (D == 3)
      if (c.quadratic(z)) {
        quadratic_zone_forces(c, z, w.scale);
        w.volume[z] = 0, w.ev[z] = 0;
        continue;
      }
    const auto& t = c.zones[z];
    // The velocities that brought the nodes here, over the zone halfway along that step (on
    // the shape at its end, a turn would read as a stretch of the angle times the step's turn).
    const std::array<VecD<D>, D + 1> v = gather<D>(c.vel, t);
    std::array<VecD<D>, D + 1> mid = gather<D>(c.pos, t);
    for (int k = 0; k <= D; ++k) mid[k] -= 0.5 * c.dt * v[k];
    const std::array<VecD<D>, D + 1> g = corner_gradients<D>(mid);
    // D! times the measure there (3D: the adjugate's row times its edge is the determinant);
    // it also weighs the zone in the nodal averages.
    double scaled;
    if constexpr (D == 2)
      scaled = cross(Vec2(mid[1] - mid[0]), Vec2(mid[2] - mid[0]));
    else
      scaled = g[1].dot(mid[1] - mid[0]);
    w.de[z] = symmetric_gradient<D>(v, g, c.dt / scaled, w.spin[z]);
    w.volume[z] = scaled / kFactorial<D>, w.ev[z] = trace<D>(w.de[z]);
    w.linear[z] = 1;
  }
  // Nodal mixed discretization of the strain: volumetric increments averaged at the nodes.
  const bool mixed = c.nodal_mixed;
  if (mixed)
    nodal_average<D + 1>(c.zones, w.volume, w.ev, nn, w.node_sum, w.node_weight, w.ev_mixed);
  // Zones: the constitutive update on the zone's own deviatoric and the mixed volumetric
  // increment (2D: plane strain keeps dezz = 0); a yielding zone's plastic correction of the
  // isotropic stress (of the plane in 2D) is what it changed beyond the elastic part of the
  // volumetric increment: (K + G/3) de_vol for a triangle's in-plane mean, K de_vol in 3D.
  bool plastic = false;
  for (size_t z = 0; z < nz; ++z) {
    w.dp[z] = 0;
    if (!w.linear[z]) continue;
    const ZoneProperties& p = c.materials[c.material[z]];
    StrainIncrement de = w.de[z];
    if (mixed) {
      const double d = (w.ev_mixed[z] - w.ev[z]) / D;
      de.xx += d, de.yy += d;
      if constexpr (D == 3) de.zz += d;
    }
    ZoneStress& s = c.stress[z];
    if constexpr (D == 2)
      rotate_plane_stress(s, w.spin[z].xy);
    else
      rotate_stress(s, w.spin[z]);
    const double before = trace<D>(s);
    p.impl->update(p, de, s, c.state[z], c.plastic[z]);
    if (mixed && (c.state[z] & (kShearNow | kTensionNow))) {
      const double k_iso = D == 2 ? p.bulk + p.shear / 3.0 : p.bulk;
      w.dp[z] = (trace<D>(s) - before) / D - k_iso * trace<D>(de);
      plastic = true;
    }
  }
  // Nodal mixed discretization of the stress: the plastic isotropic corrections averaged the
  // same way, so that dilatant flow leaves no zone-by-zone pressure for the mixed strain to miss.
  if (plastic)
    nodal_average<D + 1>(c.zones, w.volume, w.dp, nn, w.node_sum, w.node_weight, w.dp_mixed);
  // Zones: the stress as nodal forces f_i = -V sigma grad N_i.
  for (size_t z = 0; z < nz; ++z) {
    if (!w.linear[z]) continue;
    const auto& t = c.zones[z];
    ZoneStress& s = c.stress[z];
    if (plastic) {
      const double d = w.dp_mixed[z] - w.dp[z];
      s.xx += d, s.yy += d;
      if constexpr (D == 3) s.zz += d;
    }
    const std::array<VecD<D>, D + 1> grad = gradients<D>(c.pos, t);
    for (int k = 0; k <= D; ++k) {
      const VecD<D>& g = grad[k];
      VecD<D> fz;
      if constexpr (D == 2)
        fz = 0.5 * Vec2(s.xx * g.x() + s.xy * g.y(), s.xy * g.x() + s.yy * g.y());
      else
        fz = Vec3(s.xx * g.x() + s.xy * g.y() + s.xz * g.z(),
                  s.xy * g.x() + s.yy * g.y() + s.yz * g.z(),
                  s.xz * g.x() + s.yz * g.y() + s.zz * g.z()) /
             6.0;
      c.force[t[k]] -= fz;
      w.scale[t[k]] += fz.norm();
    }
  }
}

template <int D>
void add_node_force(ContinuumT<D>& c, size_t n, const typename ContinuumT<D>::Vec& f) {
  c.force[n] += f;
  c.scratch.scale[n] += f.norm();
}

template <int D>
double move_nodes(ContinuumT<D>& c) {
  const size_t nn = c.pos.size();
  std::vector<double>& scale = c.scratch.scale;
  if (scale.size() != nn) scale.assign(nn, 0.0);
  // Motion: local damping against the unbalanced force, fixed components held.
  double max_move = 0;
  double max_unbalanced = 0, sum_applied = 0;
  size_t free_nodes = 0;
  for (size_t n = 0; n < nn; ++n) {
    if (c.mass[n] <= 0) continue;
    VecD<D> f = c.force[n];
    for (int k = 0; k < D; ++k) {
      if (c.fixity[n] & node_fix_bit(k)) {
        c.vel[n][k] = c.fixed_vel[n][k];
        continue;
      }
      max_unbalanced = std::max(max_unbalanced, std::abs(f[k]));
      const double v = c.vel[n][k];
      f[k] -= c.local_damping * std::abs(f[k]) * (v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0);
      c.vel[n][k] = v + c.dt * f[k] / c.inertia[n];
    }
    sum_applied += scale[n];
    ++free_nodes;
    c.pos[n] += c.dt * c.vel[n];
    max_move = std::max(max_move, c.dt * c.vel[n].norm());
  }
  c.ratio = free_nodes && sum_applied > 0
                ? max_unbalanced / (sum_applied / static_cast<double>(free_nodes))
                : 0.0;
  c.time += c.dt;
  ++c.cycle;
  return max_move;
}

// The kernel in both dimensions.
#define TESSERA_CONTINUUM(D)                                                                     \
  template StrainIncrement total_strain(const ContinuumT<D>&, size_t);                           \
  template double zone_volume(const ContinuumT<D>&, size_t);                                     \
  template void lump_masses(ContinuumT<D>&);                                                     \
  template double zone_timestep(const ContinuumT<D>&, size_t);                                   \
  template double critical_timestep(const ContinuumT<D>&, double);                               \
  template std::vector<double> node_steps(const ContinuumT<D>&);                                 \
  template void initialize_stress(ContinuumT<D>&, const ZoneStress&, const ZoneStress&, double); \
  template void continuum_cycle(ContinuumT<D>&);                                                 \
  template void zone_forces(ContinuumT<D>&);                                                     \
  template void add_node_force(ContinuumT<D>&, size_t, const ContinuumT<D>::Vec&);               \
  template double move_nodes(ContinuumT<D>&);
TESSERA_CONTINUUM(2)
TESSERA_CONTINUUM(3)
#undef TESSERA_CONTINUUM

}  // namespace tessera
