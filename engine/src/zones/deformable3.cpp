// Deformable 3D blocks: zoning, corners and faces from nodes, contact forces on nodes, removal.
#include "tessera/zones/deformable3.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tessera/core/block_loads.hpp"
#include "tessera/core/timestep.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {

// Block b's face triangles: `on_face[f - first face]` for each of its faces, spliced into the
// face-ordered list of every block's surface triangles.
void set_face_triangles(Blocks3& B, size_t b,
                        const std::vector<std::vector<std::array<uint32_t, 3>>>& on_face) {
  const uint32_t f0 = B.face_begin[b], f1 = B.face_begin[b + 1];
  std::vector<std::array<uint32_t, 3>> tris(B.ftri.begin(), B.ftri.begin() + B.ftri_begin[f0]);
  std::vector<uint32_t> begin(B.ftri_begin.begin(), B.ftri_begin.begin() + f0 + 1);
  for (uint32_t f = f0; f < f1; ++f) {
    tris.insert(tris.end(), on_face[f - f0].begin(), on_face[f - f0].end());
    begin.push_back(static_cast<uint32_t>(tris.size()));
  }
  const uint32_t shift = static_cast<uint32_t>(tris.size()) - B.ftri_begin[f1];
  tris.insert(tris.end(), B.ftri.begin() + B.ftri_begin[f1], B.ftri.end());
  for (size_t f = f1 + 1; f < B.ftri_begin.size(); ++f) begin.push_back(B.ftri_begin[f] + shift);
  B.ftri = std::move(tris), B.ftri_begin = std::move(begin);
}

// Makes block b (piece `piece` of the mesh, whose nodes start at `first`) deformable: its
// corners become the nodes there, its faces the surface triangles of its own zones.
void attach_piece(Blocks3& B, size_t b, const ZoneMesh3& mesh, uint32_t piece, uint32_t first) {
  // Each corner is a node of the mesh (the mesher protects the block's edges).
  const double eps = 1e-9 * B.bound_radius[b];
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
    size_t best = 0;
    double d = 1e300;
    for (size_t n = 0; n < mesh.nodes.size(); ++n)
      if (const double e = (mesh.nodes[n] - B.world_vertex[v]).norm(); e < d) d = e, best = n;
    if (d > 1e3 * eps) throw std::invalid_argument("the mesher moved a corner of the block");
    B.vertex_node[v] = static_cast<int32_t>(first + best);
  }
  // The piece's own zones, and each of their surface triangles on the face whose plane it lies in
  // and whose normal it shares.
  ZoneMesh3 own;
  for (size_t z = 0; z < mesh.tets.size(); ++z)
    if (mesh.piece.empty() || mesh.piece[z] == piece) {
      own.tets.push_back(mesh.tets[z]);
      if (!mesh.mid.empty()) own.mid.push_back(mesh.mid[z]);
    }
  const uint32_t f0 = B.face_begin[b], f1 = B.face_begin[b + 1];
  std::vector<std::vector<std::array<uint32_t, 3>>> on_face(f1 - f0);
  for (const auto& t : boundary_faces(own)) {
    const Vec3 n = (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
    uint32_t face = f1;
    for (uint32_t f = f0; f < f1 && face == f1; ++f) {
      const Vec3& fn = B.world_normal[f];
      bool in = fn.dot(n) > 0.99 * n.norm();
      for (uint32_t k : t)
        in = in && std::abs(fn.dot(mesh.nodes[k]) - B.world_offset[f]) < 1e3 * eps;
      if (in) face = f;
    }
    if (face == f1)
      throw std::invalid_argument(
          "a surface triangle of its zones lies on no face (near " +
          point_text((mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]]) / 3.0) + ")");
    on_face[face - f0].push_back({first + t[0], first + t[1], first + t[2]});
  }
  set_face_triangles(B, b, on_face);
  // The body's motion is replaced by the nodes'.
  B.deformable[b] = 1;
  B.fixity[b] = kFix3All;
  B.body[b].velocity = B.body[b].momentum = Vec3::Zero();
  B.fixed_v[b] = B.fixed_w[b] = B.omega[b] = Vec3::Zero();
}

}  // namespace

