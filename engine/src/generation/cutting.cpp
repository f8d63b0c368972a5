// Exact cutting with a CGAL arrangement (the only file of the engine that includes CGAL).
#include "tessera/generation/cutting.hpp"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace tessera {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using SegmentTraits = CGAL::Arr_segment_traits_2<K>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Curve = Traits::Curve_2;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Halfedge = Arrangement::Halfedge_const_handle;
using Face = Arrangement::Face_const_handle;

// The tag of an arrangement edge: the latest cut over it (tags grow with each cut).
int edge_tag(Halfedge e) {
  int tag = -1;
  for (int t : e->curve().data()) tag = std::max(tag, t);
  return tag;
}

// A coordinate as a double, from its exact value. The lazy kernel's own to_double returns whatever
// approximation it holds, which depends on what was computed before; the exact value does not.
double exact_double(const K::FT& v) {
  return CGAL::to_double(CGAL::exact(v));
}

// A point rounded to doubles.
Vec2 rounded(const Point& p) {
  return {exact_double(p.x()), exact_double(p.y())};
}

// An edge that has the same face on both sides (a trace ending inside a block).
bool dangling(Halfedge e) {
  return e->twin()->face() == e->face();
}

// Halfedges of a connected boundary component, dangling ones left out.
template <class Circulator>
std::vector<Halfedge> boundary(Circulator first) {
  std::vector<Halfedge> out;
  Circulator c = first;
  do {
    if (!dangling(c)) out.push_back(c);
  } while (++c != first);
  return out;
}

// Whether an inner boundary of a face is a real hole (not just a dangling trace).
template <class Circulator>
bool real_hole(Circulator first) {
  return !boundary(first).empty();
}

// Horizontal chords from a hole to the rest of its face's boundary, which split the ring.
std::vector<Curve> hole_splitters(Face f, Arrangement::Inner_ccb_const_iterator hole, int tag) {
  const std::vector<Halfedge> hole_edges = boundary(*hole);
  std::vector<K::FT> ys;
  for (Halfedge e : hole_edges) ys.push_back(e->source()->point().y());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  // All boundary edges of the face, and the y values of their vertices, which the line avoids.
  std::vector<std::pair<Halfedge, bool>> edges;  // edge, on this hole
  for (Halfedge e : boundary(f->outer_ccb())) edges.emplace_back(e, false);
  for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h)
    for (Halfedge e : boundary(*h)) edges.emplace_back(e, h == hole);
  std::vector<K::FT> taken;
  for (const auto& [e, on_hole] : edges) taken.push_back(e->source()->point().y());
  std::sort(taken.begin(), taken.end());
  // The line through the middle of the widest gap between vertex heights of the face (hole and
  // outline alike) within the hole's height: it meets no vertex. (Gaps of the hole's heights
  // alone could all be blocked by an outline vertex, e.g. an octagon around a square centred
  // on it, and the ring then went unsplit and was taken whole as a piece.)
  if (ys.size() < 2) return {};
  taken.erase(std::unique(taken.begin(), taken.end()), taken.end());
  K::FT c = 0;
  bool found = false;
  K::FT best = -1;
  for (size_t i = 0; i + 1 < taken.size(); ++i) {
    if (taken[i] < ys.front() || taken[i + 1] > ys.back()) continue;
    if (taken[i + 1] - taken[i] > best)
      best = taken[i + 1] - taken[i], c = (taken[i] + taken[i + 1]) / 2, found = true;
  }
  if (!found) return {};
  // Crossings of the line with the boundary, in order along it.
  std::vector<std::pair<K::FT, bool>> xs;
  for (const auto& [e, on_hole] : edges) {
    const Point &p = e->source()->point(), &q = e->target()->point();
    if ((p.y() < c) == (q.y() < c)) continue;
    xs.emplace_back(p.x() + (c - p.y()) * (q.x() - p.x()) / (q.y() - p.y()), on_hole);
  }
  std::sort(xs.begin(), xs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // Inside the face between crossings 0-1, 2-3, ...: keep the chords that touch the hole.
  std::vector<Curve> out;
  for (size_t i = 0; i + 1 < xs.size(); i += 2)
    if (xs[i].second != xs[i + 1].second)
      out.emplace_back(K::Segment_2(Point(xs[i].first, c), Point(xs[i + 1].first, c)), tag);
  return out;
}

