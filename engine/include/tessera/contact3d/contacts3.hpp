// Contacts between 3D blocks (chapter 5.3.2): Cundall's common plane and its sub-contacts.
//
// Design. A contact is one pair of blocks (a < b) within the contact tolerance. Its common plane
// (CP) bisects the space between them with the normal from b towards a; of all planes it is the
// one that maximises the gap, or minimises the overlap: the largest over unit normals n of
//   gap(n) = min over a's vertices of n.x  -  max over b's vertices of n.x.
// For convex blocks that maximum, while they overlap, lies at a face normal of either block or
// at a cross product of an edge direction of each (the separating-axis candidates); while they
// are apart it is at least the best candidate's value. Detection passes search every candidate;
// each cycle moves the plane with the blocks by re-evaluating the candidate found (its
// direction turns continuously with the blocks), so the normal never jumps between passes.
//
// Sub-contacts. Each block's face that faces the plane (outward normal most nearly against its
// side of the plane, kept while no other face is better by a margin) is projected onto the CP;
// the two projections overlap in a convex polygon whose corners are the sub-contacts: vertices
// of a's face inside b's (vertex-to-face), vertices of b's face inside a's (face-to-vertex) and
// crossings of their edges (edge-to-edge) - the union of 3DEC's two sub-contact sets, each point
// once, so no halving of forces is needed. Each takes half of the two fan triangles (from the
// polygon's centroid) beside it as its area, so the areas add up to the contact area; its gap is
// measured between the two faces along the normal. A sub-contact keeps its joint state from
// cycle to cycle by its key (which features make it), or failing that by its position (the
// nearest within the tolerance: blocks move far less in a step), so shear force survives while
// the overlap polygon changes shape.
//
// Rebuilding the overlap polygon is most of a contact's cost, so it is done when the blocks have
// moved against each other by a hundredth of the contact tolerance since the last rebuild (every
// cycle for a sliding or rocking block, seldom in a settling wall); in between each sub-contact
// rides on block a (its point is kept in the frame of a's body) and its gap is measured afresh
// between the two faces' current planes, and the plane's normal is the candidate face's current
// normal.
//
// Deformable blocks (§5.3.2). A face of a deformable block touches as its surface nodes: each
// surface triangle of the facing face is clipped by the other face on the plane, and the clipped
// area goes to the triangle's three nodes in the barycentric weights of its centroid, so the
// nodes' areas add up to the contact area and their first moment is the overlap's. Each node
// with area is a sub-contact whose gap is measured from the node to the other face (to the
// surface triangle it meets on a deformable one) along the normal. Where both blocks are
// deformable both sets act with half the area each: the same total stiffness and force.
//
// The shear force is a vector in the CP, kept as its two components in a tangent basis of the
// plane that turns with it: each cycle a touching contact projects its first tangent onto the
// plane as it now is (the least turn that keeps it in the plane, so the force neither twists
// about the normal nor changes magnitude); a rebuild that moves the plane re-expresses the
// forces in the new basis. The joint law's state is the sub-contact's own (no copy a cycle).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tessera/contact3d/polyhedron.hpp"
#include "tessera/core/joint_law.hpp"

namespace tessera {

// How the best common-plane candidate was found: a face of b, a face of a, or an edge
// direction of each.
enum PlaneKind : uint8_t { kPlaneFaceB = 0, kPlaneFaceA = 1, kPlaneEdges = 2 };
// What touches, from how many vertices of each block lie within the tolerance of the plane.
enum ContactType3 : uint8_t { kVertexFace = 0, kEdgeEdge = 1, kEdgeFace = 2, kFaceFace = 3 };

// A surface node of a deformable block against the other block's face (§5.3.2): the node, its
// side (0: a, 1: b), and on a deformable opposite face the surface triangle met, with the
// weights that share its motion and force.
struct NodeLink {
  int32_t node = -1;
  uint8_t side = 0;
  std::array<int32_t, 3> tri{-1, -1, -1};
  Vec3 weight = Vec3::Zero();
};

// 160 bytes: what the cycle reads and writes at a corner of the overlap or at a node. Its joint
// law state (JointState: normal force, compression positive; shear force on a and total shear
// displacement as components along the contact's t1 and t2; normal displacement of the last
// cycle; dilation; flags; plastic shear travel) is the law's argument itself.
struct SubContact : JointState {
  uint64_t key = 0;
  // Its point on the common plane in the frame of a's moving body (about its centroid, in its
  // axes): between rebuilds it rides on a with no update. world_point() gives it in world axes.
  Vec3 local = Vec3::Zero();
  double area = 0.0, gap = 0.0;
  double closure = 0.0;       // in-situ closure sigma_n / kn added to the overlap (as 2D's)
  Vec3 force = Vec3::Zero();  // on a this cycle
  int32_t link = -1;          // its node in the contact's `nodes`; -1 at a corner of rigid faces
};

struct Contact3 {
  uint32_t a = 0, b = 0;
  uint32_t joint = 0;
  int tag = -1;
  // The candidate that gives the plane: its kind and the face or edge-direction indices.
  uint8_t kind = kPlaneFaceB;
  uint32_t ia = 0, ib = 0;
  // The faces of a and b facing the plane (global face indices).
  uint32_t face_a = 0, face_b = 0;
  uint8_t type = kFaceFace;
  // Every sub-contact stayed open last cycle (a hint: the plane's pass tries the law's open
  // branch for them all first, and leaves the law nothing to do if it holds).
  bool open = false;
  Vec3 normal = Vec3::UnitZ();
  // The plane's first tangent, in which the sub-contacts' shear is kept (t2 = normal x t1); zero
  // until the first rebuild sets it.
  Vec3 t1 = Vec3::Zero();
  Vec3 t2() const { return normal.cross(t1); }
  double offset = 0.0, gap = 0.0;  // plane: normal . x = offset (at the last rebuild)
  // Relative motion of the blocks since the sub-contacts were last rebuilt (bounded at their
  // reach); a new contact starts due.
  double drift = 1e300;
  std::vector<SubContact> subs;
  // The nodes of the node sub-contacts (a deformable block's side), none between rigid blocks.
  std::vector<NodeLink> nodes;
  // Resultant on a this cycle (b takes the opposite), with the torques about each centroid, and
  // the sum of |Fn| + |Fs| over the sub-contacts.
  Vec3 force = Vec3::Zero(), torque_a = Vec3::Zero(), torque_b = Vec3::Zero();
  double force_mag = 0.0;
};

// A sub-contact's shear force on a, in world axes.
inline Vec3 shear_force(const Contact3& c, const SubContact& s) {
  return s.fs * c.t1 + s.fs2 * c.t2();
}

}  // namespace tessera
