// Sub-contacts of a 3D contact: the overlap of the two facing faces on the common plane, and
// the joint law at each of its corners (see contacts3.hpp).
#include "tessera/contact3d/subcontacts.hpp"

#include <algorithm>
#include <cmath>

#include "contact3d/face_overlap.hpp"
#include "core/coulomb_law.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/contact3d/common_plane.hpp"

namespace tessera {

void carry_state(const Model& m, const Contact3& c, SubContact& s,
                 const std::vector<SubContact>& old, std::vector<uint8_t>& used) {
  int match = -1;
  for (size_t o = 0; o < old.size() && match < 0; ++o)
    if (!used[o] && old[o].key == s.key) match = static_cast<int>(o);
  double best = m.tolerance();
  for (size_t o = 0; o < old.size() && match < 0; ++o) {
    const double d = (old[o].local - s.local).norm();
    if (!used[o] && d < best) best = d, match = static_cast<int>(o);
  }
  if (match < 0) {
    if (m.cycle == 0 && s.gap <= m.bond_gap()) {
      const JointProperties& jp = m.joints[c.joint];
      if (jp.cohesion > 0.0 || jp.tension > 0.0) s.flags |= kBonded;
    }
    return;
  }
  const SubContact& o = old[static_cast<size_t>(match)];
  used[static_cast<size_t>(match)] = 1;
  static_cast<JointState&>(s) = o;
  s.closure = o.closure;
}

namespace {

// The face of block b that faces the plane: of the faces through its vertex nearest the plane
// (support value `support` along `dir`, outwards), the one whose outward normal is most nearly
// along `dir`. The current one is kept unless another is better by a margin, so the choice does
// not flicker between two.
uint32_t facing_face(const Blocks3& B, uint32_t b, const Vec3& dir, double support,
                     uint32_t current) {
  const double eps = 1e-9 * B.bound_radius[b];
  const auto touches = [&](uint32_t f) {
    for (uint32_t k = B.fv_begin[f]; k < B.fv_begin[f + 1]; ++k)
      if (dir.dot(B.world_vertex[B.face_vert[k]]) >= support - eps) return true;
    return false;
  };
  uint32_t best = current;
  const bool valid =
      current >= B.face_begin[b] && current < B.face_begin[b + 1] && touches(current);
  // A face lying along the plane is kept without a search (face-to-face contacts, the most).
  if (valid && B.world_normal[current].dot(dir) > 1.0 - 1e-6) return current;
  double best_dot = valid ? B.world_normal[current].dot(dir) + 1e-3 : -2.0;
  for (uint32_t f = B.face_begin[b]; f < B.face_begin[b + 1]; ++f) {
    const double d = B.world_normal[f].dot(dir);
    if (d > best_dot && touches(f)) best_dot = d, best = f;
  }
  return best;
}

// Scratch space of one thread.
struct Work {
  std::vector<PolyVertex> poly, clip, scratch;
  std::vector<uint32_t> clip_vertex;
  std::vector<SubContact> old;
  std::vector<uint8_t> used;
};
thread_local Work work;

// Builds the sub-contacts afresh: facing faces, their overlap on the plane, areas, gaps, and the
// joint state carried over from the sub-contacts before.
void corner_subcontacts(const Model& m, Contact3& c, const Vec3& n) {
  const Blocks3& B = m.blocks3;
  const uint32_t a = c.a, b = c.b;
  const auto [t1, t2] = tangents(n);
  const auto project = [&](const Vec3& x) { return Eigen::Vector2d(x.dot(t1), x.dot(t2)); };
  // a's face is counter-clockwise seen from below the plane: walk it backwards.
  Work& w = work;
  w.poly.clear(), w.clip.clear(), w.clip_vertex.clear();
  const uint32_t fa0 = B.fv_begin[c.face_a], fa1 = B.fv_begin[c.face_a + 1];
  for (uint32_t k = fa1; k-- > fa0;) {
    const uint32_t prev = k > fa0 ? k - 1 : fa1 - 1;
    w.poly.push_back({project(B.world_vertex[B.face_vert[k]]), kKeyVertexA | B.face_vert[k], prev});
  }
  const uint32_t fb0 = B.fv_begin[c.face_b], fb1 = B.fv_begin[c.face_b + 1];
  for (uint32_t k = fb0; k < fb1; ++k) {
    w.clip.push_back({project(B.world_vertex[B.face_vert[k]]), kKeyVertexB | B.face_vert[k],
                      kEdgeB | (k - fb0)});
    w.clip_vertex.push_back(B.face_vert[k]);
  }
  const double scale = B.bound_radius[a] + B.bound_radius[b];
  clip_polygon(w.poly, w.clip, w.clip_vertex, 1e-12 * scale * scale, w.scratch);
  // Corners closer than a billionth of the blocks' size are one.
  {
    std::vector<PolyVertex>& p = w.poly;
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i)
      if (k == 0 || (p[i].p - p[k - 1].p).norm() > 1e-9 * scale) p[k++] = p[i];
    while (k > 1 && (p[k - 1].p - p[0].p).norm() <= 1e-9 * scale) --k;
    p.resize(k);
  }
  // Areas: half of each fan triangle beside a corner, the fan about the overlap's centroid: a
  // uniform pressure's resultant then acts at the centroid, as it should (about the corners'
  // mean it acts halfway from the centroid to that mean: off on a trapezoid, say).
  const size_t np = w.poly.size();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const PolyVertex& v : w.poly) centre += v.p;
  if (np) centre /= static_cast<double>(np);
  {
    double twice_area = 0.0;
    Eigen::Vector2d moment = Eigen::Vector2d::Zero();
    for (size_t i = 0; i < np; ++i) {
      const Eigen::Vector2d p = w.poly[i].p - centre, q = w.poly[(i + 1) % np].p - centre;
      const double fan = cross2(p, q);
      twice_area += fan, moment += fan * (p + q);
    }
    // (A sliver of no area keeps the mean.)
    if (std::abs(twice_area) > 1e-12 * scale * scale) centre += moment / (3.0 * twice_area);
  }
  w.old.swap(c.subs);
  c.subs.clear(), c.nodes.clear();
  const Vec3 ma = B.world_normal[c.face_a], mb = B.world_normal[c.face_b];
  const double da = B.world_offset[c.face_a], db = B.world_offset[c.face_b];
  const double mna = ma.dot(n), mnb = mb.dot(n);
  std::vector<uint8_t>& used = w.used;
  used.assign(w.old.size(), 0);
  for (size_t i = 0; i < np && std::abs(mna) > 0.05 && std::abs(mnb) > 0.05; ++i) {
    const Eigen::Vector2d& p = w.poly[i].p;
    const Eigen::Vector2d& pp = w.poly[(i + np - 1) % np].p;
    const Eigen::Vector2d& pn = w.poly[(i + 1) % np].p;
    SubContact s;
    s.key = w.poly[i].key;
    s.area = 0.25 * (std::abs(cross2(pp - centre, p - centre)) +
                     std::abs(cross2(p - centre, pn - centre)));
    const Vec3 x = c.offset * n + p.x() * t1 + p.y() * t2;
    s.local = frame_point(B, c, x);
    // Heights of the two faces above the plane along n.
    const double ha = (da - ma.dot(x)) / mna, hb = (db - mb.dot(x)) / mnb;
    s.gap = ha - hb;
    carry_state(m, c, s, w.old, used);
    c.subs.push_back(s);
  }
}

