// Clipping one face's projection by another's on a common plane.
#include "contact3d/face_overlap.hpp"

namespace tessera {

// Clips polygon `poly` (counter-clockwise) by the counter-clockwise convex polygon `clip`
// (Sutherland-Hodgman), keeping track of the features that make every corner.
void clip_polygon(std::vector<PolyVertex>& poly, const std::vector<PolyVertex>& clip,
                  const std::vector<uint32_t>& clip_vertex, double eps,
                  std::vector<PolyVertex>& scratch) {
  const size_t nc = clip.size();
  for (size_t j = 0; j < nc && !poly.empty(); ++j) {
    const Eigen::Vector2d q0 = clip[j].p, q1 = clip[(j + 1) % nc].p, e = q1 - q0;
    const uint64_t edge_j = clip[j].next_edge;
    scratch.clear();
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
      const PolyVertex& s = poly[i];
      const PolyVertex& t = poly[(i + 1) % n];
      const double ds = cross2(e, s.p - q0), dt = cross2(e, t.p - q0);
      const bool s_in = ds >= -eps, t_in = dt >= -eps;
      // Where edge s-t meets clip line j: an A edge crossing a B edge, or a corner of B.
      const auto meet = [&](uint64_t next) {
        const double r = ds / (ds - dt);
        uint64_t key;
        if (s.next_edge & kEdgeB) {
          const uint32_t i_edge = static_cast<uint32_t>(s.next_edge & (kEdgeB - 1));
          const uint32_t j_edge = static_cast<uint32_t>(edge_j & (kEdgeB - 1));
          key = kKeyVertexB | clip_vertex[(i_edge + 1) % nc == j_edge ? j_edge : i_edge];
        } else {
          key = kKeyCross | (s.next_edge << 31) | (edge_j & (kEdgeB - 1));
        }
        return PolyVertex{s.p + r * (t.p - s.p), key, next};
      };
      if (s_in && t_in) {
        scratch.push_back(t);
      } else if (s_in && !t_in) {
        if (ds > eps) scratch.push_back(meet(edge_j));
      } else if (!s_in && t_in) {
        if (dt > eps) scratch.push_back(meet(s.next_edge));
        scratch.push_back(t);
      }
    }
    poly.swap(scratch);
  }
}

}  // namespace tessera
