// Binary state file: a magic word, a version, then every field of the model in a fixed order.
// Doubles are written as their bytes, so a restored run continues bit for bit.
#include "tessera/io/state_io.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <type_traits>

#include "tessera/contact2d/detection.hpp"
#include "tessera/zones/deformable.hpp"
#include "tessera/zones/deformable3.hpp"

namespace tessera {

namespace {

constexpr char kMagic[8] = {'T', 'E', 'S', 'S', 'E', 'R', 'A', '2'};
constexpr uint32_t kVersion = 21;
static_assert(sizeof(Vec2) == 2 * sizeof(double));
// Sub-contacts and their node links are written as their bytes: a change of either's layout
// changes the file, and kVersion with it.
static_assert(sizeof(SubContact) == 160 && sizeof(NodeLink) == 48);

// Records written as their bytes whose structs have padding: their members, so that the padding
// can be written as zeros (it holds whatever the memory held, and a state file of the same model
// must be the same file every time).
template <class F>
void members(const SubContact& s, F f) {
  f(s.fn), f(s.fs), f(s.un_prev), f(s.dilation), f(s.shear_disp), f(s.flags), f(s.fs2);
  f(s.shear_disp2), f(s.plastic), f(s.key), f(s.local), f(s.area), f(s.gap), f(s.closure);
  f(s.force), f(s.link);
}
template <class F>
void members(const NodeLink& l, F f) {
  f(l.node), f(l.side), f(l.tri), f(l.weight);
}
template <class F>
void members(const RigidBody3& b, F f) {
  f(b.mass), f(b.principal), f(b.orientation), f(b.position), f(b.velocity), f(b.momentum);
}
template <class T>
constexpr bool kPadded =
    std::is_same_v<T, SubContact> || std::is_same_v<T, NodeLink> || std::is_same_v<T, RigidBody3>;

class Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out) {}
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod<uint64_t>(v.size());
    if constexpr (std::is_same_v<T, Vec2>) {
      for (const Vec2& p : v) pod(p.x()), pod(p.y());
    } else if constexpr (kPadded<T>) {
      for (const T& r : v) {
        char bytes[sizeof(T)] = {};
        const char* base = reinterpret_cast<const char*>(&r);
        members(r, [&](const auto& x) {
          std::memcpy(bytes + (reinterpret_cast<const char*>(&x) - base), &x, sizeof x);
        });
        out_.write(bytes, sizeof bytes);
      }
    } else {
      out_.write(reinterpret_cast<const char*>(v.data()),
                 static_cast<std::streamsize>(v.size() * sizeof(T)));
    }
  }
  // A count of records that follow (each at least 8 bytes in the file).
  void items(uint64_t& n) { pod(n); }
  void str(const std::string& s) {
    pod<uint64_t>(s.size());
    out_.write(s.data(), static_cast<std::streamsize>(s.size()));
  }

 private:
  std::ostream& out_;
};

class Reader {
 public:
  // `left`: the bytes of the file after the magic word, so that no count read from it can ask for
  // more memory than the file could fill.
  Reader(std::istream& in, const std::string& path, uint64_t left)
      : in_(in), path_(path), left_(left) {}
  template <class T>
  void pod(T& v) {
    take(sizeof v);
    in_.read(reinterpret_cast<char*>(&v), sizeof v);
    check();
  }
  template <class T>
  void vec(std::vector<T>& v) {
    uint64_t n = 0;
    pod(n);
    if (n > left_ / sizeof(T))
      fail("a list of " + std::to_string(n) + " items is longer than the rest of the file");
    if constexpr (!std::is_same_v<T, Vec2>) take(n * sizeof(T));
    v.resize(n);
    if constexpr (std::is_same_v<T, Vec2>) {
      for (Vec2& p : v) pod(p.x()), pod(p.y());
    } else {
      in_.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
      check();
    }
  }
  // A count of records that follow, each at least 8 bytes in the file: no more than it holds.
  void items(uint64_t& n) {
    pod(n);
    if (n > left_ / 8)
      fail("a count of " + std::to_string(n) + " records is more than the rest of the file holds");
  }
  void str(std::string& s) {
    uint64_t n = 0;
    pod(n);
    if (n > (1ULL << 24) || n > left_) fail("a name is implausibly long");
    take(n);
    s.resize(n);
    in_.read(s.data(), static_cast<std::streamsize>(n));
    check();
  }
  [[noreturn]] void fail(const std::string& why) {
    throw std::runtime_error(path_ + ": not a readable Tessera state file (" + why + ")");
  }