// Tangent t moved into the plane of normal n by the least turn (or any tangent, if t is none or
// the plane has turned too far from it for that).
Vec3 in_plane_tangent(const Vec3& t, const Vec3& n) {
  const Vec3 u = t - t.dot(n) * n;
  return u.squaredNorm() > 0.25 ? Vec3(u.normalized()) : tangents(n).first;
}

// The plane's normal is now n: the first tangent moves into the plane, and each sub-contact's
// shear force, turned into the plane with its magnitude kept, is written in the new basis.
void turn_shear_basis(Contact3& c, const Vec3& n) {
  const Vec3 t1 = c.t1, t2 = c.t2();
  const Vec3 u1 = in_plane_tangent(t1, n), u2 = n.cross(u1);
  for (SubContact& s : c.subs) {
    if (s.fs == 0.0 && s.fs2 == 0.0) continue;
    Vec3 f = s.fs * t1 + s.fs2 * t2;
    const double size2 = f.squaredNorm();
    f -= f.dot(n) * n;
    if (f.squaredNorm() > 0.0) f *= std::sqrt(size2 / f.squaredNorm());
    s.fs = f.dot(u1), s.fs2 = f.dot(u2);
  }
  c.t1 = u1, c.normal = n;
}

void rebuild(const Model& m, Contact3& c, const PlaneFit& fit) {
  const Blocks3& B = m.blocks3;
  const uint32_t a = c.a, b = c.b;
  const Vec3 n = fit.normal;
  const double lo_a = fit.lo_a, hi_b = fit.hi_b;
  c.gap = lo_a - hi_b, c.offset = 0.5 * (lo_a + hi_b);
  c.face_a = facing_face(B, a, -n, -lo_a, c.face_a);
  c.face_b = facing_face(B, b, n, hi_b, c.face_b);
  if (B.deformable[a] || B.deformable[b])
    rebuild_node_subcontacts(m, c, n);
  else
    corner_subcontacts(m, c, n);
  // The shear carried over, in the basis of the plane as it is now.
  turn_shear_basis(c, n);
  const double tol = m.tolerance();
  // Contact type from the vertices of each block within the tolerance of the plane.
  int near_a = 0, near_b = 0;
  for (uint32_t v = B.vert_begin[a]; v < B.vert_begin[a + 1]; ++v)
    near_a += n.dot(B.world_vertex[v]) <= lo_a + tol;
  for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
    near_b += n.dot(B.world_vertex[v]) >= hi_b - tol;
  const int lo = std::min(near_a, near_b), hi = std::max(near_a, near_b);
  c.type = lo <= 1 ? kVertexFace : hi == 2 ? kEdgeEdge : lo == 2 ? kEdgeFace : kFaceFace;
}

