// Uniform-strain triangles with nodal mixed discretization, and nodal central differences.
#include "tessera/zones/continuum.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "tessera/contact2d/blocks.hpp"

namespace tessera {

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
    c.stress.emplace_back(), c.state.push_back(0), c.material.push_back(material);
  }
  return first;
}

void zone_strain(const Continuum& c, size_t z, double& exx, double& eyy, double& exy) {
  const auto& t = c.zones[z];
  const double a2 = cross(c.pos0[t[1]] - c.pos0[t[0]], c.pos0[t[2]] - c.pos0[t[0]]);
  double ux_x = 0, ux_y = 0, uy_x = 0, uy_y = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec2& pj = c.pos0[t[(k + 1) % 3]];
    const Vec2& pk = c.pos0[t[(k + 2) % 3]];
    const Vec2 u = c.pos[t[k]] - c.pos0[t[k]];
    const double bx = pj.y() - pk.y(), by = pk.x() - pj.x();
    ux_x += u.x() * bx, ux_y += u.x() * by, uy_x += u.y() * bx, uy_y += u.y() * by;
  }
  exx = ux_x / a2, eyy = uy_y / a2, exy = 0.5 * (ux_y + uy_x) / a2;
}

void principal_stresses(const ZoneStress& s, double& s1, double& s3) {
  double a = 0, b = 0, angle = 0;
  principal_2d(s, a, b, angle);
  s1 = std::min(a, s.zz), s3 = std::max(b, s.zz);
}

double zone_area(const Continuum& c, size_t z) {
  const auto& t = c.zones[z];
  return 0.5 * cross(c.pos[t[1]] - c.pos[t[0]], c.pos[t[2]] - c.pos[t[0]]);
}

void lump_masses(Continuum& c) {
  std::fill(c.mass.begin(), c.mass.end(), 0.0);
  for (size_t z = 0; z < c.zones.size(); ++z) {
    const ZoneProperties& p = c.materials[c.material[z]];
    if (!p.impl->solid()) continue;
    const double m = p.density * zone_area(c, z) / 3.0;
    for (uint32_t n : c.zones[z]) c.mass[n] += m;
  }
  c.inertia = c.mass;
}

double zone_timestep(const Continuum& c, size_t z) {
  const ZoneProperties& p = c.materials[c.material[z]];
  if (!p.impl->solid()) return 1e300;
  const auto& t = c.zones[z];
  double longest = 0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, (c.pos[t[(k + 1) % 3]] - c.pos[t[k]]).norm());
  const double height = 2.0 * zone_area(c, z) / longest;
  return height / std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.density);
}

double critical_timestep(const Continuum& c, double safety) {
  double dt = 1e300;
  for (size_t z = 0; z < c.zones.size(); ++z) dt = std::min(dt, zone_timestep(c, z));
  return safety * dt;
}

