// Placing a liner on an opening's wall, and keeping it through block deletion.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/liners.hpp"

namespace tessera {

size_t install_liner(Model& m, const std::string& name, int tag, double a0, double a1,
                     const LinerProperties& props, double spacing) {
  const OpeningWall wall = opening_wall(m, tag);
  const bool ring = a1 - a0 >= 360.0 - 1e-9;
  // The wall edges within the angles, in order about the opening.
  std::vector<WallEdge> edges;
  for (const WallEdge& e : wall.edges) {
    double deg = e.angle * 180.0 / M_PI;
    while (deg < a0) deg += 360.0;
    while (deg >= a0 + 360.0) deg -= 360.0;
    if (ring || deg <= a1) edges.push_back(e);
  }
  if (edges.empty()) throw ModelError("liner '" + name + "': its angles hold no wall");
  // An open liner starts after the widest angular gap, so that it runs the wall in one piece.
  if (!ring) {
    size_t start = 0;
    double widest = -1.0;
    for (size_t k = 0; k < edges.size(); ++k) {
      const double prev = edges[(k + edges.size() - 1) % edges.size()].angle;
      const double gap = std::remainder(edges[k].angle - prev - M_PI, 2.0 * M_PI) + M_PI;
      if (gap > widest) widest = gap, start = k;
    }
    std::rotate(edges.begin(), edges.begin() + static_cast<long>(start), edges.end());
  }
  // The chain must be unbroken: each edge starts where the one before ends, to within the
  // contact tolerance (blocks that have moved along a joint since they were cut, as in a model
  // settled before it is dug, leave their walls' ends apart by that much).
  const double tol = std::max(m.tolerance(), 1e-6 * (edges.front().to - edges.front().from).norm());
  for (size_t k = 1; k < edges.size() + (ring ? 1 : 0); ++k) {
    const WallEdge &a = edges[k - 1], &b = edges[k % edges.size()];
    if ((a.to - b.from).norm() > tol) {
      std::ostringstream msg;
      msg << "liner '" << name << "': the wall is broken at x=" << a.to.x() << ", y=" << a.to.y()
          << " (its ends " << (a.to - b.from).norm() << " m apart, beyond the contact tolerance "
          << m.tolerance() << " m; is all of the opening excavated?)";
      throw ModelError(msg.str());
    }
  }
  // Nodes at most `spacing` apart: each wall edge split into equal pieces on its own rock.
  if (spacing > 0.0) {
    std::vector<WallEdge> pieces;
    for (const WallEdge& e : edges) {
      const int k =
          std::max(1, static_cast<int>(std::ceil((e.to - e.from).norm() / spacing - 1e-9)));
      for (int j = 0; j < k; ++j) {
        WallEdge piece = e;
        piece.from = e.from + (e.to - e.from) * (static_cast<double>(j) / k);
        piece.to = j + 1 == k ? e.to : e.from + (e.to - e.from) * (static_cast<double>(j + 1) / k);
        pieces.push_back(piece);
      }
    }
    edges = std::move(pieces);
  }
  // A node at each vertex, on the rock of the edge that starts there (the last: the one ending).
  const size_t n = ring ? edges.size() : edges.size() + 1;
  std::vector<Anchor2> hosts;
  std::vector<Vec2> at, normals;
  std::vector<double> lengths;
  for (size_t k = 0; k < n; ++k) {
    const WallEdge* after = k < edges.size() ? &edges[k] : nullptr;
    const WallEdge* before = k > 0 ? &edges[k - 1] : ring ? &edges.back() : nullptr;
    const Vec2 p = after ? after->from : before->to;
    const int b = after ? after->block : before->block;
    hosts.push_back(make_anchor(m, static_cast<size_t>(b), p));
    at.push_back(p);
    Vec2 nrm = Vec2::Zero();
    double len = 0.0;
    for (const WallEdge* e : {before, after})
      if (e) nrm += e->inward, len += 0.5 * (e->to - e->from).norm();
    normals.push_back(nrm.normalized()), lengths.push_back(len);
  }
  Liner l;
  l.name = name, l.props = props, l.closed = ring ? 1 : 0;
  m.liners.add(l, hosts, at, normals, lengths);
  m.dt_dirty = true;
  return n;
}

void remap_liners(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map) {
  Liners& L = m.liners;
  if (L.empty()) return;
  // A liner goes whole when any of its rock goes (it cannot stand half on nothing).
  Liners kept;
  std::vector<int32_t> node_to(L.size(), -1);
  for (const Liner& l : L.liners) {
    std::vector<Anchor2> hosts;
    bool ok = true;
    for (uint32_t i = l.first; ok && i < l.first + l.count; ++i) {
      Anchor2 a = L.host[i];
      ok = follow_anchor(a, map, node_map);
      hosts.push_back(a);
    }
    if (!ok) continue;
    const auto b = L.pos0.begin() + l.first, e = b + l.count;
    const size_t f = kept.size();
    kept.add(l, hosts, {b, e}, {L.normal.begin() + l.first, L.normal.begin() + l.first + l.count},
             {L.length.begin() + l.first, L.length.begin() + l.first + l.count});
    for (uint32_t k = 0; k < l.count; ++k) {
      const size_t o = l.first + k, w = f + k;
      node_to[o] = static_cast<int32_t>(w);
      kept.disp[w] = L.disp[o], kept.vel[w] = L.vel[o], kept.rot[w] = L.rot[o];
      kept.spin[w] = L.spin[o], kept.shear[w] = L.shear[o], kept.axial[w] = L.axial[o];
      kept.m_start[w] = L.m_start[o], kept.m_end[w] = L.m_end[o], kept.v_shear[w] = L.v_shear[o];
      kept.plastic_axial[w] = L.plastic_axial[o], kept.hinge_start[w] = L.hinge_start[o];
      kept.hinge_end[w] = L.hinge_end[o], kept.pressure[w] = L.pressure[o];
      kept.state[w] = L.state[o];
    }
  }
  L = std::move(kept);
  m.dt_dirty = true;
  for (auto& s : m.histories.series)
    if (s.element >= 0 && is_liner_quantity(s.quantity))
      s.element = node_to[static_cast<size_t>(s.element)];
}

}  // namespace tessera
