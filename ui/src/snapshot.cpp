// Copies the model into a snapshot for the view.
#include "tessera/ui/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <type_traits>

#include "tessera/contact2d/interfaces.hpp"
#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/core/block_loads.hpp"
#include "tessera/core/model.hpp"
#include "tessera/script/script.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera::ui {

namespace {
std::string number(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Zone nodes held or loaded (`boundary`): how many along each axis, at which velocities, and
// the resultant of the applied loads.
template <class C>
void add_node_conditions(const C& c, Snapshot& s) {
  constexpr int D = static_cast<int>(std::tuple_size_v<typename C::Zone>) - 1;
  const char* axis[3] = {"x", "y", "z"};
  for (int k = 0; k < D; ++k) {
    size_t held = 0;
    double vmin = 0, vmax = 0;
    for (size_t n = 0; n < c.node_count(); ++n)
      if (c.fixity[n] & node_fix_bit(k)) {
        const double v = c.fixed_vel[n][k];
        vmin = held ? std::min(vmin, v) : v, vmax = held ? std::max(vmax, v) : v, ++held;
      }
    if (!held) continue;
    const bool moving = vmin != 0 || vmax != 0;
    s.conditions.push_back(
        {std::string(moving ? "velocity on " : "fixed ") + axis[k] + " (zone nodes)",
         {{"nodes", std::to_string(held)},
          {std::string(axis[k]) + " velocity",
           vmin == vmax ? number(vmin) + " m/s" : number(vmin) + " to " + number(vmax) + " m/s"}}});
  }
  size_t loaded = 0;
  typename C::Vec total = C::Vec::Zero();
  for (size_t n = 0; n < c.node_count(); ++n)
    if (c.applied[n].squaredNorm() > 0) ++loaded, total += c.applied[n];
  if (!loaded) return;
  Entry e{"applied stress or pressure (zone nodes)", {{"nodes", std::to_string(loaded)}}};
  for (int k = 0; k < D; ++k)
    e.properties.push_back(
        {std::string("resultant ") + axis[k], number(total[k]) + (D == 2 ? " N/m" : " N")});
  s.conditions.push_back(std::move(e));
}

void copy_catalogue(const Model& m, Snapshot& s) {
  s.groups = m.groups;
  s.joint_names = m.joint_tags;
  for (const Material& mat : m.materials)
    s.materials.push_back({mat.name, {{"density", number(mat.density) + " kg/m³"}}});
  for (const JointProperties& j : m.joints)
    s.joints.push_back({j.name,
                        {{"law", j.law},
                         {"kn", number(j.kn) + " Pa/m"},
                         {"ks", number(j.ks) + " Pa/m"},
                         {"friction", number(j.friction) + "°"},
                         {"cohesion", number(j.cohesion) + " Pa"},
                         {"tension", number(j.tension) + " Pa"},
                         {"dilation", number(j.dilation) + "°"}}});
  // Boundary conditions: one entry per kind of condition (what is fixed, at which velocities),
  // listing the blocks it holds (2D and 3D blocks alike).
  const Blocks& B = m.blocks;
  const Blocks3& B3 = m.blocks3;
  std::map<std::string, std::pair<Entry, std::vector<int>>> kinds;
  const auto add_block = [&](int id, const std::vector<std::pair<std::string, double>>& held,
                             const char* unit_of_last, bool last_is_rotation) {
    if (held.empty()) return;
    Entry e;
    std::string what;
    bool moving = false;
    for (size_t i = 0; i < held.size(); ++i) {
      const bool rotation = last_is_rotation && i + 1 == held.size();
      what += held[i].first + " ";
      e.properties.push_back({rotation ? "angular velocity" : held[i].first + " velocity",
                              number(held[i].second) + (rotation ? unit_of_last : " m/s")});
      moving |= held[i].second != 0;
    }
    e.name = (moving ? "velocity on " : "fixed ") + what.substr(0, what.size() - 1);
    std::string key = e.name;
    for (const auto& [k, v] : e.properties) key += "|" + v;
    auto& slot = kinds[key];
    if (slot.second.empty()) slot.first = std::move(e);
    slot.second.push_back(id);
  };
  for (size_t b = 0; b < B.size(); ++b) {
    std::vector<std::pair<std::string, double>> held;
    if (B.fixity[b] & kFixX) held.push_back({"x", B.fixed_vx[b]});
    if (B.fixity[b] & kFixY) held.push_back({"y", B.fixed_vy[b]});
    if (B.fixity[b] & kFixRot) held.push_back({"rotation", B.fixed_omega[b]});
    add_block(B.id[b], held, " rad/s", B.fixity[b] & kFixRot);
  }
  for (size_t b = 0; b < B3.size(); ++b) {
    std::vector<std::pair<std::string, double>> held;
    const char* axis[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      if (B3.fixity[b] & (1 << k)) held.push_back({axis[k], B3.fixed_v[b][k]});
    if (B3.fixity[b] & kFix3Rot) held.push_back({"rotation", B3.fixed_w[b].norm()});
    add_block(B3.id[b], held, " rad/s", B3.fixity[b] & kFix3Rot);
  }
  // Loads ('load'): one entry per distinct load, listing the blocks that carry it.
  const auto add_load = [&](int id, const std::string& force, const std::string& moment) {
    auto& slot = kinds["load|" + force + "|" + moment];
    if (slot.second.empty()) slot.first = Entry{"load", {{"force", force}, {"moment", moment}}};
    slot.second.push_back(id);
  };
  const auto vec_text = [](std::initializer_list<double> v, const char* unit) {
    std::string t;
    for (double x : v) t += (t.empty() ? "" : ", ") + number(x);
    return "(" + t + ") " + unit;
  };
  for (size_t b = 0; b < B.size(); ++b)
    if (loaded(B, b))
      add_load(B.id[b], vec_text({B.load_fx[b], B.load_fy[b]}, "N/m"),
               number(B.load_m[b]) + " N m/m");
  for (size_t b = 0; b < B3.size(); ++b) {
    const Vec3 &f = B3.load_force[b], &t = B3.load_moment[b];
    if (f != Vec3::Zero() || t != Vec3::Zero())
      add_load(B3.id[b], vec_text({f.x(), f.y(), f.z()}, "N"),
               vec_text({t.x(), t.y(), t.z()}, "N m"));
  }
  for (auto& [key, kind] : kinds) {
    auto& [e, ids] = kind;
    std::string list;
    for (size_t i = 0; i < ids.size() && i < 40; ++i)
      list += (i ? ", " : "") + std::to_string(ids[i]);
    if (ids.size() > 40) list += ", ...";
    e.properties.insert(e.properties.begin(),
                        {{"blocks", std::to_string(ids.size())}, {"ids", list}});
    s.conditions.push_back(std::move(e));
  }
  add_node_conditions(m.continuum, s);
  add_node_conditions(m.continuum3, s);
  const Vec3& g3 = m.settings.gravity3;
  if (m.dim == 3 && g3.norm() > 0)
    s.conditions.push_back({"gravity",
                            {{"gx", number(g3.x()) + " m/s²"},
                             {"gy", number(g3.y()) + " m/s²"},
                             {"gz", number(g3.z()) + " m/s²"}}});
  if (m.settings.gravity.norm() > 0)
    s.conditions.push_back({"gravity",
                            {{"gx", number(m.settings.gravity.x()) + " m/s²"},
                             {"gy", number(m.settings.gravity.y()) + " m/s²"}}});
}

void copy_histories(const Model& m, Snapshot& s) {
  const Histories& h = m.histories;
  for (const auto& series : h.series) {
    s.history_labels.push_back(series.label);
    const std::string unit = history_quantity_unit(series.quantity, m.dim);
    s.history_titles.push_back(history_quantity_name(series.quantity) +
                               (unit.empty() ? "" : " [" + unit + "]"));
  }
  s.history_values.assign(h.columns(), {});
  const size_t rows = h.rows();
  const size_t stride = rows > Snapshot::kHistoryRows
                            ? (rows + Snapshot::kHistoryRows - 1) / Snapshot::kHistoryRows
                            : 1;
  for (size_t r = 0; r < rows; r += stride) {
    // Always end on the newest sample.
    const size_t row = r + stride >= rows ? rows - 1 : r;
    s.history_cycles.push_back(static_cast<double>(h.cycles[row]));
    for (size_t c = 0; c < h.columns(); ++c) s.history_values[c].push_back(h.at(row, c));
  }
}

void copy_zones(const Model& m, Snapshot& s) {
  const Continuum& c = m.continuum;
  if (c.zone_count() == 0) return;
  const std::vector<int> owner = node_owners(m);
  s.nodes = c.pos, s.nodes_start = c.pos0;
  s.zones.reserve(c.zone_count());
  for (size_t z = 0; z < c.zone_count(); ++z) {
    if (!c.materials[c.material[z]].impl->solid()) continue;
    SnapshotZone o;
    o.index = static_cast<uint32_t>(z);
    for (int k = 0; k < 3; ++k) o.n[k] = c.zones[z][static_cast<size_t>(k)];
    o.block = owner[o.n[0]];
    const ZoneStress& st = c.stress[z];
    o.sxx = st.xx, o.syy = st.yy, o.sxy = st.xy, o.szz = st.zz, o.state = c.state[z];
    s.zones.push_back(o);
  }
}
void copy_stages(const std::vector<StageRecord>& stages, Snapshot& s) {
  for (const StageRecord& st : stages)
    s.stages.push_back(
        {st.command,
         {{"at", st.file + ":" + std::to_string(st.line)},
          {"cycles", std::to_string(st.first_cycle) + " to " + std::to_string(st.last_cycle)},
          {"converged", st.converged ? "yes" : "no"}}});
}

// 3D zones: their stresses, the nodes, and each face's surface triangles with the zone each
// bounds (the zone around the triangle's first node holding all three).
void copy_zones3(const Model& m, Snapshot& s) {
  const Continuum3& c = m.continuum3;
  const Blocks3& B = m.blocks3;
  if (c.zone_count() == 0) return;
  s.nodes3 = c.pos, s.nodes3_start = c.pos0;
  s.zones.resize(c.zone_count());
  std::vector<uint32_t> around_begin(c.node_count() + 1, 0), around;
  for (size_t z = 0; z < c.zone_count(); ++z)
    c.for_zone_nodes(z, [&](uint32_t n) { ++around_begin[n + 1]; });
  for (size_t n = 0; n < c.node_count(); ++n) around_begin[n + 1] += around_begin[n];
  around.resize(around_begin.back());
  std::vector<uint32_t> fill(around_begin.begin(), around_begin.end() - 1);
  for (uint32_t z = 0; z < c.zone_count(); ++z) {
    c.for_zone_nodes(z, [&](uint32_t n) { around[fill[n]++] = z; });
    SnapshotZone& o = s.zones[z];
    o.index = z;
    for (size_t k = 0; k < 4; ++k) o.n[k] = c.zones[z][k];
    const ZoneStress& st = c.stress[z];
    o.sxx = st.xx, o.syy = st.yy, o.szz = st.zz, o.sxy = st.xy, o.syz = st.yz, o.sxz = st.xz;
    o.state = c.state[z];
  }
  for (size_t b = 0; b < B.size(); ++b) {
    if (!B.deformable[b]) continue;
    // (null zones, excavated, keep block -1: nothing is drawn of them)
    for (uint32_t z = B.zone_begin[b]; z < B.zone_end[b]; ++z)
      if (c.materials[c.material[z]].impl->solid()) s.zones[z].block = static_cast<int>(b);
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f)
      for (uint32_t k = B.ftri_begin[f]; k < B.ftri_begin[f + 1]; ++k) {
        const auto& t = B.ftri[k];
        Snapshot::Tri3 tri;
        tri.n[0] = t[0], tri.n[1] = t[1], tri.n[2] = t[2], tri.face = f;
        for (uint32_t i = around_begin[t[0]]; i < around_begin[t[0] + 1]; ++i) {
          int has = 0;
          c.for_zone_nodes(around[i], [&](uint32_t n) { has += n == t[1] || n == t[2]; });
          if (has == 2) tri.zone = around[i];
        }
        s.tris3.push_back(tri);
      }
  }
}

// 3D models: blocks (centroid, displacement, velocity, angle turned), every face as a polygon of
// world points, every sub-contact.
void copy_blocks3(const Model& m, Snapshot& s) {
  const Blocks3& B = m.blocks3;
  s.three = true;
  s.blocks.resize(B.size());
  bool first = true;
  for (size_t b = 0; b < B.size(); ++b) {
    SnapshotBlock& o = s.blocks[b];
    const auto mb = static_cast<size_t>(B.master[b]);  // the body that moves this piece
    const RigidBody3& body = B.body[mb];
    o.id = B.id[b], o.group = B.group[b], o.material = B.material[b];
    o.x = body.position.x(), o.y = body.position.y(), o.z = body.position.z();
    o.x_ref = B.ref[mb].x(), o.y_ref = B.ref[mb].y(), o.z_ref = B.ref[mb].z();
    o.vx = body.velocity.x(), o.vy = body.velocity.y(), o.vz = body.velocity.z();
    o.theta = 2.0 * std::acos(std::min(1.0, std::abs(body.orientation.dot(B.ref_q[mb]))));
    o.omega = B.omega[mb].norm();
    o.area = B.volume[b], o.mass = body.mass, o.fixity = B.fixity[b];
    o.deformable = B.deformable[b] != 0;
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f) {
      Snapshot::Face3 face;
      face.block = static_cast<int>(b);
      face.begin = static_cast<uint32_t>(s.points3.size());
      for (uint32_t k = B.fv_begin[f]; k < B.fv_begin[f + 1]; ++k)
        s.points3.push_back(B.world_vertex[B.face_vert[k]]);
      face.end = static_cast<uint32_t>(s.points3.size());
      s.faces3.push_back(face);
    }
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
      const Vec2 w(B.world_vertex[v].x(), B.world_vertex[v].y());
      s.lo = first ? w : s.lo.cwiseMin(w), s.hi = first ? w : s.hi.cwiseMax(w);
      first = false;
    }
  }
  copy_zones3(m, s);
  for (const Contact3& c : m.contacts3)
    for (const SubContact& sub : c.subs) {
      SnapshotContact o;
      o.a = static_cast<int>(c.a), o.b = static_cast<int>(c.b);
      o.point3 = world_point(m.blocks3, c, sub), o.normal3 = c.normal;
      o.point = o.from = o.to = Vec2(o.point3.x(), o.point3.y());
      o.length = 0.5 * std::sqrt(sub.area), o.gap = sub.gap, o.fn = sub.fn, o.fs = sub.shear();
      o.shear_disp = sub.shear_travel(), o.flags = sub.flags;
      if (c.joint < m.joints.size()) o.joint = m.joints[c.joint].name;
      if (c.tag >= 0 && static_cast<size_t>(c.tag) < m.joint_tags.size())
        o.joint_set = m.joint_tags[static_cast<size_t>(c.tag)];
      s.contacts.push_back(std::move(o));
    }
}
}  // namespace

