// Rigid convex polyhedral blocks in 3D (chapter 5.3.1).
//
// Design: per-block motion is a RigidBody3 (quaternion orientation, angular momentum); the shape
// is stored once in the block's principal frame about its centroid, and world positions of
// vertices, face normals and edge directions are a cache refreshed after each step (the
// vertices and edge directions only where the cycle reads them: see vertices_behind). Faces list
// their vertices counter-clockwise seen from outside as global vertex indices; each face keeps
// the joint tag of the cut that made it. The distinct edge directions of a block are kept apart
// (a box has three): the common-plane search needs only directions, not edges.
//
// Concave blocks (§5.3.1) are a master and convex slave pieces moving as one body: every piece
// is a block of its own for contacts, but `master` names the block whose RigidBody3 carries the
// whole body (common mass, centroid and inertia); a slave's shape is kept in its master's frame,
// its forces go to its master, and contacts between pieces of one body are never made.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"
#include "tessera/contact3d/rigid3d.hpp"

namespace tessera {

// Which degrees of freedom of a 3D block are held at a prescribed velocity.
enum Fixity3 : uint8_t { kFix3X = 1, kFix3Y = 2, kFix3Z = 4, kFix3Rot = 8, kFix3All = 15 };

struct Blocks3 {
  std::vector<RigidBody3> body;
  // World angular velocity at the half step, refreshed with the motion (read by the contacts).
  std::vector<Vec3> omega;
  // Force and torque (about the centroid) of the current cycle, and the sum of the magnitudes
  // of all forces applied (for the unbalanced-force ratio).
  std::vector<Vec3> force, torque;
  std::vector<double> applied;
  // Centroid and orientation at creation, for displacements; fixity and prescribed velocities.
  std::vector<Vec3> ref;
  std::vector<Eigen::Quaterniond> ref_q;
  std::vector<uint8_t> fixity;
  std::vector<Vec3> fixed_v, fixed_w;
  // Loads applied at the body's centroid (the 'load' command; on masters only): force, moment.
  std::vector<Vec3> load_force, load_moment;
  // Geometry: volume, surface area, largest centroid-to-vertex distance.
  std::vector<double> volume, surface, bound_radius;
  // Vertices of block b are [vert_begin[b], vert_begin[b+1]).
  std::vector<uint32_t> vert_begin{0};
  std::vector<Vec3> local_vertex;
  mutable std::vector<Vec3> world_vertex;  // (a cache: see vertices_behind)
  // Faces of block b are [face_begin[b], face_begin[b+1]); face f's vertices are
  // face_vert[fv_begin[f] .. fv_begin[f+1]) (global vertex indices, counter-clockwise outside).
  std::vector<uint32_t> face_begin{0}, fv_begin{0}, face_vert;
  // Rotation of the block's moving body (its axes to world axes), refreshed with the face planes.
  std::vector<Mat3> rotation;
  std::vector<Vec3> local_normal, world_normal;
  std::vector<double> local_offset;  // local_normal . x on the face plane (block frame)
  std::vector<double> world_offset;  // world_normal . x on the face plane
  std::vector<int> face_tag;
  // Distinct edge directions of block b: [dir_begin[b], dir_begin[b+1]).
  std::vector<uint32_t> dir_begin{0};
  std::vector<Vec3> local_dir;
  mutable std::vector<Vec3> world_dir;
  // The block whose body moves this one (itself unless it is a slave piece of a concave block).
  std::vector<int32_t> master;
  // Deformable blocks (§5.3.1): the block moves with its zones' nodes, not as a body. Each vertex
  // is a node (-1 for rigid blocks), and face f of the block is covered by the surface triangles
  // ftri[ftri_begin[f] .. ftri_begin[f+1]) (node triples, counter-clockwise outside); the world
  // vertices and face planes are refreshed from the nodes (zones/deformable3.cpp). The block's
  // nodes and zones are [node_begin[b], node_end[b]) and [zone_begin[b], zone_end[b]).
  std::vector<uint8_t> deformable;
  std::vector<int32_t> vertex_node;
  std::vector<uint32_t> ftri_begin{0};
  std::vector<std::array<uint32_t, 3>> ftri;
  std::vector<uint32_t> node_begin, node_end, zone_begin, zone_end;
  // Cold data.
  std::vector<int> group, material, id;
  // Set by the cycle, which moves every block's face planes each step but its vertices and edge
  // directions only when a contact of the block is about to read them (a plane re-fit or
  // rebuild). catch_up() makes all current: a detection pass, the end of a run, and whatever
  // reads or copies the vertices (output, snapshots, polyhedron, remove, join, state files)
  // call it first.
  mutable bool vertices_behind = false;

  size_t size() const { return body.size(); }
  // Adds a convex block from a polyhedron in world coordinates; face_tags per face (or empty).
  // Throws std::invalid_argument if the polyhedron is open, flat or not convex.
  size_t add(const Polyhedron& world, double density, int group_id, int material_id,
             const std::vector<int>& face_tags = {});
  // Removes the blocks whose flag is set; returns the new index of every old block (-1: gone).
  // A joined body goes whole (std::invalid_argument, nothing changed, if a piece would stay
  // without its master).
  std::vector<int> remove(const std::vector<uint8_t>& doomed);
  void set_density(size_t b, double density);
  // Refreshes the world cache of block b from its position and orientation: the face planes
  // (update_planes) and the vertices and edge directions (update_vertices).
  void update_world(size_t b);
  void update_planes(size_t b);
  void update_vertices(size_t b) const;
  // Brings every rigid block's vertices and edge directions up to its body if vertices_behind
  // (not thread-safe: one thread at a time reads a model that may be behind).
  void catch_up() const;
  // The block's surface in world coordinates (vertex indices local to the block).
  Polyhedron polyhedron(size_t b) const;
  // Joins blocks into one body (the first is the master): combined mass, centroid and inertia
  // from each piece's density, the pieces' shapes re-expressed in the master's principal frame,
  // the mass-weighted velocity and no spin. Joined bodies may be joined again.
  void join(const std::vector<size_t>& pieces, const std::vector<double>& densities);
  bool is_slave(size_t b) const { return master[b] != static_cast<int32_t>(b); }
  // The rotation of block b's moving body, from its orientation (what `rotation` keeps).
  Mat3 body_rotation(size_t b) const {
    return body[static_cast<size_t>(master[b])].orientation.toRotationMatrix();
  }
  // World angular velocity of block b's body from its momentum, through its rotation:
  // R (I^-1 (R^T L)) (the cycle's form, so that a run split in two steps as one).
  Vec3 spin(size_t b) const { return spin(b, body[b].principal.cwiseInverse()); }
  // (inv_moment: the principal moments' reciprocals, if the caller has them.)
  Vec3 spin(size_t b, const Vec3& inv_moment) const {
    const Mat3& r = rotation[b];
    return r * (r.transpose() * body[b].momentum).cwiseProduct(inv_moment);
  }
  // How fast block b's farthest point moves by its body's turning: |w| times its bound radius.
  double turn_speed(size_t b) const {
    return omega[static_cast<size_t>(master[b])].norm() * bound_radius[b];
  }
  // Held still or at a prescribed velocity as a whole (a deformable block moves with its nodes).
  bool held(size_t b) const { return fixity[b] == kFix3All && !deformable[b]; }
  // Whether a world point lies inside block b (on the surface counts).
  bool contains(size_t b, const Vec3& p) const;
};

}  // namespace tessera