ZoningReport make_deformable3(Model& m, size_t b, double max_edge, const ZoneGrading3* grading,
                              const std::atomic<bool>* stop, bool quadratic) {
  Blocks3& B = m.blocks3;
  if (B.deformable[b]) throw std::invalid_argument("it is deformable already");
  if (loaded(B, b))
    throw std::invalid_argument(
        "it carries a load ('load'): zone it first, then load its nodes ('boundary stress')");
  if (!m.cables3.empty())
    throw std::invalid_argument("cables are placed already: zone blocks before placing support");
  // The body's pieces (one for a convex block), in block order: one mesh for all of them.
  std::vector<size_t> pieces;
  for (size_t k = 0; k < B.size(); ++k)
    if (B.master[k] == B.master[b]) pieces.push_back(k);
  for (size_t k : pieces) {
    const int mat = B.material[k];
    if (mat < 0 || m.materials[static_cast<size_t>(mat)].zone.model.empty())
      throw std::invalid_argument(
          (pieces.size() > 1 ? "the material of its piece, block " + std::to_string(B.id[k]) + ","
                             : std::string("its material")) +
          " has no elastic constants (give E and nu, or K and G, on 'material define')");
  }
  sync_zone_materials(m);
  std::vector<Polyhedron> polys;
  for (size_t k : pieces) polys.push_back(B.polyhedron(k));
  ZoneMesh3 mesh = zone_pieces(polys, max_edge, 2000000, grading, stop);
  // A zone of no volume has no stiffness and no stable step: refused, with where it is.
  if (mesh.min_dihedral < 1e-3)
    throw std::invalid_argument("the mesher left a flat zone (no volume) inside it at " +
                                point_text(mesh.worst_at) +
                                ": try a slightly different edge= or fine=");
  if (quadratic) make_quadratic(mesh);
  Continuum3& c = m.continuum3;
  const auto zone0 = static_cast<uint32_t>(c.zone_count());
  const uint32_t first = add_mesh(c, mesh, 0);
  // Each piece: its material, its zones (contiguous: sorted by piece), the body's nodes.
  for (uint32_t i = 0; i < pieces.size(); ++i) {
    const size_t k = pieces[i];
    B.node_begin[k] = first, B.node_end[k] = static_cast<uint32_t>(c.node_count());
    B.zone_begin[k] = B.zone_end[k] = zone0;
    for (uint32_t z = 0; z < mesh.tets.size(); ++z) {
      if (mesh.piece[z] != i) continue;
      if (B.zone_end[k] == zone0) B.zone_begin[k] = zone0 + z;
      B.zone_end[k] = zone0 + z + 1;
      c.material[zone0 + z] = static_cast<uint32_t>(B.material[k] + 1);
    }
    attach_piece(B, k, mesh, i, first);
  }
  lump_masses(c);
  m.contacts3.clear();
  m.block_contact_begin.clear();
  m.touch();
  return {mesh.min_dihedral, mesh.worst_at, mesh.poor};
}

void update_deformable_world3(Model& m) {
  Blocks3& B = m.blocks3;
  const std::vector<Vec3>& pos = m.continuum3.pos;
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b]) continue;
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
      B.world_vertex[v] = pos[static_cast<size_t>(B.vertex_node[v])];
    // A face's plane: the best-fit normal of its corners, through their mean.
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f) {
      const std::span<const uint32_t> face(B.face_vert.data() + B.fv_begin[f],
                                           B.fv_begin[f + 1] - B.fv_begin[f]);
      const Vec3 n = newell_normal(B.world_vertex, face);
      double off = 0.0;
      for (uint32_t v : face) off += n.dot(B.world_vertex[v]);
      B.world_normal[f] = n, B.world_offset[f] = off / static_cast<double>(face.size());
    }
  }
}

