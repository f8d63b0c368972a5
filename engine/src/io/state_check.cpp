// Structural check of a restored model: every array the size its counts say, every index into
// what it indexes. A state file that was cut short, edited or corrupted is refused here, once,
// rather than read out of bounds in the first cycle.
#include <sstream>
#include <string>

#include "tessera/io/state_io.hpp"

namespace tessera {

namespace {

// Collects the first problem found; every later test is skipped once one is.
class Checker {
 public:
  bool ok() const { return why_.empty(); }
  const std::string& why() const { return why_; }
  bool require(bool good, const std::string& what) {
    if (ok() && !good) why_ = what;
    return ok();
  }
  template <class V>
  bool size(const V& v, size_t n, const char* what) {
    return require(v.size() == n, std::string(what) + " has " + std::to_string(v.size()) +
                                      " entries for " + std::to_string(n));
  }
  // Offsets into an array of `total` items: `count + 1` of them, from 0, never decreasing.
  template <class V>
  bool offsets(const V& begin, size_t count, size_t total, const char* what) {
    if (!size(begin, count + 1, what)) return false;
    for (size_t k = 0; k < count; ++k)
      if (!require(begin[k] <= begin[k + 1], std::string(what) + " decrease")) return false;
    return require(begin.front() == 0 && begin.back() == total,
                   std::string(what) + " do not cover the " + std::to_string(total) + " items");
  }