 private:
  void check() {
    if (!in_) fail("it ends early");
  }
  void take(uint64_t bytes) {
    if (bytes > left_) fail("it ends early");
    left_ -= bytes;
  }
  std::istream& in_;
  std::string path_;
  uint64_t left_;
};

// Cables of either dimension.
template <class IO, int D>
void cable_fields(IO& io, CablesT<D>& K) {
  size_t count = K.cables.size();
  io.items(count);
  K.cables.resize(count);
  for (auto& c : K.cables)
    io.str(c.name), io.pod(c.props), io.pod(c.first), io.pod(c.count), io.pod(c.head);
  io.vec(K.cable), io.vec(K.host), io.vec(K.bonded), io.vec(K.slip), io.vec(K.slip_plastic);
  io.vec(K.vel), io.vec(K.inertia), io.vec(K.bond), io.vec(K.state), io.vec(K.rest);
  io.vec(K.plastic), io.vec(K.axial), io.vec(K.pos), io.vec(K.axis), io.vec(K.host_force);
}

// One field list for both directions, so save and restore cannot drift apart.
template <class IO>
void fields(IO& io, auto& m) {
  auto& S = m.settings;
  io.pod(S.gravity.x()), io.pod(S.gravity.y()), io.pod(S.rounding), io.pod(S.contact_tolerance);
  io.pod(S.damping), io.pod(S.local_alpha), io.pod(S.global_ratio), io.pod(S.dt_safety);
  io.pod(S.dt_fixed), io.pod(S.dt_scaled), io.pod(S.kinetic_alpha);
  auto& B = m.blocks;
  for (auto* v : B.block_doubles()) io.vec(*v);
  io.vec(B.arc_radius), io.vec(B.round_length);
  io.vec(B.fixity), io.vec(B.vert_begin), io.vec(B.local_vertex), io.vec(B.local_arc_centre);
  io.vec(B.convex), io.vec(B.local_edge_dir), io.vec(B.edge_length), io.vec(B.all_convex);
  io.vec(B.edge_tag);
  io.vec(B.group), io.vec(B.material), io.vec(B.id);
  io.vec(B.node), io.vec(B.deformable);
  auto& C = m.contacts;
  io.vec(C.a), io.vec(C.b), io.vec(C.corner), io.vec(C.slot), io.vec(C.kind), io.vec(C.feature),
      io.vec(C.flags);
  io.vec(C.joint), io.vec(C.tag), io.vec(C.normal), io.vec(C.point), io.vec(C.gap);
  io.vec(C.length), io.vec(C.fn), io.vec(C.fs), io.vec(C.un_prev), io.vec(C.dilation);
  io.vec(C.shear_disp), io.vec(C.closure), io.vec(C.plastic);
  io.vec(C.damp_fn), io.vec(C.damp_fs), io.vec(C.pair_begin);
  uint64_t count = m.materials.size();
  io.items(count);
  m.materials.resize(count);
  for (auto& mat : m.materials) {
    io.str(mat.name), io.pod(mat.density);
    auto& z = mat.zone;
    io.str(z.name), io.str(z.model), io.pod(z.density), io.pod(z.bulk), io.pod(z.shear);
    io.pod(z.friction), io.pod(z.cohesion), io.pod(z.tension), io.pod(z.dilation);
    io.vec(z.ctable), io.vec(z.ftable), io.vec(z.dtable), io.vec(z.ttable);
    io.pod(z.jfriction), io.pod(z.jcohesion), io.pod(z.jtension), io.pod(z.jdilation);
    io.pod(z.e1), io.pod(z.e3), io.pod(z.nu12), io.pod(z.nu13), io.pod(z.g13);
    io.pod(z.jangle), io.pod(z.jdip), io.pod(z.jdipdir), io.pod(z.orientation);
  }
  count = m.joints.size();
  io.items(count);
  m.joints.resize(count);
  for (auto& j : m.joints) {
    io.str(j.name), io.str(j.law), io.pod(j.kn), io.pod(j.ks), io.pod(j.friction);
    io.pod(j.cohesion), io.pod(j.tension), io.pod(j.dilation), io.pod(j.dilation_limit);
    io.pod(j.residual_friction), io.pod(j.residual_cohesion), io.pod(j.normal_damping);
    io.pod(j.shear_damping), io.pod(j.en), io.pod(j.es), io.pod(j.sref), io.pod(j.smax);
    io.pod(j.initial_friction), io.pod(j.roughness), io.pod(j.jrc), io.pod(j.jcs), io.pod(j.vm);
    io.pod(j.dpeak), io.pod(j.lj), io.pod(j.kn_cap), io.pod(j.strength_divisor);
  }
  io.vec(m.joint_table);
  count = m.groups.size();
  io.items(count);
  m.groups.resize(count);
  for (auto& g : m.groups) io.str(g);
  count = m.joint_tags.size();
  io.items(count);
  m.joint_tags.resize(count);
  for (auto& t : m.joint_tags) io.str(t);
  auto& H = m.histories;
  io.pod(H.interval);
  count = H.series.size();
  io.items(count);
  H.series.resize(count);
  for (auto& s : H.series)
    io.pod(s.quantity), io.pod(s.block), io.pod(s.node), io.str(s.label), io.pod(s.zone);
  for (auto& s : H.series) io.pod(s.element);
  io.vec(H.cycles), io.vec(H.values);
  io.pod(m.cycle), io.pod(m.time), io.pod(m.dt), io.pod(m.dt_dirty), io.pod(m.global_c);
  io.vec(m.block_scale), io.pod(m.kinetic_last);
  io.pod(m.max_unbalanced), io.pod(m.mean_applied), io.pod(m.ratio);
  io.vec(m.det_x), io.vec(m.det_y), io.vec(m.det_theta), io.pod(m.detection_due);
  io.pod(m.detection_passes);
  auto& Z = m.continuum;
  io.vec(Z.pos), io.vec(Z.pos0), io.vec(Z.vel), io.vec(Z.force), io.vec(Z.applied);
  io.vec(Z.mass), io.vec(Z.inertia), io.vec(Z.fixity), io.vec(Z.fixed_vel), io.vec(Z.zones),
      io.vec(Z.stress);
  io.vec(Z.state), io.vec(Z.plastic), io.vec(Z.material), io.pod(Z.local_damping);
  io.pod(Z.dt), io.pod(Z.time);
  io.pod(Z.cycle), io.pod(Z.ratio), io.vec(m.det_node);
  // 3D models.
  io.pod(m.dim), io.pod(S.gravity3.x()), io.pod(S.gravity3.y()), io.pod(S.gravity3.z());
  auto& B3 = m.blocks3;
  io.vec(B3.body), io.vec(B3.omega), io.vec(B3.force), io.vec(B3.torque), io.vec(B3.applied);
  io.vec(B3.ref), io.vec(B3.ref_q), io.vec(B3.fixity), io.vec(B3.fixed_v), io.vec(B3.fixed_w);
  io.vec(B3.load_force), io.vec(B3.load_moment);
  io.vec(B3.volume), io.vec(B3.surface), io.vec(B3.bound_radius), io.vec(B3.vert_begin);
  io.vec(B3.local_vertex), io.vec(B3.world_vertex), io.vec(B3.face_begin), io.vec(B3.fv_begin);
  io.vec(B3.face_vert), io.vec(B3.local_normal), io.vec(B3.local_offset), io.vec(B3.world_normal),
      io.vec(B3.world_offset);
  io.vec(B3.face_tag), io.vec(B3.dir_begin), io.vec(B3.local_dir), io.vec(B3.world_dir);
  io.vec(B3.group), io.vec(B3.material), io.vec(B3.id), io.vec(B3.master);
  io.vec(B3.deformable), io.vec(B3.vertex_node), io.vec(B3.ftri_begin), io.vec(B3.ftri);
  io.vec(B3.node_begin), io.vec(B3.node_end), io.vec(B3.zone_begin), io.vec(B3.zone_end);
  auto& Z3 = m.continuum3;
  io.vec(Z3.pos), io.vec(Z3.pos0), io.vec(Z3.vel), io.vec(Z3.force), io.vec(Z3.applied);
  io.vec(Z3.mass), io.vec(Z3.inertia), io.vec(Z3.fixity), io.vec(Z3.fixed_vel);
  io.vec(Z3.zones), io.vec(Z3.stress), io.vec(Z3.state), io.vec(Z3.plastic), io.vec(Z3.material);
  io.vec(Z3.mid), io.vec(Z3.gp_stress), io.vec(Z3.gp_state), io.vec(Z3.gp_plastic);
  io.vec(Z3.edge_node);
  io.pod(Z3.local_damping), io.pod(Z3.dt), io.pod(Z3.time), io.pod(Z3.cycle), io.pod(Z3.ratio);
  io.vec(m.det_node3);
  count = m.contacts3.size();
  io.items(count);
  m.contacts3.resize(count);
  for (auto& c : m.contacts3) {
    io.pod(c.a), io.pod(c.b), io.pod(c.joint), io.pod(c.tag), io.pod(c.kind), io.pod(c.ia);
    io.pod(c.ib), io.pod(c.face_a), io.pod(c.face_b), io.pod(c.type);
    for (int k = 0; k < 3; ++k) io.pod(c.normal[k]), io.pod(c.t1[k]);
    io.pod(c.offset), io.pod(c.gap), io.vec(c.subs), io.vec(c.nodes);
    for (int k = 0; k < 3; ++k) io.pod(c.force[k]), io.pod(c.torque_a[k]), io.pod(c.torque_b[k]);
    io.pod(c.force_mag), io.pod(c.drift);
  }
  io.vec(m.det_pos3), io.vec(m.det_q3);
  // Rock support.
  auto& R = m.support;
  count = R.bolts.size();
  io.items(count);
  R.bolts.resize(count);
  for (auto& b : R.bolts) {
    io.str(b.name), io.pod(b.props), io.pod(b.end0), io.pod(b.end1), io.pod(b.first);
    io.pod(b.count);
  }
  io.vec(R.bolt), io.vec(R.side_a), io.vec(R.side_b), io.vec(R.axis0), io.vec(R.axial);
  io.vec(R.shear), io.vec(R.ua), io.vec(R.us), io.vec(R.state), io.vec(R.point), io.vec(R.force);
  cable_fields(io, m.cables);
  cable_fields(io, m.cables3);
  auto& L = m.liners;
  count = L.liners.size();
  io.items(count);
  L.liners.resize(count);
  for (auto& l : L.liners)
    io.str(l.name), io.pod(l.props), io.pod(l.first), io.pod(l.count), io.pod(l.closed);
  io.vec(L.liner), io.vec(L.host), io.vec(L.pos0), io.vec(L.normal), io.vec(L.disp);
  io.vec(L.vel), io.vec(L.force), io.vec(L.host_force), io.vec(L.length), io.vec(L.rot);
  io.vec(L.spin), io.vec(L.mass), io.vec(L.inertia), io.vec(L.shear), io.vec(L.pressure);
  io.vec(L.moment_sum), io.vec(L.state), io.vec(L.axial), io.vec(L.m_start), io.vec(L.m_end);
  io.vec(L.v_shear), io.vec(L.plastic_axial), io.vec(L.hinge_start), io.vec(L.hinge_end);
}

}  // namespace