void add_contact_forces_to_nodes3(Model& m) {
  const Blocks3& B = m.blocks3;
  Continuum3& c = m.continuum3;
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b]) continue;
    for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k) {
      const Contact3& ct = m.contacts3[m.block_contacts[k] >> 1];
      const uint8_t side = m.block_contacts[k] & 1;
      const double sign = side ? -1.0 : 1.0;  // a sub-contact's force is on a
      for (const SubContact& s : ct.subs) {
        if (s.link < 0) continue;
        const NodeLink& l = ct.nodes[static_cast<size_t>(s.link)];
        if (l.side == side) {
          add_node_force(c, static_cast<size_t>(l.node), Vec3(sign * s.force));
        } else {
          for (int i = 0; i < 3; ++i)
            if (l.tri[i] >= 0)
              add_node_force(c, static_cast<size_t>(l.tri[i]), Vec3(sign * l.weight[i] * s.force));
        }
      }
    }
  }
}

namespace {
// Nodes of zones that host cables: their weight's share of the grout (or a tied head's segment).
void cable_node_limits(const Model& m, std::vector<double>& dt) {
  const Continuum3& c = m.continuum3;
  const Cables3& K = m.cables3;
  for (size_t i = 0; i < K.size(); ++i) {
    const Anchor3& a = K.host[i];
    const double kc = cable_host_stiffness(K, i);
    for (int k = 0; a.node[0] >= 0 && k < 4; ++k) {
      const auto n = static_cast<size_t>(a.node[k]);
      if (c.mass[n] > 0 && a.w[k] * kc > 0)
        dt[n] = std::min(dt[n], std::sqrt(c.mass[n] / (a.w[k] * kc)));
    }
  }
}
}  // namespace

void add_cable_forces_to_nodes3(Model& m) {
  Continuum3& c = m.continuum3;
  const Cables3& K = m.cables3;
  // In node order, by the weights of the zone's corners.
  for (size_t i = 0; i < K.size(); ++i) {
    const Anchor3& a = K.host[i];
    for (int k = 0; a.node[0] >= 0 && k < 4; ++k)
      add_node_force(c, static_cast<size_t>(a.node[k]), Vec3(a.w[k] * K.host_force[i]));
  }
}

std::vector<double> node_timesteps3(const Model& m) {
  const Continuum3& c = m.continuum3;
  std::vector<double> dt = node_steps(c);
  // Surface nodes: their share of each surface triangle around them (a third; on a quadratic
  // zone's face, the mid-edge nodes' parts: traction_shares), as 2D's half of each edge.
  cable_node_limits(m, dt);
  const double kmax = stiffest_joint_pair(m);
  if (kmax <= 0) return dt;
  std::vector<double> share(c.node_count(), 0.0);
  for (const auto& t : m.blocks3.ftri) {
    const double area = 0.5 * (c.pos[t[1]] - c.pos[t[0]]).cross(c.pos[t[2]] - c.pos[t[0]]).norm();
    const Vec3 part = traction_shares(t, c.edge_node);
    for (int k = 0; k < 3; ++k) share[t[k]] += part[k] * area;
  }
  for (size_t n = 0; n < c.node_count(); ++n)
    if (share[n] > 0 && c.mass[n] > 0)
      dt[n] = std::min(dt[n], std::sqrt(c.mass[n] / (kmax * share[n])));
  return dt;
}

