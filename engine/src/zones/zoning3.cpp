// Tetrahedral zoning of a polyhedral block (CGAL's 3D mesher, the block's edges protected).
#include "tessera/zones/zoning3.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>

namespace tessera {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<K::Point_3>;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

Vec3 vec(const K::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}

// The mesher's size field: the grading's size at a point, or the uniform size.
struct SizeField {
  double max_edge;
  const ZoneGrading3* grading;
  double factor;  // the bound as a multiple of the edge length
  using FT = K::FT;
  using Point_3 = K::Point_3;
  using Index = Domain::Index;
  FT operator()(const Point_3& p, int, const Index&) const {
    return factor * (grading ? grading->size_at(vec(p), max_edge) : max_edge);
  }
};

// The block's surface, its faces fanned into triangles.
Surface surface_of(const Polyhedron& block) {
  Surface s;
  std::vector<Surface::Vertex_index> v;
  for (const Vec3& p : block.vertices) v.push_back(s.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& face : block.faces) {
    std::vector<Surface::Vertex_index> f;
    for (uint32_t k : face) {
      if (k >= v.size()) throw std::invalid_argument("a face names a missing corner");
      f.push_back(v[k]);
    }
    if (s.add_face(f) == Surface::null_face())
      throw std::invalid_argument("the block's faces do not make one closed surface");
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(s);
  return s;
}
}  // namespace

double min_dihedral_angle(const std::array<Vec3, 4>& p) {
  // Each edge (i, j) is shared by the faces through k and through l: the angle between them.
  static constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                      {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double smallest = 180.0;
  for (const auto& e : edges) {
    const Vec3 axis = p[e[1]] - p[e[0]];
    const Vec3 u = axis.cross(p[e[2]] - p[e[0]]), w = axis.cross(p[e[3]] - p[e[0]]);
    if (u.norm() == 0 || w.norm() == 0) return 0.0;
    const double c = std::clamp(u.dot(w) / (u.norm() * w.norm()), -1.0, 1.0);
    smallest = std::min(smallest, std::acos(c) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

ZoneMesh3 zone_polyhedron(const Polyhedron& block, double max_edge, size_t max_zones,
                          const ZoneGrading3* grading) {
  if (!(max_edge > 0)) throw std::invalid_argument("the zone size must be positive");
  const Surface surface = surface_of(block);
  if (!CGAL::is_closed(surface)) throw std::invalid_argument("the block's surface is not closed");
  const double volume = CGAL::Polygon_mesh_processing::volume(surface);
  if (!(volume > 0)) throw std::invalid_argument("the block's faces are turned inside out");
  // A regular tetrahedron of edge h holds h^3 / (6 sqrt 2); refined meshes hold about as many.
  const double smallest = grading ? std::min(max_edge, grading->fine_edge) : max_edge;
  if (volume / (smallest * smallest * smallest / (6 * std::numbers::sqrt2)) >
      static_cast<double>(max_zones))
    throw std::invalid_argument("zones of size " + std::to_string(smallest) +
                                " would make more than " + std::to_string(max_zones) +
                                " zones; use a larger size");
  // The block's edges are protected, so the faces and corners are kept as they are; an edge far
  // shorter than the zones would make the mesher refine without end.
  for (const auto& face : block.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const double length =
          (block.vertices[face[k]] - block.vertices[face[(k + 1) % face.size()]]).norm();
      if (length < 1e-6 * smallest) {
        char why[160];
        std::snprintf(why, sizeof why,
                      "the block has an edge %.3g m long, too short to zone at "
                      "size %.3g",
                      length, smallest);
        throw std::invalid_argument(why);
      }
    }
  CGAL::Random rng(0);
  Domain domain(surface, &rng);
  std::vector<std::vector<K::Point_3>> edges;
  for (const auto& face : block.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const uint32_t a = face[k], b = face[(k + 1) % face.size()];
      if (a >= b) continue;  // each edge once (the other face lists it as b -> a)
      const Vec3 &pa = block.vertices[a], &pb = block.vertices[b];
      edges.push_back({K::Point_3(pa.x(), pa.y(), pa.z()), K::Point_3(pb.x(), pb.y(), pb.z())});
    }
  domain.add_features(edges.begin(), edges.end());
  // Sizes: the block's edges split into pieces of at most the size; surface triangles and zones
  // bounded by the circumradius of the equilateral triangle and the regular tetrahedron of that
  // edge (h / sqrt 3, h sqrt(3/8)), so that zones of a regular shape have edges of about h.
  const SizeField edge{max_edge, grading, 1.0}, facet{max_edge, grading, 1.0 / std::sqrt(3.0)},
      cell{max_edge, grading, std::sqrt(3.0 / 8.0)};
  namespace params = CGAL::parameters;
  const Criteria criteria(params::edge_size = edge, params::facet_angle = 25.0,
                          params::facet_size = facet, params::facet_distance = 0.1 * max_edge,
                          params::cell_radius_edge_ratio = 2.0, params::cell_size = cell);
  // The perturber draws from CGAL's default generator: seeded here, the same block gives the
  // same mesh whatever ran before on this thread. It runs while its steps succeed: CGAL's
  // default stops it after as much CPU time as the refinement took, so a busy machine meshed
  // the same block differently (1659 zones against 1656).
  CGAL::get_default_random() = CGAL::Random(0);
  const C3t3 c3t3 =
      CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_lloyd(), params::no_odt(),
                              params::perturb(params::time_limit = 0), params::no_exude());
  // The mesher's cells come in an order that depends on memory addresses, its vertices not:
  // nodes are numbered in coordinate order and zones sorted, so the numbering is the same on
  // every run. Each zone lists its nodes ascending, the last two swapped for positive volume.
  std::vector<Tr::Vertex_handle> used;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for (int k = 0; k < 4; ++k) used.push_back(c->vertex(k));
  auto point = [](const Tr::Vertex_handle& v) { return vec(v->point().point()); };
  auto before = [&](const Tr::Vertex_handle& a, const Tr::Vertex_handle& b) {
    const Vec3 p = point(a), q = point(b);
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  };
  std::sort(used.begin(), used.end(), before);
  used.erase(std::unique(used.begin(), used.end()), used.end());
  ZoneMesh3 mesh;
  std::map<Tr::Vertex_handle, uint32_t> number;
  for (const Tr::Vertex_handle& v : used) {
    number.emplace(v, static_cast<uint32_t>(mesh.nodes.size()));
    mesh.nodes.push_back(point(v));
    mesh.on_boundary.push_back(c3t3.in_dimension(v) < 3);
  }
  mesh.min_dihedral = 180.0;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<uint32_t, 4> tet;
    for (int k = 0; k < 4; ++k) tet[k] = number.at(c->vertex(k));
    std::sort(tet.begin(), tet.end());
    std::array<Vec3, 4> at;
    for (int k = 0; k < 4; ++k) at[k] = mesh.nodes[tet[k]];
    if ((at[1] - at[0]).cross(at[2] - at[0]).dot(at[3] - at[0]) < 0)
      std::swap(tet[2], tet[3]), std::swap(at[2], at[3]);
    mesh.tets.push_back(tet);
    mesh.min_dihedral = std::min(mesh.min_dihedral, min_dihedral_angle(at));
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        mesh.max_edge = std::max(mesh.max_edge, (at[i] - at[j]).norm());
  }
  std::sort(mesh.tets.begin(), mesh.tets.end());
  if (mesh.tets.empty()) throw std::invalid_argument("the block is too thin to zone");
  return mesh;
}

}  // namespace tessera
