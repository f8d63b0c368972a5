// The joint lines of 2D interfaces: a lone corner's wedge length, whether the joint runs between
// two contacts, and each contact's stretch of joint for output.
#include "contact2d/joint_lines.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/contact2d/interfaces.hpp"

namespace tessera {

// The stretch of joint a corner stands for when it is alone on its joint line (its neighbour
// has lifted off): the corner as a sharp wedge cut by the other block's surface, each of its two
// edges overlapping up to where it leaves that surface (at most the edge's straight part), and
// half of that extent, since a spring bed under a wedge carries kn o s / 2. Without it the
// length is the arc's chord, which vanishes as the overlap passes 2d, and a toppling block on
// soft joints sinks through its base on its toe. Just after the neighbour lifts, the wedge runs
// the whole face and the length is the share the two had: (w - 2d) / 2.
double wedge_length(const Blocks& B, uint32_t a, uint32_t v, const Vec2& nrm, const Vec2& point,
                    double gap) {
  const uint32_t vp = B.prev_vertex(a, v);
  const Vec2 t = perp(nrm);
  // Depth of the sharp corner below the other block's surface (normals point to the owner).
  const Vec2 surface = point - 0.5 * gap * nrm;
  const double depth = (surface - B.world_vertex[v]).dot(nrm);
  if (!(depth > 0.0)) return 0.0;
  const uint32_t v0 = B.vert_begin[a], n = B.vertex_count(a);
  const uint32_t next = v0 + (v - v0 + 1) % n;
  double width = 0.0;
  // One edge leaving the corner along u: it rises out of the surface after depth / rise.
  const auto edge = [&](const Vec2& u, double straight) {
    const double rise = u.dot(nrm), cap = std::max(straight, 0.0);
    const double s = rise * cap > depth ? depth / rise : cap;
    width += s * std::abs(u.dot(t));
  };
  edge(B.world_edge_dir[v], B.edge_length[v] - B.round_length[v] - B.round_length[next]);
  edge(-B.world_edge_dir[vp], B.edge_length[vp] - B.round_length[vp] - B.round_length[v]);
  return 0.5 * width;
}

namespace {

// Whether block b's outline passes within `reach` of p.
bool outline_near(const Blocks& B, uint32_t b, const Vec2& p, double reach) {
  const uint32_t v0 = B.vert_begin[b], v1 = B.vert_begin[b + 1];
  for (uint32_t v = v0; v < v1; ++v)
    if (segment_distance(p, B.world_vertex[v], B.world_vertex[v + 1 < v1 ? v + 1 : v0]) <= reach)
      return true;
  return false;
}

}  // namespace

bool joint_between(const Blocks& B, uint32_t a, uint32_t b, const Vec2& p, const Vec2& q,
                   double reach) {
  const Vec2 mid = 0.5 * (p + q);
  return outline_near(B, a, mid, reach) && outline_near(B, b, mid, reach);
}

std::vector<ContactStretch> contact_stretches(const Model& m) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  std::vector<ContactStretch> out(C.size());
  for (size_t i = 0; i < C.size(); ++i) out[i] = {C.point[i], C.point[i]};
  if (C.pair_begin.empty() || C.pair_begin.back() != C.size()) return out;
  std::vector<LinePoint> along;
  std::vector<uint8_t> placed;
  const double merge = contact_merge(m), reach = m.tolerance();
  for (size_t p = 0; p < C.pair_count(); ++p) {
    const uint32_t c0 = C.pair_begin[p], c1 = C.pair_begin[p + 1];
    const auto joined = joined_test(B, C, c0, reach, C.gap.data(), C.point.data());
    for_each_joint_line(C, c0, c1, C.kind.data(), C.normal.data(), C.point.data(), along, placed,
                        [&](std::vector<LinePoint>& line, const Vec2& t) {
                          // Each contact's length (what the cycle used) at the middle of its part
                          // of the stretch.
                          share_length(
                              line, merge, joined, [](uint32_t) { return 0.0; },
                              [&](uint32_t i, double, double lo, double hi) {
                                const Vec2 centre =
                                    C.point[i] + (0.5 * (lo + hi) - C.point[i].dot(t)) * t;
                                const Vec2 half = 0.5 * C.length[i] * t;
                                out[i] = {centre - half, centre + half};
                              });
                        });
  }
  return out;
}

}  // namespace tessera
