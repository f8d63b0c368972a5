// Exact cutting of convex polyhedra by planes (see cutting3.hpp).
#include "tessera/generation/cutting3.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

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
  std::vector<CGAL::Oriented_side> side(nv);
  bool any_pos = false, any_neg = false;
  for (size_t i = 0; i < nv; ++i) {
    side[i] = plane.oriented_side(blk.v[i]);
    any_pos |= side[i] == CGAL::ON_POSITIVE_SIDE;
    any_neg |= side[i] == CGAL::ON_NEGATIVE_SIDE;
  }
  if (!any_pos || !any_neg) return false;
  // A plane that would shave off less than a billionth of the block's size passes along its
  // face: no sliver.
  double reach_pos = 0.0, reach_neg = 0.0;
  const double size = (blk.hi - blk.lo).norm();
  for (size_t i = 0; i < nv; ++i) {
    const double d = CGAL::to_double(plane.a() * blk.v[i].x() + plane.b() * blk.v[i].y() +
                                     plane.c() * blk.v[i].z() + plane.d());
    reach_pos = std::max(reach_pos, d), reach_neg = std::max(reach_neg, -d);
  }
  if (std::min(reach_pos, reach_neg) < 1e-9 * size * jp.normal.norm()) return false;
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
  for (size_t i = 0; i < blocks.size(); ++i) {
    ExactBlock e;
    for (const Vec3& p : blocks[i].poly.vertices) e.v.emplace_back(p.x(), p.y(), p.z());
    e.faces = blocks[i].poly.faces;
    e.tags = blocks[i].face_tags;
    e.tags.resize(e.faces.size(), -1);
    e.parent = i;
    bound(e);
    current.push_back(std::move(e));
  }
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
  for (const ExactBlock& e : current) {
    CutBlock c;
    for (const Point& p : e.v)
      c.poly.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                   CGAL::to_double(p.z()));
    c.poly.faces = e.faces;
    c.face_tags = e.tags;
    c.parent = e.parent;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace tessera
