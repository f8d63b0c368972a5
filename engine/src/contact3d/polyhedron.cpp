#include "tessera/contact3d/polyhedron.hpp"

#include <Eigen/Eigenvalues>
#include <map>
#include <stdexcept>
#include <utility>

namespace tessera {

namespace {
// Every edge used once in each direction: the surface is closed and consistently oriented.
void check_closed(const Polyhedron& p) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& face = p.faces[f];
    if (face.size() < 3)
      throw std::invalid_argument("face " + std::to_string(f + 1) + " has fewer than 3 vertices");
    for (size_t k = 0; k < face.size(); ++k) {
      const uint32_t a = face[k], b = face[(k + 1) % face.size()];
      if (a >= p.vertices.size() || b >= p.vertices.size())
        throw std::invalid_argument("face " + std::to_string(f + 1) + " names a missing vertex");
      ++uses[{a, b}];
    }
  }
  for (const auto& [edge, n] : uses)
    if (n != 1 || uses.count({edge.second, edge.first}) != 1)
      throw std::invalid_argument("the surface is not closed and consistently oriented at edge " +
                                  std::to_string(edge.first + 1) + "-" +
                                  std::to_string(edge.second + 1));
}
}  // namespace

SolidProperties solid_properties(const Polyhedron& p) {
  check_closed(p);
  // Second moments of the canonical tetrahedron (0, e1, e2, e3): integral of x x^T.
  Mat3 canonical;
  canonical << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  canonical /= 120.0;
  // Fans from a point near the surface keep the tetrahedra small (less cancellation).
  const Vec3 o = p.vertices.front();
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // integral of (x - o)(x - o)^T
  for (const auto& face : p.faces)
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      Mat3 a;
      a.col(0) = p.vertices[face[0]] - o;
      a.col(1) = p.vertices[face[k]] - o;
      a.col(2) = p.vertices[face[k + 1]] - o;
      const double det = a.determinant();
      volume += det / 6.0;
      first += det / 24.0 * (a.col(0) + a.col(1) + a.col(2));
      second += det * a * canonical * a.transpose();
    }
  if (!(volume > 0.0))
    throw std::invalid_argument("the polyhedron has no volume (faces inside out or flat)");
  SolidProperties s;
  s.volume = volume;
  const Vec3 c = first / volume;  // centroid relative to o
  s.centroid = o + c;
  const Mat3 about_centroid = second - volume * c * c.transpose();
  s.inertia = about_centroid.trace() * Mat3::Identity() - about_centroid;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(s.inertia);
  s.principal_moments = eig.eigenvalues();
  s.principal_axes = eig.eigenvectors();
  if (s.principal_axes.determinant() < 0) s.principal_axes.col(2) *= -1.0;
  return s;
}

Polyhedron box(const Vec3& lo, const Vec3& hi) {
  Polyhedron p;
  for (int k = 0; k < 8; ++k)
    p.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(),
                            k & 4 ? hi.z() : lo.z());
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return p;
}

Polyhedron prism(const std::vector<Eigen::Vector2d>& base, double z0, double z1) {
  Polyhedron p;
  const auto n = static_cast<uint32_t>(base.size());
  for (double z : {z0, z1})
    for (const auto& b : base) p.vertices.emplace_back(b.x(), b.y(), z);
  std::vector<uint32_t> bottom, top;
  for (uint32_t k = 0; k < n; ++k) bottom.push_back(n - 1 - k), top.push_back(n + k);
  p.faces = {bottom, top};
  for (uint32_t k = 0; k < n; ++k) {
    const uint32_t j = (k + 1) % n;
    p.faces.push_back({k, j, n + j, n + k});
  }
  return p;
}

Vec3 newell_normal(const std::vector<Vec3>& v, std::span<const uint32_t> face) {
  Vec3 n = Vec3::Zero();
  for (size_t k = 0; k < face.size(); ++k) {
    const Vec3& p = v[face[k]];
    const Vec3& q = v[face[(k + 1) % face.size()]];
    n += Vec3((p.y() - q.y()) * (p.z() + q.z()), (p.z() - q.z()) * (p.x() + q.x()),
              (p.x() - q.x()) * (p.y() + q.y()));
  }
  return n.normalized();
}

}  // namespace tessera
