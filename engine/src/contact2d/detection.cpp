// Contact detection pass: cell-grid broad phase on bounding boxes, rounded-corner search for
// each candidate pair, and a merge that keeps the history of contacts that persist.
#include "tessera/contact2d/detection.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "tessera/contact2d/contact_geometry.hpp"
#include "tessera/core/step.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {

struct Box {
  double x0, y0, x1, y1;
};

bool overlap(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

// Bounding boxes of the blocks, grown by `grow` on every side.
std::vector<Box> block_boxes(const Blocks& B, double grow) {
  std::vector<Box> boxes(B.size());
  for (size_t b = 0; b < B.size(); ++b) {
    Box x{1e300, 1e300, -1e300, -1e300};
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
      const Vec2& p = B.world_vertex[v];
      x.x0 = std::min(x.x0, p.x()), x.y0 = std::min(x.y0, p.y());
      x.x1 = std::max(x.x1, p.x()), x.y1 = std::max(x.y1, p.y());
    }
    boxes[b] = {x.x0 - grow, x.y0 - grow, x.x1 + grow, x.y1 + grow};
  }
  return boxes;
}

// Candidate pairs (lo, hi) whose boxes overlap, sorted. Blocks go into the cells of a uniform
// grid sized by the median block; a block covering many cells is tested against all others.
std::vector<std::pair<uint32_t, uint32_t>> broad_phase(const std::vector<Box>& boxes) {
  const size_t n = boxes.size();
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  if (n < 2) return pairs;
  std::vector<double> sizes(n);
  for (size_t b = 0; b < n; ++b)
    sizes[b] = std::max(boxes[b].x1 - boxes[b].x0, boxes[b].y1 - boxes[b].y0);
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(n / 2), sizes.end());
  const double h = std::max(sizes[n / 2], 1e-12);
  auto cell = [h](double v) { return static_cast<int64_t>(std::floor(v / h)); };
  std::vector<std::pair<int64_t, uint32_t>> entries;
  std::vector<uint32_t> large;
  entries.reserve(4 * n);
  for (uint32_t b = 0; b < n; ++b) {
    const int64_t ix0 = cell(boxes[b].x0), ix1 = cell(boxes[b].x1);
    const int64_t iy0 = cell(boxes[b].y0), iy1 = cell(boxes[b].y1);
    if ((ix1 - ix0 + 1) * (iy1 - iy0 + 1) > 16) {
      large.push_back(b);
      continue;
    }
    for (int64_t ix = ix0; ix <= ix1; ++ix)
      for (int64_t iy = iy0; iy <= iy1; ++iy)
        entries.emplace_back((ix << 32) ^ (iy & 0xffffffffLL), b);
  }
  std::sort(entries.begin(), entries.end());
  auto keep = [&](uint32_t a, uint32_t b) {
    if (overlap(boxes[a], boxes[b])) pairs.emplace_back(std::min(a, b), std::max(a, b));
  };
  for (size_t s = 0; s < entries.size();) {
    size_t e = s;
    while (e < entries.size() && entries[e].first == entries[s].first) ++e;
    for (size_t i = s; i < e; ++i)
      for (size_t j = i + 1; j < e; ++j) {
        const uint32_t a = entries[i].second, b = entries[j].second;
        // Report the pair only from the cell holding the corner of the boxes' overlap.
        const int64_t ox = cell(std::max(boxes[a].x0, boxes[b].x0));
        const int64_t oy = cell(std::max(boxes[a].y0, boxes[b].y0));
        if (((ox << 32) ^ (oy & 0xffffffffLL)) != entries[s].first) continue;
        keep(a, b);
      }
    s = e;
  }
  for (uint32_t l : large)
    for (uint32_t b = 0; b < n; ++b) {
      if (b == l) continue;
      const bool b_large = std::binary_search(large.begin(), large.end(), b);
      if (b_large && b < l) continue;
      keep(l, b);
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// A contact found in this pass: corner `corner` of `owner` against the feature of `other` it
// meets, the feature's vertex index with its kind and slot in the top bits (a pass holds one
// pair's; the geometry is computed again from these when the contact is stored).
struct Found {
  uint32_t owner, corner, other, packed;
  Found(uint32_t o, uint32_t c, uint32_t b, uint32_t feature, uint8_t slot, uint8_t kind)
      : owner(o),
        corner(c),
        other(b),
        packed(feature | uint32_t(kind) << 30 | uint32_t(slot) << 31) {
    if (feature >= (1u << 30)) throw ModelError("too many block vertices (2^30 at most)");
  }
  uint32_t feature() const { return packed & ((1u << 30) - 1); }
  uint8_t kind() const { return static_cast<uint8_t>((packed >> 30) & 1u); }
  uint8_t slot() const { return static_cast<uint8_t>(packed >> 31); }
  uint32_t lo() const { return std::min(owner, other); }
  uint32_t hi() const { return std::max(owner, other); }
};

// The geometry of a find, as the search computed it.
FeatureHit found_hit(const Blocks& B, const Found& f) {
  FeatureHit hit;
  const CornerArc arc = corner_arc(B, f.owner, f.corner);
  const double depth = max_contact_depth(B, f.owner, f.other);
  const bool ok = f.kind() == kCornerEdge
                      ? edge_feature(B, f.other, f.feature(), arc, depth, hit, nullptr)
                      : corner_feature(B, f.other, f.feature(), arc, depth, hit);
  if (!ok) throw std::logic_error("a contact found in detection has lost its feature");
  return hit;
}

// Corners of `owner` within reach of block `other` (a gap below `reach`); `other_box` is its box
// grown by reach - margin, so a corner's arc is tested against it grown by `margin` more.
void corner_search(const Blocks& B, uint32_t owner, uint32_t other, const Box& other_box,
                   double reach, double margin, std::vector<Found>& out) {
  const bool corners = owner < other;
  const int nf = 2 * static_cast<int>(B.vertex_count(other));
  for (uint32_t v = B.vert_begin[owner]; v < B.vert_begin[owner + 1]; ++v) {
    if (!B.convex[v]) continue;
    const CornerArc arc = corner_arc(B, owner, v);
    const Vec2& c = arc.centre;
    const double r = arc.radius + margin;
    if (c.x() + r < other_box.x0 || c.x() - r > other_box.x1 || c.y() + r < other_box.y0 ||
        c.y() - r > other_box.y1)
      continue;
    FeatureHit hit;
    const double depth = max_contact_depth(B, owner, other);
    if (!nearest_feature(B, other, arc, corners, 0, nf, depth, hit) || hit.gap >= reach) continue;
    out.emplace_back(owner, v, other, hit.feature, 0, hit.kind);
    if (B.all_convex[other] || hit.kind != kCornerEdge) continue;
    // In the notch of a concave block the corner also touches a second face: one it is near,
    // not a face of the block far behind the first.
    FeatureHit second, h;
    bool has_second = false;
    for (uint32_t e = B.vert_begin[other]; e < B.vert_begin[other + 1]; ++e)
      if (edge_feature(B, other, e, arc, depth, h, nullptr) && std::abs(h.gap) < reach &&
          h.normal.dot(hit.normal) < 0.7 && (!has_second || std::abs(h.gap) < std::abs(second.gap)))
        second = h, has_second = true;
    if (!has_second) continue;
    out.emplace_back(owner, v, other, second.feature, 1, second.kind);
  }
}

}  // namespace

