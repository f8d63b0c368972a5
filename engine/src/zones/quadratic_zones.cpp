// Quadratic (10-node) tetrahedra: four integration points, straight edges, lumped masses.
#include "quadratic_zones.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace tessera {

namespace {
// Gauss's four points for a tetrahedron (exact for quadratics), each of weight 1/4.
constexpr double kGaussA = 0.5854101966249685, kGaussB = 0.1381966011250105;

// sum_k u_k g_k^T, symmetrised, times f (tensor shears); with spin, its antisymmetric part.
StrainIncrement strain_of(const std::array<Vec3, 10>& u, const std::array<Vec3, 10>& g, double f,
                          Spin* spin = nullptr) {
  // Plain sums in node order: Eigen's outer products gave the same sums, but took half of a
  // 10-node model's run under the sanitizers.
  double l[3][3] = {};
  for (int k = 0; k < 10; ++k) {
    const double *a = u[k].data(), *b = g[k].data();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) l[i][j] += b[j] * a[i];
  }
  if (spin) {
    spin->xy = 0.5 * (l[0][1] - l[1][0]) * f, spin->yz = 0.5 * (l[1][2] - l[2][1]) * f;
    spin->xz = 0.5 * (l[0][2] - l[2][0]) * f;
  }
  return {l[0][0] * f,
          l[1][1] * f,
          0.5 * (l[0][1] + l[1][0]) * f,
          l[2][2] * f,
          0.5 * (l[1][2] + l[2][1]) * f,
          0.5 * (l[0][2] + l[2][0]) * f};
}

std::array<Vec3, 4> corners_of(const std::vector<Vec3>& pos, const Continuum3::Zone& t) {
  return {pos[t[0]], pos[t[1]], pos[t[2]], pos[t[3]]};
}
}  // namespace

double gauss_coordinate(int point, int corner) {
  return point == corner ? kGaussA : kGaussB;
}

std::array<Vec3, 4> volume_gradients(const std::array<Vec3, 4>& x, double& volume) {
  const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0], e3 = x[3] - x[0];
  const double six_v = e1.cross(e2).dot(e3);
  std::array<Vec3, 4> dl;
  dl[1] = e2.cross(e3) / six_v, dl[2] = e3.cross(e1) / six_v, dl[3] = e1.cross(e2) / six_v;
  dl[0] = -(dl[1] + dl[2] + dl[3]);
  volume = six_v / 6.0;
  return dl;
}

std::array<Vec3, 10> quadratic_gradients(const std::array<Vec3, 4>& dl, int point) {
  // Corners N = L (2L - 1); mid-edge nodes N = 4 Li Lj.
  std::array<Vec3, 10> g;
  for (int k = 0; k < 4; ++k) g[k] = (4.0 * gauss_coordinate(point, k) - 1.0) * dl[k];
  for (int e = 0; e < 6; ++e) {
    const int i = kTetEdge[e][0], j = kTetEdge[e][1];
    g[4 + e] = 4.0 * (gauss_coordinate(point, i) * dl[j] + gauss_coordinate(point, j) * dl[i]);
  }
  return g;
}

std::array<uint32_t, 10> quadratic_nodes(const Continuum3& c, size_t z) {
  std::array<uint32_t, 10> n;
  for (int k = 0; k < 4; ++k) n[k] = c.zones[z][k];
  for (int k = 0; k < 6; ++k) n[4 + k] = c.mid[z][k];
  return n;
}

void quadratic_zone_forces(Continuum3& c, size_t z, std::vector<double>& scale) {
  const ZoneProperties& p = c.materials[c.material[z]];
  const std::array<uint32_t, 10> nodes = quadratic_nodes(c, z);
  double volume = 0;
  const std::array<Vec3, 4> dl = volume_gradients(corners_of(c.pos, c.zones[z]), volume);
  std::array<Vec3, 10> v;
  for (int k = 0; k < 10; ++k) v[k] = c.vel[nodes[k]];
  // The strain over the zone halfway along the step that brought its nodes here (as a linear
  // zone's: on the shape at its end a turn would read as a stretch).
  std::array<Vec3, 4> mid = corners_of(c.pos, c.zones[z]);
  for (int k = 0; k < 4; ++k) mid[k] -= 0.5 * c.dt * c.vel[c.zones[z][static_cast<size_t>(k)]];
  double mid_volume = 0;
  const std::array<Vec3, 4> dl_mid = volume_gradients(mid, mid_volume);
  ZoneStress mean;
  uint8_t state = 0;
  double plastic = 0;
  for (int g = 0; g < 4; ++g) {
    const std::array<Vec3, 10> grad = quadratic_gradients(dl, g);
    // The law at the point, on its strain increment.
    ZoneStress& s = c.gp_stress[z][g];
    Spin spin;
    const StrainIncrement de = strain_of(v, quadratic_gradients(dl_mid, g), c.dt, &spin);
    rotate_stress(s, spin);
    p.impl->update(p, de, s, c.gp_state[z][g], c.gp_plastic[z][g]);
    state |= c.gp_state[z][g], plastic += c.gp_plastic[z][g] / 4;
    mean.xx += s.xx / 4, mean.yy += s.yy / 4, mean.zz += s.zz / 4;
    mean.xy += s.xy / 4, mean.yz += s.yz / 4, mean.xz += s.xz / 4;
    // Its share of the nodal forces, f_k = -(V / 4) sigma grad N_k.
    for (int k = 0; k < 10; ++k) {
      const Vec3& gk = grad[k];
      const Vec3 f = (0.25 * volume) * Vec3(s.xx * gk.x() + s.xy * gk.y() + s.xz * gk.z(),
                                            s.xy * gk.x() + s.yy * gk.y() + s.yz * gk.z(),
                                            s.xz * gk.x() + s.yz * gk.y() + s.zz * gk.z());
      c.force[nodes[k]] -= f;
      scale[nodes[k]] += f.norm();
    }
  }
  c.stress[z] = mean, c.state[z] = state, c.plastic[z] = plastic;
}