void save_state(const Model& m, const std::string& path) {
  m.blocks3.catch_up();  // the file holds the vertices where the blocks are
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out.write(kMagic, sizeof kMagic);
  Writer w(out);
  w.pod(kVersion);
  // The field list is shared with restore; it only reads through the const model here.
  fields(w, const_cast<Model&>(m));
  if (!out) throw std::runtime_error(path + ": writing failed");
}

Model restore_state(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open for reading");
  char magic[sizeof kMagic] = {};
  in.read(magic, sizeof magic);
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  Reader r(in, path, ec || size < sizeof magic ? 0 : size - sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) r.fail("wrong magic word");
  uint32_t version = 0;
  r.pod(version);
  if (version != kVersion)
    throw std::runtime_error(path + ": a state file of version " + std::to_string(version) +
                             ", and this Tessera reads version " + std::to_string(kVersion) +
                             ": run the script that made it again to make it anew");
  Model m;
  fields(r, m);
  // A file with more in it than the state is not the file save wrote.
  if (in.peek() != std::char_traits<char>::eof()) r.fail("data after the end of the state");
  // Every index and count checked once, before anything follows them.
  if (const std::string why = state_problem(m); !why.empty()) r.fail(why);
  for (auto& j : m.joints) {
    if (!find_joint_law(j.law)) r.fail("joint properties '" + j.name + "' name no known law");
    j.finalize();
  }
  for (auto& mat : m.materials)
    if (!mat.zone.model.empty()) mat.zone.finalize();
  sync_zone_materials(m);
  m.continuum.gravity = m.settings.gravity;
  m.continuum3.gravity = m.settings.gravity3;
  // World caches are a pure function of the saved positions.
  m.blocks.world_vertex.resize(m.blocks.local_vertex.size());
  m.blocks.world_arc_centre.resize(m.blocks.local_vertex.size());
  m.blocks.world_edge_dir.resize(m.blocks.local_vertex.size());
  for (size_t b = 0; b < m.blocks.size(); ++b) m.blocks.update_world(b);
  auto& B3 = m.blocks3;
  B3.rotation.resize(B3.size());
  for (size_t b = 0; b < B3.size(); ++b) B3.rotation[b] = B3.body_rotation(b);
  update_deformable_world(m);
  update_deformable_world3(m);
  m.build_block_contacts();
  return m;
}

}  // namespace tessera