// The law's open branch (joint_forces3's, and the plane's pass for open contacts): whether a
// sub-contact at this overlap stays open, and if so what the law writes.
[[gnu::always_inline]] inline bool open_branch(SubContact& s, double overlap) {
  const double un_now = overlap + s.dilation;
  if (!stays_open(un_now, s.fn, s.flags)) return false;
  s.fs = 0.0, s.fs2 = 0.0, s.un_prev = un_now, s.force = Vec3::Zero();
  return true;
}

// Between rebuilds: each sub-contact's point rides on block a (in its frame), its gap is measured
// afresh between the two facing faces' planes along the plane's normal. With try_open, for a
// contact open last cycle, the law's open branch is tried at each sub-contact as its gap is
// formed: returns true if they all stayed open (deepest: the deepest overlap, as the law's).
bool follow(const Model& m, Contact3& c, const Vec3& n, bool try_open, double& deepest) {
  const Blocks3& B = m.blocks3;
  // A turn of the plane beyond a hundredth of a radian in a step (as when its candidate changes)
  // re-expresses the shear at once; the law keeps the tangent in the plane through smaller ones.
  if (c.normal.dot(n) < 0.99995) turn_shear_basis(c, n);
  if (B.deformable[c.a] || B.deformable[c.b]) {
    follow_node_subcontacts(m, c, n);
    return false;
  }
  const RigidBody3& ba = frame_body(B, c);
  const Vec3 ma_n = B.world_normal[c.face_a], mb_n = B.world_normal[c.face_b];
  const double da = B.world_offset[c.face_a], db = B.world_offset[c.face_b];
  const double mna = ma_n.dot(n), mnb = mb_n.dot(n);
  c.normal = n;
  // The gap (da - ma_n . p) / mna - (db - mb_n . p) / mnb at p = xa + R q (q the point in a's
  // frame) is g0 - k . q: per point one dot product, per contact two divisions.
  const double ia = 1.0 / mna, ib = 1.0 / mnb;
  const Vec3 kw = ma_n * ia - mb_n * ib;
  const double g0 = da * ia - db * ib - kw.dot(ba.position);
  const Vec3 k = B.rotation[c.a].transpose() * kw;
  const double kx = k.x(), ky = k.y(), kz = k.z();
  const auto gap = [&](const SubContact& s) {
    const Vec3& q = s.local;
    return g0 - (kx * q.x() + ky * q.y() + kz * q.z());
  };
  auto s = c.subs.begin();
  if (try_open && c.open) {
    const double roundoff = m.roundoff_gap();
    double d = 0.0;
    for (; s != c.subs.end(); ++s) {
      s->gap = gap(*s);
      d = std::max(d, -s->gap);
      if (!open_branch(*s, without_roundoff(-s->gap + s->closure, roundoff))) break;
    }
    if (s == c.subs.end()) {
      deepest = d;
      return true;
    }
    ++s;
  }
  for (; s != c.subs.end(); ++s) s->gap = gap(*s);
  return false;
}