namespace {
void copy_bolts(const Model& m, Snapshot& s) {
  const Reinforcement& R = m.support;
  for (size_t b = 0; b < R.bolts.size(); ++b) {
    SnapshotBolt o;
    o.name = R.bolts[b].name;
    for (const BoltPoint& p : bolt_path(m, b)) {
      const auto e = static_cast<size_t>(p.element);
      const bool crossing = p.element >= 0;
      o.points.push_back(p.at);
      o.block.push_back(crossing ? R.side_a[e].block
                                 : (o.block.empty() ? R.bolts[b].end0 : R.bolts[b].end1).block);
      o.axial.push_back(crossing ? R.axial[e] : 0.0);
      o.shear.push_back(crossing ? R.shear[e] : 0.0);
      o.state.push_back(crossing ? R.state[e] : 0);
    }
    s.bolts.push_back(std::move(o));
  }
  // Cables of either dimension: their nodes (and in 3D the nodes' 3D points).
  auto copy_cables = [&](const auto& K) {
    for (const Cable& c : K.cables) {
      SnapshotBolt o;
      o.name = c.name, o.cable = true;
      for (uint32_t i = c.first; i < c.first + c.count; ++i) {
        if constexpr (std::is_same_v<std::decay_t<decltype(K)>, Cables3>)
          o.points3.push_back(K.pos[i]);
        o.points.push_back(K.pos[i].template head<2>());
        o.block.push_back(K.host[i].block);
        o.axial.push_back(K.axial[i]);
        o.shear.push_back(0.0);
        o.state.push_back(K.state[i] ? kBoltAxialYield : 0);
      }
      s.bolts.push_back(std::move(o));
    }
  };
  copy_cables(m.cables);
  copy_cables(m.cables3);
  const Liners& L = m.liners;
  for (const Liner& l : L.liners) {
    SnapshotBolt o;
    o.name = l.name, o.cable = true, o.liner = true, o.closed = l.closed;
    // (A closed ring's first node again at the end, to draw its last element.)
    for (uint32_t k = 0; k < l.count + (l.closed ? 1u : 0u); ++k) {
      const uint32_t i = l.first + k % l.count;
      o.points.push_back(liner_position(L, i));
      o.block.push_back(L.host[i].block);
      o.axial.push_back(L.next(i) >= 0 ? L.axial[i] : 0.0);
      o.shear.push_back(0.0);
      // At a capacity (thrust or moment) or slipping on the rock: yielding; open: drawn elastic.
      const bool yielding = L.state[i] & (kLinerSlip | kLinerHinge | kLinerThrustYield);
      o.state.push_back(static_cast<uint8_t>((yielding ? kBoltAxialYield : 0) |
                                             (L.state[i] & kLinerOpen ? kLinerNodeOpen : 0)));
    }
    s.bolts.push_back(std::move(o));
  }
}
}  // namespace