 private:
  std::string why_;
};

std::string name(const char* what, size_t i) {
  return std::string(what) + " " + std::to_string(i + 1);
}

void check_blocks2(Checker& c, const Model& m) {
  const Blocks& B = m.blocks;
  const size_t n = B.size();
  for (auto* v : const_cast<Blocks&>(B).block_doubles()) c.size(*v, n, "a block array");
  c.size(B.fixity, n, "block fixity"), c.size(B.all_convex, n, "block convexity");
  c.size(B.deformable, n, "block deformability"), c.size(B.group, n, "block groups");
  c.size(B.material, n, "block materials"), c.size(B.id, n, "block numbers");
  const size_t nv = B.local_vertex.size();
  c.offsets(B.vert_begin, n, nv, "block vertex offsets");
  c.size(B.local_arc_centre, nv, "arc centres"), c.size(B.arc_radius, nv, "arc radii");
  c.size(B.round_length, nv, "rounding lengths"), c.size(B.convex, nv, "corner convexity");
  c.size(B.local_edge_dir, nv, "edge directions"), c.size(B.edge_length, nv, "edge lengths");
  c.size(B.edge_tag, nv, "edge tags"), c.size(B.node, nv, "vertex nodes");
  if (!c.ok()) return;
  const size_t nodes = m.continuum.pos.size();
  for (size_t b = 0; b < n && c.ok(); ++b) {
    c.require(B.vertex_count(b) >= 3, name("block", b) + " has fewer than 3 vertices");
    c.require(B.group[b] >= -1 && B.group[b] < int(m.groups.size()),
              name("block", b) + " names a group that does not exist");
    c.require(B.material[b] >= -1 && B.material[b] < int(m.materials.size()),
              name("block", b) + " names a material that does not exist");
  }
  for (size_t v = 0; v < nv && c.ok(); ++v) {
    c.require(B.node[v] >= -1 && B.node[v] < int64_t(nodes), "a vertex names a missing node");
    c.require(B.edge_tag[v] >= -1 && B.edge_tag[v] < int(m.joint_tags.size()),
              "an edge names a joint tag that does not exist");
  }
}

void check_contacts2(Checker& c, const Model& m) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const size_t n = C.a.size();
  c.size(C.b, n, "contact blocks"), c.size(C.corner, n, "contact corners");
  c.size(C.slot, n, "contact slots"), c.size(C.kind, n, "contact kinds");
  c.size(C.feature, n, "contact features"), c.size(C.flags, n, "contact flags");
  c.size(C.joint, n, "contact joints"), c.size(C.tag, n, "contact tags");
  c.size(C.normal, n, "contact normals"), c.size(C.point, n, "contact points");
  for (auto* v : {&C.gap, &C.length, &C.fn, &C.fs, &C.un_prev, &C.dilation, &C.shear_disp})
    c.size(*v, n, "a contact array");
  for (auto* v : {&C.closure, &C.plastic, &C.damp_fn, &C.damp_fs})
    if (!v->empty()) c.size(*v, n, "a contact array held when used");
  if (!c.ok()) return;
  c.require(!C.pair_begin.empty() && C.pair_begin.front() == 0 && C.pair_begin.back() == n,
            "contact interface ranges do not cover the contacts");
  for (size_t p = 0; p + 1 < C.pair_begin.size() && c.ok(); ++p)
    c.require(C.pair_begin[p] <= C.pair_begin[p + 1], "contact interface ranges decrease");
  const size_t blocks = B.size();
  for (size_t i = 0; i < n && c.ok(); ++i) {
    const std::string who = name("contact", i);
    if (!c.require(C.a[i] < blocks && C.b[i] < blocks && C.a[i] != C.b[i],
                   who + " names a block that does not exist"))
      return;
    c.require(C.corner[i] >= B.vert_begin[C.a[i]] && C.corner[i] < B.vert_begin[C.a[i] + 1],
              who + " names a corner of another block");
    c.require(C.kind[i] == kLost ||
                  (C.feature[i] >= B.vert_begin[C.b[i]] && C.feature[i] < B.vert_begin[C.b[i] + 1]),
              who + " faces a feature of another block");
    c.require(C.joint[i] < m.joints.size(), who + " names joint properties that do not exist");
  }
}

void check_blocks3(Checker& c, const Model& m) {
  const Blocks3& B = m.blocks3;
  const size_t n = B.body.size();
  c.size(B.omega, n, "3D block spins"), c.size(B.force, n, "3D block forces");
  c.size(B.torque, n, "3D block torques"), c.size(B.applied, n, "3D applied forces");
  c.size(B.ref, n, "3D reference positions"), c.size(B.ref_q, n, "3D reference orientations");
  c.size(B.fixity, n, "3D fixity"), c.size(B.fixed_v, n, "3D fixed velocities");
  c.size(B.fixed_w, n, "3D fixed spins"), c.size(B.volume, n, "3D volumes");
  c.size(B.load_force, n, "3D loads"), c.size(B.load_moment, n, "3D load moments");
  c.size(B.surface, n, "3D surfaces"), c.size(B.bound_radius, n, "3D block radii");
  c.size(B.group, n, "3D groups"), c.size(B.material, n, "3D materials");
  c.size(B.id, n, "3D block numbers"), c.size(B.master, n, "3D masters");
  const size_t nv = B.local_vertex.size();
  c.offsets(B.vert_begin, n, nv, "3D vertex offsets");
  c.size(B.world_vertex, nv, "3D world vertices");
  const size_t nf = B.local_normal.size();
  c.offsets(B.face_begin, n, nf, "3D face offsets");
  c.offsets(B.fv_begin, nf, B.face_vert.size(), "3D face vertex offsets");
  c.size(B.local_offset, nf, "3D face offsets"), c.size(B.world_normal, nf, "3D face normals");
  c.size(B.world_offset, nf, "3D face planes"), c.size(B.face_tag, nf, "3D face tags");
  c.offsets(B.dir_begin, n, B.local_dir.size(), "3D edge direction offsets");
  c.size(B.world_dir, B.local_dir.size(), "3D edge directions");
  c.size(B.deformable, n, "3D deformable flags"), c.size(B.vertex_node, nv, "3D corner nodes");
  c.offsets(B.ftri_begin, nf, B.ftri.size(), "3D surface triangle offsets");
  for (auto* r : {&B.node_begin, &B.node_end, &B.zone_begin, &B.zone_end})
    c.size(*r, n, "3D node and zone ranges");
  const Continuum3& Z = m.continuum3;
  const size_t nn = Z.pos.size(), nz = Z.zones.size();
  c.size(Z.pos0, nn, "3D node origins"), c.size(Z.vel, nn, "3D node velocities");
  c.size(Z.force, nn, "3D node forces"), c.size(Z.applied, nn, "3D node loads");
  c.size(Z.mass, nn, "3D node masses"), c.size(Z.inertia, nn, "3D node inertias");
  c.size(Z.fixity, nn, "3D node fixity"), c.size(Z.fixed_vel, nn, "3D node fixed velocities");
  c.size(Z.stress, nz, "3D zone stresses"), c.size(Z.state, nz, "3D zone states");
  c.size(Z.plastic, nz, "3D zone plastic strains");
  c.size(Z.material, nz, "3D zone materials");
  if (!Z.mid.empty()) {
    c.size(Z.mid, nz, "3D mid-edge nodes"), c.size(Z.gp_stress, nz, "3D integration points");
    c.size(Z.gp_state, nz, "3D integration point states");
    c.size(Z.gp_plastic, nz, "3D integration point plastic strains");
    c.size(Z.edge_node, nn, "3D mid-edge node flags");
  }
  if (!c.ok()) return;
  for (size_t z = 0; z < nz && c.ok(); ++z) {
    Z.for_zone_nodes(
        z, [&](uint32_t k) { c.require(k < nn, name("3D zone", z) + " names a missing node"); });
    c.require(Z.material[z] <= m.materials.size(),
              name("3D zone", z) + " names a missing material");
  }
  for (const auto& t : B.ftri)
    for (uint32_t k : t) c.require(k < nn, "a 3D surface triangle names a missing node");
  for (size_t v = 0; v < nv; ++v)
    c.require(B.vertex_node[v] >= -1 && B.vertex_node[v] < int64_t(nn),
              "a 3D block corner names a missing node");
  for (size_t b = 0; b < n; ++b)
    c.require(B.node_begin[b] <= B.node_end[b] && B.node_end[b] <= nn &&
                  B.zone_begin[b] <= B.zone_end[b] && B.zone_end[b] <= nz,
              name("block", b) + " names nodes or zones that do not exist");
  if (!c.ok()) return;
  for (size_t b = 0; b < n && c.ok(); ++b) {
    const std::string who = name("block", b);
    c.require(B.vert_begin[b + 1] - B.vert_begin[b] >= 4, who + " has fewer than 4 vertices");
    c.require(B.face_begin[b + 1] - B.face_begin[b] >= 4, who + " has fewer than 4 faces");
    c.require(B.master[b] >= 0 && size_t(B.master[b]) < n, who + " names a missing master");
    c.require(B.group[b] >= -1 && B.group[b] < int(m.groups.size()),
              who + " names a group that does not exist");
    c.require(B.material[b] >= -1 && B.material[b] < int(m.materials.size()),
              who + " names a material that does not exist");
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1] && c.ok(); ++f) {
      c.require(B.fv_begin[f + 1] - B.fv_begin[f] >= 3,
                who + " has a face of fewer than 3 corners");
      for (uint32_t k = B.fv_begin[f]; k < B.fv_begin[f + 1] && c.ok(); ++k)
        c.require(B.face_vert[k] >= B.vert_begin[b] && B.face_vert[k] < B.vert_begin[b + 1],
                  who + " has a face corner that is not one of its vertices");
    }
  }
  for (size_t i = 0; i < m.contacts3.size() && c.ok(); ++i) {
    const Contact3& k = m.contacts3[i];
    const std::string who = name("3D contact", i);
    if (!c.require(k.a < n && k.b < n && k.a != k.b, who + " names a block that does not exist"))
      return;
    c.require(k.joint < m.joints.size(), who + " names joint properties that do not exist");
    c.require(k.face_a >= B.face_begin[k.a] && k.face_a < B.face_begin[k.a + 1] &&
                  k.face_b >= B.face_begin[k.b] && k.face_b < B.face_begin[k.b + 1],
              who + " faces a face of another block");
    // The plane's candidate: a face of b or a, or an edge direction of each.
    const bool fits =
        k.kind == kPlaneFaceB   ? k.ib >= B.face_begin[k.b] && k.ib < B.face_begin[k.b + 1]
        : k.kind == kPlaneFaceA ? k.ia >= B.face_begin[k.a] && k.ia < B.face_begin[k.a + 1]
        : k.kind == kPlaneEdges ? k.ia >= B.dir_begin[k.a] && k.ia < B.dir_begin[k.a + 1] &&
                                      k.ib >= B.dir_begin[k.b] && k.ib < B.dir_begin[k.b + 1]
                                : false;
    c.require(fits, who + " has a common plane from features of other blocks");
    for (const SubContact& s : k.subs)
      c.require(s.link >= -1 && s.link < int64_t(k.nodes.size()),
                who + " has a sub-contact whose node is not listed");
    for (const NodeLink& l : k.nodes) {
      bool nodes = l.node >= 0 && l.node < int64_t(nn) && l.side < 2;
      for (int32_t t : l.tri) nodes = nodes && t >= -1 && t < int64_t(nn);
      c.require(nodes, who + " has a sub-contact at a node that does not exist");
    }
  }
}