void detect_contacts(Model& m) {
  Blocks& B = m.blocks;
  const double tol = m.tolerance();
  const size_t n = B.size();
  Contacts& old = m.contacts;
  // Length and the interfaces' sums are recomputed before they are read (the geometry stage,
  // then the interfaces): the pass drops them, so that its own arrays fit in their room, as
  // soon as it cannot fail. It fails only where no joint properties apply to a new contact,
  // which cannot happen when some assignment covers every contact.
  const auto release_recomputed = [&] {
    std::vector<double>().swap(old.length);
    std::vector<Vec2>().swap(old.pair_force);
    std::vector<double>().swap(old.pair_moment), std::vector<double>().swap(old.pair_load);
  };
  const bool covered = std::any_of(m.joint_table.begin(), m.joint_table.end(), [](const auto& j) {
    return j.tag < 0 && j.group_a < 0 && j.group_b < 0;
  });
  // Freed memory goes back to the system as the pass turns (glibc keeps freed pages of its heap
  // resident, and the arrays a pass frees and makes, megabytes each, would leave holes that add
  // to the resident set pass after pass).
  const auto give_back = [] {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
  };
  if (covered) release_recomputed();
  give_back();
  for (size_t b = 0; b < n; ++b) B.update_world(b);
  update_deformable_world(m);
  std::vector<Box> boxes = block_boxes(B, 0.5 * tol);
  // Held blocks meet each other too: one may be driven at a velocity into the other, and a
  // bond made now must be there when either is freed.
  auto pairs = broad_phase(boxes);
  // Narrow phase, pair by pair in sorted order, run again for each use rather than holding a
  // list of finds (16 bytes a contact at the pass's peak): to check that joint properties apply
  // to each new contact (where that can fail), to learn where each find's contact was, and,
  // once the arrays are gathered, to fill in identity and geometry. The same blocks give the
  // same finds in the same order every time.
  constexpr uint32_t kNew = std::numeric_limits<uint32_t>::max();
  std::vector<Found> scratch;  // one pair's finds
  const auto pair_finds = [&](uint32_t lo, uint32_t hi) {
    scratch.clear();
    corner_search(B, lo, hi, boxes[hi], tol, 0.5 * tol, scratch);
    corner_search(B, hi, lo, boxes[lo], tol, 0.5 * tol, scratch);
  };
  // The joint of a new contact, from the tag of the face met (for a rounded corner, the later
  // of its two edges); -1 when no joint properties apply.
  const auto joint_of = [&](const Found& f) {
    const uint32_t e = f.feature();
    const uint32_t v0 = B.vert_begin[f.other], nv = B.vertex_count(f.other);
    const uint32_t prev = v0 + (e - v0 + nv - 1) % nv;
    int tag = std::max(B.edge_tag[e], B.edge_tag[prev]);
    if (f.kind() == kCornerEdge) {
      // The face met, and the owner's edge that lies along it (a joint is tagged on either
      // side, or only on the side a generator made).
      const uint32_t o0 = B.vert_begin[f.owner], no = B.vertex_count(f.owner);
      const uint32_t oprev = o0 + (f.corner - o0 + no - 1) % no;
      const Vec2& u = B.world_edge_dir[e];
      const bool in_along =
          std::abs(B.world_edge_dir[oprev].dot(u)) >= std::abs(B.world_edge_dir[f.corner].dot(u));
      tag = std::max(B.edge_tag[e], B.edge_tag[in_along ? oprev : f.corner]);
    }
    return std::pair{m.joint_for(f.owner, f.other, tag), tag};
  };
  // Where each find's contact was: the finds merged with the old contacts (both sorted by key).
  // For a new contact, whether joint properties apply is checked when `check` is set (it may
  // fail, and nothing is changed yet; the joint is looked up again when the contact is made).
  std::vector<uint32_t> from;
  const auto match = [&](bool check) {
    size_t j = 0;
    auto old_key = [&](size_t i) {
      const uint32_t lo = std::min(old.a[i], old.b[i]), hi = std::max(old.a[i], old.b[i]);
      return std::make_tuple(lo, hi, old.a[i], old.corner[i], old.slot[i]);
    };
    for (const auto& [lo, hi] : pairs) {
      pair_finds(lo, hi);
      for (const Found& f : scratch) {
        const auto key = std::make_tuple(f.lo(), f.hi(), f.owner, f.corner, f.slot());
        while (j < old.size() && old_key(j) < key) ++j;
        if (j < old.size() && old_key(j) == key) {
          if (!check) from.push_back(static_cast<uint32_t>(j));
          continue;
        }
        if (check && joint_of(f).first < 0)
          throw ModelError("no joint properties apply to the contact between " +
                           m.block_label(f.owner) + " and " + m.block_label(f.other) +
                           ": use 'joint assign'");
        if (!check) from.push_back(kNew);
      }
    }
  };
  // The check needs a pass of its own unless some assignment covers every contact; length and
  // the interfaces' sums go after it. Then `from` is filled (room for about as many as last time,
  // or on a first pass three a pair: two or three corners meet a neighbour).
  if (!covered) {
    match(true);
    release_recomputed();
  }
  from.reserve(std::max(old.size() + old.size() / 16, 3 * pairs.size()) + 64);
  match(false);
  // Contacts dropped while dilation held them loaded (for a warning).
  {
    std::vector<uint8_t> kept(old.size(), 0);
    for (uint32_t k : from)
      if (k != kNew) kept[k] = 1;
    for (size_t i = 0; i < old.size(); ++i)
      if (!kept[i]) m.note_lost(old.flags[i], old.fn[i], old.dilation[i]);
  }
  const size_t count = from.size();
  Contacts next;
  // Each array gathered from the old store, zeros for new contacts. In place when the old array
  // has room (kept contacts keep their order, so those moving down can be moved first, lowest
  // first, then those moving up, highest first, and no value is overwritten before it is read):
  // a pass then never holds two copies of an array. Otherwise into a new array (on a later pass,
  // with a little room to grow), the old one freed at once.
  const auto gather = [&](auto& to, auto& was) {
    using T = typename std::decay_t<decltype(to)>::value_type;
    const T zero = [] {
      if constexpr (std::is_arithmetic_v<T>)
        return T(0);
      else
        return T(T::Zero());
    }();
    if (count > was.capacity()) {
      to.reserve(was.empty() ? count : count + count / 64);
      to.assign(count, zero);
      for (size_t k = 0; k < count; ++k)
        if (from[k] != kNew) to[k] = was[from[k]];
      std::decay_t<decltype(was)>().swap(was);
      return;
    }
    if (count > was.size()) was.resize(count);
    for (size_t k = 0; k < count; ++k)
      if (from[k] != kNew && from[k] > k) was[k] = was[from[k]];
    for (size_t k = count; k-- > 0;)
      if (from[k] != kNew && from[k] < k) was[k] = was[from[k]];
    for (size_t k = 0; k < count; ++k)
      if (from[k] == kNew) was[k] = zero;
    was.resize(count);
    to.swap(was);
  };
  Contacts::each_carried(gather, next, old);
  // Optional arrays stay absent unless the old store held them.
  Contacts::each_optional(
      [&](auto& to, auto& was) {
        if (!was.empty()) gather(to, was);
      },
      next, old);
  size_t k = 0;
  for (const auto& [lo, hi] : pairs) {
    pair_finds(lo, hi);
    for (size_t q = 0; q < scratch.size(); ++q, ++k) {
      if (k >= count) throw std::logic_error("a detection pass found different contacts twice");
      const Found& f = scratch[q];
      const FeatureHit hit = found_hit(B, f);
      if (from[k] == kNew) {
        // A new contact: who it joins and the joint it is on; no history (zeros).
        next.a[k] = f.owner, next.b[k] = f.other, next.corner[k] = f.corner;
        next.slot[k] = f.slot();
        const auto [joint, tag] = joint_of(f);
        next.joint[k] = static_cast<uint32_t>(joint), next.tag[k] = tag;
        const JointProperties& jp = m.joints[static_cast<size_t>(joint)];
        // Joints shut when the model is assembled are bonded (cohesion and tension act); a
        // contact open by more than round-off is a gap, not a joint.
        if (m.cycle == 0 && (jp.cohesion > 0.0 || jp.tension > 0.0) && hit.gap <= m.bond_gap())
          next.flags[k] |= kBonded;
      }
      next.kind[k] = hit.kind, next.feature[k] = hit.feature, next.gap[k] = hit.gap;
      next.normal[k] = hit.normal, next.point[k] = hit.point;
      // Both contacts of a corner in a notch keep their own face (its second follows it).
      const bool notch = f.slot() == 1 || (q + 1 < scratch.size() && scratch[q + 1].slot() == 1);
      next.flags[k] =
          static_cast<uint8_t>(notch ? next.flags[k] | kNotch : next.flags[k] & ~kNotch);
    }
  }
  if (k != count) throw std::logic_error("a detection pass found different contacts twice");
  // The pass's arrays go before length comes back.
  std::vector<uint32_t>().swap(from), std::vector<Found>().swap(scratch);
  decltype(pairs)().swap(pairs), std::vector<Box>().swap(boxes);
  give_back();
  next.length.assign(count, 0.0);
  // Interface ranges.
  next.pair_begin.assign(1, 0);
  for (size_t i = 0; i < next.size(); ++i) {
    if (i > 0 && (std::min(next.a[i], next.b[i]) != std::min(next.a[i - 1], next.b[i - 1]) ||
                  std::max(next.a[i], next.b[i]) != std::max(next.a[i - 1], next.b[i - 1])))
      next.pair_begin.push_back(static_cast<uint32_t>(i));
  }
  if (next.size() > 0) next.pair_begin.push_back(static_cast<uint32_t>(next.size()));
  m.contacts = std::move(next);
  m.build_block_contacts();
  m.det_x = B.x, m.det_y = B.y, m.det_theta = B.theta;
  m.det_node = m.continuum.pos;
  m.detection_due = false;
  ++m.detection_passes;
  give_back();
}