void initialize_stress(Continuum& c, const ZoneStress& s0, const ZoneStress& g, double y0) {
  for (size_t z = 0; z < c.zones.size(); ++z) {
    if (!c.materials[c.material[z]].impl->solid()) continue;
    const auto& t = c.zones[z];
    const double dy = (c.pos[t[0]].y() + c.pos[t[1]].y() + c.pos[t[2]].y()) / 3.0 - y0;
    c.stress[z] = {s0.xx + g.xx * dy, s0.yy + g.yy * dy, s0.xy + g.xy * dy, s0.zz + g.zz * dy};
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

namespace {
// The size of the forces meeting at each node, for the unbalanced-force ratio.
thread_local std::vector<double> scale;
// Scratch of the nodal mixed discretization, per zone: strain increment, area, in-plane
// volumetric increment, isotropic part of the plastic correction, and their nodal averages;
// per node: weighted sums and weights.
thread_local std::vector<StrainIncrement> zone_de;
thread_local std::vector<double> zone_area_now, zone_ev, zone_ev_mixed, zone_dp, zone_dp_mixed;
thread_local std::vector<double> node_sum, node_weight;

// A zone's shape-function gradients on the current shape, each times twice the area.
std::array<Vec2, 3> zone_gradients(const Continuum& c, const std::array<uint32_t, 3>& t) {
  std::array<Vec2, 3> grad;
  for (int k = 0; k < 3; ++k) {
    const Vec2& pj = c.pos[t[(k + 1) % 3]];
    const Vec2& pk = c.pos[t[(k + 2) % 3]];
    grad[k] = Vec2(pj.y() - pk.y(), pk.x() - pj.x());
  }
  return grad;
}
}  // namespace

void continuum_cycle(Continuum& c) {
  zone_forces(c);
  move_nodes(c);
}

void zone_forces(Continuum& c) {
  const size_t nn = c.pos.size(), nz = c.zones.size();
  scale.assign(nn, 0.0);
  for (size_t n = 0; n < nn; ++n) {
    c.force[n] = c.applied[n] + c.mass[n] * c.gravity;
    scale[n] = c.applied[n].norm() + c.mass[n] * c.gravity.norm();
  }
  zone_de.resize(nz), zone_area_now.resize(nz), zone_ev.resize(nz), zone_ev_mixed.resize(nz);
  zone_dp.resize(nz), zone_dp_mixed.resize(nz), node_sum.resize(nn), node_weight.resize(nn);
  // Zones: strain increment from the nodal velocities (uniform gradient of the linear field).
  for (size_t z = 0; z < nz; ++z) {
    const ZoneProperties& p = c.materials[c.material[z]];
    if (!p.impl->solid()) {
      zone_area_now[z] = 0, zone_ev[z] = 0;
      continue;
    }
    const auto& t = c.zones[z];
    const double a2 = 2.0 * zone_area(c, z);
    const std::array<Vec2, 3> grad = zone_gradients(c, t);
    double dvx_dx = 0, dvx_dy = 0, dvy_dx = 0, dvy_dy = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec2& v = c.vel[t[k]];
      dvx_dx += v.x() * grad[k].x(), dvx_dy += v.x() * grad[k].y();
      dvy_dx += v.y() * grad[k].x(), dvy_dy += v.y() * grad[k].y();
    }
    const double f = c.dt / a2;
    zone_de[z] = {dvx_dx * f, dvy_dy * f, 0.5 * (dvx_dy + dvy_dx) * f};
    zone_area_now[z] = 0.5 * a2, zone_ev[z] = zone_de[z].xx + zone_de[z].yy;
  }
  // Nodal mixed discretization of the strain: volumetric increments averaged at the nodes.
  const bool mixed = c.nodal_mixed;
  if (mixed)
    nodal_average<3>(c.zones, zone_area_now, zone_ev, nn, node_sum, node_weight, zone_ev_mixed);
  // Zones: the constitutive update on the zone's own deviatoric and the mixed volumetric
  // increment (in the plane: plane strain keeps dezz = 0); a yielding zone's plastic correction
  // of the in-plane isotropic stress is what it changed beyond the elastic (K + G/3) de_vol
  // (for tetrahedra: the mean stress beyond K de_vol).
  bool plastic = false;
  for (size_t z = 0; z < nz; ++z) {
    const ZoneProperties& p = c.materials[c.material[z]];
    zone_dp[z] = 0;
    if (!p.impl->solid()) continue;
    StrainIncrement de = zone_de[z];
    if (mixed) {
      const double d = 0.5 * (zone_ev_mixed[z] - zone_ev[z]);
      de.xx += d, de.yy += d;
    }
    ZoneStress& s = c.stress[z];
    const double before = s.xx + s.yy;
    p.impl->update(p, de, s, c.state[z]);
    if (mixed && (c.state[z] & (kShearNow | kTensionNow))) {
      zone_dp[z] = 0.5 * (s.xx + s.yy - before) - (p.bulk + p.shear / 3.0) * (de.xx + de.yy);
      plastic = true;
    }
  }
  // Nodal mixed discretization of the stress: the plastic isotropic corrections averaged the
  // same way, so that dilatant flow leaves no zone-by-zone pressure for the mixed strain to miss.
  if (plastic)
    nodal_average<3>(c.zones, zone_area_now, zone_dp, nn, node_sum, node_weight, zone_dp_mixed);
  // Zones: the stress as nodal forces f_i = -A sigma grad N_i.
  for (size_t z = 0; z < nz; ++z) {
    if (!c.materials[c.material[z]].impl->solid()) continue;
    const auto& t = c.zones[z];
    ZoneStress& s = c.stress[z];
    if (plastic) {
      const double d = zone_dp_mixed[z] - zone_dp[z];
      s.xx += d, s.yy += d;
    }
    const std::array<Vec2, 3> grad = zone_gradients(c, t);
    for (int k = 0; k < 3; ++k) {
      const Vec2& g = grad[k];
      const Vec2 fz = 0.5 * Vec2(s.xx * g.x() + s.xy * g.y(), s.xy * g.x() + s.yy * g.y());
      c.force[t[k]] -= fz;
      scale[t[k]] += fz.norm();
    }
  }
}

void add_node_force(Continuum& c, size_t n, const Vec2& f) {
  c.force[n] += f;
  scale[n] += f.norm();
}

double move_nodes(Continuum& c) {
  const size_t nn = c.pos.size();
  if (scale.size() != nn) scale.assign(nn, 0.0);
  // Motion: local damping against the unbalanced force, fixed components held.
  double max_move = 0;
  double max_unbalanced = 0, sum_applied = 0;
  size_t free_nodes = 0;
  for (size_t n = 0; n < nn; ++n) {
    if (c.mass[n] <= 0) continue;
    Vec2 f = c.force[n];
    for (int k = 0; k < 2; ++k) {
      const uint8_t bit = k == 0 ? kFixX : kFixY;
      if (c.fixity[n] & bit) {
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

}  // namespace tessera
