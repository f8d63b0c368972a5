// Deformable blocks: zoning, outline from nodes, contact forces on nodes, removal.
#include "tessera/zones/deformable.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "tessera/core/block_loads.hpp"
#include "tessera/core/geometry.hpp"
#include "tessera/core/timestep.hpp"
#include "tessera/support/reinforcement.hpp"
#include "tessera/zones/deformable3.hpp"

namespace tessera {

void sync_zone_materials(Model& m) {
  for (std::vector<ZoneProperties>* zm : {&m.continuum.materials, &m.continuum3.materials}) {
    std::vector<ZoneProperties>& c = *zm;
    c.resize(m.materials.size() + 1);
    c[0].name = "null";
    c[0].model = "null";
    c[0].finalize();
    for (size_t k = 0; k < m.materials.size(); ++k)
      if (!m.materials[k].zone.model.empty()) c[k + 1] = m.materials[k].zone;
  }
}

namespace {
// The outline nodes of a mesh in order, starting at the polygon's first vertex, with each
// sub-edge's tag taken from the polygon edge it lies on.
void ordered_outline(const ZoneMesh& mesh, const std::vector<Vec2>& poly,
                     const std::vector<int>& tags, std::vector<uint32_t>& nodes,
                     std::vector<int>& node_tags) {
  std::map<uint32_t, uint32_t> next;
  for (const auto& e : boundary_edges(mesh)) next[e[0]] = e[1];
  uint32_t start = 0;
  double best = 1e300;
  for (uint32_t n = 0; n < mesh.nodes.size(); ++n)
    if (const double d = (mesh.nodes[n] - poly[0]).norm(); d < best) best = d, start = n;
  size_t corner = 0;  // polygon edge the walk is on
  uint32_t n = start;
  do {
    nodes.push_back(n);
    // Moving past the next polygon corner moves to the next polygon edge.
    if (corner + 1 < poly.size() && n != start &&
        (mesh.nodes[n] - poly[corner + 1]).norm() < 1e-9 * (1 + poly[corner + 1].norm()))
      ++corner;
    node_tags.push_back(corner < tags.size() ? tags[corner] : -1);
    const auto it = next.find(n);
    if (it == next.end()) throw std::invalid_argument("the zoned outline is not closed");
    n = it->second;
  } while (n != start && nodes.size() <= mesh.nodes.size());
}
}  // namespace

void make_deformable(Model& m, size_t b, double max_edge, const ZoneGrading* grading) {
  Blocks& B = m.blocks;
  if (B.deformable[b]) throw std::invalid_argument("it is deformable already");
  if (loaded(B, b))
    throw std::invalid_argument(
        "it carries a load ('load'): zone it first, then load its nodes ('boundary stress')");
  if (!m.support.empty() || !m.cables.empty() || !m.liners.empty())
    throw std::invalid_argument(
        "bolts or cables are placed already: zone blocks before placing support");
  const int mat = B.material[b];
  if (mat < 0 || m.materials[static_cast<size_t>(mat)].zone.model.empty())
    throw std::invalid_argument(
        "its material has no elastic constants (give E and nu, or K "
        "and G, on 'material define')");
  sync_zone_materials(m);
  B.update_world(b);
  const std::vector<Vec2> poly = B.world_polygon(b);
  std::vector<int> tags(B.edge_tag.begin() + B.vert_begin[b],
                        B.edge_tag.begin() + B.vert_begin[b + 1]);
  const ZoneMesh mesh = zone_polygon(poly, max_edge, 2000000, grading);
  const uint32_t first = add_mesh(m.continuum, mesh, static_cast<uint32_t>(mat + 1));
  std::vector<uint32_t> outline;
  std::vector<int> outline_tags;
  ordered_outline(mesh, poly, tags, outline, outline_tags);
  std::vector<Vec2> pts;
  std::vector<int32_t> nodes;
  for (uint32_t n : outline)
    pts.push_back(mesh.nodes[n]), nodes.push_back(static_cast<int32_t>(first + n));
  B.theta[b] = 0.0;
  B.set_outline(b, pts, m.settings.rounding, outline_tags, nodes);
  B.deformable[b] = 1;
  // Nodes along a straight edge touch other blocks as points (§5.2.2, case 1): contact corners
  // with no rounding.
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
    if (!B.convex[v] &&
        std::abs(cross(B.world_edge_dir[v], B.world_edge_dir[B.prev_vertex(b, v)])) < 1e-9) {
      B.convex[v] = 1, B.arc_radius[v] = 0.0, B.round_length[v] = 0.0;
      B.local_arc_centre[v] = B.local_vertex[v], B.world_arc_centre[v] = B.world_vertex[v];
    }
  // Straight nodes are no notches: the block is as convex as its original outline.
  B.all_convex[b] = 1;
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
    if (!B.convex[v]) B.all_convex[b] = 0;
  // The rigid motion is replaced by the nodes' motion.
  B.fixity[b] = kFixAll;
  B.vx[b] = B.vy[b] = B.omega[b] = 0.0;
  B.fixed_vx[b] = B.fixed_vy[b] = B.fixed_omega[b] = 0.0;
  B.refresh_inverse_mass(b);
  lump_masses(m.continuum);
  m.contacts.clear();
  m.touch();
}

void update_deformable_world(Model& m) {
  Blocks& B = m.blocks;
  const double d = m.settings.rounding;
  std::vector<Vec2> pts;
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b]) continue;
    const uint32_t v0 = B.vert_begin[b], v1 = B.vert_begin[b + 1];
    pts.clear();
    for (uint32_t v = v0; v < v1; ++v)
      pts.push_back(m.continuum.pos[static_cast<size_t>(B.node[v])]);
    const std::vector<RoundedCorner> corners = round_corners(pts, d);
    for (uint32_t v = v0; v < v1; ++v) {
      const size_t k = v - v0;
      const Vec2 e = pts[(k + 1) % pts.size()] - pts[k];
      B.world_vertex[v] = pts[k];
      // Rounded corners follow the deformed outline; straight nodes stay points.
      B.world_arc_centre[v] =
          B.arc_radius[v] > 0.0 && corners[k].convex ? corners[k].centre : pts[k];
      B.edge_length[v] = e.norm();
      B.world_edge_dir[v] = e / e.norm();
    }
  }
}

