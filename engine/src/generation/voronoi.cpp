// Voronoi cell walls from a CGAL Delaunay triangulation (part of the CGAL library target).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "tessera/core/random.hpp"
#include "tessera/generation/generators.hpp"

namespace tessera {

std::vector<CutLine> voronoi_traces(const Vec2& lo, const Vec2& hi, double size, uint64_t seed,
                                    int tag) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Delaunay = CGAL::Delaunay_triangulation_2<K>;
  // Seeds spread uniformly over the box grown by one cell, so that cells at the edges are whole.
  const Vec2 a = lo - Vec2(size, size), b = hi + Vec2(size, size);
  const auto count =
      static_cast<size_t>(std::ceil((b.x() - a.x()) * (b.y() - a.y()) / (size * size)));
  Random rng(seed);
  std::vector<K::Point_2> seeds;
  for (size_t i = 0; i < count; ++i) {
    const double x = a.x() + rng.uniform() * (b.x() - a.x());
    const double y = a.y() + rng.uniform() * (b.y() - a.y());
    seeds.emplace_back(x, y);
  }
  Delaunay dt(seeds.begin(), seeds.end());
  // Each finite Delaunay edge gives one wall: a segment, or a ray cut at a far distance.
  const double far = 10.0 * ((b - a).norm() + size);
  std::vector<CutLine> out;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    CGAL::Object o = dt.dual(e);
    K::Segment_2 s;
    K::Ray_2 r;
    if (CGAL::assign(s, o)) {
      out.push_back(
          {{Vec2(s.source().x(), s.source().y()), Vec2(s.target().x(), s.target().y())}, tag});
    } else if (CGAL::assign(r, o)) {
      const K::Vector_2 d = r.to_vector();
      const double len = std::sqrt(CGAL::to_double(d.squared_length()));
      const Vec2 p(r.source().x(), r.source().y());
      out.push_back({{p, p + Vec2(d.x(), d.y()) * (far / len)}, tag});
    }
  }
  // A fixed order, whatever order the triangulation keeps its edges in.
  std::sort(out.begin(), out.end(), [](const CutLine& l, const CutLine& m) {
    return std::make_tuple(l.points[0].x(), l.points[0].y(), l.points[1].x(), l.points[1].y()) <
           std::make_tuple(m.points[0].x(), m.points[0].y(), m.points[1].x(), m.points[1].y());
  });
  return out;
}

}  // namespace tessera
