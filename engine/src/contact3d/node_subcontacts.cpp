// Node-to-face sub-contacts of deformable 3D blocks (§5.3.2; the scheme is in contacts3.hpp).
#include <algorithm>
#include <cmath>

#include "contact3d/face_overlap.hpp"
#include "tessera/contact3d/subcontacts.hpp"

namespace tessera {

namespace {

// Keys of node sub-contacts: the node's number, and which side it is on.
constexpr uint64_t kKeyNode = 1ull << 60, kKeyNodeB = 1ull << 61;

struct NodeWork {
  std::vector<PolyVertex> poly, clip, scratch;
  std::vector<uint32_t> clip_vertex;
  std::vector<std::pair<uint32_t, double>> share;
  std::vector<SubContact> old;
  std::vector<uint8_t> used;
};
thread_local NodeWork node_work;

using Vec2d = Eigen::Vector2d;

// Twice the signed area of triangle p q r.
double area2(const Vec2d& p, const Vec2d& q, const Vec2d& r) {
  return cross2(q - p, r - p);
}

// Barycentric weights of x in triangle p (either orientation).
Vec3 barycentric(const std::array<Vec2d, 3>& p, const Vec2d& x) {
  const double whole = area2(p[0], p[1], p[2]);
  if (whole == 0.0) return Vec3(1.0, 0.0, 0.0);
  return Vec3(area2(x, p[1], p[2]), area2(p[0], x, p[2]), area2(p[0], p[1], x)) / whole;
}

// Where the line through x along n meets the plane m . y = d: the parameter t of y = x + t n.
double along(const Vec3& x, const Vec3& n, const Vec3& mn, double d) {
  return (d - mn.dot(x)) / mn.dot(n);
}

// The opposite side of a node sub-contact: a rigid face's plane, or the surface triangle of a
// deformable face (its nodes and weights in l) - the point met along n from the node, as t.
double meet_opposite(const Model& m, const Contact3& c, const NodeLink& l, const Vec3& n,
                     const Vec3& x) {
  const Blocks3& B = m.blocks3;
  if (l.tri[0] < 0) {
    const uint32_t f = l.side == 0 ? c.face_b : c.face_a;
    return along(x, n, B.world_normal[f], B.world_offset[f]);
  }
  const std::vector<Vec3>& pos = m.continuum3.pos;
  const Vec3& p0 = pos[static_cast<size_t>(l.tri[0])];
  const Vec3 mt = (pos[static_cast<size_t>(l.tri[1])] - p0)
                      .cross(pos[static_cast<size_t>(l.tri[2])] - p0)
                      .normalized();
  return along(x, n, mt, mt.dot(p0));
}

// Gap and point of a node sub-contact from the node's position and the opposite side.
void measure(const Model& m, const Contact3& c, const NodeLink& l, SubContact& s, const Vec3& n) {
  const Vec3& x = m.continuum3.pos[static_cast<size_t>(l.node)];
  const double t = meet_opposite(m, c, l, n, x);
  // The node is on a (the plane's positive side) or on b.
  s.gap = l.side == 0 ? -t : t;
  s.local = frame_point(m.blocks3, c, x + 0.5 * t * n);
}

// Face f's corners projected on the plane, counter-clockwise about n.
void face_polygon(const Blocks3& B, uint32_t f, bool reverse, const Vec3& t1, const Vec3& t2,
                  std::vector<PolyVertex>& out, std::vector<uint32_t>& corner) {
  out.clear(), corner.clear();
  const uint32_t k0 = B.fv_begin[f], k1 = B.fv_begin[f + 1];
  for (uint32_t i = 0; i < k1 - k0; ++i) {
    const uint32_t k = reverse ? k1 - 1 - i : k0 + i;
    const Vec3& x = B.world_vertex[B.face_vert[k]];
    out.push_back({Vec2d(x.dot(t1), x.dot(t2)), kKeyVertexB | B.face_vert[k], kEdgeB | i});
    corner.push_back(B.face_vert[k]);
  }
}

// The nodes of block `own`'s facing face (on side `side`) with their shares of its overlap with
// the other block's facing face, as sub-contacts appended to c.subs.
void side_subcontacts(const Model& m, Contact3& c, const Vec3& n, int side, double share) {
  const Blocks3& B = m.blocks3;
  const Continuum3& z = m.continuum3;
  NodeWork& w = node_work;
  const auto [t1, t2] = tangents(n);
  const auto project = [&](const Vec3& x) { return Vec2d(x.dot(t1), x.dot(t2)); };
  const uint32_t own_face = side == 0 ? c.face_a : c.face_b;
  const uint32_t other_face = side == 0 ? c.face_b : c.face_a;
  const uint32_t other = side == 0 ? c.b : c.a;
  // a's faces look down the normal: their corners and triangles turn clockwise about it.
  face_polygon(B, other_face, side == 1, t1, t2, w.clip, w.clip_vertex);
  const double scale = B.bound_radius[c.a] + B.bound_radius[c.b];
  w.share.clear();
  for (uint32_t k = B.ftri_begin[own_face]; k < B.ftri_begin[own_face + 1]; ++k) {
    std::array<uint32_t, 3> t = B.ftri[k];
    if (side == 0) std::swap(t[1], t[2]);
    const std::array<Vec2d, 3> p{project(z.pos[t[0]]), project(z.pos[t[1]]), project(z.pos[t[2]])};
    w.poly.clear();
    for (int i = 0; i < 3; ++i) w.poly.push_back({p[i], 0, static_cast<uint64_t>(i)});
    clip_polygon(w.poly, w.clip, w.clip_vertex, 1e-12 * scale * scale, w.scratch);
    // The clipped area and its centroid (shoelace), shared by barycentric weights.
    double a2 = 0.0;
    Vec2d centroid = Vec2d::Zero();
    for (size_t i = 0; i < w.poly.size(); ++i) {
      const Vec2d& u = w.poly[i].p;
      const Vec2d& v = w.poly[(i + 1) % w.poly.size()].p;
      const double cr = cross2(u, v);
      a2 += cr, centroid += cr * (u + v);
    }
    if (!(a2 > 1e-12 * std::abs(area2(p[0], p[1], p[2])))) continue;
    centroid /= 3.0 * a2;
    // (A piece of a quadratic zone's face: its area to its mid-edge nodes only, so that a
    // uniform pressure closes the joint uniformly.)
    const Vec3 lambda = mid_edge_weights(t, barycentric(p, centroid).cwiseMax(0.0), z.edge_node);
    const double area = 0.5 * a2 * share / lambda.sum();
    for (int i = 0; i < 3; ++i)
      if (lambda[i] > 0.0) w.share.emplace_back(t[i], area * lambda[i]);
  }
  std::sort(w.share.begin(), w.share.end());
  const bool other_deformable = B.deformable[other];
  const Vec3 other_normal = B.world_normal[other_face];
  for (size_t i = 0; i < w.share.size();) {
    SubContact s;
    NodeLink nl;
    nl.node = static_cast<int32_t>(w.share[i].first);
    nl.side = static_cast<uint8_t>(side);
    s.key = kKeyNode | (side ? kKeyNodeB : 0) | w.share[i].first;
    for (; i < w.share.size() && static_cast<int32_t>(w.share[i].first) == nl.node; ++i)
      s.area += w.share[i].second;
    if (std::abs(other_normal.dot(n)) < 0.05) continue;
    const Vec3& x = z.pos[static_cast<size_t>(nl.node)];
    if (other_deformable) {
      // The other face's surface triangle the node faces: the one it is most inside of.
      const Vec2d px = project(x);
      double best = -1e300;
      for (uint32_t k = B.ftri_begin[other_face]; k < B.ftri_begin[other_face + 1]; ++k) {
        const auto& t = B.ftri[k];
        const Vec3 l =
            barycentric({project(z.pos[t[0]]), project(z.pos[t[1]]), project(z.pos[t[2]])}, px);
        if (l.minCoeff() > best) {
          best = l.minCoeff();
          for (int j = 0; j < 3; ++j) nl.tri[j] = static_cast<int32_t>(t[j]);
          // (its force and the velocity it sees in the same weights; the gap is to the plane)
          nl.weight = mid_edge_weights(t, l.cwiseMax(0.0) / l.cwiseMax(0.0).sum(), z.edge_node);
        }
      }
    }
    measure(m, c, nl, s, n);
    carry_state(m, c, s, w.old, w.used);
    s.link = static_cast<int32_t>(c.nodes.size());
    c.subs.push_back(s);
    c.nodes.push_back(nl);
  }
}

}  // namespace

void rebuild_node_subcontacts(const Model& m, Contact3& c, const Vec3& n) {
  const Blocks3& B = m.blocks3;
  NodeWork& w = node_work;
  w.old.swap(c.subs);
  c.subs.clear(), c.nodes.clear();
  w.used.assign(w.old.size(), 0);
  // Both faces deformable: both node sets act, each with half the area.
  const bool both = B.deformable[c.a] && B.deformable[c.b];
  for (int side = 0; side < 2; ++side)
    if (B.deformable[side == 0 ? c.a : c.b]) side_subcontacts(m, c, n, side, both ? 0.5 : 1.0);
}

void follow_node_subcontacts(const Model& m, Contact3& c, const Vec3& n) {
  c.normal = n;
  for (SubContact& s : c.subs) measure(m, c, c.nodes[static_cast<size_t>(s.link)], s, n);
}

Vec3 side_velocity(const Model& m, const Contact3& c, const SubContact& s, int side) {
  const Blocks3& B = m.blocks3;
  const uint32_t blk = side == 0 ? c.a : c.b;
  if (!B.deformable[blk]) {
    const auto mb = static_cast<size_t>(B.master[blk]);
    return B.body[mb].velocity + B.omega[mb].cross(world_point(B, c, s) - B.body[mb].position);
  }
  const std::vector<Vec3>& vel = m.continuum3.vel;
  const NodeLink& l = c.nodes[static_cast<size_t>(s.link)];
  if (l.side == side) return vel[static_cast<size_t>(l.node)];
  Vec3 v = Vec3::Zero();
  for (int i = 0; i < 3; ++i) v += l.weight[i] * vel[static_cast<size_t>(l.tri[i])];
  return v;
}

}  // namespace tessera
