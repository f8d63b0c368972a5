// Rigid polygonal blocks stored as struct-of-arrays.
//
// Design: the cycle walks blocks by index, so every per-block quantity the cycle touches lives in
// its own flat vector (positions, velocities, forces, inverse masses). Vertex geometry is stored
// once in the block's own frame (relative to its centroid, at rotation zero) in flat arrays with
// an offset table, and the world positions are a cache refreshed after each integration. Cold
// data (user names, groups) sit beside the hot arrays and are only read by scripts and output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessera/core/geometry.hpp"

namespace tessera {

// Which degrees of freedom of a block are held at a prescribed velocity.
enum Fixity : uint8_t { kFree = 0, kFixX = 1, kFixY = 2, kFixRot = 4, kFixAll = 7 };

struct Blocks {
  // Motion, at the centroid: position and rotation at t, velocities at t - dt/2.
  std::vector<double> x, y, theta;
  std::vector<double> vx, vy, omega;
  // Force and moment resultants of the current cycle (before damping).
  std::vector<double> fx, fy, moment;
  // Sum of magnitudes of all forces applied to the block (for the unbalanced-force ratio).
  std::vector<double> applied;
  // Centroid at creation, for displacements.
  std::vector<double> x_ref, y_ref;
  // Mass properties (the inverse is zero on a fixed degree of freedom).
  std::vector<double> mass, inertia, inv_mass, inv_inertia;
  // Fixity bits and the velocities prescribed on fixed degrees of freedom.
  std::vector<uint8_t> fixity;
  std::vector<double> fixed_vx, fixed_vy, fixed_omega;
  // Loads applied at the centroid (the 'load' command): force (N/m) and moment (N m/m).
  std::vector<double> load_fx, load_fy, load_m;
  // Vertices of block b are [vert_begin[b], vert_begin[b+1]) in the vertex arrays.
  std::vector<uint32_t> vert_begin{0};
  // Per vertex, in the block frame: corner position and rounded-arc centre.
  std::vector<Vec2> local_vertex, local_arc_centre;
  std::vector<double> arc_radius, round_length;
  std::vector<uint8_t> convex;
  // Per vertex: unit direction (block frame) and length of the edge that starts there, and the
  // joint tag of that edge (the joint set or crack that made it; -1 none).
  std::vector<Vec2> local_edge_dir;
  std::vector<double> edge_length;
  std::vector<int> edge_tag;
  // Per vertex, world cache refreshed after integration: corner, arc centre, edge direction.
  std::vector<Vec2> world_vertex, world_arc_centre, world_edge_dir;
  // Per vertex of a deformable block: the continuum node it is (-1 on rigid blocks).
  std::vector<int32_t> node;
  // Per block geometry: area, perimeter, largest centroid-to-vertex distance, and whether every
  // corner is convex.
  std::vector<double> area, perimeter, bound_radius;
  std::vector<uint8_t> all_convex;
  // Deformable blocks (zoned): their outline follows their boundary nodes; the rigid degrees of
  // freedom stay fixed.
  std::vector<uint8_t> deformable;
  // Cold data.
  std::vector<int> group, material;
  std::vector<int> id;  // the user's 1-based block number

  size_t size() const { return x.size(); }
  uint32_t vertex_count(size_t b) const { return vert_begin[b + 1] - vert_begin[b]; }
  // The vertex before v around block b's outline.
  uint32_t prev_vertex(size_t b, uint32_t v) const {
    return v > vert_begin[b] ? v - 1 : vert_begin[b + 1] - 1;
  }
  // The stretch of outline vertex v stands for: half of each edge meeting there.
  double vertex_share(size_t b, uint32_t v) const {
    return 0.5 * (edge_length[v] + edge_length[prev_vertex(b, v)]);
  }
  // Adds a block from counter-clockwise vertices; returns its index.
  size_t add(const std::vector<Vec2>& ccw_pts, double rounding, double density, int group_id,
             int material_id, const std::vector<int>& edge_tags = {});
  // Removes the blocks whose flag is set, keeping the order of the rest; returns the new index
  // of every old block (-1 for removed ones).
  std::vector<int> remove(const std::vector<uint8_t>& doomed);
  // Mass properties from area and density (after a material change).
  void set_density(size_t b, double density);
  // Recomputes the world vertex cache of one block from its position and rotation (deformable
  // blocks are refreshed from their nodes by update_deformable_world, model.hpp).
  void update_world(size_t b);
  // Replaces the outline of block b (same centroid frame; used when a block is zoned).
  void set_outline(size_t b, const std::vector<Vec2>& ccw_pts, double rounding,
                   const std::vector<int>& edge_tags, const std::vector<int32_t>& nodes);
  // Applies f(array of this, same array of other) to every per-vertex array.
  template <class F>
  void each_vertex_array(Blocks& other, F&& f) {
    f(local_vertex, other.local_vertex), f(local_arc_centre, other.local_arc_centre);
    f(arc_radius, other.arc_radius), f(round_length, other.round_length);
    f(convex, other.convex), f(local_edge_dir, other.local_edge_dir);
    f(edge_length, other.edge_length), f(edge_tag, other.edge_tag);
    f(world_vertex, other.world_vertex), f(world_arc_centre, other.world_arc_centre);
    f(world_edge_dir, other.world_edge_dir), f(node, other.node);
  }
  // World vertices of a block as a polygon (for output and checks).
  std::vector<Vec2> world_polygon(size_t b) const;
  // Every per-block double array, in a fixed order (for copying and saving).
  std::vector<std::vector<double>*> block_doubles();
  // Gives back the spare capacity the arrays grew while blocks were added one by one (up to
  // half of each), before cycling.
  void shrink_to_fit();
  // Applies the fixity bits to the inverse masses.
  void refresh_inverse_mass(size_t b);
};

}  // namespace tessera