namespace {
template <int D>
size_t set_nodes_of(ContinuumT<D>& c, const std::vector<size_t>& nodes, uint8_t bits, bool free,
                    const double* velocity, uint8_t set_velocity) {
  for (size_t n : nodes)
    for (int k = 0; k < D; ++k) {
      const uint8_t bit = node_fix_bit(k);
      if (bits & bit) {
        if (free) {
          c.fixity[n] &= static_cast<uint8_t>(~bit);
        } else {
          c.fixity[n] |= bit;
          c.fixed_vel[n][k] = velocity ? velocity[k] : c.vel[n][k];
        }
      }
      // A prescribed velocity: held axes take it at the next step, free ones start with it.
      if ((set_velocity & bit) && velocity) {
        c.fixed_vel[n][k] = velocity[k];
        if (!(c.fixity[n] & bit)) c.vel[n][k] = velocity[k];
      }
    }
  return nodes.size();
}
}  // namespace

size_t set_block_nodes(Model& m, size_t b, uint8_t bits, bool free, const double* velocity,
                       uint8_t set_velocity) {
  std::vector<size_t> nodes;
  if (m.dim == 3) {
    const Blocks3& B = m.blocks3;
    // A joined body is one mesh: the nodes of every deformable piece of it.
    for (size_t k = 0; k < B.size(); ++k)
      if (B.master[k] == B.master[b] && B.deformable[k])
        for (uint32_t n = B.node_begin[k]; n < B.node_end[k]; ++n) nodes.push_back(n);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return set_nodes_of(m.continuum3, nodes, bits, free, velocity, set_velocity);
  }
  const std::vector<int> owner = node_owners(m);
  for (size_t n = 0; n < owner.size(); ++n)
    if (owner[n] == static_cast<int>(b)) nodes.push_back(n);
  return set_nodes_of(m.continuum, nodes, bits, free, velocity, set_velocity);
}

std::vector<int> node_owners(const Model& m) {
  const Blocks& B = m.blocks;
  const Continuum& c = m.continuum;
  // Each block's mesh is its own connected set of zones: join nodes through zones (union-find),
  // then name each set after the block of an outline node in it.
  std::vector<uint32_t> root(c.node_count());
  for (uint32_t n = 0; n < root.size(); ++n) root[n] = n;
  auto find = [&](uint32_t n) {
    while (root[n] != n) n = root[n] = root[root[n]];
    return n;
  };
  for (const auto& t : c.zones)
    for (int k = 1; k < 3; ++k) root[find(t[k])] = find(t[0]);
  std::vector<int> set_block(c.node_count(), -1), owner(c.node_count(), -1);
  for (size_t b = 0; b < B.size(); ++b)
    if (B.deformable[b])
      for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
        set_block[find(static_cast<uint32_t>(B.node[v]))] = static_cast<int>(b);
  for (uint32_t n = 0; n < root.size(); ++n) owner[n] = set_block[find(n)];
  return owner;
}

