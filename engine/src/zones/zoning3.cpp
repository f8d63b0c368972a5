// Tetrahedral zoning of a polyhedral block (CGAL's 3D mesher, the block's edges protected).
#include "tessera/zones/zoning3.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/Slivers_exuder.h>
#include <CGAL/Mesh_3/sliver_criteria.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace tessera {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// A body of convex pieces (one for a block): each point labelled with the piece holding it,
// every piece's edges protected.
using PieceDomain = CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K>>;

Vec3 vec(const K::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}
K::Point_3 point3(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

// The mesher's size field: the grading's size at a point, or the uniform size.
template <class Index>
// The mesher asks it for the size at every point it refines, so it is also where a stop asked
// for from another thread (a signal, the window's Stop) ends the meshing: by ZoningStopped.
struct SizeField {
  double max_edge;
  const ZoneGrading3* grading;
  double factor;  // the bound as a multiple of the edge length
  const std::atomic<bool>* stop;
  using FT = K::FT;
  using Point_3 = K::Point_3;
  FT operator()(const Point_3& p, int, const Index&) const {
    if (stop && stop->load(std::memory_order_relaxed)) throw ZoningStopped();
    return factor * (grading ? grading->size_at(vec(p), max_edge) : max_edge);
  }
};

// Refuses a size that would make more than `max_zones` zones in `volume`, or an edge far shorter
// than the zones (the mesher would refine without end); returns the smallest zone size.
double check_sizes(const std::vector<const Polyhedron*>& pieces, double volume, double max_edge,
                   size_t max_zones, const ZoneGrading3* grading) {
  // A regular tetrahedron of edge h holds h^3 / (6 sqrt 2); refined meshes hold about as many.
  // Graded, the mean of 1 / h^3 over a grid across the pieces' box stands for the volume's.
  const double smallest = grading ? std::min(max_edge, grading->fine_edge) : max_edge;
  double per_volume = 1.0 / (smallest * smallest * smallest);
  if (grading) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Polyhedron* block : pieces)
      for (const Vec3& v : block->vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    constexpr int kGrid = 24;
    double sum = 0.0;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j)
        for (int k = 0; k < kGrid; ++k) {
          const Vec3 t = (Vec3(i, j, k) + Vec3::Constant(0.5)) / kGrid;
          const double h = grading->size_at(lo + t.cwiseProduct(hi - lo), max_edge);
          sum += 1.0 / (h * h * h);
        }
    per_volume = sum / (kGrid * kGrid * kGrid);
  }
  if (volume * per_volume * 6 * std::numbers::sqrt2 > static_cast<double>(max_zones))
    throw std::invalid_argument("zones of size " + std::to_string(smallest) +
                                " would make more than " + std::to_string(max_zones) +
                                " zones; use a larger size");
  for (const Polyhedron* block : pieces)
    for (const auto& face : block->faces)
      for (size_t k = 0; k < face.size(); ++k) {
        const double length =
            (block->vertices[face[k]] - block->vertices[face[(k + 1) % face.size()]]).norm();
        if (length < 1e-6 * smallest) {
          char why[160];
          std::snprintf(why, sizeof why,
                        "the block has an edge %.3g m long, too short to zone at size %.3g", length,
                        smallest);
          throw std::invalid_argument(why);
        }
      }
  return smallest;
}

