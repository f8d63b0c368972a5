// The overlap of two faces on a contact's common plane, shared by the corner sub-contacts of
// rigid faces (subcontacts.cpp) and the node sub-contacts of deformable ones
// (node_subcontacts.cpp). Internal to the engine.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

// Keys: what made a corner of the overlap polygon.
constexpr uint64_t kKeyVertexA = 1ull << 62, kKeyVertexB = 2ull << 62, kKeyCross = 3ull << 62;
// Edge identities while clipping: A's edges are face_vert positions, B's are offset by this.
constexpr uint64_t kEdgeB = 1ull << 31;

struct PolyVertex {
  Eigen::Vector2d p;
  uint64_t key;
  uint64_t next_edge;  // the edge from this vertex to the next
};

inline double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// Clips polygon `poly` (counter-clockwise) by the counter-clockwise convex polygon `clip`
// (Sutherland-Hodgman), keeping track of the features that make every corner.
void clip_polygon(std::vector<PolyVertex>& poly, const std::vector<PolyVertex>& clip,
                  const std::vector<uint32_t>& clip_vertex, double eps,
                  std::vector<PolyVertex>& scratch);

// Tangent basis of a plane (t1 x t2 = n).
inline std::pair<Vec3, Vec3> tangents(const Vec3& n) {
  const Vec3 t1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  return {t1, n.cross(t1)};
}

// A new sub-contact's joint state: that of last cycle's sub-contact with its key, or else of the
// nearest within the tolerance (blocks move far less in a step); `used` marks those taken. A
// new one of a contact bonded when the model was made is bonded too.
void carry_state(const Model& m, const Contact3& c, SubContact& s,
                 const std::vector<SubContact>& old, std::vector<uint8_t>& used);

// Node sub-contacts (either block deformable): rebuilt from the facing faces on the plane of
// normal n, or followed between rebuilds; the velocity of one side (0: a, 1: b) at a sub-contact.
void rebuild_node_subcontacts(const Model& m, Contact3& c, const Vec3& n);
void follow_node_subcontacts(const Model& m, Contact3& c, const Vec3& n);
Vec3 side_velocity(const Model& m, const Contact3& c, const SubContact& s, int side);

}  // namespace tessera
