// Exact cutting of convex polyhedra by planes (see cutting3.hpp).
#include "tessera/generation/cutting3.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "tessera/core/random.hpp"

namespace tessera {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;

struct ExactBlock {
  std::vector<Point> v;
  std::vector<std::vector<uint32_t>> faces;
  std::vector<int> tags;
  size_t parent = 0;
  Vec3 lo, hi;  // bounding box of the rounded vertices
};

void bound(ExactBlock& b) {
  b.lo = Vec3::Constant(1e300), b.hi = Vec3::Constant(-1e300);
  for (const Point& p : b.v) {
    const Vec3 x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    b.lo = b.lo.cwiseMin(x), b.hi = b.hi.cwiseMax(x);
  }
}

// Keeps only the vertices the faces use, renumbered in order of first use.
ExactBlock compact(const std::vector<Point>& pts, std::vector<std::vector<uint32_t>> faces,
                   std::vector<int> tags, size_t parent) {
  ExactBlock out;
  std::map<uint32_t, uint32_t> index;
  for (auto& f : faces)
    for (uint32_t& k : f) {
      const auto [it, fresh] = index.emplace(k, static_cast<uint32_t>(out.v.size()));
      if (fresh) out.v.push_back(pts[k]);
      k = it->second;
    }
  out.faces = std::move(faces), out.tags = std::move(tags), out.parent = parent;
  bound(out);
  return out;
}

// Cuts a convex block by a joint's plane into the pieces on its positive and negative sides;
// false if the plane does not pass through the inside (touching a vertex, edge or face is not a
// cut) or, for a disc, if the section is not wholly inside it.
bool cut_one(const ExactBlock& blk, const K::Plane_3& plane, const JointPlane& jp, ExactBlock& pos,
             ExactBlock& neg) {
  const size_t nv = blk.v.size();
  // A vertex within a billionth of the block's size of the plane is taken as on it, so that a
  // plane passing a hair's breadth from a corner (as round-off puts it) leaves no sliver edge;
  // a plane that would shave off no more passes along a face and does not cut.
  const double size = (blk.hi - blk.lo).norm(), snap = 1e-9 * size * jp.normal.norm();
  std::vector<CGAL::Oriented_side> side(nv);
  bool any_pos = false, any_neg = false;
  for (size_t i = 0; i < nv; ++i) {
    const double d = CGAL::to_double(plane.a() * blk.v[i].x() + plane.b() * blk.v[i].y() +
                                     plane.c() * blk.v[i].z() + plane.d());
    side[i] = std::abs(d) <= snap ? CGAL::ON_ORIENTED_BOUNDARY : plane.oriented_side(blk.v[i]);
    any_pos |= side[i] == CGAL::ON_POSITIVE_SIDE;
    any_neg |= side[i] == CGAL::ON_NEGATIVE_SIDE;
  }
  if (!any_pos || !any_neg) return false;
  std::vector<Point> pts = blk.v;
  // One new vertex per crossing edge, shared by both sides.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> crossing;
  const auto cross_at = [&](uint32_t p, uint32_t q) {
    const auto key = std::minmax(p, q);
    const auto it = crossing.find(key);
    if (it != crossing.end()) return it->second;
    const K::FT sp =
        plane.a() * pts[p].x() + plane.b() * pts[p].y() + plane.c() * pts[p].z() + plane.d();
    const K::FT sq =
        plane.a() * pts[q].x() + plane.b() * pts[q].y() + plane.c() * pts[q].z() + plane.d();
    const K::FT t = sp / (sp - sq);
    pts.push_back(pts[p] + (pts[q] - pts[p]) * t);
    const auto k = static_cast<uint32_t>(pts.size() - 1);
    crossing.emplace(key, k);
    return k;
  };
  const auto on_plane = [&](uint32_t k) {
    return k >= nv || side[k] == CGAL::ON_ORIENTED_BOUNDARY;
  };
  std::vector<std::vector<uint32_t>> faces[2];
  std::vector<int> tags[2];
  std::map<uint32_t, uint32_t> cap_edges[2];  // cap boundary: start vertex -> end vertex
  for (size_t f = 0; f < blk.faces.size(); ++f) {
    const auto& face = blk.faces[f];
    for (int s = 0; s < 2; ++s) {
      const CGAL::Oriented_side keep = s == 0 ? CGAL::ON_POSITIVE_SIDE : CGAL::ON_NEGATIVE_SIDE;
      std::vector<uint32_t> out;
      for (size_t k = 0; k < face.size(); ++k) {
        const uint32_t p = face[k], q = face[(k + 1) % face.size()];
        if (side[p] !=
            (keep == CGAL::ON_POSITIVE_SIDE ? CGAL::ON_NEGATIVE_SIDE : CGAL::ON_POSITIVE_SIDE))
          out.push_back(p);
        const bool strict =
            (side[p] == CGAL::ON_POSITIVE_SIDE && side[q] == CGAL::ON_NEGATIVE_SIDE) ||
            (side[p] == CGAL::ON_NEGATIVE_SIDE && side[q] == CGAL::ON_POSITIVE_SIDE);
        if (strict) out.push_back(cross_at(p, q));
      }
      if (out.size() < 3) continue;
      // Wholly on the plane: the face lies in the cut (cannot happen for a true cut).
      if (std::all_of(out.begin(), out.end(), on_plane)) continue;
      // Edges of this piece's face that lie in the plane bound the cap (walked backwards).
      for (size_t k = 0; k < out.size(); ++k) {
        const uint32_t p = out[k], q = out[(k + 1) % out.size()];
        if (on_plane(p) && on_plane(q)) cap_edges[s][q] = p;
      }
      faces[s].push_back(std::move(out));
      tags[s].push_back(blk.tags[f]);
    }
  }
  // Chain each side's cap.
  for (int s = 0; s < 2; ++s) {
    auto& edges = cap_edges[s];
    if (edges.size() < 3) return false;
    std::vector<uint32_t> cap;
    uint32_t k = edges.begin()->first;
    for (size_t guard = 0; guard <= edges.size(); ++guard) {
      cap.push_back(k);
      const auto it = edges.find(k);
      if (it == edges.end()) return false;
      k = it->second;
      if (k == cap.front()) break;
    }
    if (cap.size() != edges.size()) return false;
    faces[s].push_back(std::move(cap));
    tags[s].push_back(jp.tag);
  }
  pos = compact(pts, std::move(faces[0]), std::move(tags[0]), blk.parent);
  neg = compact(pts, std::move(faces[1]), std::move(tags[1]), blk.parent);
  // A finite joint cuts only a block whose section lies inside its disc.
  if (jp.radius > 0.0) {
    const Point centre(jp.point.x(), jp.point.y(), jp.point.z());
    for (size_t k = 0; k < pts.size(); ++k) {
      if (!on_plane(static_cast<uint32_t>(k))) continue;
      if (CGAL::to_double(CGAL::squared_distance(pts[k], centre)) > jp.radius * jp.radius)
        return false;
    }
  }
  return true;
}

// Which side of a plane a block lies on: +1 positive, -1 negative (touching is not crossing), 0
// when it is cut into `pos` and `neg`, whose new faces take `tag`.
int split(const ExactBlock& blk, const K::Plane_3& plane, int tag, ExactBlock& pos,
          ExactBlock& neg) {
  JointPlane jp;
  jp.normal =
      Vec3(CGAL::to_double(plane.a()), CGAL::to_double(plane.b()), CGAL::to_double(plane.c()));
  jp.tag = tag;
  if (cut_one(blk, plane, jp, pos, neg)) return 0;
  double reach_pos = 0.0, reach_neg = 0.0;
  for (const Point& p : blk.v) {
    const double d =
        CGAL::to_double(plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d());
    reach_pos = std::max(reach_pos, d), reach_neg = std::max(reach_neg, -d);
  }
  return reach_pos >= reach_neg ? 1 : -1;
}

ExactBlock exact(const CutBlock& c, size_t parent) {
  ExactBlock e;
  for (const Vec3& p : c.poly.vertices) e.v.emplace_back(p.x(), p.y(), p.z());
  e.faces = c.poly.faces;
  e.tags = c.face_tags;
  e.tags.resize(e.faces.size(), -1);
  e.parent = parent;
  bound(e);
  return e;
}

CutBlock rounded(const ExactBlock& e, int label) {
  CutBlock c;
  for (const Point& p : e.v)
    c.poly.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                 CGAL::to_double(p.z()));
  c.poly.faces = e.faces;
  c.face_tags = e.tags;
  c.parent = e.parent;
  c.label = label;
  return c;
}

}  // namespace