std::vector<int64_t> drop_deformable3(Model& m, const std::vector<uint8_t>& doomed) {
  Blocks3& B = m.blocks3;
  Continuum3& c = m.continuum3;
  std::vector<int64_t> node_map(c.node_count()), zone_map(c.zone_count());
  for (size_t n = 0; n < node_map.size(); ++n) node_map[n] = static_cast<int64_t>(n);
  for (size_t z = 0; z < zone_map.size(); ++z) zone_map[z] = static_cast<int64_t>(z);
  bool any = false;
  for (size_t b = 0; b < B.size(); ++b)
    if (doomed[b] && B.deformable[b]) {
      any = true;
      for (uint32_t n = B.node_begin[b]; n < B.node_end[b]; ++n) node_map[n] = -1;
      for (uint32_t z = B.zone_begin[b]; z < B.zone_end[b]; ++z) zone_map[z] = -1;
    }
  if (!any) return {};
  int64_t next = 0;
  for (auto& k : node_map)
    if (k >= 0) k = next++;
  next = 0;
  for (auto& k : zone_map)
    if (k >= 0) k = next++;
  // Keep the rest in order (the kernel's arrays, then every reference to a node or zone).
  const auto keep = [](auto& v, const std::vector<int64_t>& map) {
    size_t j = 0;
    for (size_t i = 0; i < map.size(); ++i)
      if (map[i] >= 0) v[j++] = v[i];
    v.resize(j);
  };
  for (auto* v : {&c.pos, &c.pos0, &c.vel, &c.force, &c.applied, &c.fixed_vel}) keep(*v, node_map);
  keep(c.mass, node_map), keep(c.inertia, node_map), keep(c.fixity, node_map);
  if (!c.edge_node.empty()) keep(c.edge_node, node_map);
  keep(c.zones, zone_map), keep(c.stress, zone_map), keep(c.state, zone_map);
  keep(c.plastic, zone_map);
  keep(c.material, zone_map);
  if (!c.mid.empty()) {
    keep(c.mid, zone_map), keep(c.gp_stress, zone_map), keep(c.gp_state, zone_map);
    keep(c.gp_plastic, zone_map);
  }
  for (auto& t : c.zones)
    for (uint32_t& n : t) n = static_cast<uint32_t>(node_map[n]);
  for (auto& t : c.mid)
    for (uint32_t& n : t)
      if (n != Continuum3::kNoMid) n = static_cast<uint32_t>(node_map[n]);
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b] || doomed[b]) continue;
    const auto first_kept = [](const std::vector<int64_t>& map, uint32_t lo) {
      int64_t before = 0;
      for (uint32_t i = 0; i < lo; ++i) before += map[i] >= 0;
      return static_cast<uint32_t>(before);
    };
    const uint32_t nb = first_kept(node_map, B.node_begin[b]);
    const uint32_t zb = first_kept(zone_map, B.zone_begin[b]);
    B.node_end[b] = nb + (B.node_end[b] - B.node_begin[b]), B.node_begin[b] = nb;
    B.zone_end[b] = zb + (B.zone_end[b] - B.zone_begin[b]), B.zone_begin[b] = zb;
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
      B.vertex_node[v] = static_cast<int32_t>(node_map[static_cast<size_t>(B.vertex_node[v])]);
  }
  // Surface triangles of kept blocks are renumbered; those of doomed ones go with their faces.
  for (auto& t : B.ftri)
    for (uint32_t& n : t)
      if (node_map[n] >= 0) n = static_cast<uint32_t>(node_map[n]);
  for (auto& s : m.histories.series)
    if (s.node >= 0 && static_cast<size_t>(s.node) < node_map.size()) {
      const int64_t n = node_map[static_cast<size_t>(s.node)];
      s.node = n >= 0 ? static_cast<int32_t>(n) : -1;
      if (n < 0) s.block = -2;
    }
  for (auto& s : m.histories.series)
    if (s.zone >= 0 && static_cast<size_t>(s.zone) < zone_map.size())
      s.zone = static_cast<int32_t>(zone_map[static_cast<size_t>(s.zone)]);
  m.det_node3.clear();
  return node_map;
}

}  // namespace tessera
