// Contact detection of 3D blocks: bounding boxes swept along the axis of widest spread, then
// the common plane of each close pair.
#include "tessera/contact3d/detection3.hpp"

#include <algorithm>
#include <sstream>

#include "tessera/contact3d/common_plane.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

namespace {

struct Box3 {
  Vec3 lo, hi;
};

std::vector<Box3> block_boxes3(const Blocks3& B, double grow) {
  std::vector<Box3> boxes(B.size());
  for (size_t b = 0; b < B.size(); ++b) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
      lo = lo.cwiseMin(B.world_vertex[v]), hi = hi.cwiseMax(B.world_vertex[v]);
    boxes[b] = {lo - Vec3::Constant(grow), hi + Vec3::Constant(grow)};
  }
  return boxes;
}

// Pairs (lo, hi) whose boxes overlap, sorted: sweep and prune along the axis on which the
// blocks spread most.
std::vector<std::pair<uint32_t, uint32_t>> broad_phase3(const std::vector<Box3>& boxes) {
  const size_t n = boxes.size();
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  if (n < 2) return pairs;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Box3& x : boxes) lo = lo.cwiseMin(x.lo), hi = hi.cwiseMax(x.hi);
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  std::vector<uint32_t> order(n);
  for (uint32_t b = 0; b < n; ++b) order[b] = b;
  std::sort(order.begin(), order.end(), [&](uint32_t p, uint32_t q) {
    return boxes[p].lo[axis] < boxes[q].lo[axis] ||
           (boxes[p].lo[axis] == boxes[q].lo[axis] && p < q);
  });
  for (size_t i = 0; i < n; ++i) {
    const Box3& a = boxes[order[i]];
    for (size_t j = i + 1; j < n && boxes[order[j]].lo[axis] <= a.hi[axis]; ++j) {
      const Box3& b = boxes[order[j]];
      if ((a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all())
        pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace

void detect_contacts3(Model& m) {
  m.blocks3.catch_up();
  const Blocks3& B = m.blocks3;
  const double tol = m.tolerance();
  std::vector<Contact3> next;
  size_t j = 0;
  auto& old = m.contacts3;
  std::vector<uint8_t> kept(old.size(), 0);
  for (const auto& [lo, hi] : broad_phase3(block_boxes3(B, 0.5 * tol))) {
    const auto mlo = static_cast<size_t>(B.master[lo]), mhi = static_cast<size_t>(B.master[hi]);
    // Pieces of one body never touch. (Held bodies do: one may be driven into the other, and a
    // bond made now must be there when either is freed.)
    if (mlo == mhi) continue;
    const PlaneFit fit = best_plane(B, lo, hi);
    if (fit.gap > tol) continue;
    while (j < old.size() && std::make_pair(old[j].a, old[j].b) < std::make_pair(lo, hi)) ++j;
    if (j < old.size() && old[j].a == lo && old[j].b == hi) {
      kept[j] = 1;
      next.push_back(std::move(old[j]));
    } else {
      Contact3 c;
      c.a = lo, c.b = hi;
      c.tag = fit.kind == kPlaneFaceB   ? B.face_tag[fit.ib]
              : fit.kind == kPlaneFaceA ? B.face_tag[fit.ia]
                                        : -1;
      const int joint = m.joint_for(lo, hi, c.tag);
      if (joint < 0)
        throw ModelError("no joint properties apply to the contact between " + m.block_label(lo) +
                         " and " + m.block_label(hi) + ": use 'joint assign'");
      c.joint = static_cast<uint32_t>(joint);
      c.face_a = B.face_begin[lo], c.face_b = B.face_begin[hi];
      next.push_back(std::move(c));
    }
    Contact3& c = next.back();
    c.kind = fit.kind, c.ia = fit.ia, c.ib = fit.ib;
  }
  for (size_t i = 0; i < old.size(); ++i)
    if (!kept[i])
      for (const SubContact& s : old[i].subs) m.note_lost(s.flags, s.fn, s.dilation);
  m.contacts3 = std::move(next);
  m.build_block_contacts();
  m.det_pos3.resize(B.size()), m.det_q3.resize(B.size());
  for (size_t b = 0; b < B.size(); ++b)
    m.det_pos3[b] = B.body[b].position, m.det_q3[b] = B.body[b].orientation;
  m.det_node3 = m.continuum3.pos;
  m.detection_due = false;
  ++m.detection_passes;
}

std::string find_overlap3(const Model& m) {
  const Blocks3& B = m.blocks3;
  B.catch_up();
  const double tol = m.tolerance();
  for (const auto& [lo, hi] : broad_phase3(block_boxes3(B, 0.0))) {
    const PlaneFit fit = best_plane(B, lo, hi);
    if (fit.gap < -tol) {
      std::ostringstream s;
      const Vec3& p = B.body[lo].position;
      s << "blocks " << B.id[lo] << " and " << B.id[hi] << " overlap by " << -fit.gap
        << " m (near x=" << p.x() << ", y=" << p.y() << ", z=" << p.z() << ")";
      return s.str();
    }
  }
  return {};
}

}  // namespace tessera