Vec3 normal_from_dip(double dip, double dip_direction) {
  const double d = dip * std::numbers::pi / 180.0, a = dip_direction * std::numbers::pi / 180.0;
  // The dip vector points down the slope towards the dip direction; the normal is up.
  Vec3 n(std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d));
  // Round-off of sin and cos at whole quadrants would tilt a vertical or level plane by 1e-17.
  for (int k = 0; k < 3; ++k)
    if (std::abs(n[k]) < 1e-15) n[k] = 0.0;
  return n;
}

std::vector<CutBlock> cut_blocks(const std::vector<CutBlock>& blocks,
                                 const std::vector<JointPlane>& planes) {
  std::vector<ExactBlock> current;
  for (size_t i = 0; i < blocks.size(); ++i) current.push_back(exact(blocks[i], i));
  for (const JointPlane& jp : planes) {
    const K::Plane_3 plane(Point(jp.point.x(), jp.point.y(), jp.point.z()),
                           K::Vector_3(jp.normal.x(), jp.normal.y(), jp.normal.z()));
    Random draw(jp.seed);
    std::vector<ExactBlock> next;
    for (ExactBlock& blk : current) {
      // Boxes wholly on one side cannot be cut (checked in doubles with a margin).
      const Vec3 c = 0.5 * (blk.lo + blk.hi), h = 0.5 * (blk.hi - blk.lo);
      const double reach = jp.normal.cwiseAbs().dot(h) * (1.0 + 1e-9) + 1e-12;
      if (std::abs(jp.normal.dot(c - jp.point)) > reach) {
        next.push_back(std::move(blk));
        continue;
      }
      ExactBlock pos, neg;
      if (!cut_one(blk, plane, jp, pos, neg) ||
          (jp.persistence < 1.0 && draw.uniform() >= jp.persistence)) {
        next.push_back(std::move(blk));
        continue;
      }
      next.push_back(std::move(pos));
      next.push_back(std::move(neg));
    }
    current = std::move(next);
  }
  std::vector<CutBlock> out;
  for (const ExactBlock& e : current) out.push_back(rounded(e, -1));
  return out;
}