// update_plane3; with try_open, true if follow found every sub-contact open (see follow).
bool move_plane(const Model& m, Contact3& c, bool try_open, double& deepest) {
  const Blocks3& B = m.blocks3;
  const uint32_t a = c.a, b = c.b;
  // The plane moves with the blocks: the same candidate, re-evaluated (a face's normal is read
  // from the block's cache; an edge pair's needs the support values).
  PlaneFit fit;
  const double refresh = plane_refresh_drift(m);
  if (follows_face_plane(c, refresh)) {
    fit.normal = c.kind == kPlaneFaceB ? B.world_normal[c.ib] : Vec3(-B.world_normal[c.ia]);
    return follow(m, c, fit.normal, try_open, deepest);
  } else {
    fit = evaluate_plane(B, a, b, c.kind, c.ia, c.ib);
    if (fit.gap <= -1e299) {
      fit = best_plane(B, a, b);
      c.kind = fit.kind, c.ia = fit.ia, c.ib = fit.ib;
    }
    if (c.drift < refresh) return follow(m, c, fit.normal, try_open, deepest);
    // At a rebuild the plane is chosen afresh if another candidate now separates the blocks
    // clearly better: a block sliding across a joint in its base meets the next base block
    // first on a vertical plane (its front face), which must give way to the base's top face
    // once the two overlap there.
    const PlaneFit best = best_plane(B, a, b);
    if (best.gap > fit.gap + 1e-9 * (B.bound_radius[a] + B.bound_radius[b])) {
      fit = best;
      c.kind = fit.kind, c.ia = fit.ia, c.ib = fit.ib;
    }
    rebuild(m, c, fit);
    c.drift = 0.0;
  }
  return false;
}

// How far any point of one block may have moved against the other this step (translation plus
// turning at the blocks' reach): the sub-contacts are rebuilt once that adds up to a hundredth
// of the tolerance.
double step_drift(const Model& m, const Contact3& c, const double* turn_speed) {
  const Blocks3& B = m.blocks3;
  const Vec3& va = B.body[static_cast<size_t>(B.master[c.a])].velocity;
  const Vec3& vb = B.body[static_cast<size_t>(B.master[c.b])].velocity;
  const double turn_a = turn_speed ? turn_speed[c.a] : B.turn_speed(c.a);
  const double turn_b = turn_speed ? turn_speed[c.b] : B.turn_speed(c.b);
  return m.dt * ((va - vb).norm() + turn_a + turn_b);
}
}  // namespace

void update_plane3(const Model& m, Contact3& c) {
  double deepest = 0.0;
  move_plane(m, c, false, deepest);
}

double contact_cycle3(const Model& m, Contact3& c, const double* turn_speed) {
  double deepest = 0.0;
  if (!move_plane(m, c, true, deepest)) return joint_forces3(m, c, turn_speed);
  // The law's results with every sub-contact open.
  c.force = Vec3::Zero(), c.torque_a = Vec3::Zero(), c.torque_b = Vec3::Zero();
  c.force_mag = 0.0;
  c.drift += step_drift(m, c, turn_speed);
  return deepest;
}

