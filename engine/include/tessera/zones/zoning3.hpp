// Zoning in 3D: a polyhedral block cut into the constant-strain tetrahedra of a deformable
// block (§5.3.1), by CGAL's 3D mesher (Delaunay refinement, then sliver perturbation), with the
// block's edges protected so that its faces and edges are kept exactly. (CGAL's sliver
// exudation is left out: it flips zones in an order that depends on memory addresses, so the
// same block would not always give the same mesh; it raised the smallest angle by 0.4 degrees.)
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"
#include "tessera/zones/zoning.hpp"

namespace tessera {

using ZoneGrading3 = Grading<Vec3>;

// Thrown when meshing is stopped by its stop flag; nothing of the mesh is kept.
struct ZoningStopped : std::runtime_error {
  ZoningStopped() : std::runtime_error("zoning stopped") {}
};

struct ZoneMesh3 {
  std::vector<Vec3> nodes;
  std::vector<uint8_t> on_boundary;           // per node: lies on the block's surface
  std::vector<std::array<uint32_t, 4>> tets;  // positive volume: (b - a) x (c - a) . (d - a) > 0
  std::vector<uint32_t> piece;                // per tet: the piece it fills (zone_pieces), or 0
  std::vector<std::array<uint32_t, 6>> mid;   // quadratic meshes: mid-edge nodes (make_quadratic)
  double min_dihedral = 0.0;                  // smallest dihedral angle of any zone, degrees
  Vec3 worst_at = Vec3::Zero();               // the centre of the zone with that angle
  size_t poor = 0;                            // zones with a dihedral angle under kPoorDihedral
  double max_edge = 0.0;                      // longest zone edge
  // Zones this flat stiffen and scatter the answer near them (a plastic zone's extent was out
  // by 30% with 77 zones under 5 degrees in a Salencon slab of 22,000; none under 9.6: 0.8%).
  static constexpr double kPoorDihedral = 5.0;
};

// One mesh of tetrahedra filling a body of convex pieces that touch along their faces (a joined
// block; one piece for a convex block). Edges of about `max_edge` (every piece's edges split
// into pieces of at most `max_edge`, zones' circumradii at most that of a regular tetrahedron
// of that edge; the longest zone edge comes out under 2 `max_edge`), finer near a grading's
// centre. The zones conform across the faces between pieces (nodes shared, no joint), each zone
// lies in one piece (`piece`, zones sorted by it), every piece's corners are nodes and its faces
// are covered by zone faces, and the zones' volumes add up to the pieces'. Edges of pieces that
// end on another's edge, or cross it, are split there. Slivers are exuded where that keeps the
// pieces filled; flat zones left on the surface (four nodes on one face) are dropped, and the
// mesh's quality is measured (`min_dihedral`, `worst_at`, `poor`). The same input gives the same
// mesh. Throws std::invalid_argument for a piece that is not a closed, outward-facing surface,
// a size that is not positive, or one that would make more than `max_zones` zones.
// `stop`, when given and set from another thread, ends the meshing by ZoningStopped.
ZoneMesh3 zone_pieces(const std::vector<Polyhedron>& pieces, double max_edge,
                      size_t max_zones = 2000000, const ZoneGrading3* grading = nullptr,
                      const std::atomic<bool>* stop = nullptr);

// A zone's four faces: the face opposite corner k, each listed so that it faces out of a
// positive zone (counter-clockwise seen from outside).
inline constexpr int kTetFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
// Face f of zone z as a key: (its piece with `by_piece`, else 0; then its nodes sorted).
std::array<uint32_t, 4> face_key(const ZoneMesh3& mesh, size_t z, int f, bool by_piece = false);
// The faces met by one zone only, by key, each with its nodes as its zone lists them: the
// body's surface, or with `by_piece` each piece's (faces between pieces included).
using OpenFaces = std::map<std::array<uint32_t, 4>, std::array<uint32_t, 3>>;
OpenFaces open_faces(const ZoneMesh3& mesh, bool by_piece = false);

// A point as a script writes it (x,y,z, four significant digits), for messages about zones.
inline std::string point_text(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "%.4g,%.4g,%.4g", p.x(), p.y(), p.z());
  return text;
}

// Smallest dihedral angle of a tetrahedron, degrees (0 for a flat one).
double min_dihedral_angle(const std::array<Vec3, 4>& corners);

}  // namespace tessera
