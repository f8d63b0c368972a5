// Constrained Delaunay refinement of a block outline into zones (CGAL's 2D mesher).
#include "tessera/zoning.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
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
using Mesher = CGAL::Delaunay_mesher_2<CDT, Criteria>;

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

ZoneMesh zone_polygon(const std::vector<Vec2>& polygon, double max_edge, size_t max_zones) {
  if (polygon.size() < 3) throw std::invalid_argument("a block outline needs three corners");
  if (!(max_edge > 0)) throw std::invalid_argument("the zone size must be positive");
  const double area = polygon_area(polygon);
  if (!(area > 0)) throw std::invalid_argument("the block outline is not counter-clockwise");
  // An equilateral zone of edge h has area h^2 sqrt(3)/4; refinement makes at most ~4x that.
  const double estimate = 4.0 * area / (max_edge * max_edge * std::sqrt(3.0) / 4.0);
  if (estimate > double(max_zones))
    throw std::invalid_argument("zones of size " + std::to_string(max_edge) + " would make about " +
                                std::to_string(size_t(estimate)) + " zones; use a larger size");
  CDT cdt;
  std::vector<CDT::Vertex_handle> corners;
  for (const Vec2& v : polygon) corners.push_back(cdt.insert(K::Point_2(v.x(), v.y())));
  for (size_t i = 0; i < corners.size(); ++i)
    cdt.insert_constraint(corners[i], corners[(i + 1) % corners.size()]);
  // 0.125 bounds the shape (B = 1/(2 sin(min angle)) squared form): about 20.7 degrees.
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, max_edge));
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
