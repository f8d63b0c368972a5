// The joint lines of a 2D interface and each contact's share of their length (chapter 5.2.1:
// L = RQ1/2 + RQ2/2), written once for the cycle (contact2d/interfaces.cpp, which stores the
// lengths) and for output (contact_stretches, which places each share along its joint).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/core/model.hpp"

namespace tessera {

// A contact's position along its joint line (the line's tangent dotted with its point), and its
// index.
using LinePoint = std::pair<double, uint32_t>;

// The stretch of joint a corner stands for when it has no neighbour to share with (wedge_length
// in joint_lines.cpp): corner v of block a, with the contact's normal, point and gap.
double wedge_length(const Blocks& B, uint32_t a, uint32_t v, const Vec2& nrm, const Vec2& point,
                    double gap);

// Whether the joint between blocks a and b runs through the midpoint of contact points p and q:
// both outlines pass within `reach` of it. Between two contacts of convex blocks it always does;
// between those of a concave block it need not (the two halves of a region meeting on either
// side of a tunnel have nothing between them across the opening).
bool joint_between(const Blocks& B, uint32_t a, uint32_t b, const Vec2& p, const Vec2& q,
                   double reach);

// Contacts closer than this along a joint line stand at one point (two corners face to face).
inline double contact_merge(const Model& m) {
  return 0.25 * m.settings.rounding;
}

// The joint test of neighbouring contacts i, j of the pair whose first contact is c0: always
// joined for two convex blocks (their touch is one stretch), else joint_between their points,
// reaching the tolerance beyond the deeper of their gaps.
inline auto joined_test(const Blocks& B, const Contacts& C, uint32_t c0, double tolerance,
                        const double* gap, const Vec2* point) {
  const uint32_t a = C.a[c0], b = C.b[c0];
  const bool convex = B.all_convex[a] && B.all_convex[b];
  return [convex, a, b, tolerance, gap, point, &B](uint32_t i, uint32_t j) {
    return convex || joint_between(B, a, b, point[i], point[j],
                                   tolerance + std::max(std::abs(gap[i]), std::abs(gap[j])));
  };
}

// Calls line(along, t) for each joint line of contacts [c0, c1) of a pair: the live contacts
// (kind not lost) split by the way they face (a concave block can touch another along two
// faces), with their positions along the line's tangent t. `along` and `placed` are scratch.
template <class Line>
void for_each_joint_line(const Contacts& C, uint32_t c0, uint32_t c1, const uint8_t* kind,
                         const Vec2* normal, const Vec2* point, std::vector<LinePoint>& along,
                         std::vector<uint8_t>& placed, const Line& line) {
  // Normals point towards the owner: compare them turned to point the same way.
  const auto facing = [&](uint32_t q) { return C.a[q] < C.b[q] ? normal[q] : Vec2(-normal[q]); };
  // Fast path (convex blocks, nearly every pair): all contacts face one way, one line.
  bool one_line = true;
  Vec2 n_first = Vec2::Zero(), t_first = Vec2::Zero();
  along.clear();
  for (uint32_t i = c0; i < c1 && one_line; ++i) {
    if (kind[i] == kLost) continue;
    const Vec2 f = facing(i);
    if (along.empty())
      n_first = f, t_first = perp(f);
    else if (!(f.dot(n_first) > 0.8))
      one_line = false;
    along.emplace_back(point[i].dot(t_first), i);
  }
  if (one_line) {
    if (!along.empty()) line(along, t_first);
    return;
  }
  placed.assign(c1 - c0, 0);
  for (uint32_t i = c0; i < c1; ++i) {
    if (kind[i] == kLost || placed[i - c0]) continue;
    const Vec2 n0 = facing(i), t = perp(n0);
    along.clear();
    for (uint32_t q = i; q < c1; ++q)
      if (kind[q] != kLost && !placed[q - c0] && facing(q).dot(n0) > 0.8) {
        placed[q - c0] = 1;
        along.emplace_back(point[q].dot(t), q);
      }
    line(along, t);
  }
}

// Shares a joint line's length among its contacts: each group of contacts (those closer than
// `merge` stand at one point, two corners meeting face to face, and split its share evenly, so
// that round-off in their order cannot move length from one to the other from cycle to cycle)
// takes half the distance to each neighbouring group the joint runs to (`joined(i, j)`, the
// facing contacts of two neighbouring groups). A group with no such neighbour (a corner whose
// neighbour lifted off, or one cut off by openings on both sides) takes its corners' wedge
// lengths (`wedge(i)`). Calls sink(i, share, lo, hi) per contact, with its part [lo, hi] of
// the group's stretch along the line (a point, for a wedge).
template <class Joined, class Wedge, class Sink>
inline void share_length(std::vector<LinePoint>& along, double merge, const Joined& joined,
                         const Wedge& wedge, const Sink& sink) {
  const size_t k = along.size();
  // Order by position, then index (std::pair's order, written out: its three-way comparison
  // costs twice the instructions).
  const auto before = [](const LinePoint& x, const LinePoint& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  };
  // Two contacts apart (the usual line): each takes half the distance between them, as below.
  if (k == 2) {
    if (before(along[1], along[0])) std::swap(along[0], along[1]);
    const double x0 = along[0].first, x1 = along[1].first;
    if (x1 - x0 > merge && joined(along[0].second, along[1].second)) {
      const double len = 0.5 * (x1 - x0);
      sink(along[0].second, len, x0, x0 + len);
      sink(along[1].second, len, x1 - len, x1);
      return;
    }
  }
  // Insertion sort: a line has a handful of contacts, mostly in order already.
  for (size_t j = 1; j < k; ++j)
    for (size_t q = j; q > 0 && before(along[q], along[q - 1]); --q)
      std::swap(along[q], along[q - 1]);
  // Centre of the group of contacts starting at g0; g1 receives the index past the group.
  auto group = [&](size_t g0, size_t& g1) {
    g1 = g0 + 1;
    double sum = along[g0].first;
    while (g1 < k && along[g1].first - along[g1 - 1].first <= merge) sum += along[g1++].first;
    return sum / static_cast<double>(g1 - g0);
  };
  size_t g0 = 0, g1 = 0;
  double prev = 0.0, centre = k ? group(0, g1) : 0.0;
  bool left = false;  // whether the joint runs to the group before
  while (g0 < k) {
    size_t g2 = g1;
    const double next = g1 < k ? group(g1, g2) : centre;
    const bool right = g1 < k && joined(along[g1 - 1].second, along[g1].second);
    const double count = static_cast<double>(g1 - g0);
    if (!left && !right) {
      for (size_t j = g0; j < g1; ++j) {
        const uint32_t i = along[j].second;
        sink(i, wedge(i) / count, centre, centre);
      }
    } else {
      const double below = left ? centre - prev : 0.0, above = right ? next - centre : 0.0;
      const double len = 0.5 * (below + above), part = len / count;
      const double lo = centre - 0.5 * below;
      for (size_t j = g0; j < g1; ++j) {
        const double at = lo + part * static_cast<double>(j - g0);
        sink(along[j].second, part, at, at + part);
      }
    }
    prev = centre, centre = next, g0 = g1, g1 = g2, left = right;
  }
}

}  // namespace tessera