// Cell key of a point in a grid of the given size.
int64_t cell_key(double x, double y, double h) {
  const auto ix = static_cast<int64_t>(std::floor(x / h)),
             iy = static_cast<int64_t>(std::floor(y / h));
  return (ix << 32) ^ (iy & 0xffffffffLL);
}

// Drops repeated and straight-through vertices (unless the tags on either side differ).
void clean(TaggedPolygon& p) {
  bool changed = true;
  while (changed && p.points.size() >= 3) {
    changed = false;
    const size_t n = p.points.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 &a = p.points[(i + n - 1) % n], &b = p.points[i], &c = p.points[(i + 1) % n];
      const bool repeated = (b - a).squaredNorm() == 0.0;
      const double scale = (b - a).norm() * (c - b).norm();
      const bool straight = std::abs(cross(b - a, c - b)) <= 1e-12 * scale &&
                            (b - a).dot(c - b) > 0 &&
                            p.edge_tags[(i + n - 1) % n] == p.edge_tags[i];
      if (repeated || straight) {
        p.points.erase(p.points.begin() + static_cast<long>(i));
        p.edge_tags.erase(p.edge_tags.begin() + static_cast<long>(repeated ? i : i));
        changed = true;
        break;
      }
    }
  }
}

// A face of the arrangement inside an input polygon, its outline rounded to doubles.
struct Piece {
  Face face;
  size_t parent;
  TaggedPolygon poly;
  double area;
};

// The outline of the faces for which `in` holds, walked from an edge of the first face: one
// simple polygon, or empty if it is not one (a hole, two parts, or parts touching at a point).
template <class In>
TaggedPolygon outline_of(const std::vector<Face>& faces, const In& in) {
  std::map<Arrangement::Vertex_const_handle, Halfedge> next_from;
  std::vector<Halfedge> order;
  for (Face f : faces)
    for (Halfedge e : boundary(f->outer_ccb()))
      if (!in(e->twin()->face())) {
        if (!next_from.emplace(e->source(), e).second) return {};
        order.push_back(e);
      }
  if (order.empty()) return {};
  TaggedPolygon out;
  Halfedge e = order[0];
  do {
    out.points.push_back(rounded(e->source()->point()));
    out.edge_tags.push_back(edge_tag(e));
    const auto it = next_from.find(e->target());
    if (it == next_from.end() || out.points.size() > order.size()) return {};
    e = it->second;
  } while (e != order[0]);
  if (out.points.size() != order.size()) return {};
  return out;
}

