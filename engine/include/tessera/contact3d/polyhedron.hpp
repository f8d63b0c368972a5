// Polyhedral blocks in 3D (chapter 5.3.1): a closed surface of planar faces, and its volume,
// centroid and inertia tensor for the rigid-body motion of 3DEC-style blocks.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tessera {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Vertices and faces; each face lists its vertices counter-clockwise seen from outside.
struct Polyhedron {
  std::vector<Vec3> vertices;
  std::vector<std::vector<uint32_t>> faces;
};

// Volume, centroid and the inertia tensor about the centroid for unit density (multiply by the
// density for a block's); principal moments (ascending) and axes (columns, right-handed).
struct SolidProperties {
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  Vec3 principal_moments = Vec3::Zero();
  Mat3 principal_axes = Mat3::Identity();
};

// Exact for any closed polyhedron with consistently oriented planar faces (sums over the
// tetrahedra that fan each face from the origin). Throws std::invalid_argument naming the
// fault if the surface is not closed, a face has fewer than three vertices or the volume is
// not positive (faces turned inside out).
SolidProperties solid_properties(const Polyhedron& p);

// Unit normal of a planar (or nearly planar) polygon of the vertices v[face[k]], by Newell's
// method: robust for nearly collinear vertices, and the best-fit normal of a warped face.
Vec3 newell_normal(const std::vector<Vec3>& v, std::span<const uint32_t> face);

// A box from its two opposite corners, and a right prism: a counter-clockwise base polygon in
// the plane z = z0 extruded to z1.
Polyhedron box(const Vec3& lo, const Vec3& hi);
Polyhedron prism(const std::vector<Eigen::Vector2d>& base, double z0, double z1);

}  // namespace tessera