double joint_forces3(const Model& m, Contact3& c, const double* turn_speed) {
  const Blocks3& B = m.blocks3;
  const uint32_t a = c.a, b = c.b;
  const Vec3 n = c.normal;
  // The bodies that move the two pieces (a slave piece moves with its master).
  const auto ma_body = static_cast<size_t>(B.master[a]), mb_body = static_cast<size_t>(B.master[b]);
  const RigidBody3& ba = B.body[ma_body];
  const RigidBody3& bb = B.body[mb_body];
  // The joint law at every sub-contact.
  const double dt = m.dt;
  const JointProperties& jp = m.joints[c.joint];
  const double roundoff = m.roundoff_gap();
  const Vec3& wa = B.omega[ma_body];
  const Vec3& wb = B.omega[mb_body];
  const bool deformable = B.deformable[a] || B.deformable[b];
  const Vec3 xab = bb.position - ba.position;
  // Sub-contact points q are kept in the frame of a's body: p - xa = R q.
  const Mat3& rot = B.rotation[a];
  // What the law needs of the contact as a whole, formed at its first sub-contact that is not
  // open (many contacts have none: the head joints of a wall under gravity).
  bool ready = false;
  Vec3 t1, t2, u1, u2, un;
  double c1 = 0.0, c2 = 0.0, cn = 0.0, area = 0.0, m_eff = 0.0;
  const bool damped = jp.normal_damping > 0.0 || jp.shear_damping > 0.0;
  const auto prepare = [&] {
    // The shear's basis kept in the plane as it turns (see contacts3.hpp).
    c.t1 = t1 = in_plane_tangent(c.t1, n), t2 = n.cross(t1);
    // Relative velocity of a over b at a point p, (va + wa x (p - xa)) - (vb + wb x (p - xb)),
    // is v0 + dw x r with r = p - xa; its component along a unit vector t is
    // v0 . t + r . (t x dw): per contact the two vectors, per sub-contact one dot product.
    const Vec3 v0 = ba.velocity - bb.velocity + wb.cross(xab), dw = wa - wb;
    c1 = v0.dot(t1), c2 = v0.dot(t2), cn = v0.dot(n);
    u1 = t1.cross(dw), u2 = t2.cross(dw), un = n.cross(dw);
    // Contact damping: the joint's area and the two bodies' effective mass.
    if (damped) {
      for (const SubContact& q : c.subs) area += q.area;
      const auto inverse = [&](size_t k, const RigidBody3& body) {
        return B.fixity[k] == kFix3All || body.mass <= 0.0 ? 0.0 : 1.0 / body.mass;
      };
      const double inv = inverse(ma_body, ba) + inverse(mb_body, bb);
      m_eff = inv > 0.0 ? 1.0 / inv : 0.0;
    }
    ready = true;
  };
  // Sums over the sub-contacts: force on a, its moment about a's centroid, |Fn| + |Fs|.
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double load = 0.0;
  double deepest = 0.0, fastest = 0.0;
  for (SubContact& s : c.subs) {
    deepest = std::max(deepest, -s.gap);
    const double overlap = without_roundoff(-s.gap + s.closure, roundoff);
    if (open_branch(s, overlap)) {
      if (s.link >= 0)
        fastest = std::max(fastest,
                           (side_velocity(m, c, s, 0) - side_velocity(m, c, s, 1)).squaredNorm());
      continue;
    }
    if (!ready) prepare();
    const Vec3 ra = rot * s.local;
    // The relative velocity in the plane's basis (n, t1, t2).
    double vn, v1, v2;
    if (s.link < 0) {
      v1 = c1 + ra.dot(u1), v2 = c2 + ra.dot(u2);
      vn = damped || deformable ? cn + ra.dot(un) : 0.0;
    } else {
      const Vec3 dv = side_velocity(m, c, s, 0) - side_velocity(m, c, s, 1);
      vn = dv.dot(n), v1 = dv.dot(t1), v2 = dv.dot(t2);
    }
    if (deformable) fastest = std::max(fastest, vn * vn + v1 * v1 + v2 * v2);
    const double shear = joint_update<false>(jp, s.area, overlap, v1 * dt, v2 * dt, s);
    // The force on a, with the dashpots' share.
    double pn = s.fn, p1 = s.fs, p2 = s.fs2;
    if (damped && (s.flags & kTouching)) {
      const Dashpot d =
          contact_dashpot(jp, s.area, s.area / area, m_eff, -vn, v1, v2, s.flags & kSlipping);
      pn += d.fn, p1 += d.fs, p2 += d.fs2;
    }
    s.force = pn * n + p1 * t1 + p2 * t2;
    force += s.force;
    torque += ra.cross(s.force);
    load += std::abs(s.fn) + shear;
  }
  c.force = force, c.torque_a = torque, c.force_mag = load;
  // b's torque about its own centroid: -sum (p - xb) x f = -(torque_a - xab x F).
  c.torque_b = ready ? Vec3(xab.cross(c.force) - c.torque_a) : Vec3::Zero();
  // The step's drift; a deformable block's nodes move on their own: the fastest sub-contact
  // counts as well.
  c.drift += step_drift(m, c, turn_speed);
  if (deformable) c.drift += dt * std::sqrt(fastest);
  c.open = !ready && !deformable;
  return deepest;
}

}  // namespace tessera