// Every piece's edges once, split at the corners of other pieces lying on them and where two
// edges cross inside both, so that the segments (the mesher's features) meet only at their ends.
// Corners within `tol` are one.
std::vector<std::array<Vec3, 2>> feature_segments(const std::vector<Polyhedron>& pieces,
                                                  double tol) {
  std::vector<Vec3> pts;
  const auto weld = [&](const Vec3& p) {
    for (size_t i = 0; i < pts.size(); ++i)
      if ((pts[i] - p).norm() <= tol) return static_cast<uint32_t>(i);
    pts.push_back(p);
    return static_cast<uint32_t>(pts.size() - 1);
  };
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const Polyhedron& p : pieces)
    for (const auto& f : p.faces)
      for (size_t k = 0; k < f.size(); ++k) {
        const uint32_t a = weld(p.vertices[f[k]]), b = weld(p.vertices[f[(k + 1) % f.size()]]);
        if (a != b) edges.insert(std::minmax(a, b));
      }
  const std::vector<std::pair<uint32_t, uint32_t>> list(edges.begin(), edges.end());
  // Crossings: the closest points of two segments, inside both and within tol of each other.
  for (size_t i = 0; i < list.size(); ++i)
    for (size_t j = i + 1; j < list.size(); ++j) {
      const auto [a, b] = list[i];
      const auto [c, d] = list[j];
      if (a == c || a == d || b == c || b == d) continue;
      const Vec3 u = pts[b] - pts[a], v = pts[d] - pts[c], w = pts[a] - pts[c];
      const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), den = uu * vv - uv * uv;
      if (den <= 1e-12 * uu * vv) continue;  // parallel: corners on edges settle these
      const double s = (uv * v.dot(w) - vv * u.dot(w)) / den,
                   t = (uu * v.dot(w) - uv * u.dot(w)) / den;
      if (s <= 0.0 || s >= 1.0 || t <= 0.0 || t >= 1.0) continue;
      const Vec3 x = pts[a] + s * u;
      if ((x - (pts[c] + t * v)).norm() <= tol) weld(x);
    }
  // Each edge split at the corners on it, in order along it.
  std::set<std::pair<uint32_t, uint32_t>> split;
  for (const auto& [a, b] : list) {
    const Vec3 d = pts[b] - pts[a];
    std::vector<std::pair<double, uint32_t>> on{{0.0, a}, {1.0, b}};
    for (size_t v = 0; v < pts.size(); ++v) {
      if (v == a || v == b) continue;
      const double t = (pts[v] - pts[a]).dot(d) / d.squaredNorm();
      if (t > 0.0 && t < 1.0 && (pts[a] + t * d - pts[v]).norm() <= tol)
        on.emplace_back(t, static_cast<uint32_t>(v));
    }
    std::sort(on.begin(), on.end());
    for (size_t k = 0; k + 1 < on.size(); ++k)
      if (on[k].second != on[k + 1].second)
        split.insert(std::minmax(on[k].second, on[k + 1].second));
  }
  std::vector<std::array<Vec3, 2>> out;
  for (const auto& [a, b] : split) out.push_back({pts[a], pts[b]});
  return out;
}

// Runs the mesher with the project's criteria on a domain whose features are added. Surface
// triangles lie within a tenth of the local zone size of the surface, so faces between pieces
// are resolved wherever zones are fine, not only where they are coarse.
template <class C3t3, class D>
C3t3 refine(const D& domain, double max_edge, const ZoneGrading3* grading,
            const std::atomic<bool>* stop) {
  using Tr = typename C3t3::Triangulation;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
  using Field = SizeField<typename D::Index>;
  // Sizes: the block's edges split into pieces of at most the size; surface triangles and zones
  // bounded by the circumradius of the equilateral triangle and the regular tetrahedron of that
  // edge (h / sqrt 3, h sqrt(3/8)), so that zones of a regular shape have edges of about h.
  const Field edge{max_edge, grading, 1.0, stop},
      facet{max_edge, grading, 1.0 / std::sqrt(3.0), stop},
      cell{max_edge, grading, std::sqrt(3.0 / 8.0), stop};
  // Surface triangles within a tenth of the local size of the surface; between pieces, a
  // surface triangle's corners on one face (else, with all three on some face, it may cut
  // across a thin piece).
  const Field distance{max_edge, grading, 0.1, stop};
  namespace params = CGAL::parameters;
  const Criteria criteria(params::edge_size = edge, params::facet_angle = 25.0,
                          params::facet_size = facet, params::facet_distance = distance,
                          params::facet_topology = CGAL::FACET_VERTICES_ON_SAME_SURFACE_PATCH,
                          params::cell_radius_edge_ratio = 2.0, params::cell_size = cell);
  // The perturber draws from CGAL's default generator: seeded here, the same block gives the
  // same mesh whatever ran before on this thread. It runs while its steps succeed: CGAL's
  // default stops it after as much CPU time as the refinement took, so a busy machine meshed
  // the same block differently (1659 zones against 1656).
  CGAL::get_default_random() = CGAL::Random(0);
  // A failure inside CGAL (e.g. "... is already inserted on surface", met where cuts meet at
  // shallow angles) becomes the command's error; the debugging dump CGAL then writes into the
  // working directory (dump-bug.mesh, dump-bug.binary.cgal) is removed if it was not there.
  const bool had_dump = std::filesystem::exists("dump-bug.mesh");
  try {
    return CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_lloyd(), params::no_odt(),
                                   params::perturb(params::time_limit = 0), params::no_exude());
  } catch (const CGAL::Failure_exception& e) {
    if (!had_dump) {
      std::error_code ec;
      std::filesystem::remove("dump-bug.mesh", ec);
      std::filesystem::remove("dump-bug.binary.cgal", ec);
    }
    std::string why = e.message().empty() ? e.expression() : e.message();
    while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back()))) why.pop_back();
    throw std::invalid_argument("CGAL's mesher failed (" + why +
                                "): try a slightly different edge= or fine=");
  }
}