void check_rest(Checker& c, const Model& m) {
  for (size_t k = 0; k < m.joint_table.size() && c.ok(); ++k) {
    const JointAssignment& j = m.joint_table[k];
    c.require(j.joint < m.joints.size() && j.group_a >= -1 && j.group_a < int(m.groups.size()) &&
                  j.group_b >= -1 && j.group_b < int(m.groups.size()) && j.tag >= -1 &&
                  j.tag < int(m.joint_tags.size()),
              name("joint assignment", k) + " names something that does not exist");
  }
  // Continuum: per-node and per-zone arrays, zone corners and materials.
  const Continuum& Z = m.continuum;
  const size_t nn = Z.pos.size(), nz = Z.zones.size();
  c.size(Z.pos0, nn, "node origins"), c.size(Z.vel, nn, "node velocities");
  c.size(Z.force, nn, "node forces"), c.size(Z.applied, nn, "node loads");
  c.size(Z.mass, nn, "node masses"), c.size(Z.inertia, nn, "node inertias");
  c.size(Z.fixity, nn, "node fixity"), c.size(Z.fixed_vel, nn, "node fixed velocities");
  c.size(Z.stress, nz, "zone stresses"), c.size(Z.state, nz, "zone states");
  c.size(Z.plastic, nz, "zone plastic strains");
  c.size(Z.material, nz, "zone materials");
  for (size_t z = 0; z < nz && c.ok(); ++z) {
    for (uint32_t k : Z.zones[z]) c.require(k < nn, name("zone", z) + " names a missing node");
    c.require(Z.material[z] <= m.materials.size(), name("zone", z) + " names a missing material");
  }
  // Histories: a value per series per row, and blocks and nodes that exist.
  const Histories& H = m.histories;
  c.size(H.values, H.cycles.size() * H.series.size(), "history values");
  for (size_t s = 0; s < H.series.size() && c.ok(); ++s) {
    const HistorySeries& h = H.series[s];
    c.require(h.block >= -2 && h.block < int64_t(m.block_count()),
              "history '" + h.label + "' names a block that does not exist");
    const size_t nodes = m.dim == 3 ? m.continuum3.pos.size() : nn;
    c.require(h.node >= -1 && h.node < int64_t(nodes),
              "history '" + h.label + "' names a node that does not exist");
    const size_t zones = m.dim == 3 ? m.continuum3.zones.size() : nz;
    c.require(h.zone >= -1 && h.zone < int64_t(zones),
              "history '" + h.label + "' names a zone that does not exist");
    const size_t elements = is_cable_quantity(h.quantity)
                                ? (m.dim == 3 ? m.cables3.size() : m.cables.size())
                            : is_liner_quantity(h.quantity) ? m.liners.size()
                                                            : m.support.size();
    c.require(h.element >= -1 && h.element < int64_t(elements),
              "history '" + h.label + "' names a bolt element or cable node that does not exist");
  }
  // Bolts: per-element arrays of one size, elements inside their bolts, anchors in the model.
  const Reinforcement& R = m.support;
  const size_t ne = R.bolt.size();
  c.size(R.side_a, ne, "bolt anchors"), c.size(R.side_b, ne, "bolt anchors");
  c.size(R.axis0, ne, "bolt axes"), c.size(R.axial, ne, "bolt forces");
  c.size(R.shear, ne, "bolt forces"), c.size(R.ua, ne, "bolt displacements");
  c.size(R.us, ne, "bolt displacements"), c.size(R.state, ne, "bolt states");
  c.size(R.point, ne, "bolt points"), c.size(R.force, ne, "bolt forces");
  auto anchor_ok = [&](const Anchor2& a) {
    if (a.block < 0 || size_t(a.block) >= m.blocks.size()) return false;
    for (int32_t n : a.node)
      if (a.node[0] >= 0 && (n < 0 || size_t(n) >= nn)) return false;
    return true;
  };
  for (size_t b = 0; b < R.bolts.size() && c.ok(); ++b) {
    const Bolt& o = R.bolts[b];
    c.require(size_t(o.first) + o.count <= ne && anchor_ok(o.end0) && anchor_ok(o.end1),
              "bolt '" + o.name + "' names elements or rock that do not exist");
    for (uint32_t e = o.first; e < o.first + o.count && c.ok(); ++e)
      c.require(R.bolt[e] == b && anchor_ok(R.side_a[e]) && anchor_ok(R.side_b[e]),
                "bolt '" + o.name + "' has an element anchored outside the model");
  }
  // Cables (2D and 3D): per-node arrays of one size, nodes inside their cables, hosts in the
  // model.
  auto check_cables = [&](const auto& K, auto host_ok) {
    const size_t nk = K.cable.size();
    for (const auto* v : {&K.bonded, &K.slip, &K.slip_plastic, &K.vel, &K.inertia, &K.bond, &K.rest,
                          &K.plastic, &K.axial})
      c.size(*v, nk, "cable node values");
    c.size(K.host, nk, "cable hosts"), c.size(K.state, nk, "cable states");
    c.size(K.pos, nk, "cable nodes"), c.size(K.axis, nk, "cable axes");
    c.size(K.host_force, nk, "cable forces");
    for (size_t i = 0; i < K.cables.size() && c.ok(); ++i) {
      const Cable& o = K.cables[i];
      c.require(o.count >= 2 && size_t(o.first) + o.count <= nk,
                "cable '" + o.name + "' names nodes that do not exist");
      for (uint32_t k = o.first; k < o.first + o.count && c.ok(); ++k)
        c.require(K.cable[k] == i && host_ok(K.host[k]) &&
                      (k + 1 == o.first + o.count || K.rest[k] > 0.0),
                  "cable '" + o.name + "' has a node outside the model or a segment of no length");
    }
  };
  check_cables(m.cables, anchor_ok);
  check_cables(m.cables3, [&](const Anchor3& a) {
    const auto n3 = int64_t(m.blocks3.size());
    for (int32_t n : a.node)
      if (a.node[0] >= 0 && (n < 0 || size_t(n) >= m.continuum3.node_count())) return false;
    return a.block >= 0 && a.block < n3 && a.body >= 0 && a.body < n3 &&
           m.blocks3.master[size_t(a.block)] == a.body;
  });
  // Liners: per-node arrays of one size, nodes inside their liners, hosts in the model.
  const Liners& L = m.liners;
  const size_t nl = L.liner.size();
  for (const auto* v :
       {&L.length, &L.rot, &L.spin, &L.mass, &L.inertia, &L.shear, &L.pressure, &L.moment_sum,
        &L.axial, &L.m_start, &L.m_end, &L.v_shear, &L.plastic_axial, &L.hinge_start, &L.hinge_end})
    c.size(*v, nl, "liner node values");
  for (const auto* v : {&L.pos0, &L.normal, &L.disp, &L.vel, &L.force, &L.host_force})
    c.size(*v, nl, "liner node vectors");
  c.size(L.host, nl, "liner hosts"), c.size(L.state, nl, "liner states");
  for (size_t i = 0; i < L.liners.size() && c.ok(); ++i) {
    const Liner& o = L.liners[i];
    c.require(o.count >= 2 && size_t(o.first) + o.count <= nl,
              "liner '" + o.name + "' names nodes that do not exist");
    for (uint32_t k = o.first; k < o.first + o.count && c.ok(); ++k)
      c.require(L.liner[k] == i && anchor_ok(L.host[k]),
                "liner '" + o.name + "' has a node outside the model");
  }
  c.require(m.dim == 2 || m.dim == 3, "the dimension is neither 2 nor 3");
  c.require(m.det_x.empty() || m.det_x.size() == m.blocks.size(), "Verlet references differ");
  c.require(m.det_pos3.empty() || m.det_pos3.size() == m.blocks3.size(),
            "3D Verlet references differ");
  c.require(m.block_scale.empty() || m.block_scale.size() == m.block_count(),
            "block density scales differ from the blocks");
}

}  // namespace

std::string state_problem(const Model& m) {
  Checker c;
  check_blocks2(c, m);
  if (c.ok()) check_contacts2(c, m);
  if (c.ok()) check_blocks3(c, m);
  if (c.ok()) check_rest(c, m);
  return c.why();
}

}  // namespace tessera
