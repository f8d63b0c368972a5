// Constrained Delaunay refinement of a block outline into zones (CGAL's 2D mesher).
#include "tessera/zones/zoning.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>

namespace tessera {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;

// Size criteria with a size field: a face is too big when its longest edge exceeds the local
// size at its centroid (CGAL's uniform criteria with the bound made a function).
class GradedCriteria : public Criteria {
 public:
  using SizeField = std::function<double(const Vec2&)>;
  GradedCriteria(double aspect, SizeField size) : Criteria(aspect, 1.0), size_(std::move(size)) {}

  class Is_bad : public Criteria::Is_bad {
   public:
    Is_bad(double aspect, const SizeField& size, const K& geom)
        : Criteria::Is_bad(aspect, 1.0, geom), size_(size) {}
    using Criteria::Is_bad::operator();
    CGAL::Mesh_2::Face_badness operator()(const CDT::Face_handle& fh, Quality& q) const {
      const auto &a = fh->vertex(0)->point(), &b = fh->vertex(1)->point(),
                 &c = fh->vertex(2)->point();
      std::array<double, 3> sq{CGAL::to_double(CGAL::squared_distance(b, c)),
                               CGAL::to_double(CGAL::squared_distance(c, a)),
                               CGAL::to_double(CGAL::squared_distance(a, b))};
      std::sort(sq.begin(), sq.end());
      const Vec2 centroid((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
      const double h = size_(centroid);
      q.second = sq[2] / (h * h);
      if (q.size() > 1) return q.first = 1, CGAL::Mesh_2::IMPERATIVELY_BAD;
      const double area2 = 2.0 * CGAL::to_double(CGAL::area(a, b, c));
      q.first = area2 * area2 / (sq[2] * sq[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    SizeField size_;
  };
  Is_bad is_bad_object() const { return Is_bad(this->bound(), size_, this->traits); }

 private:
  SizeField size_;
};

double polygon_area(const std::vector<Vec2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

double angle_at(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return std::atan2(std::abs(cross(u, v)), u.dot(v)) * 180.0 / std::numbers::pi;
}
}  // namespace

ZoneMesh zone_polygon(const std::vector<Vec2>& polygon, double max_edge, size_t max_zones,
                      const ZoneGrading* grading) {
  if (polygon.size() < 3) throw std::invalid_argument("a block outline needs three corners");
  if (!(max_edge > 0)) throw std::invalid_argument("the zone size must be positive");
  if (grading && !(grading->fine_edge > 0 && grading->radius >= 0 && grading->growth > 0))
    throw std::invalid_argument("a zone grading needs a positive fine size and growth");
  const double area = polygon_area(polygon);
  if (!(area > 0)) throw std::invalid_argument("the block outline is not counter-clockwise");
  // At least this many zones even where the mesh is coarsest: refuse at once if too many.
  const double fewest = area / (max_edge * max_edge * std::sqrt(3.0) / 4.0);
  if (fewest > static_cast<double>(max_zones))
    throw std::invalid_argument("zones of size " + std::to_string(max_edge) +
                                " would make more than " + std::to_string(max_zones) +
                                " zones; use a larger size");
  CDT cdt;
  std::vector<CDT::Vertex_handle> corners;
  for (const Vec2& v : polygon) corners.push_back(cdt.insert(K::Point_2(v.x(), v.y())));
  for (size_t i = 0; i < corners.size(); ++i)
    cdt.insert_constraint(corners[i], corners[(i + 1) % corners.size()]);
  // 0.125 bounds the squared smallest sine: angles of about 20.7 degrees. Refined a step at a
  // time so that a size far too small is refused before it fills the memory.
  GradedCriteria criteria(
      0.125, [&](const Vec2& p) { return grading ? grading->size_at(p, max_edge) : max_edge; });
  CGAL::Delaunay_mesher_2<CDT, GradedCriteria> mesher(cdt, criteria);
  mesher.init();
  while (!mesher.is_refinement_done()) {
    mesher.step_by_step_refine_mesh();
    if (cdt.number_of_vertices() > max_zones / 2)
      throw std::invalid_argument("zones of size " + std::to_string(max_edge) +
                                  " would make more than " + std::to_string(max_zones) +
                                  " zones; use a larger size");
  }
  ZoneMesh m;
  std::map<CDT::Vertex_handle, uint32_t> index;
  // Nodes in a fixed order: the triangulation's vertex order, which depends only on the input.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const auto v = f->vertex(k);
      auto [it, fresh] = index.try_emplace(v, static_cast<uint32_t>(m.nodes.size()));
      if (fresh) m.nodes.emplace_back(v->point().x(), v->point().y()), m.on_boundary.push_back(0);
      tri[static_cast<size_t>(k)] = it->second;
    }
    m.triangles.push_back(tri);
    // Boundary nodes: on a constrained edge of an in-domain face.
    for (int k = 0; k < 3; ++k)
      if (cdt.is_constrained(CDT::Edge(f, k))) {
        m.on_boundary[index[f->vertex(CDT::cw(k))]] = 1;
        m.on_boundary[index[f->vertex(CDT::ccw(k))]] = 1;
      }
  }
  if (m.triangles.empty()) throw std::invalid_argument("the block outline encloses no zone");
  m.min_angle = 180.0;
  for (auto& t : m.triangles) {
    const Vec2 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
    if (cross(b - a, c - a) < 0) std::swap(t[1], t[2]);
    m.min_angle = std::min({m.min_angle, angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
    m.max_edge = std::max({m.max_edge, (b - a).norm(), (c - b).norm(), (a - c).norm()});
  }
  return m;
}

}  // namespace tessera