// Merges each sliver (see SliverMerge) into a neighbour; `pieces` with `root[i] != i` are merged
// into piece root[i], whose outline is then `joined[root]`. Round-off faces (area <= `tiny`) are
// left to be dropped.
void merge_slivers(const std::vector<Piece>& pieces, const std::map<Face, size_t>& index,
                   const std::vector<CutLine>& cuts, const SliverMerge& merge, double tiny,
                   std::vector<size_t>& root, std::map<size_t, TaggedPolygon>& joined,
                   CutResult& out) {
  // Closed cut lines are outlines (openings): no merge across them.
  std::vector<int> outline_tags;
  for (const CutLine& c : cuts)
    if (c.points.size() > 3 && c.points.front() == c.points.back()) outline_tags.push_back(c.tag);
  auto on_outline = [&](Halfedge e) {
    for (int t : e->curve().data())
      if (std::find(outline_tags.begin(), outline_tags.end(), t) != outline_tags.end()) return true;
    return false;
  };
  auto kind = [&](size_t i) { return merge.kind.empty() ? 0 : merge.kind[pieces[i].parent]; };
  // Pieces per parent (round-off faces aside): slivers come only from polygons a cut split.
  std::map<size_t, size_t> count;
  for (const Piece& p : pieces) count[p.parent] += p.area > tiny;
  std::vector<size_t> slivers;
  for (size_t i = 0; i < pieces.size(); ++i)
    if (count[pieces[i].parent] > 1 && pieces[i].area < merge.min_area && pieces[i].area > tiny)
      slivers.push_back(i);
  std::stable_sort(slivers.begin(), slivers.end(),
                   [&](size_t a, size_t b) { return pieces[a].area < pieces[b].area; });
  std::vector<double> area;
  std::map<size_t, std::vector<Face>> members;
  for (const Piece& p : pieces) area.push_back(p.area);
  for (size_t s : slivers) {
    // Edge length shared with each neighbour big enough to take it, on the same side of outlines.
    std::map<size_t, double> shared;
    std::vector<size_t> barred;
    for (Halfedge e : boundary(pieces[s].face->outer_ccb())) {
      const auto it = index.find(e->twin()->face());
      if (it == index.end()) continue;
      const size_t r = root[it->second];
      if (area[r] < merge.min_area || kind(r) != kind(s)) continue;
      shared[r] += (rounded(e->target()->point()) - rounded(e->source()->point())).norm();
      if (on_outline(e)) barred.push_back(r);
    }
    std::vector<std::pair<double, size_t>> by_length;
    for (const auto& [r, len] : shared)
      if (std::find(barred.begin(), barred.end(), r) == barred.end())
        by_length.emplace_back(len, r);
    std::stable_sort(by_length.begin(), by_length.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    bool done = false;
    for (const auto& [len, r] : by_length) {
      std::vector<Face>& faces = members[r];
      if (faces.empty()) faces.push_back(pieces[r].face);
      faces.push_back(pieces[s].face);
      TaggedPolygon u = outline_of(faces, [&](Face f) {
        const auto it = index.find(f);
        return it != index.end() && (root[it->second] == r || it->second == s);
      });
      if (u.points.empty()) {
        faces.pop_back();
        continue;
      }
      root[s] = r, area[r] += area[s], joined[r] = std::move(u), done = true;
      break;
    }
    ++(done ? out.slivers_merged : out.slivers_left);
  }
}

}  // namespace

Vec2 interior_point(const std::vector<Vec2>& pts) {
  // A height between two vertex heights, so the line meets no vertex.
  std::vector<double> ys;
  for (const Vec2& p : pts) ys.push_back(p.y());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  Vec2 best = pts[0];
  double best_w = -1.0;
  for (size_t g = 0; g + 1 < ys.size(); ++g) {
    const double y = 0.5 * (ys[g] + ys[g + 1]);
    std::vector<double> xs;
    for (size_t i = 0, n = pts.size(); i < n; ++i) {
      const Vec2 &a = pts[i], &b = pts[(i + 1) % n];
      if ((a.y() < y) != (b.y() < y))
        xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2)
      if (xs[i + 1] - xs[i] > best_w)
        best_w = xs[i + 1] - xs[i], best = Vec2(0.5 * (xs[i] + xs[i + 1]), y);
  }
  return best;
}