StrainIncrement quadratic_total_strain(const Continuum3& c, size_t z) {
  const std::array<uint32_t, 10> nodes = quadratic_nodes(c, z);
  double volume = 0;
  const std::array<Vec3, 4> dl = volume_gradients(corners_of(c.pos0, c.zones[z]), volume);
  std::array<Vec3, 10> u;
  for (int k = 0; k < 10; ++k) u[k] = c.pos[nodes[k]] - c.pos0[nodes[k]];
  StrainIncrement e;
  for (int g = 0; g < 4; ++g) {
    const StrainIncrement eg = strain_of(u, quadratic_gradients(dl, g), 0.25);
    e.xx += eg.xx, e.yy += eg.yy, e.zz += eg.zz, e.xy += eg.xy, e.yz += eg.yz, e.xz += eg.xz;
  }
  return e;
}

namespace {
// The zone's elastic stiffness matrix (30 x 30: x, y, z of each node) and its volume.
Eigen::Matrix<double, 30, 30> stiffness(const Continuum3& c, size_t z, double& volume) {
  const ZoneProperties& p = c.materials[c.material[z]];
  // Elastic moduli (Voigt, engineering shears).
  const double lambda = p.bulk - 2.0 * p.shear / 3.0;
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) d(i, i) = lambda + 2.0 * p.shear, d(3 + i, 3 + i) = p.shear;
  const std::array<Vec3, 4> dl = volume_gradients(corners_of(c.pos, c.zones[z]), volume);
  Eigen::Matrix<double, 30, 30> k = Eigen::Matrix<double, 30, 30>::Zero();
  for (int g = 0; g < 4; ++g) {
    const std::array<Vec3, 10> grad = quadratic_gradients(dl, g);
    Eigen::Matrix<double, 6, 30> b = Eigen::Matrix<double, 6, 30>::Zero();
    for (int n = 0; n < 10; ++n) {
      const Vec3& gn = grad[n];
      b(0, 3 * n) = gn.x(), b(1, 3 * n + 1) = gn.y(), b(2, 3 * n + 2) = gn.z();
      b(3, 3 * n) = gn.y(), b(3, 3 * n + 1) = gn.x();
      b(4, 3 * n + 1) = gn.z(), b(4, 3 * n + 2) = gn.y();
      b(5, 3 * n) = gn.z(), b(5, 3 * n + 2) = gn.x();
    }
    k += (0.25 * volume) * b.transpose() * d * b;
  }
  return k;
}

double node_mass(int n) {
  return n < 4 ? kCornerMass : kMidMass;
}
}  // namespace

std::array<double, 10> quadratic_row_sums(const Continuum3& c, size_t z, double* volume) {
  std::array<double, 10> out{};
  if (!c.materials[c.material[z]].impl->solid()) return out;
  double v = 0;
  const Eigen::Matrix<double, 30, 30> k = stiffness(c, z, v);
  for (int n = 0; n < 10; ++n)
    out[n] = k.middleRows<3>(3 * n).cwiseAbs().rowwise().sum().maxCoeff();
  if (volume) *volume = v;
  return out;
}

double quadratic_zone_step(const Continuum3& c, size_t z) {
  const ZoneProperties& p = c.materials[c.material[z]];
  if (!p.impl->solid()) return 1e300;
  double volume = 0;
  const std::array<double, 10> rows = quadratic_row_sums(c, z, &volume);
  double step = 1e300;
  for (int n = 0; n < 10; ++n)
    if (rows[n] > 0)
      step = std::min(step, 2.0 * std::sqrt(p.density * volume * node_mass(n) / rows[n]));
  return step;
}

void make_quadratic(ZoneMesh3& mesh) {
  // The surface triangles of the corners, before the mesh is quadratic.
  const std::vector<std::array<uint32_t, 3>> surface =
      mesh.on_boundary.empty() ? std::vector<std::array<uint32_t, 3>>{} : boundary_faces(mesh);
  // One node per edge, numbered in the order the zones first meet it (deterministic).
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> at;
  mesh.mid.resize(mesh.tets.size());
  for (size_t z = 0; z < mesh.tets.size(); ++z)
    for (int e = 0; e < 6; ++e) {
      const uint32_t a = mesh.tets[z][kTetEdge[e][0]], b = mesh.tets[z][kTetEdge[e][1]];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto [it, added] = at.try_emplace(key, static_cast<uint32_t>(mesh.nodes.size()));
      if (added) {
        mesh.nodes.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
        if (!mesh.on_boundary.empty()) mesh.on_boundary.push_back(0);
      }
      mesh.mid[z][e] = it->second;
    }
  // A mid-edge node is on the surface where its edge lies in a surface triangle.
  for (const auto& f : surface)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = f[k], b = f[(k + 1) % 3];
      mesh.on_boundary[at.at({std::min(a, b), std::max(a, b)})] = 1;
    }
}

}  // namespace tessera