// The mesher may leave a flat zone on the surface: four nodes on one face of the block, no
// volume (its two outer faces and its two inner ones triangulate the same quadrilateral). Such
// a cap is dropped: the zones behind it then show its inner faces, the same plane, and the
// mesh loses no volume. (A flat zone inside the block cannot go so simply; measure_quality
// reports it.)
void drop_flat_caps(ZoneMesh3& mesh) {
  for (bool dropped = true; dropped;) {
    dropped = false;
    const auto open = open_faces(mesh, false);
    std::vector<uint8_t> drop(mesh.tets.size(), 0);
    for (size_t z = 0; z < mesh.tets.size(); ++z) {
      const auto& t = mesh.tets[z];
      double longest = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          longest = std::max(longest, (mesh.nodes[t[i]] - mesh.nodes[t[j]]).norm());
      const Vec3 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]];
      const double six_v = (b - a).cross(c - a).dot(mesh.nodes[t[3]] - a);
      int outer = 0;
      for (int f = 0; f < 4; ++f) outer += static_cast<int>(open.count(face_key(mesh, z, f)));
      drop[z] = std::abs(six_v) <= 1e-9 * longest * longest * longest && outer >= 2;
      dropped = dropped || drop[z];
    }
    size_t kept = 0;
    for (size_t z = 0; z < mesh.tets.size(); ++z)
      if (!drop[z]) mesh.tets[kept] = mesh.tets[z], mesh.piece[kept] = mesh.piece[z], ++kept;
    mesh.tets.resize(kept), mesh.piece.resize(kept);
  }
}

// The zones' smallest dihedral angle and longest edge, and those under kPoorDihedral degrees.
void measure_quality(ZoneMesh3& mesh) {
  mesh.min_dihedral = 180.0, mesh.max_edge = 0.0, mesh.poor = 0;
  for (const auto& t : mesh.tets) {
    std::array<Vec3, 4> at;
    for (int k = 0; k < 4; ++k) at[k] = mesh.nodes[t[k]];
    const double angle = min_dihedral_angle(at);
    if (angle < mesh.min_dihedral)
      mesh.min_dihedral = angle, mesh.worst_at = 0.25 * (at[0] + at[1] + at[2] + at[3]);
    mesh.poor += angle < ZoneMesh3::kPoorDihedral;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        mesh.max_edge = std::max(mesh.max_edge, (at[i] - at[j]).norm());
  }
}

// Cells of the mesh as zones, each with its piece (0 for one block). The mesher's cells come in
// an order that depends on memory addresses, its vertices not: nodes are numbered in coordinate
// order and zones sorted (by piece, then nodes), so the numbering is the same on every run.
// Each zone lists its nodes ascending, the last two swapped for positive volume.
template <class Cell>
ZoneMesh3 zones_of(const std::vector<std::pair<uint32_t, Cell>>& cells) {
  using Vertex = std::decay_t<decltype(cells[0].second->vertex(0))>;
  std::vector<Vertex> used;
  for (const auto& pc : cells)
    for (int k = 0; k < 4; ++k) used.push_back(pc.second->vertex(k));
  auto point = [](const Vertex& v) { return vec(v->point().point()); };
  auto before = [&](const Vertex& a, const Vertex& b) {
    const Vec3 p = point(a), q = point(b);
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  };
  std::sort(used.begin(), used.end(), before);
  used.erase(std::unique(used.begin(), used.end()), used.end());
  ZoneMesh3 mesh;
  std::map<Vertex, uint32_t> number;
  for (const Vertex& v : used) {
    number.emplace(v, static_cast<uint32_t>(mesh.nodes.size()));
    mesh.nodes.push_back(point(v));
  }
  std::vector<std::pair<uint32_t, std::array<uint32_t, 4>>> tets;
  for (const auto& [piece, c] : cells) {
    std::array<uint32_t, 4> tet;
    for (int k = 0; k < 4; ++k) tet[k] = number.at(c->vertex(k));
    std::sort(tet.begin(), tet.end());
    std::array<Vec3, 4> at;
    for (int k = 0; k < 4; ++k) at[k] = mesh.nodes[tet[k]];
    if ((at[1] - at[0]).cross(at[2] - at[0]).dot(at[3] - at[0]) < 0) std::swap(tet[2], tet[3]);
    tets.emplace_back(piece, tet);
  }
  std::sort(tets.begin(), tets.end());
  for (const auto& [p, t] : tets) mesh.piece.push_back(p), mesh.tets.push_back(t);
  return mesh;
}

