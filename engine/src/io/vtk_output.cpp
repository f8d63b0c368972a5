#include "tessera/io/vtk_output.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "tessera/contact2d/interfaces.hpp"
#include "tessera/contact3d/subcontacts.hpp"

namespace tessera {

namespace {

// Text of a list of numbers, for a DataArray body: nine significant digits, or (points) the
// shortest text that reads back as the same double, since a model at map coordinates (a
// northing of 4e6) needs eleven digits for a millimetre.
template <class F>
void numbers(std::ostream& out, size_t n, F value, bool exact) {
  char buf[32];
  for (size_t i = 0; i < n; ++i) {
    const double v = static_cast<double>(value(i));
    if (exact)
      *std::to_chars(buf, buf + sizeof buf - 1, v).ptr = '\0';
    else
      std::snprintf(buf, sizeof buf, "%.9g", v);
    out << buf << ((i % 12 == 11) ? '\n' : ' ');
  }
  out << '\n';
}

// One DataArray element with `comps` components per tuple; the points' coordinates exact.
template <class F>
void array(std::ostream& out, const char* type, const char* name, int comps, size_t n, F value) {
  out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << comps
      << "\" format=\"ascii\">\n";
  numbers(out, n * static_cast<size_t>(comps), value, std::string_view(name) == "Points");
  out << "</DataArray>\n";
}

// Plane vectors as 3-component tuples (z = 0).
template <class F>
void vec2_array(std::ostream& out, const char* name, size_t n, F vec) {
  array(out, "Float64", name, 3, n, [&](size_t k) {
    const Vec2 v = vec(k / 3);
    return k % 3 == 0 ? v.x() : k % 3 == 1 ? v.y() : 0.0;
  });
}

// Space vectors as 3-component tuples.
template <class F>
void vec3_array(std::ostream& out, const char* name, size_t n, F vec) {
  array(out, "Float64", name, 3, n, [&](size_t k) { return vec(k / 3)[static_cast<int>(k % 3)]; });
}

// File header, piece sizes and the points of a PolyData piece of polygons, lines or vertices.
template <class F>
void begin_piece(std::ostream& out, size_t points, size_t cells, const char* cell_kind, F point) {
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n"
      << "<PolyData>\n<Piece NumberOfPoints=\"" << points << "\" NumberOf" << cell_kind << "=\""
      << cells << "\">\n<Points>\n";
  if constexpr (std::is_same_v<std::decay_t<decltype(point(size_t{0}))>, Vec3>)
    vec3_array(out, "Points", points, point);
  else
    vec2_array(out, "Points", points, point);
  out << "</Points>\n";
}

std::ofstream open_file(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  return out;
}

void write_blocks(const Model& m, const std::string& path) {
  const Blocks& B = m.blocks;
  const size_t n = B.size(), nv = B.world_vertex.size();
  std::ofstream out = open_file(path);
  begin_piece(out, nv, n, "Polys", [&](size_t v) { return B.world_vertex[v]; });
  out << "<Polys>\n";
  array(out, "Int64", "connectivity", 1, nv, [](size_t k) { return k; });
  array(out, "Int64", "offsets", 1, n, [&](size_t b) { return B.vert_begin[b + 1]; });
  out << "</Polys>\n<CellData Scalars=\"group\">\n";
  array(out, "Int32", "id", 1, n, [&](size_t b) { return B.id[b]; });
  array(out, "Int32", "group", 1, n, [&](size_t b) { return B.group[b]; });
  array(out, "Int32", "material", 1, n, [&](size_t b) { return B.material[b]; });
  array(out, "Int32", "fixed", 1, n, [&](size_t b) { return B.fixity[b]; });
  vec2_array(out, "velocity", n, [&](size_t b) { return Vec2(B.vx[b], B.vy[b]); });
  vec2_array(out, "displacement", n,
             [&](size_t b) { return Vec2(B.x[b] - B.x_ref[b], B.y[b] - B.y_ref[b]); });
  array(out, "Float64", "rotation", 1, n, [&](size_t b) { return B.theta[b]; });
  array(out, "Float64", "angular_velocity", 1, n, [&](size_t b) { return B.omega[b]; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

void write_contacts(const Model& m, const std::string& path) {
  const Contacts& C = m.contacts;
  const Blocks& B = m.blocks;
  const size_t n = C.size();
  std::ofstream out = open_file(path);
  // Each contact is drawn as the stretch of joint it stands for (a lone point as a micrometre).
  const std::vector<ContactStretch> stretch = contact_stretches(m);
  begin_piece(out, 2 * n, n, "Lines", [&](size_t k) {
    const size_t i = k / 2;
    const ContactStretch& s = stretch[i];
    if ((s.to - s.from).norm() >= 1e-6) return k % 2 ? s.to : s.from;
    return Vec2(C.point[i] + perp(C.normal[i]) * (0.5e-6 * (k % 2 ? 1.0 : -1.0)));
  });
  out << "<Lines>\n";
  array(out, "Int64", "connectivity", 1, 2 * n, [](size_t k) { return k; });
  array(out, "Int64", "offsets", 1, n, [](size_t i) { return 2 * (i + 1); });
  out << "</Lines>\n<CellData Scalars=\"normal_force\">\n";
  auto per_length = [&](double f, size_t i) { return C.length[i] > 0.0 ? f / C.length[i] : 0.0; };
  array(out, "Float64", "normal_force", 1, n, [&](size_t i) { return C.fn[i]; });
  array(out, "Float64", "shear_force", 1, n, [&](size_t i) { return C.fs[i]; });
  array(out, "Float64", "normal_stress", 1, n, [&](size_t i) { return per_length(C.fn[i], i); });
  array(out, "Float64", "shear_stress", 1, n, [&](size_t i) { return per_length(C.fs[i], i); });
  array(out, "Float64", "opening", 1, n,
        [&](size_t i) { return std::isfinite(C.gap[i]) ? C.gap[i] : 0.0; });
  array(out, "Float64", "shear_displacement", 1, n, [&](size_t i) { return C.shear_disp[i]; });
  array(out, "Float64", "dilation", 1, n, [&](size_t i) { return C.dilation[i]; });
  array(out, "Float64", "plastic_shear", 1, n, [&](size_t i) { return C.plastic_at(i); });
  array(out, "Float64", "length", 1, n, [&](size_t i) { return C.length[i]; });
  array(out, "Int32", "state", 1, n, [&](size_t i) { return contact_state_code(C.flags[i]); });
  array(out, "Int32", "joint_properties", 1, n, [&](size_t i) { return C.joint[i]; });
  array(out, "Int32", "joint_tag", 1, n, [&](size_t i) { return C.tag[i]; });
  array(out, "Int32", "block_a", 1, n, [&](size_t i) { return B.id[C.a[i]]; });
  array(out, "Int32", "block_b", 1, n, [&](size_t i) { return B.id[C.b[i]]; });
  vec2_array(out, "normal", n, [&](size_t i) { return C.normal[i]; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

// Bolts as polylines through their crossings: forces, displacements and state at each crossing
// (zero at the ends), the bolt's number per segment. Then cables through their nodes: the axial
// force of the segment from each node (zero at the last), the grout's slip and force per metre
// at each node; then liners through their nodes (a ring closed): axial force (tension positive),
// thrust, moment and the interface's pressure at each node; `kind` 1 for a bolt's segments, 2
// for a cable's, 3 for a liner's, and its number.
void write_support(const Model& m, const std::string& path) {
  const Reinforcement& R = m.support;
  // The cables of the model's dimension (the same fields in 2D and 3D); points in 3D (z = 0 in
  // 2D models).
  const bool three = m.dim == 3;
  const std::vector<Cable>& cables = three ? m.cables3.cables : m.cables.cables;
  const std::vector<uint32_t>& cable_of = three ? m.cables3.cable : m.cables.cable;
  const std::vector<double>& k_axial = three ? m.cables3.axial : m.cables.axial;
  const std::vector<double>& k_slip = three ? m.cables3.slip : m.cables.slip;
  const std::vector<double>& k_bond = three ? m.cables3.bond : m.cables.bond;
  const std::vector<uint8_t>& k_state = three ? m.cables3.state : m.cables.state;
  auto flat = [](const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); };
  struct Point {
    Vec3 at;
    int32_t element = -1;
  };
  std::vector<Point> pts;
  std::vector<int32_t> seg_bolt, seg_kind;
  std::vector<size_t> seg_start, seg_end;
  for (size_t b = 0; b < R.bolts.size(); ++b) {
    const std::vector<BoltPoint> p = bolt_path(m, b);
    for (size_t k = 0; k + 1 < p.size(); ++k)
      seg_start.push_back(pts.size() + k), seg_end.push_back(pts.size() + k + 1),
          seg_bolt.push_back(static_cast<int32_t>(b + 1));
    for (const BoltPoint& q : p) pts.push_back({flat(q.at), q.element});
  }
  seg_kind.assign(seg_bolt.size(), 1);
  const size_t first_node = pts.size();
  for (size_t c = 0; c < cables.size(); ++c) {
    const Cable& cab = cables[c];
    for (uint32_t k = 0; k + 1 < cab.count; ++k) {
      seg_start.push_back(pts.size() + k), seg_end.push_back(pts.size() + k + 1);
      seg_bolt.push_back(static_cast<int32_t>(c + 1)), seg_kind.push_back(2);
    }
    for (uint32_t i = cab.first; i < cab.first + cab.count; ++i)
      pts.push_back({three ? m.cables3.pos[i] : flat(m.cables.pos[i]), -1});
  }
  // Liners after the cables: a closed one's last element back to its first node (kind 3).
  const size_t first_liner = pts.size();
  const Liners& L = m.liners;
  for (size_t l = 0; l < L.liners.size(); ++l) {
    const Liner& ln = L.liners[l];
    for (uint32_t k = 0; k < ln.count; ++k) {
      const int64_t next = L.next(ln.first + k);
      if (next < 0) continue;
      seg_start.push_back(pts.size() + k);
      seg_end.push_back(pts.size() + static_cast<size_t>(next) - ln.first);
      seg_bolt.push_back(static_cast<int32_t>(l + 1));
      seg_kind.push_back(3);
    }
    for (uint32_t i = ln.first; i < ln.first + ln.count; ++i)
      pts.push_back({flat(liner_position(L, i)), -1});
  }
  // A liner node's value, or zero elsewhere.
  auto at_liner = [&](auto value) {
    return [&, value](size_t k) { return k >= first_liner ? value(k - first_liner) : 0.0; };
  };
  // A cable node's value, or zero at a bolt's points.
  auto node = [&](const std::vector<double>& v, bool last_zero) {
    return [&, last_zero](size_t k) {
      if (k < first_node || k >= first_liner) return 0.0;
      const size_t i = k - first_node;
      const bool last = i + 1 == cable_of.size() || cable_of[i + 1] != cable_of[i];
      return last && last_zero ? 0.0 : v[i];
    };
  };
  const size_t n = pts.size(), ns = seg_start.size();
  std::ofstream out = open_file(path);
  begin_piece(out, n, ns, "Lines", [&](size_t k) { return pts[k].at; });
  out << "<Lines>\n";
  array(out, "Int64", "connectivity", 1, 2 * ns,
        [&](size_t k) { return k % 2 ? seg_end[k / 2] : seg_start[k / 2]; });
  array(out, "Int64", "offsets", 1, ns, [](size_t s) { return 2 * (s + 1); });
  out << "</Lines>\n<PointData Scalars=\"axial_force\">\n";
  auto at = [&](const std::vector<double>& v) {
    return [&](size_t k) { return pts[k].element >= 0 ? v[size_t(pts[k].element)] : 0.0; };
  };
  const auto cable_axial = node(k_axial, true);
  array(out, "Float64", "axial_force", 1, n, [&](size_t k) {
    return k < first_node    ? at(R.axial)(k)
           : k < first_liner ? cable_axial(k)
                             : (L.next(k - first_liner) >= 0 ? L.axial[k - first_liner] : 0.0);
  });
  array(out, "Float64", "shear_force", 1, n, at(R.shear));
  array(out, "Float64", "axial_displacement", 1, n, at(R.ua));
  array(out, "Float64", "shear_displacement", 1, n, at(R.us));
  array(out, "Float64", "bond_slip", 1, n, node(k_slip, false));
  array(out, "Float64", "bond_force", 1, n, node(k_bond, false));
  array(out, "Float64", "moment", 1, n, at_liner([&](size_t i) { return liner_moment(L, i); }));
  array(out, "Float64", "thrust", 1, n, at_liner([&](size_t i) { return liner_thrust(L, i); }));
  array(out, "Float64", "pressure", 1, n, at_liner([&](size_t i) { return L.pressure[i]; }));
  array(out, "Int32", "state", 1, n, [&](size_t k) {
    return k >= first_liner      ? int{L.state[k - first_liner]}
           : k >= first_node     ? int{k_state[k - first_node]}
           : pts[k].element >= 0 ? int{R.state[size_t(pts[k].element)]}
                                 : 0;
  });
  out << "</PointData>\n<CellData Scalars=\"kind\">\n";
  array(out, "Int32", "kind", 1, ns, [&](size_t s) { return seg_kind[s]; });
  array(out, "Int32", "number", 1, ns, [&](size_t s) { return seg_bolt[s]; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

// 3D blocks: every face a polygon, carrying its block's data and its own joint tag.
void write_blocks3(const Model& m, const std::string& path) {
  m.blocks3.catch_up();
  const Blocks3& B = m.blocks3;
  const size_t nf = B.local_normal.size();
  std::vector<uint32_t> owner(nf);
  // Each face carries the motion of its block's body (a slave piece's master).
  std::vector<uint32_t> mover(nf);
  for (uint32_t b = 0; b < B.size(); ++b)
    for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f)
      owner[f] = b, mover[f] = static_cast<uint32_t>(B.master[b]);
  std::ofstream out = open_file(path);
  begin_piece(out, B.world_vertex.size(), nf, "Polys", [&](size_t v) { return B.world_vertex[v]; });
  out << "<Polys>\n";
  array(out, "Int64", "connectivity", 1, B.face_vert.size(),
        [&](size_t k) { return B.face_vert[k]; });
  array(out, "Int64", "offsets", 1, nf, [&](size_t f) { return B.fv_begin[f + 1]; });
  out << "</Polys>\n<CellData Scalars=\"group\">\n";
  const auto per_block = [&](const char* type, const char* name, auto value) {
    array(out, type, name, 1, nf, [&](size_t f) { return value(owner[f]); });
  };
  per_block("Int32", "id", [&](size_t b) { return B.id[b]; });
  per_block("Int32", "group", [&](size_t b) { return B.group[b]; });
  per_block("Int32", "material", [&](size_t b) { return B.material[b]; });
  per_block("Int32", "fixed", [&](size_t b) { return B.fixity[b]; });
  array(out, "Int32", "joint_tag", 1, nf, [&](size_t f) { return B.face_tag[f]; });
  vec3_array(out, "velocity", nf, [&](size_t f) { return B.body[mover[f]].velocity; });
  vec3_array(out, "displacement", nf,
             [&](size_t f) { return Vec3(B.body[mover[f]].position - B.ref[mover[f]]); });
  vec3_array(out, "angular_velocity", nf, [&](size_t f) { return B.omega[mover[f]]; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

// 3D sub-contacts as points with their forces, stresses and state.
void write_contacts3(const Model& m, const std::string& path) {
  const Blocks3& B = m.blocks3;
  std::vector<const SubContact*> subs;
  std::vector<const Contact3*> of;
  for (const Contact3& c : m.contacts3)
    for (const SubContact& s : c.subs) subs.push_back(&s), of.push_back(&c);
  const size_t n = subs.size();
  std::ofstream out = open_file(path);
  begin_piece(out, n, n, "Verts", [&](size_t i) { return world_point(B, *of[i], *subs[i]); });
  out << "<Verts>\n";
  array(out, "Int64", "connectivity", 1, n, [](size_t k) { return k; });
  array(out, "Int64", "offsets", 1, n, [](size_t i) { return i + 1; });
  out << "</Verts>\n<PointData Scalars=\"normal_stress\">\n";
  const auto per_area = [&](double f, size_t i) {
    return subs[i]->area > 0 ? f / subs[i]->area : 0.0;
  };
  array(out, "Float64", "normal_force", 1, n, [&](size_t i) { return subs[i]->fn; });
  const auto shear = [&](size_t i) { return subs[i]->shear(); };
  array(out, "Float64", "shear_force", 1, n, shear);
  array(out, "Float64", "normal_stress", 1, n, [&](size_t i) { return per_area(subs[i]->fn, i); });
  array(out, "Float64", "shear_stress", 1, n, [&](size_t i) { return per_area(shear(i), i); });
  array(out, "Float64", "opening", 1, n, [&](size_t i) { return subs[i]->gap; });
  array(out, "Float64", "area", 1, n, [&](size_t i) { return subs[i]->area; });
  array(out, "Float64", "shear_displacement", 1, n,
        [&](size_t i) { return subs[i]->shear_travel(); });
  array(out, "Float64", "dilation", 1, n, [&](size_t i) { return subs[i]->dilation; });
  array(out, "Float64", "plastic_shear", 1, n, [&](size_t i) { return subs[i]->plastic; });
  array(out, "Int32", "state", 1, n, [&](size_t i) { return contact_state_code(subs[i]->flags); });
  array(out, "Int32", "contact_type", 1, n, [&](size_t i) { return of[i]->type; });
  array(out, "Int32", "block_a", 1, n, [&](size_t i) { return B.id[of[i]->a]; });
  array(out, "Int32", "block_b", 1, n, [&](size_t i) { return B.id[of[i]->b]; });
  vec3_array(out, "normal", n, [&](size_t i) { return of[i]->normal; });
  vec3_array(out, "force", n, [&](size_t i) { return subs[i]->force; });
  out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

// Zones of the deformable blocks: nodes as points (with displacement and velocity), zones as
// triangles with stresses (tension positive), principal stresses, strains and plastic state.
void write_zones(const Model& m, const std::string& path) {
  const Continuum& c = m.continuum;
  const size_t nn = c.node_count(), nz = c.zone_count();
  std::ofstream out = open_file(path);
  begin_piece(out, nn, nz, "Polys", [&](size_t n) { return c.pos[n]; });
  out << "<Polys>\n";
  array(out, "Int64", "connectivity", 1, 3 * nz, [&](size_t k) { return c.zones[k / 3][k % 3]; });
  array(out, "Int64", "offsets", 1, nz, [](size_t z) { return 3 * (z + 1); });
  out << "</Polys>\n<PointData Vectors=\"displacement\">\n";
  vec2_array(out, "displacement", nn, [&](size_t n) { return Vec2(c.pos[n] - c.pos0[n]); });
  vec2_array(out, "velocity", nn, [&](size_t n) { return c.vel[n]; });
  out << "</PointData>\n<CellData Scalars=\"syy\">\n";
  array(out, "Float64", "sxx", 1, nz, [&](size_t z) { return c.stress[z].xx; });
  array(out, "Float64", "syy", 1, nz, [&](size_t z) { return c.stress[z].yy; });
  array(out, "Float64", "sxy", 1, nz, [&](size_t z) { return c.stress[z].xy; });
  array(out, "Float64", "szz", 1, nz, [&](size_t z) { return c.stress[z].zz; });
  auto principal = [&](size_t z, bool major) {
    double s1 = 0, s3 = 0;
    principal_stresses(c.stress[z], s1, s3);
    return major ? s1 : s3;
  };
  array(out, "Float64", "sigma1", 1, nz, [&](size_t z) { return principal(z, true); });
  array(out, "Float64", "sigma3", 1, nz, [&](size_t z) { return principal(z, false); });
  auto strain = [&](size_t z, int k) {
    double e[3];
    zone_strain(c, z, e[0], e[1], e[2]);
    return e[k];
  };
  array(out, "Float64", "exx", 1, nz, [&](size_t z) { return strain(z, 0); });
  array(out, "Float64", "eyy", 1, nz, [&](size_t z) { return strain(z, 1); });
  array(out, "Float64", "exy", 1, nz, [&](size_t z) { return strain(z, 2); });
  array(out, "Int32", "state", 1, nz, [&](size_t z) { return c.state[z]; });
  array(out, "Float64", "plastic_strain", 1, nz, [&](size_t z) { return c.plastic[z]; });
  array(out, "Int32", "material", 1, nz,
        [&](size_t z) { return static_cast<int>(c.material[z]) - 1; });
  out << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

// Zones of deformable 3D blocks as an UnstructuredGrid of tetrahedra (VTK cell type 10, 24 for
// a quadratic one): node
// displacement and velocity; per zone the stress tensor, principal stresses, strains, state.
void write_zones3(const Model& m, const std::string& path) {
  const Continuum3& c = m.continuum3;
  const size_t nn = c.node_count(), nz = c.zone_count();
  std::ofstream out = open_file(path);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
      << nn << "\" NumberOfCells=\"" << nz << "\">\n<Points>\n";
  vec3_array(out, "Points", nn, [&](size_t n) { return c.pos[n]; });
  out << "</Points>\n<Cells>\n";
  // Each zone's nodes: corners, then (quadratic tetra) the mid-edge nodes in VTK's order.
  std::vector<uint32_t> conn;
  std::vector<size_t> ends;
  for (size_t z = 0; z < nz; ++z) {
    c.for_zone_nodes(z, [&](uint32_t n) { conn.push_back(n); });
    ends.push_back(conn.size());
  }
  array(out, "Int64", "connectivity", 1, conn.size(), [&](size_t k) { return conn[k]; });
  array(out, "Int64", "offsets", 1, nz, [&](size_t z) { return ends[z]; });
  array(out, "UInt8", "types", 1, nz, [&](size_t z) { return c.quadratic(z) ? 24 : 10; });
  out << "</Cells>\n<PointData Vectors=\"displacement\">\n";
  vec3_array(out, "displacement", nn, [&](size_t n) { return Vec3(c.pos[n] - c.pos0[n]); });
  vec3_array(out, "velocity", nn, [&](size_t n) { return c.vel[n]; });
  out << "</PointData>\n<CellData Scalars=\"sigma1\">\n";
  // The stress tensor in ParaView's order for symmetric tensors: XX, YY, ZZ, XY, YZ, XZ.
  array(out, "Float64", "stress", 6, nz, [&](size_t k) {
    const ZoneStress& t = c.stress[k / 6];
    const double v[6] = {t.xx, t.yy, t.zz, t.xy, t.yz, t.xz};
    return v[k % 6];
  });
  std::vector<Principal> p(nz);
  for (size_t z = 0; z < nz; ++z) p[z] = principal_3d(c.stress[z]);
  array(out, "Float64", "sigma1", 1, nz, [&](size_t z) { return p[z].s[0]; });
  array(out, "Float64", "sigma2", 1, nz, [&](size_t z) { return p[z].s[1]; });
  array(out, "Float64", "sigma3", 1, nz, [&](size_t z) { return p[z].s[2]; });
  array(out, "Float64", "strain", 6, nz, [&](size_t k) {
    const StrainIncrement e = total_strain(c, k / 6);
    const double v[6] = {e.xx, e.yy, e.zz, e.xy, e.yz, e.xz};
    return v[k % 6];
  });
  array(out, "Int32", "state", 1, nz, [&](size_t z) { return c.state[z]; });
  array(out, "Float64", "plastic_strain", 1, nz, [&](size_t z) { return c.plastic[z]; });
  array(out, "Int32", "material", 1, nz,
        [&](size_t z) { return static_cast<int>(c.material[z]) - 1; });
  out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw std::runtime_error(path + ": writing failed");
}

}  // namespace

int contact_state_code(uint8_t flags) {
  if (!(flags & kTouching)) return 0;
  if (flags & kSlipping) return 2;
  if (flags & kBonded) return 3;
  return 1;
}

VtkSeries::VtkSeries(std::string dir) : dir_(std::move(dir)) {}

void VtkSeries::write(const Model& m) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec)
    throw std::runtime_error(dir_ + ": cannot create the output folder (" + ec.message() + ")");
  char name[64];
  std::snprintf(name, sizeof name, "%04zu.vtp", times_.size());
  if (m.dim == 3) {
    write_blocks3(m, dir_ + "/blocks_" + name);
    write_contacts3(m, dir_ + "/contacts_" + name);
  } else {
    write_blocks(m, dir_ + "/blocks_" + name);
    write_contacts(m, dir_ + "/contacts_" + name);
  }
  // Zones from the first snapshot that has them; a collection lists only files that exist.
  if (m.continuum.zone_count() > 0 || m.continuum3.zone_count() > 0) {
    if (zones_from_ < 0) zones_from_ = static_cast<int>(times_.size());
    if (m.dim == 3) {
      std::snprintf(name, sizeof name, "%04zu.vtu", times_.size());
      write_zones3(m, dir_ + "/zones_" + name);
      zones_ext_ = "vtu";
    } else {
      write_zones(m, dir_ + "/zones_" + name);
    }
  }
  // Support likewise, from the first snapshot that has some (empty once it is all gone).
  if (!m.support.empty() || !m.cables.empty() || !m.cables3.empty() || !m.liners.empty() ||
      support_from_ >= 0) {
    if (support_from_ < 0) support_from_ = static_cast<int>(times_.size());
    std::snprintf(name, sizeof name, "%04zu.vtp", times_.size());
    write_support(m, dir_ + "/support_" + name);
  }
  // The collections list one snapshot per time, in time: a snapshot at or before one listed
  // (after a `restore`, or the run's last at the cycle of an interval one) takes the place of
  // those from then on. Their files stay.
  while (!listed_.empty() && times_[listed_.back()] >= m.time) listed_.pop_back();
  listed_.push_back(times_.size());
  times_.push_back(m.time);
  write_collection("blocks");
  write_collection("contacts");
  if (support_from_ >= 0) write_collection("support", static_cast<size_t>(support_from_));
  if (zones_from_ >= 0) write_collection("zones", static_cast<size_t>(zones_from_), zones_ext_);
}

void VtkSeries::write_collection(const std::string& name, size_t first, const char* ext) const {
  const std::string path = dir_ + "/" + name + ".pvd";
  std::ofstream out = open_file(path);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  char buf[160];
  for (const size_t f : listed_) {
    if (f < first) continue;
    std::snprintf(buf, sizeof buf,
                  "<DataSet timestep=\"%.17g\" part=\"0\" file=\"%s_%04zu.%s\"/>\n", times_[f],
                  name.c_str(), f, ext);
    out << buf;
  }
  out << "</Collection>\n</VTKFile>\n";
}

}  // namespace tessera