std::vector<int64_t> drop_deformable(Model& m, const std::vector<uint8_t>& doomed) {
  const Blocks& B = m.blocks;
  Continuum& c = m.continuum;
  std::vector<uint8_t> drop(c.node_count(), 0);
  bool any = false;
  for (size_t b = 0; b < B.size(); ++b)
    if (doomed[b] && B.deformable[b])
      for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) any = true;
  if (!any) return {};
  // Nodes of a doomed block: every node of its zones.
  const std::vector<int> node_block = node_owners(m);
  std::vector<int64_t> map(c.node_count(), -1);
  Continuum kept;
  kept.materials = c.materials, kept.gravity = c.gravity, kept.local_damping = c.local_damping;
  kept.dt = c.dt, kept.time = c.time, kept.cycle = c.cycle;
  for (size_t n = 0; n < c.node_count(); ++n) {
    if (node_block[n] >= 0 && doomed[static_cast<size_t>(node_block[n])]) continue;
    map[n] = static_cast<int64_t>(kept.pos.size());
    kept.pos.push_back(c.pos[n]), kept.pos0.push_back(c.pos0[n]), kept.vel.push_back(c.vel[n]);
    kept.force.push_back(c.force[n]), kept.applied.push_back(c.applied[n]);
    kept.mass.push_back(c.mass[n]), kept.inertia.push_back(c.inertia[n]);
    kept.fixity.push_back(c.fixity[n]);
    kept.fixed_vel.push_back(c.fixed_vel[n]);
  }
  std::vector<int32_t> zone_map(c.zone_count(), -1);
  for (size_t z = 0; z < c.zone_count(); ++z) {
    const auto& t = c.zones[z];
    if (map[t[0]] < 0 || map[t[1]] < 0 || map[t[2]] < 0) continue;
    zone_map[z] = static_cast<int32_t>(kept.zones.size());
    kept.zones.push_back({static_cast<uint32_t>(map[t[0]]), static_cast<uint32_t>(map[t[1]]),
                          static_cast<uint32_t>(map[t[2]])});
    kept.stress.push_back(c.stress[z]), kept.state.push_back(c.state[z]);
    kept.plastic.push_back(c.plastic[z]);
    kept.material.push_back(c.material[z]);
  }
  c = std::move(kept);
  // Outline node numbers of the blocks that stay.
  Blocks& W = m.blocks;
  for (size_t b = 0; b < W.size(); ++b)
    if (W.deformable[b] && !doomed[b])
      for (uint32_t v = W.vert_begin[b]; v < W.vert_begin[b + 1]; ++v)
        W.node[v] = static_cast<int32_t>(map[static_cast<size_t>(W.node[v])]);
  // Histories at a node or zone follow its new number; those of removed ones end.
  for (auto& s : m.histories.series)
    if (s.zone >= 0 && static_cast<size_t>(s.zone) < zone_map.size())
      s.zone = zone_map[static_cast<size_t>(s.zone)];
  for (auto& s : m.histories.series)
    if (s.node >= 0 && static_cast<size_t>(s.node) < map.size()) {
      const int64_t n = map[static_cast<size_t>(s.node)];
      s.node = n >= 0 ? static_cast<int32_t>(n) : -1;
      if (n < 0) s.block = -2;
    }
  m.det_node.clear();
  return map;
}

namespace {
// Where a contact meets block b's feature: the two nodes and the weight of the second.
struct EdgeShare {
  int32_t n0 = -1, n1 = -1;
  double w1 = 0.0;
};
EdgeShare feature_share(const Model& m, size_t i) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const uint32_t bb = C.b[i], v = C.feature[i];
  EdgeShare s;
  s.n0 = B.node[v];
  if (C.kind[i] != kCornerEdge) return s;
  const uint32_t next = v + 1 < B.vert_begin[bb + 1] ? v + 1 : B.vert_begin[bb];
  s.n1 = B.node[next];
  const double len = B.edge_length[v];
  s.w1 = len > 0
             ? std::clamp((C.point[i] - B.world_vertex[v]).dot(B.world_edge_dir[v]) / len, 0.0, 1.0)
             : 0.0;
  return s;
}
}  // namespace