CutResult cut_polygons(const std::vector<TaggedPolygon>& polygons, const std::vector<CutLine>& cuts,
                       double snap, int split_tag, const SliverMerge& merge) {
  // Every polygon edge and cut segment, exactly.
  std::vector<Curve> curves;
  auto add = [&](const Vec2& a, const Vec2& b, int tag) {
    if (a == b) return;
    curves.emplace_back(K::Segment_2(Point(a.x(), a.y()), Point(b.x(), b.y())), tag);
  };
  for (const TaggedPolygon& p : polygons)
    for (size_t k = 0, n = p.points.size(); k < n; ++k)
      add(p.points[k], p.points[(k + 1) % n], p.edge_tags[k]);
  for (const CutLine& c : cuts)
    for (size_t k = 0; k + 1 < c.points.size(); ++k) add(c.points[k], c.points[k + 1], c.tag);
  Arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  size_t splits = 0;
  // Split the faces that enclose holes until none does.
  for (int pass = 0; pass < 16; ++pass) {
    std::vector<Curve> splitters;
    const Arrangement& carr = arr;
    for (auto f = carr.faces_begin(); f != carr.faces_end(); ++f) {
      if (f->is_unbounded()) continue;
      for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h)
        if (real_hole(*h)) {
          for (Curve& c : hole_splitters(f, h, split_tag)) splitters.push_back(c);
          break;  // one hole per face per pass
        }
    }
    if (splitters.empty()) break;
    splits += splitters.size();
    for (const Curve& c : splitters) CGAL::insert(arr, c);
  }
  // Bounding boxes of the input polygons in a grid, to find the parent of each face.
  double size = 0.0;
  std::vector<std::array<double, 4>> boxes;
  for (const TaggedPolygon& p : polygons) {
    std::array<double, 4> b{1e300, 1e300, -1e300, -1e300};
    for (const Vec2& v : p.points)
      b = {std::min(b[0], v.x()), std::min(b[1], v.y()), std::max(b[2], v.x()),
           std::max(b[3], v.y())};
    size = std::max({size, b[2] - b[0], b[3] - b[1]});
    boxes.push_back(b);
  }
  auto parent_of = [&](const Vec2& q) -> long {
    for (size_t i = 0; i < polygons.size(); ++i) {
      const auto& b = boxes[i];
      if (q.x() < b[0] || q.x() > b[2] || q.y() < b[1] || q.y() > b[3]) continue;
      if (point_in_polygon(q, polygons[i].points)) return static_cast<long>(i);
    }
    return -1;
  };
  // Faces inside an input polygon are the pieces; slivers among them merge into neighbours.
  std::vector<Piece> found;
  std::map<Face, size_t> index;
  const Arrangement& carr = arr;
  for (auto f = carr.faces_begin(); f != carr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    TaggedPolygon p;
    for (Halfedge e : boundary(f->outer_ccb())) {
      p.points.push_back(rounded(e->source()->point()));
      p.edge_tags.push_back(edge_tag(e));
    }
    if (p.points.size() < 3) continue;
    const long parent = parent_of(interior_point(p.points));
    if (parent < 0) continue;
    index[f] = found.size();
    const double a = signed_area(p.points);
    found.push_back({f, static_cast<size_t>(parent), std::move(p), a});
  }
  CutResult out;
  std::vector<size_t> root(found.size());
  for (size_t i = 0; i < root.size(); ++i) root[i] = i;
  std::map<size_t, TaggedPolygon> joined;
  if (merge.min_area > 0.0)
    merge_slivers(found, index, cuts, merge, 1e-12 * size * size, root, joined, out);
  struct Raw {
    TaggedPolygon poly;
    size_t parent;
  };
  std::vector<Raw> raw;
  for (size_t i = 0; i < found.size(); ++i) {
    if (root[i] != i) continue;
    const auto it = joined.find(i);
    raw.push_back(
        {it != joined.end() ? std::move(it->second) : std::move(found[i].poly), found[i].parent});
  }
  // Canonical order: by parent, then lowest vertex; each piece starts at its lowest vertex.
  auto lowest = [](const TaggedPolygon& p) {
    return static_cast<size_t>(std::min_element(p.points.begin(), p.points.end(),
                                                [](const Vec2& a, const Vec2& b) {
                                                  return std::make_pair(a.x(), a.y()) <
                                                         std::make_pair(b.x(), b.y());
                                                }) -
                               p.points.begin());
  };
  for (Raw& r : raw) {
    const size_t k = lowest(r.poly);
    std::rotate(r.poly.points.begin(), r.poly.points.begin() + static_cast<long>(k),
                r.poly.points.end());
    std::rotate(r.poly.edge_tags.begin(), r.poly.edge_tags.begin() + static_cast<long>(k),
                r.poly.edge_tags.end());
  }
  std::sort(raw.begin(), raw.end(), [](const Raw& a, const Raw& b) {
    const Vec2 &pa = a.poly.points[0], &pb = b.poly.points[0];
    return std::make_tuple(a.parent, pa.x(), pa.y(), a.poly.points[1].x(), a.poly.points[1].y()) <
           std::make_tuple(b.parent, pb.x(), pb.y(), b.poly.points[1].x(), b.poly.points[1].y());
  });
  // Snap vertices within `snap` to the first one met, the same for every piece.
  out.splits = splits;
  const double h = snap > 0.0 ? snap : 1e-12 * std::max(size, 1.0);
  std::unordered_map<int64_t, std::vector<Vec2>> grid;
  auto snapped = [&](const Vec2& v) {
    const auto ix = static_cast<int64_t>(std::floor(v.x() / h)),
               iy = static_cast<int64_t>(std::floor(v.y() / h));
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find(((ix + dx) << 32) ^ ((iy + dy) & 0xffffffffLL));
        if (it == grid.end()) continue;
        for (const Vec2& r : it->second)
          if ((r - v).norm() <= h) return r;
      }
    grid[cell_key(v.x(), v.y(), h)].push_back(v);
    return v;
  };
  for (Raw& r : raw) {
    for (Vec2& v : r.poly.points) v = snapped(v);
    clean(r.poly);
    // Slivers: round-off of near-degenerate cuts, far below any block a model can use.
    if (r.poly.points.size() < 3 || signed_area(r.poly.points) <= 1e-12 * size * size) {
      ++out.slivers_dropped;
      continue;
    }
    out.pieces.push_back(std::move(r.poly));
    out.parent.push_back(r.parent);
  }
  return out;
}