std::string find_overlap2d(const Model& m) {
  const Blocks& B = m.blocks;
  const double tol = m.tolerance();
  const std::vector<Box> boxes = block_boxes(B, 0.0);
  for (const auto& [lo, hi] : broad_phase(boxes)) {
    const auto pa = B.world_polygon(lo), pb = B.world_polygon(hi);
    // Any vertex deeper than the tolerance inside the other block, or a centroid inside it.
    auto deep_inside = [&](const std::vector<Vec2>& pts, const std::vector<Vec2>& poly) {
      for (const Vec2& p : pts) {
        if (!point_in_polygon(p, poly)) continue;
        double depth = 1e300;
        for (size_t k = 0; k < poly.size(); ++k) {
          const Vec2 &q0 = poly[k], &q1 = poly[(k + 1) % poly.size()];
          const Vec2 u = (q1 - q0).normalized();
          const double t = std::clamp((p - q0).dot(u), 0.0, (q1 - q0).norm());
          depth = std::min(depth, (p - (q0 + t * u)).norm());
        }
        if (depth > tol) return true;
      }
      return false;
    };
    // Two edges crossing each other by more than the tolerance (a "+" of two blocks, where
    // no vertex of either lies inside the other).
    auto edges_cross = [&] {
      for (size_t i = 0; i < pa.size(); ++i)
        for (size_t k = 0; k < pb.size(); ++k) {
          const Vec2 &a0 = pa[i], &a1 = pa[(i + 1) % pa.size()];
          const Vec2 &b0 = pb[k], &b1 = pb[(k + 1) % pb.size()];
          const Vec2 ua = (a1 - a0).normalized(), ub = (b1 - b0).normalized();
          const double d1 = cross(ua, b0 - a0), d2 = cross(ua, b1 - a0);
          const double d3 = cross(ub, a0 - b0), d4 = cross(ub, a1 - b0);
          if (std::min(d1, d2) < -tol && std::max(d1, d2) > tol && std::min(d3, d4) < -tol &&
              std::max(d3, d4) > tol)
            return true;
        }
      return false;
    };
    // A block's centroid (when it lies in the block) deep inside the other: a block inside
    // another, or two blocks made twice over, where no vertex is deeper than the other's edges.
    auto centroid_inside = [&](uint32_t p, const std::vector<Vec2>& own,
                               const std::vector<Vec2>& poly) {
      const Vec2 c(B.x[p], B.y[p]);
      return point_in_polygon(c, own) && deep_inside({c}, poly);
    };
    if (deep_inside(pa, pb) || deep_inside(pb, pa) || edges_cross() ||
        centroid_inside(lo, pa, pb) || centroid_inside(hi, pb, pa)) {
      std::ostringstream s;
      s << "blocks " << B.id[lo] << " and " << B.id[hi] << " overlap (near x=" << B.x[lo]
        << ", y=" << B.y[lo] << ")";
      return s.str();
    }
  }
  return {};
}

}  // namespace tessera