std::pair<Vec3, Vec3> opening_frame(const Vec3& axis) {
  const Vec3 a = axis.normalized();
  // Up is +z seen along the axis; a vertical shaft takes +y.
  Vec3 v = Vec3::UnitZ() - a.z() * a;
  if (v.norm() < 1e-6) v = Vec3::UnitY() - a.y() * a;
  v.normalize();
  return {v.cross(a), v};
}

std::vector<CutBlock> cut_opening(const std::vector<CutBlock>& blocks, const Opening3& o) {
  const Vec3 a = o.axis.normalized();
  const auto [u, v] = opening_frame(a);
  const auto exact_point = [](const Vec3& x) { return Point(x.x(), x.y(), x.z()); };
  const size_t n = o.section.size();
  std::vector<Point> corner;
  Eigen::Vector2d mid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& s : o.section) {
    corner.push_back(exact_point(o.start + s.x() * u + s.y() * v));
    mid += s / static_cast<double>(n);
  }
  const Point c = exact_point(o.start + mid.x() * u + mid.y() * v);
  const K::Vector_3 along(a.x(), a.y(), a.z());
  // Walls (outside positive), planes through the axis and each corner (positive ahead of it,
  // counter-clockwise seen along the axis), and the round boundaries across the axis (positive
  // further along; the first is the portal, the last the end).
  std::vector<K::Plane_3> wall, radial, across;
  for (size_t k = 0; k < n; ++k) {
    wall.emplace_back(corner[k], corner[(k + 1) % n], corner[k] + along);
    radial.emplace_back(c, c + along, corner[k]);
  }
  for (int i = 0; i <= o.rounds; ++i)
    across.emplace_back(exact_point(o.start + (o.length * i / o.rounds) * a), along);
  std::vector<CutBlock> out;
  for (size_t i = 0; i < blocks.size(); ++i) {
    const ExactBlock blk = exact(blocks[i], i);
    ExactBlock pos, neg, part = blk;
    // Blocks the open prism does not reach stay whole.
    bool reached = true;
    for (size_t k = 0; k <= n + 1 && reached; ++k) {
      const bool portal = k == n, end = k == n + 1;
      const K::Plane_3 p = portal ? across.front().opposite() : end ? across.back() : wall[k];
      const int s = split(part, p, o.split_tag, pos, neg);
      if (s > 0) reached = false;
      if (s == 0) part = neg;
    }
    if (!reached) {
      out.push_back(rounded(blk, -1));
      continue;
    }
    // Rock past the portal or the end touches the rest along 'split' faces, not walls.
    const auto add_rock = [&](ExactBlock e, bool past) {
      if (past) std::replace(e.tags.begin(), e.tags.end(), o.wall_tag, o.split_tag);
      out.push_back(rounded(e, -1));
    };
    // Rock along the opening, cut across at the portal and the end.
    const auto add_along = [&](ExactBlock e) {
      int s = split(e, across.front(), o.split_tag, pos, neg);
      if (s < 0) return add_rock(e, true);
      if (s == 0) add_rock(neg, true), e = pos;
      s = split(e, across.back(), o.split_tag, pos, neg);
      if (s > 0) return add_rock(e, true);
      if (s == 0) add_rock(pos, true), e = neg;
      add_rock(e, false);
    };
    // The rock around: each sector between two corners, outside its wall.
    for (size_t k = 0; k < n; ++k) {
      part = blk;
      int s = split(part, radial[k], o.split_tag, pos, neg);
      if (s < 0) continue;
      if (s == 0) part = pos;
      s = split(part, radial[(k + 1) % n], o.split_tag, pos, neg);
      if (s > 0) continue;
      if (s == 0) part = neg;
      s = split(part, wall[k], o.wall_tag, pos, neg);
      if (s > 0) add_along(part);
      if (s == 0) add_along(pos);
    }
    // Inside the walls: rock before the portal and beyond the end, a piece per round between.
    part = blk;
    for (size_t k = 0; k < n; ++k)
      if (split(part, wall[k], o.wall_tag, pos, neg) == 0) part = neg;
    bool left = true;
    for (int r = 0; r <= o.rounds && left; ++r) {
      const int s = split(part, across[r], o.split_tag, pos, neg);
      if (s < 0 && r == 0) add_rock(part, true);
      if (s < 0 && r > 0) out.push_back(rounded(part, r - 1));
      if (s < 0) left = false;
      if (s == 0 && r == 0) add_rock(neg, true);
      if (s == 0 && r > 0) out.push_back(rounded(neg, r - 1));
      if (s == 0) part = pos;
    }
    if (left) add_rock(part, true);
  }
  return out;
}

}  // namespace tessera