Snapshot make_snapshot(const Model& m, const std::string& title,
                       const std::vector<StageRecord>& stages) {
  Snapshot s;
  s.title = title;
  s.cycle = m.cycle, s.time = m.time, s.dt = m.dt, s.ratio = m.ratio;
  s.rounding = m.settings.rounding;
  if (m.dim == 3) {
    m.blocks3.catch_up();  // (a progress report may come while the vertices lag their blocks)
    copy_blocks3(m, s);
    copy_bolts(m, s);
    copy_catalogue(m, s);
    copy_stages(stages, s);
    copy_histories(m, s);
    return s;
  }
  const Blocks& B = m.blocks;
  s.blocks.resize(B.size());
  s.local.reserve(B.local_vertex.size());
  bool first = true;
  for (size_t b = 0; b < B.size(); ++b) {
    SnapshotBlock& o = s.blocks[b];
    o.id = B.id[b], o.group = B.group[b], o.material = B.material[b];
    o.x = B.x[b], o.y = B.y[b], o.x_ref = B.x_ref[b], o.y_ref = B.y_ref[b], o.theta = B.theta[b];
    o.vx = B.vx[b], o.vy = B.vy[b], o.omega = B.omega[b];
    o.area = B.area[b], o.mass = B.mass[b], o.fixity = B.fixity[b];
    o.vert_begin = static_cast<uint32_t>(s.local.size());
    o.deformable = B.deformable[b];
    // A deformable block: outline nodes as they are and as they started; its displacement and
    // velocity are the means over the outline.
    Vec2 disp = Vec2::Zero(), vel = Vec2::Zero();
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v) {
      if (o.deformable) {
        const auto n = static_cast<size_t>(B.node[v]);
        s.local.push_back(m.continuum.pos[n]);
        s.start.push_back(m.continuum.pos0[n]);
        disp += m.continuum.pos[n] - m.continuum.pos0[n], vel += m.continuum.vel[n];
      } else {
        s.local.push_back(B.local_vertex[v]);
        s.start.push_back(Vec2::Zero());
      }
      const Vec2& w = B.world_vertex[v];
      s.lo = first ? w : s.lo.cwiseMin(w), s.hi = first ? w : s.hi.cwiseMax(w);
      first = false;
    }
    o.vert_end = static_cast<uint32_t>(s.local.size());
    if (o.deformable && o.vert_end > o.vert_begin) {
      const double k = 1.0 / static_cast<double>(o.vert_end - o.vert_begin);
      o.x = o.x_ref + k * disp.x(), o.y = o.y_ref + k * disp.y();
      o.vx = k * vel.x(), o.vy = k * vel.y(), o.theta = 0.0, o.omega = 0.0;
    }
  }
  const Contacts& C = m.contacts;
  const std::vector<ContactStretch> stretch = contact_stretches(m);
  s.contacts.reserve(C.size());
  for (size_t c = 0; c < C.size(); ++c) {
    if (C.kind[c] == kLost) continue;
    SnapshotContact o;
    o.a = static_cast<int>(C.a[c]), o.b = static_cast<int>(C.b[c]);
    o.point = C.point[c], o.normal = C.normal[c];
    o.length = C.length[c], o.gap = C.gap[c], o.fn = C.fn[c], o.fs = C.fs[c];
    o.shear_disp = C.shear_disp[c], o.flags = C.flags[c];
    if (C.joint[c] < m.joints.size()) o.joint = m.joints[C.joint[c]].name;
    if (C.tag[c] >= 0 && static_cast<size_t>(C.tag[c]) < m.joint_tags.size())
      o.joint_set = m.joint_tags[static_cast<size_t>(C.tag[c])];
    o.from = stretch[c].from, o.to = stretch[c].to;
    s.contacts.push_back(std::move(o));
  }
  copy_bolts(m, s);
  copy_zones(m, s);
  copy_catalogue(m, s);
  copy_stages(stages, s);
  copy_histories(m, s);
  return s;
}

Vec2 shown_vertex(const Snapshot& s, const SnapshotBlock& b, uint32_t v, double magnify) {
  if (b.deformable) return s.start[v] + magnify * (s.local[v] - s.start[v]);
  const double t = b.theta * magnify;
  const double c = std::cos(t), sn = std::sin(t);
  const Vec2& p = s.local[v];
  const Vec2 centre(b.x_ref + magnify * (b.x - b.x_ref), b.y_ref + magnify * (b.y - b.y_ref));
  return centre + Vec2(c * p.x() - sn * p.y(), sn * p.x() + c * p.y());
}

}  // namespace tessera::ui
