// Placing cables (nodes in blocks, bonded lengths) and keeping them through block deletion.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/cables.hpp"

namespace tessera {

namespace {
// The block holding p, or the one whose outline is nearest within `tol` (a node on a joint).
int host_block(const Model& m, const std::vector<std::vector<Vec2>>& polys, Vec2 p, double tol) {
  if (const int b = block_at(m, polys, p); b >= 0) return b;
  int best = -1;
  double dist = tol;
  for (size_t b = 0; b < polys.size(); ++b)
    for (size_t i = 0; i < polys[b].size(); ++i) {
      const double d = segment_distance(p, polys[b][i], polys[b][(i + 1) % polys[b].size()]);
      if (d <= dist) dist = d, best = static_cast<int>(b);
    }
  return best;
}

// Places a cable of `segments` from p0 to p1 with nodes hosted by host(p) (-1: in no block);
// in_rock(p) says whether a point of a half segment lies in rock (and bonds its node).
template <int D, class HostAt, class InRock>
size_t install(Model& m, CablesT<D>& K, const std::string& name, const typename CablesT<D>::V& p0,
               const typename CablesT<D>::V& p1, int segments, const CableProperties& props,
               double free, bool head, HostAt host, InRock in_rock) {
  using V = typename CablesT<D>::V;
  const double len = (p1 - p0).norm();
  std::ostringstream what;
  auto point = [](std::ostream& o, const V& p) {
    o << "(";
    for (int k = 0; k < D; ++k) o << (k ? ", " : "") << p[k];
    o << ")";
  };
  what << "cable '" << name << "' from ";
  point(what, p0);
  what << " to ";
  point(what, p1);
  if (!(len > 0.0)) throw ModelError(what.str() + " has no length");
  if (segments < 1) throw ModelError(what.str() + " needs at least one segment");
  const auto n = static_cast<size_t>(segments) + 1;
  const double h = len / segments;
  std::vector<typename CablesT<D>::Host> hosts;
  std::vector<double> bonded(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    const V p = p0 + (static_cast<double>(k) / segments) * (p1 - p0);
    const auto anchor = host(p);
    if (anchor.block < 0) {
      std::ostringstream s;
      s << what.str() << ": node " << k + 1 << " at ";
      point(s, p);
      s << " lies in no block (a cable runs through rock; start it on the wall)";
      throw ModelError(s.str());
    }
    hosts.push_back(anchor);
  }
  // Each half segment in rock and past the free length bonds its node.
  for (size_t k = 0; k + 1 < n; ++k)
    for (int side = 0; side < 2; ++side) {
      const double at = (static_cast<double>(k) + (side ? 0.75 : 0.25)) * h;
      if (at < free || !in_rock(V(p0 + at / len * (p1 - p0)))) continue;
      bonded[k + static_cast<size_t>(side)] += 0.5 * h;
    }
  if (std::all_of(bonded.begin(), bonded.end(), [](double b) { return b == 0.0; }) && !head)
    throw ModelError(what.str() + " is bonded nowhere and has no head: nothing holds it");
  Cable c;
  c.name = name, c.props = props, c.head = head ? 1 : 0;
  const size_t i = K.add(c, hosts, bonded);
  const Cable& added = K.cables[i];
  for (uint32_t k = added.first; k + 1 < added.first + added.count; ++k) K.rest[k] = h;
  for (uint32_t k = added.first; k < added.first + added.count; ++k)
    K.pos[k] = anchor_position(m, K.host[k]), K.axis[k] = (p1 - p0) / len;
  m.dt_dirty = true;
  return i;
}
}  // namespace

size_t install_cable(Model& m, const std::string& name, Vec2 p0, Vec2 p1, int segments,
                     const CableProperties& props, double free, bool head) {
  const Blocks& B = m.blocks;
  std::vector<std::vector<Vec2>> polys(B.size());
  for (size_t b = 0; b < B.size(); ++b) polys[b] = B.world_polygon(b);
  return install(
      m, m.cables, name, p0, p1, segments, props, free, head,
      [&](const Vec2& p) {
        const int b = host_block(m, polys, p, m.tolerance());
        return b < 0 ? Anchor2{} : make_anchor(m, static_cast<size_t>(b), p);
      },
      [&](const Vec2& p) { return block_at(m, polys, p) >= 0; });
}

size_t install_cable3(Model& m, const std::string& name, const Vec3& p0, const Vec3& p1,
                      int segments, const CableProperties& props, double free, bool head) {
  return install(
      m, m.cables3, name, p0, p1, segments, props, free, head,
      [&](const Vec3& p) {
        const int b = block3_at(m, p, m.tolerance());
        return b < 0 ? Anchor3{} : make_anchor3(m, static_cast<size_t>(b), p);
      },
      [&](const Vec3& p) { return block3_at(m, p, 0.0) >= 0; });
}

namespace {
// Nodes whose rock is excavated go (follow(host) false); a cable cut by the excavation goes on
// as its runs of two or more nodes left in rock (the second and later named NAME.2, NAME.3,
// ...). Histories at a node follow it; those at a removed one end.
template <int D, class Follow>
void remap_nodes(Model& m, CablesT<D>& K, Follow follow) {
  if (K.empty()) return;
  CablesT<D> kept;
  std::vector<int32_t> node_to(K.size(), -1);
  for (const Cable& c : K.cables) {
    std::vector<typename CablesT<D>::Host> hosts(c.count);
    std::vector<uint8_t> ok(c.count);
    for (uint32_t k = 0; k < c.count; ++k) {
      hosts[k] = K.host[c.first + k];
      ok[k] = follow(hosts[k]) ? 1 : 0;
    }
    int run = 0;
    for (uint32_t k0 = 0; k0 < c.count;) {
      uint32_t k1 = k0;
      while (k1 < c.count && ok[k1]) ++k1;
      if (k1 - k0 >= 2) {
        Cable nc = c;
        if (++run > 1) nc.name.append(".").append(std::to_string(run));
        nc.head = c.head && k0 == 0;
        const std::vector<typename CablesT<D>::Host> h(hosts.begin() + k0, hosts.begin() + k1);
        const std::vector<double> bonded(K.bonded.begin() + c.first + k0,
                                         K.bonded.begin() + c.first + k1);
        const uint32_t f = kept.cables[kept.add(nc, h, bonded)].first;
        for (uint32_t k = k0; k < k1; ++k) {
          const uint32_t o = c.first + k, e = f + k - k0;
          node_to[o] = static_cast<int32_t>(e);
          kept.slip[e] = K.slip[o], kept.slip_plastic[e] = K.slip_plastic[o];
          kept.vel[e] = K.vel[o], kept.inertia[e] = K.inertia[o], kept.bond[e] = K.bond[o];
          kept.state[e] = K.state[o], kept.rest[e] = K.rest[o], kept.plastic[e] = K.plastic[o];
          kept.axial[e] = k + 1 < k1 ? K.axial[o] : 0.0;
          kept.pos[e] = K.pos[o], kept.axis[e] = K.axis[o];
        }
      }
      k0 = std::max(k1, k0 + 1);
    }
  }
  K = std::move(kept);
  m.dt_dirty = true;
  for (auto& s : m.histories.series)
    if (s.element >= 0 && is_cable_quantity(s.quantity))
      s.element = node_to[static_cast<size_t>(s.element)];
}
}  // namespace

void remap_cables(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map) {
  remap_nodes(m, m.cables, [&](Anchor2& a) { return follow_anchor(a, map, node_map); });
}

void remap_cables3(Model& m, const std::vector<int>& map, const std::vector<int64_t>& node_map) {
  remap_nodes(m, m.cables3, [&](Anchor3& a) { return follow_anchor(a, map, node_map); });
}

}  // namespace tessera