// Refuses a piece whose faces do not close: each edge must be met once each way.
void check_closed(const Polyhedron& p) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const auto& face : p.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const uint32_t a = face[k], b = face[(k + 1) % face.size()];
      if (a >= p.vertices.size() || b >= p.vertices.size())
        throw std::invalid_argument("a face names a missing corner");
      ++edges[{a, b}];
    }
  for (const auto& [e, n] : edges)
    if (n != 1 || edges.count({e.second, e.first}) == 0 || edges.at({e.second, e.first}) != 1)
      throw std::invalid_argument("the block's faces do not make one closed surface");
}

// A convex piece's faces as half-spaces n . x <= d (n the outward unit normal).
struct Half {
  Vec3 n;
  double d;
};
std::vector<Half> halves_of(const Polyhedron& p) {
  std::vector<Half> out;
  for (const auto& f : p.faces) {
    const Vec3 n = newell_normal(p.vertices, f);
    double d = -1e300;
    for (uint32_t k : f) d = std::max(d, n.dot(p.vertices[k]));
    out.push_back({n, d});
  }
  return out;
}

// Whether the zones of each piece fill it: every surface triangle of a piece's zones lies in one
// of its faces (within `tol`) and faces out through it.
bool fills_pieces(const ZoneMesh3& mesh, const std::vector<std::vector<Half>>& halves, double tol) {
  const auto open = open_faces(mesh, true);
  for (const auto& [key, tri] : open) {
    const Vec3 &a = mesh.nodes[tri[0]], &b = mesh.nodes[tri[1]], &c = mesh.nodes[tri[2]];
    const Vec3 n = (b - a).cross(c - a);
    bool on = false;
    for (const Half& h : halves.at(key[0]))
      on = on || (h.n.dot(n) > 0.99 * n.norm() && std::abs(h.n.dot(a) - h.d) < tol &&
                  std::abs(h.n.dot(b) - h.d) < tol && std::abs(h.n.dot(c) - h.d) < tol);
    if (!on) return false;
  }
  return true;
}

// The mesher finds points on a face by bisection, to about 1e-11 of the body's size: surface
// nodes within `tol` of a piece's face are put on its plane, so faces stay flat and the zones'
// volumes add up to the pieces'.
void snap_to_faces(ZoneMesh3& mesh, const std::vector<std::vector<Half>>& halves, double tol) {
  std::set<std::pair<uint32_t, uint32_t>> on;  // (node, piece) on that piece's surface
  for (const auto& [key, face] : open_faces(mesh, true))
    for (uint32_t n : face) on.emplace(n, key[0]);
  for (const auto& [n, piece] : on)
    for (const Half& h : halves.at(piece))
      if (const double off = h.n.dot(mesh.nodes[n]) - h.d; std::abs(off) < tol)
        mesh.nodes[n] -= off * h.n;
}

// The exuder's visitor, called after each cell it treats: a stop asked for ends the exudation
// (ZoningStopped), and so does a budget of cells treated (ExudeSpent), counted, not timed, so
// that every machine gets the same mesh; CGAL's exuder can cycle on a bad mesh without end.
struct ExudeSpent {};
struct ExuderBudget {
  const std::atomic<bool>* stop;
  size_t* left;
  void after_cell_pumped(std::size_t) {
    if (stop && stop->load(std::memory_order_relaxed)) throw ZoningStopped();
    if ((*left)-- == 0) throw ExudeSpent();
  }
};

