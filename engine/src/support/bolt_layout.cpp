// Placing bolts: where a segment crosses joints between blocks, and patterns around openings.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

namespace {

std::string where(Vec2 p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// Parameters along p0-p1 where it crosses a block outline, sorted, with 0 and 1.
std::vector<double> crossings(const std::vector<std::vector<Vec2>>& polys, Vec2 p0, Vec2 p1) {
  std::vector<double> t{0.0, 1.0};
  const Vec2 d = p1 - p0;
  for (const auto& poly : polys)
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], e = poly[(i + 1) % poly.size()] - a;
      const double den = cross(d, e);
      if (std::abs(den) < 1e-14 * d.norm() * e.norm()) continue;  // along the edge: no crossing
      const double s = cross(a - p0, e) / den, u = cross(a - p0, d) / den;
      if (s > 0.0 && s < 1.0 && u >= 0.0 && u <= 1.0) t.push_back(s);
    }
  std::sort(t.begin(), t.end());
  std::vector<double> out;
  for (double s : t)
    if (out.empty() || s - out.back() > 1e-9) out.push_back(s);
  return out;
}

}  // namespace

// The block holding p (inside its outline), or -1.
int block_at(const Model& m, const std::vector<std::vector<Vec2>>& polys, Vec2 p) {
  const Blocks& B = m.blocks;
  for (size_t b = 0; b < polys.size(); ++b) {
    const double r = B.bound_radius[b] * 1.01 + 1e-12;
    if ((p - Vec2(B.x[b], B.y[b])).squaredNorm() > r * r) continue;
    if (point_in_polygon(p, polys[b])) return static_cast<int>(b);
  }
  return -1;
}

size_t install_bolt(Model& m, const std::string& name, Vec2 p0, Vec2 p1,
                    const BoltProperties& props) {
  const Blocks& B = m.blocks;
  const double len = (p1 - p0).norm();
  if (!(len > 0.0)) throw ModelError("bolt '" + name + "' has no length");
  std::vector<std::vector<Vec2>> polys(B.size());
  for (size_t b = 0; b < B.size(); ++b) polys[b] = B.world_polygon(b);
  const std::vector<double> t = crossings(polys, p0, p1);
  // Which block each stretch between crossings lies in (-1: empty space).
  const size_t n = t.size() - 1;
  std::vector<int> owner(n);
  for (size_t i = 0; i < n; ++i)
    owner[i] = block_at(m, polys, p0 + 0.5 * (t[i] + t[i + 1]) * (p1 - p0));
  // A joint held open by less than the contact tolerance is still crossed (at its middle).
  const double gap = m.tolerance() / len;
  std::vector<std::array<Anchor2, 2>> sides;
  int first = -1, last = -1;
  for (size_t i = 0; i < n; ++i) {
    if (owner[i] < 0) continue;
    if (first < 0) first = static_cast<int>(i);
    if (last >= 0 && owner[static_cast<size_t>(last)] != owner[i] &&
        t[i] - t[static_cast<size_t>(last) + 1] <= gap) {
      const Vec2 at = p0 + 0.5 * (t[static_cast<size_t>(last) + 1] + t[i]) * (p1 - p0);
      sides.push_back({make_anchor(m, static_cast<size_t>(owner[static_cast<size_t>(last)]), at),
                       make_anchor(m, static_cast<size_t>(owner[i]), at)});
    }
    last = static_cast<int>(i);
  }
  const std::string what = "bolt '" + name + "' from " + where(p0) + " to " + where(p1);
  if (first < 0) throw ModelError(what + " crosses no block");
  if (sides.empty())
    throw ModelError(what + " lies in " + m.block_label(static_cast<size_t>(owner[first])) +
                     " and crosses no joint between two blocks");
  Bolt bolt;
  bolt.name = name;
  bolt.props = props;
  const auto f = static_cast<size_t>(first), l = static_cast<size_t>(last);
  bolt.end0 = make_anchor(m, static_cast<size_t>(owner[f]), p0 + t[f] * (p1 - p0));
  bolt.end1 = make_anchor(m, static_cast<size_t>(owner[l]), p0 + t[l + 1] * (p1 - p0));
  m.support.add(bolt, sides, (p1 - p0) / len);
  return m.support.bolts.size() - 1;
}

OpeningWall opening_wall(const Model& m, int tag) {
  const Blocks& B = m.blocks;
  std::vector<std::vector<Vec2>> polys(B.size());
  for (size_t b = 0; b < B.size(); ++b) polys[b] = B.world_polygon(b);
  // Outline edges along the tag with empty space just outside them.
  OpeningWall out;
  double total = 0.0;
  for (size_t b = 0; b < B.size(); ++b)
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
      if (B.edge_tag[v] != tag) continue;
      const uint32_t w = v + 1 < B.vert_begin[b + 1] ? v + 1 : B.vert_begin[b];
      const Vec2 p = B.world_vertex[v], q = B.world_vertex[w], mid = 0.5 * (p + q);
      const double l = (q - p).norm();
      if (!(l > 0.0) || block_at(m, polys, mid - 1e-4 * perp(q - p)) >= 0) continue;
      out.edges.push_back({p, q, perp(q - p) / l, static_cast<int>(b)});
      out.centre += l * mid, total += l;
    }
  if (out.edges.empty())
    throw ModelError(
        "no wall of an excavated opening lies along the joints named: delete the "
        "opening's blocks before placing support on it");
  out.centre /= total;
  // Each edge from its end first met going anticlockwise about the centre; sorted by angle.
  for (WallEdge& e : out.edges) {
    if (cross(e.from - out.centre, e.to - e.from) < 0.0) std::swap(e.from, e.to);
    const Vec2 r = 0.5 * (e.from + e.to) - out.centre;
    e.angle = std::atan2(r.y(), r.x());
  }
  std::sort(out.edges.begin(), out.edges.end(),
            [](const WallEdge& x, const WallEdge& y) { return x.angle < y.angle; });
  return out;
}

size_t install_pattern(Model& m, int tag, double spacing, double length, double a0, double a1,
                       const std::function<void(size_t, Vec2, Vec2)>& place) {
  const OpeningWall wall = opening_wall(m, tag);
  const Vec2 centre = wall.centre;
  size_t placed = 0, tried = 0;
  double s = 0.5 * spacing, along = 0.0;
  // Bolts every `spacing` along the wall, normal to it into rock.
  for (const WallEdge& e : wall.edges) {
    const double l = (e.to - e.from).norm();
    for (; s < along + l; s += spacing) {
      const Vec2 p = e.from + (s - along) / l * (e.to - e.from), in = e.inward;
      const Vec2 r = p - centre;
      double deg = std::atan2(r.y(), r.x()) * 180.0 / M_PI;
      while (deg < a0) deg += 360.0;
      while (deg >= a0 + 360.0) deg -= 360.0;
      if (deg > a1) continue;
      ++tried;
      try {
        place(tried, p - 1e-6 * length * in, p + length * in);
        ++placed;
      } catch (const ModelError&) {
        // A bolt wholly inside one block carries nothing in this model.
      }
    }
    along += l;
  }
  if (tried == 0) throw ModelError("the pattern's angles leave no room for a bolt or cable");
  return placed;
}

size_t install_bolt_pattern(Model& m, const std::string& name, int tag, double spacing,
                            double length, double a0, double a1, const BoltProperties& props) {
  return install_pattern(m, tag, spacing, length, a0, a1, [&](size_t k, Vec2 p0, Vec2 p1) {
    install_bolt(m, name + "-" + std::to_string(k), p0, p1, props);
  });
}

}  // namespace tessera