TaggedPolygon join_polygons(const std::vector<TaggedPolygon>& polygons, std::string& why) {
  // The arrangement of all edges: the faces inside the polygons merge when the edges between two
  // of them (an edge with input polygons on both sides) are left out of the outline.
  std::vector<Curve> curves;
  for (const TaggedPolygon& p : polygons)
    for (size_t k = 0, n = p.points.size(); k < n; ++k) {
      const Vec2 &a = p.points[k], &b = p.points[(k + 1) % n];
      if (a != b)
        curves.emplace_back(K::Segment_2(Point(a.x(), a.y()), Point(b.x(), b.y())), p.edge_tags[k]);
    }
  Arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  // A face belongs to the union if its interior point lies in an input polygon.
  auto inside = [&](Face f) {
    if (f->is_unbounded()) return false;
    std::vector<Vec2> pts;
    for (Halfedge e : boundary(f->outer_ccb())) pts.push_back(rounded(e->source()->point()));
    if (pts.size() < 3) return false;
    const Vec2 q = interior_point(pts);
    for (const TaggedPolygon& p : polygons)
      if (point_in_polygon(q, p.points)) return true;
    return false;
  };
  // The outline: halfedges with the union on their left and the outside on their right.
  const Arrangement& carr = arr;
  std::map<Arrangement::Vertex_const_handle, Halfedge> next_from;
  size_t count = 0;
  for (auto e = carr.halfedges_begin(); e != carr.halfedges_end(); ++e)
    if (inside(e->face()) && !inside(e->twin()->face())) {
      if (next_from.count(e->source())) {
        why = "the blocks meet at a single point; the union is not a simple polygon";
        return {};
      }
      next_from[e->source()] = e, ++count;
    }
  if (count == 0) {
    why = "the blocks enclose nothing";
    return {};
  }
  // Walk the outline once around; every outline edge must be on it.
  TaggedPolygon out;
  Halfedge start = next_from.begin()->second, e = start;
  size_t walked = 0;
  do {
    out.points.push_back(rounded(e->source()->point()));
    out.edge_tags.push_back(edge_tag(e));
    const auto it = next_from.find(e->target());
    if (it == next_from.end() || ++walked > count) break;
    e = it->second;
  } while (e != start);
  if (walked != count) {
    why = "the blocks do not form one piece without holes (they must touch along edges)";
    return {};
  }
  clean(out);
  if (signed_area(out.points) < 0.0) {
    why = "the outline runs the wrong way";
    return {};
  }
  return out;
}

}  // namespace tessera