// Exudes c3t3 in place (CGAL's exude_mesh_3 with no time limit and no sliver bound, under a
// budget of `cells` treated); false if the budget ran out (c3t3 is then half done).
template <class C3t3>
bool exude(C3t3& c3t3, size_t cells, const std::atomic<bool>* stop) {
  using Criterion = CGAL::Mesh_3::Min_dihedral_angle_criterion<typename C3t3::Triangulation>;
  using Exuder = CGAL::Mesh_3::Slivers_exuder<C3t3, Criterion, ExuderBudget>;
  Criterion criterion(0.0, c3t3.triangulation());
  Exuder exuder(c3t3, criterion);
  exuder.set_time_limit(0);
  size_t left = cells;
  try {
    exuder(ExuderBudget{stop, &left});
  } catch (const ExudeSpent&) {
    return false;
  }
  return true;
}

// The zones of the mesher's cells (`cells_of` picks them, with their pieces), after CGAL's
// sliver exuder when that is sound. The exuder gives the nodes weights that flip slivers out of
// the triangulation (at 0.14 a in the Salencon slab: 77 zones under 5 degrees -> 2); it runs on
// a copy, to the end (no time limit, so a busy machine gets the same mesh; a budget of cells
// instead, past which the plain mesh is kept), and its zones are
// kept when they still fill every piece exactly and have no more slivers, since a flip may
// take a zone across a face between pieces.
template <class C3t3, class CellsOf>
ZoneMesh3 exuded_zones(const C3t3& plain, const CellsOf& cells_of,
                       const std::vector<std::vector<Half>>& halves, double tol,
                       const std::atomic<bool>* stop) {
  // The zones with their nodes on the faces, flat caps dropped, surface nodes marked, and the
  // quality measured.
  const auto finish = [&](ZoneMesh3 mesh) {
    snap_to_faces(mesh, halves, tol);
    drop_flat_caps(mesh);
    if (mesh.tets.empty()) throw std::invalid_argument("the block is too thin to zone");
    mesh.on_boundary.assign(mesh.nodes.size(), 0);
    for (const auto& [key, face] : open_faces(mesh, false))
      for (uint32_t k : face) mesh.on_boundary[k] = 1;
    measure_quality(mesh);
    return mesh;
  };
  ZoneMesh3 mesh = finish(zones_of(cells_of(plain)));
  if (mesh.poor == 0) return mesh;
  C3t3 copy(plain);
  // A normal exudation treats fewer cells than the triangulation has (17,365 of 27,939 in the
  // Salencon slab); one four times over is going round in circles.
  if (!exude(copy, 4 * copy.triangulation().number_of_finite_cells() + 1000, stop)) return mesh;
  const ZoneMesh3 exuded = finish(zones_of(cells_of(copy)));
  const bool better = exuded.poor < mesh.poor ||
                      (exuded.poor == mesh.poor && exuded.min_dihedral > mesh.min_dihedral);
  return better && fills_pieces(exuded, halves, tol) ? exuded : mesh;
}

}  // namespace

std::array<uint32_t, 4> face_key(const ZoneMesh3& mesh, size_t z, int f, bool by_piece) {
  const auto& t = mesh.tets[z];
  const int* corner = kTetFace[f];
  std::array<uint32_t, 4> key{by_piece ? mesh.piece[z] : 0, t[corner[0]], t[corner[1]],
                              t[corner[2]]};
  std::sort(key.begin() + 1, key.end());
  return key;
}

OpenFaces open_faces(const ZoneMesh3& mesh, bool by_piece) {
  OpenFaces open;
  for (size_t z = 0; z < mesh.tets.size(); ++z)
    for (int f = 0; f < 4; ++f) {
      const auto key = face_key(mesh, z, f, by_piece);
      const auto& t = mesh.tets[z];
      if (!open.erase(key))
        open.emplace(
            key, std::array<uint32_t, 3>{t[kTetFace[f][0]], t[kTetFace[f][1]], t[kTetFace[f][2]]});
    }
  return open;
}

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