Vec2 contact_side_velocity(const Model& m, size_t i, bool side_b) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const uint32_t blk = side_b ? C.b[i] : C.a[i];
  if (!B.deformable[blk]) {
    const Vec2 r = C.point[i] - Vec2(B.x[blk], B.y[blk]);
    return Vec2(B.vx[blk] - B.omega[blk] * r.y(), B.vy[blk] + B.omega[blk] * r.x());
  }
  const Continuum& c = m.continuum;
  if (!side_b) return c.vel[static_cast<size_t>(B.node[C.corner[i]])];
  const EdgeShare s = feature_share(m, i);
  if (s.n1 < 0) return c.vel[static_cast<size_t>(s.n0)];
  return (1 - s.w1) * c.vel[static_cast<size_t>(s.n0)] + s.w1 * c.vel[static_cast<size_t>(s.n1)];
}

void add_contact_forces_to_nodes(Model& m) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  Continuum& c = m.continuum;
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b]) continue;
    // The block's interfaces, and each one's contacts: owned by b (at its node) or facing b
    // (shared between the nodes of the edge faced).
    for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k) {
      const uint32_t p = m.block_contacts[k] >> 1;
      for (uint32_t i = C.pair_begin[p]; i < C.pair_begin[p + 1]; ++i) {
        const bool side_b = C.a[i] != b;
        const Vec2 f = side_b ? Vec2(-C.force(i)) : C.force(i);
        if (!side_b) {
          add_node_force(c, static_cast<size_t>(B.node[C.corner[i]]), f);
          continue;
        }
        const EdgeShare s = feature_share(m, i);
        if (s.n1 < 0) {
          add_node_force(c, static_cast<size_t>(s.n0), f);
        } else {
          add_node_force(c, static_cast<size_t>(s.n0), (1 - s.w1) * f);
          add_node_force(c, static_cast<size_t>(s.n1), s.w1 * f);
        }
      }
    }
  }
}

namespace {
// Each node's own stable step with its lumped mass (1e300 for a massless node): the smallest of
// its zones', and for an outline node, its mass against the stiffest joint over its share of
// the outline (normal and shear springs together), counted four times: a node bears its own
// contact and the other side's contact on its edges, and the two nodes move against each other
// (a corner node at a joint junction flip-flopped every cycle with the count of one).
std::vector<double> node_timesteps2(const Model& m) {
  const Continuum& c = m.continuum;
  std::vector<double> dt = node_steps(c);
  const double kmax = stiffest_joint_pair(m);
  const Blocks& B = m.blocks;
  if (kmax > 0)
    for (size_t b = 0; b < B.size(); ++b) {
      if (!B.deformable[b]) continue;
      for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
        const double share = B.vertex_share(b, v);
        const auto n = static_cast<size_t>(B.node[v]);
        if (c.mass[n] > 0) dt[n] = std::min(dt[n], std::sqrt(c.mass[n] / (kmax * share)));
      }
    }
  // Bolts anchored in zones: each node against its share of the stiffer spring.
  const Reinforcement& R = m.support;
  for (size_t e = 0; e < R.size(); ++e) {
    const BoltProperties& p = R.bolts[R.bolt[e]].props;
    for (const Anchor2* a : {&R.side_a[e], &R.side_b[e]})
      for (int k = 0; a->node[0] >= 0 && k < 3; ++k) {
        const auto n = static_cast<size_t>(a->node[k]);
        const double kn = a->w[k] * std::max(p.ka, p.ks);
        if (c.mass[n] > 0 && kn > 0) dt[n] = std::min(dt[n], std::sqrt(c.mass[n] / kn));
      }
  }
  // Cable and liner nodes hosted in zones: the same with their grout (or a tied head's
  // segment) and interface.
  const size_t nc = m.cables.size();
  for (size_t i = 0; i < nc + m.liners.size(); ++i) {
    const Anchor2& a = i < nc ? m.cables.host[i] : m.liners.host[i - nc];
    const double kc = i < nc ? cable_host_stiffness(m.cables, i) : liner_host_stiffness(m, i - nc);
    for (int k = 0; a.node[0] >= 0 && k < 3; ++k) {
      const auto n = static_cast<size_t>(a.node[k]);
      if (c.mass[n] > 0 && a.w[k] * kc > 0)
        dt[n] = std::min(dt[n], std::sqrt(c.mass[n] / (a.w[k] * kc)));
    }
  }
  return dt;
}

}  // namespace

std::vector<double> node_timesteps(const Model& m) {
  if (m.dim == 3) return m.continuum3.zone_count() ? node_timesteps3(m) : std::vector<double>{};
  return m.continuum.zone_count() ? node_timesteps2(m) : std::vector<double>{};
}

}  // namespace tessera