ZoneMesh3 zone_pieces(const std::vector<Polyhedron>& pieces, double max_edge, size_t max_zones,
                      const ZoneGrading3* grading, const std::atomic<bool>* stop) {
  if (!(max_edge > 0)) throw std::invalid_argument("the zone size must be positive");
  if (pieces.empty()) throw std::invalid_argument("no pieces to zone");
  // Each piece's faces as half-spaces (the pieces are convex), and the body's box.
  std::vector<std::vector<Half>> halves(pieces.size());
  std::vector<std::pair<Vec3, Vec3>> boxes;
  std::vector<const Polyhedron*> all;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  double volume = 0.0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Polyhedron& p = pieces[i];
    check_closed(p);
    const double piece_volume = solid_properties(p).volume;
    if (!(piece_volume > 0)) throw std::invalid_argument("the block's faces are turned inside out");
    volume += piece_volume;
    Vec3 plo = Vec3::Constant(1e300), phi = Vec3::Constant(-1e300);
    for (const Vec3& v : p.vertices) plo = plo.cwiseMin(v), phi = phi.cwiseMax(v);
    boxes.emplace_back(plo, phi);
    lo = lo.cwiseMin(plo), hi = hi.cwiseMax(phi);
    halves[i] = halves_of(p);
    all.push_back(&p);
  }
  check_sizes(all, volume, max_edge, max_zones, grading);
  const double scale = (hi - lo).norm(), tol = 1e-9 * scale;
  // The label of a point: 1 + the first piece holding it, 0 outside the body.
  const auto label = [halves, boxes](const K::Point_3& q) {
    const Vec3 x = vec(q);
    for (size_t i = 0; i < halves.size(); ++i) {
      if ((x.array() < boxes[i].first.array()).any() || (x.array() > boxes[i].second.array()).any())
        continue;
      bool in = true;
      for (const Half& h : halves[i]) in = in && h.n.dot(x) <= h.d;
      if (in) return static_cast<int>(i) + 1;
    }
    return 0;
  };
  const Vec3 blo = lo - Vec3::Constant(0.1 * scale), bhi = hi + Vec3::Constant(0.1 * scale);
  CGAL::Random rng(0);
  PieceDomain domain(std::function<int(const K::Point_3&)>(label),
                     CGAL::Bbox_3(blo.x(), blo.y(), blo.z(), bhi.x(), bhi.y(), bhi.z()),
                     K::FT(1e-10), CGAL::Null_subdomain_index(), &rng);
  // Every piece's edges protected, split where another piece's corner or edge meets them, so the
  // features meet only at their ends and every piece's faces and corners are kept.
  const std::vector<std::array<Vec3, 2>> features = feature_segments(pieces, tol);
  std::vector<std::vector<K::Point_3>> edges;
  for (const auto& e : features) edges.push_back({point3(e[0]), point3(e[1])});
  domain.add_features(edges.begin(), edges.end());
  using Tr = CGAL::Mesh_triangulation_3<PieceDomain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, PieceDomain::Corner_index,
                                                       PieceDomain::Curve_index>;
  const C3t3 c3t3 = refine<C3t3>(domain, max_edge, grading, stop);
  // A zone's piece: the one holding its centroid. The mesher labels a cell by its circumcentre,
  // which for a sliver against a face can lie in the next piece or outside: such a sliver would
  // be in the wrong piece or missing. A cell it left out is a zone if its centroid lies inside a
  // piece by a millionth of its longest edge (not a flat cell on a face; a 3+1 cell across a
  // thin plate lies in by a fraction of its edges, and dropping it left a hole).
  const auto depth = [&](const Vec3& x, size_t i) {
    double d = 1e300;
    for (const Half& h : halves[i]) d = std::min(d, h.d - h.n.dot(x));
    return d;
  };
  const auto cells_of = [&](const C3t3& c3) {
    std::vector<std::pair<uint32_t, C3t3::Cell_handle>> cells;
    const auto& tr = c3.triangulation();
    for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
      std::array<Vec3, 4> at;
      for (int k = 0; k < 4; ++k) at[k] = vec(c->vertex(k)->point().point());
      const Vec3 centroid = (at[0] + at[1] + at[2] + at[3]) / 4.0;
      const int in = label(point3(centroid));
      if (in == 0) continue;
      if (!c3.is_in_complex(c)) {
        double longest = 0.0;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (at[i] - at[j]).norm());
        if (depth(centroid, static_cast<size_t>(in - 1)) < 1e-6 * longest) continue;
      }
      cells.emplace_back(static_cast<uint32_t>(in - 1), c);
    }
    return cells;
  };
  return exuded_zones(c3t3, cells_of, halves, 1e3 * tol, stop);
}

}  // namespace tessera
