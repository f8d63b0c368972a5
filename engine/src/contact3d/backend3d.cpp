// The 3D back end of the cycle: common-plane contacts with sub-contacts (subcontacts.cpp,
// detection3.cpp) and rigid blocks with six degrees of freedom (rigid3d.cpp: central
// differences for translation, the DRL splitting for rotation).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/backend.hpp"
#include "tessera/contact3d/detection3.hpp"
#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

namespace {

void prepare3d(Model& m) {
  const Blocks3& B = m.blocks3;
  // Joint properties are asked for by the first contact that needs them, naming its blocks.
  if (m.tolerance() <= 0.0 && B.size() > 1)
    throw ModelError("the contact tolerance is not set (use 'tolerance T' or 'round D')");
  for (size_t b = 0; b < B.size(); ++b)
    if (B.body[b].mass <= 0.0 && B.fixity[b] != kFix3All && !B.is_slave(b))
      throw ModelError("block " + std::to_string(B.id[b]) +
                       " has no mass: give it a material with a density");
  // Angular velocities from the momenta (a script may have set either).
  for (size_t b = 0; b < B.size(); ++b)
    m.blocks3.omega[b] = B.body[b].mass > 0.0 && B.fixity[b] != kFix3All ? B.spin(b) : B.fixed_w[b];
  if (m.det_pos3.size() != B.size()) m.detection_due = true;
  if (m.block_contact_begin.size() != B.size() + 1) m.build_block_contacts();
}

// Deepest plausible overlap between two blocks: a quarter of the smaller one's size (as 2D).
double max_contact_depth3(const Blocks3& B, uint32_t a, uint32_t b) {
  return 0.25 * std::min(B.bound_radius[a], B.bound_radius[b]);
}

// Stops the run on contact i's deepest sub-contact.
[[noreturn]] void throw_overlap3(const Model& m, uint32_t i) {
  const Contact3& c = m.contacts3[i];
  const SubContact* deepest = &c.subs.front();
  for (const SubContact& s : c.subs)
    if (s.gap < deepest->gap) deepest = &s;
  const Vec3 x = world_point(m.blocks3, c, *deepest);
  std::ostringstream where;
  where << "x=" << x.x() << ", y=" << x.y() << ", z=" << x.z();
  throw_overlap(m, c.a, c.b, -deepest->gap, kOverlapLimit * max_contact_depth3(m.blocks3, c.a, c.b),
                where.str(), "a corner of the faces' overlap on their common plane");
}

// Each contact's plane and sub-contacts moved with its blocks, then the joint law at its
// sub-contacts: one pass over the sub-contacts, which are most of the cycle's memory.
void joint_forces3d(Model& m) {
  // Each block's spin times its reach, once for all its contacts' drift.
  const Blocks3& B = m.blocks3;
  std::vector<double> turn_speed(B.size());
  parallel_for(B.size(), [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) turn_speed[b] = B.turn_speed(b);
  });
  // The first contact (lowest index, whatever the threads) whose overlap is beyond belief.
  FirstFlagged too_deep;
  const double refresh = plane_refresh_drift(m);
  m.reads_vertices3.resize(m.contacts3.size());
  parallel_for(
      m.contacts3.size(),
      [&](size_t c0, size_t c1) {
        for (size_t i = c0; i < c1; ++i) {
          Contact3& c = m.contacts3[i];
          const double deepest = contact_cycle3(m, c, turn_speed.data());
          m.reads_vertices3[i] = !follows_face_plane(c, refresh);
          if (deepest > kOverlapLimit * max_contact_depth3(B, c.a, c.b))
            too_deep.flag(static_cast<uint32_t>(i));
        }
      },
      64);
  if (too_deep.any()) throw_overlap3(m, too_deep.index());
  // Then the cables (locally damped in static runs).
  if (!m.cables3.empty())
    update_cables(m, m.settings.damping == DampingMode::kNone ? 0.0 : m.settings.local_alpha);
}

// Block b's gravity, loads and contact forces, gathered in a fixed order (the law leaves each
// contact's torque about both centroids: nothing the step moves is read).
void resultant3d(Model& m, size_t b) {
  Blocks3& B = m.blocks3;
  const Vec3 g = m.settings.gravity3;
  const double mass = B.body[b].mass;
  Vec3 f = mass * g + B.load_force[b], t = B.load_moment[b];
  double applied = mass * g.norm() + B.load_force[b].norm();
  for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k) {
    const Contact3& c = m.contacts3[m.block_contacts[k] >> 1];
    if (m.block_contacts[k] & 1)
      f -= c.force, t += c.torque_b;
    else
      f += c.force, t += c.torque_a;
    applied += c.force_mag;
  }
  B.force[b] = f, B.torque[b] = t, B.applied[b] = applied;
}

// Every block's resultant; slave pieces hand theirs to their masters (in block order:
// deterministic), and cables theirs to their hosts.
void resultants3d(Model& m) {
  Blocks3& B = m.blocks3;
  const size_t n = B.size();
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) resultant3d(m, b);
  });
  for (size_t b = 0; b < n; ++b)
    if (B.is_slave(b)) {
      const auto mb = static_cast<size_t>(B.master[b]);
      B.force[mb] += B.force[b], B.torque[mb] += B.torque[b], B.applied[mb] += B.applied[b];
    }
  add_cable_forces3(m);
}

bool gathers_in_step3d(const Model& m) {
  const Blocks3& B = m.blocks3;
  if (!m.cables3.empty()) return false;
  for (size_t b = 0; b < B.size(); ++b)
    if (B.is_slave(b)) return false;
  return true;
}

// As in 2D, on translation and rotation.
double motion_energy3d(const Model& m) {
  const Blocks3& B = m.blocks3;
  const auto& S = m.block_scale;
  return deterministic_sum(B.size(), [&](size_t b) {
    const RigidBody3& body = B.body[b];
    if (B.fixity[b] == kFix3All || body.mass <= 0.0) return 0.0;
    if (S.empty()) return 2.0 * body.kinetic_energy();
    return S[b][0] * body.mass * body.velocity.squaredNorm() +
           S[b][1] * body.momentum.dot(body.angular_velocity());
  });
}

Power power3d(const Model& m) {
  const Blocks3& B = m.blocks3;
  Power p;
  p.power = deterministic_sum(B.size(), [&](size_t b) {
    if (B.fixity[b] == kFix3All || B.body[b].mass <= 0.0) return 0.0;
    return B.force[b].cwiseProduct(B.body[b].velocity).cwiseAbs().sum() +
           B.torque[b].cwiseProduct(B.body[b].angular_velocity()).cwiseAbs().sum();
  });
  p.kin2 = motion_energy3d(m);
  return p;
}

void stop3d(Model& m) {
  Blocks3& B = m.blocks3;
  for (size_t b = 0; b < B.size(); ++b)
    if (!B.deformable[b])
      B.body[b].velocity.setZero(), B.body[b].momentum.setZero(), B.omega[b].setZero();
}

// An upper bound of the rotation angle between two orientations (2 asin s <= pi s, with s the
// sine of the half angle), cheaper than the angle itself.
double turned(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1) {
  return M_PI * (q0.conjugate() * q1).vec().norm();
}

// Whether a contact of block b will re-fit its plane or rebuild its sub-contacts when the next
// cycle moves it (update_plane3), reading b's vertices and edge directions (as this cycle's law
// found).
bool vertices_read(const Model& m, size_t b) {
  for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k)
    if (m.reads_vertices3[m.block_contacts[k] >> 1]) return true;
  return false;
}

// The block's face planes follow its body every cycle, its vertices only if a contact reads them.
void move_surface(const Model& m, Blocks3& B, size_t b) {
  B.update_planes(b);
  if (vertices_read(m, b)) B.update_vertices(b);
}

void integrate3d(Model& m, const Damping& d, bool gather, BlockMotion& out) {
  Blocks3& B = m.blocks3;
  const double dt = m.dt;
  const auto& S = m.block_scale;
  const size_t n = B.size();
  out.reset(n);
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      if (gather) resultant3d(m, b);
      if (B.deformable[b]) continue;  // its nodes move in the zone stage
      RigidBody3& body = B.body[b];
      const uint8_t fix = B.fixity[b];
      out.moves[b] = body.mass > 0.0 && (fix & 7) != 7;
      out.applied[b] = out.moves[b] ? B.applied[b] : 0.0;
      if (B.is_slave(b)) continue;  // moved with its master below
      const bool moving = body.mass > 0.0 && fix != kFix3All;
      const Vec3 inv_moment = moving ? Vec3(body.principal.cwiseInverse()) : Vec3::Zero();
      if (!moving) {
        // Held: moves at its prescribed velocity.
        body.velocity = B.fixed_v[b];
        body.momentum = Vec3::Zero();
        if (B.fixed_w[b].squaredNorm() > 0.0) {
          const double angle = B.fixed_w[b].norm() * dt;
          body.orientation =
              Eigen::Quaterniond(Eigen::AngleAxisd(angle, B.fixed_w[b].normalized())) *
              body.orientation;
          body.orientation.normalize();
        }
        body.position += dt * body.velocity;
      } else {
        Vec3 f = B.force[b], t = B.torque[b];
        out.unbalanced[b] = f.norm();
        // Local damping on each component against its velocity; global viscous damping.
        const Vec3 v = body.velocity, w = B.omega[b];
        for (int k = 0; k < 3; ++k) {
          f[k] = locally_damped(f[k], v[k], d.alpha);
          t[k] = locally_damped(t[k], w[k], d.alpha);
        }
        // Density scaling: the scaled mass and moments of inertia take the forces (the body's
        // momentum stays the real inertia times the spin).
        const double st = S.empty() ? 1.0 : S[b][0], sr = S.empty() ? 1.0 : S[b][1];
        f -= d.viscosity * (body.mass * st) * v;
        t -= d.viscosity * sr * body.momentum;
        if (!S.empty()) f /= st, t /= sr;
        // Fixed components: no force, the prescribed velocity.
        for (int k = 0; k < 3; ++k)
          if (fix & (1 << k)) f[k] = 0.0, body.velocity[k] = B.fixed_v[b][k];
        if (fix & kFix3Rot) t = Vec3::Zero(), body.momentum = Vec3::Zero();
        step_body(body, f, t, dt, inv_moment);
      }
      move_surface(m, B, b);
      // (Through the rotation the face planes were just turned by.)
      B.omega[b] = moving ? B.spin(b, inv_moment) : B.fixed_w[b];
    }
    // The measures of the step, in a loop of their own: the square roots and divisions of one
    // block do not wait for its step, and those of many blocks overlap.
    for (size_t b = b0; b < b1; ++b) {
      if (B.deformable[b] || B.is_slave(b)) continue;
      const RigidBody3& body = B.body[b];
      out.drift[b] = (body.position - m.det_pos3[b]).norm() +
                     B.bound_radius[b] * turned(body.orientation, m.det_q3[b]);
      out.jump[b] = dt * (body.velocity.norm() + B.turn_speed(b)) / B.bound_radius[b];
      if (!std::isfinite(out.jump[b])) out.jump[b] = 1e300;
    }
  });
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b)
      if (B.is_slave(b) && !B.deformable[b]) move_surface(m, B, b);  // (zoned: nodes)
  });
  B.vertices_behind = true;
}

// Each body: the joint area in touch is at most its surface (all its pieces'), at most
// bound_radius away.
std::vector<std::array<double, 2>> block_steps3d(const Model& m, double k) {
  const Blocks3& B = m.blocks3;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 2>> steps(B.size(), {kInf, kInf});
  std::vector<double> surface(B.size(), 0.0);
  for (size_t b = 0; b < B.size(); ++b) surface[static_cast<size_t>(B.master[b])] += B.surface[b];
  // Cables add their grout's stiffness to the bodies that host them.
  const std::vector<double> cables = cable_stiffness3(m);
  for (size_t b = 0; b < B.size(); ++b) {
    const double kb = k * surface[b] + cables[b];
    if (B.fixity[b] == kFix3All || kb <= 0.0 || B.body[b].mass <= 0.0 || B.is_slave(b)) continue;
    const double r = B.bound_radius[b];
    steps[b][0] = 2.0 * std::sqrt(B.body[b].mass / kb);
    steps[b][1] = 2.0 * std::sqrt(B.body[b].principal.minCoeff() / (kb * r * r));
  }
  return steps;
}

double kinetic_energy3d(const Model& m) {
  const Blocks3& B = m.blocks3;
  return deterministic_sum(B.size(), [&](size_t b) {
    return B.fixity[b] == kFix3All ? 0.0 : B.body[b].kinetic_energy();
  });
}

}  // namespace

const Backend& backend3d() {
  static const Backend be{.prepare = prepare3d,
                          .detect = detect_contacts3,
                          .geometry = nullptr,
                          .joint_forces = joint_forces3d,
                          .resultants = resultants3d,
                          .gathers_in_step = gathers_in_step3d,
                          .power = power3d,
                          .motion_energy = motion_energy3d,
                          .stop = stop3d,
                          .integrate = integrate3d,
                          .block_steps = block_steps3d,
                          .kinetic_energy = kinetic_energy3d,
                          .find_overlap = find_overlap3,
                          .validate = validate3d};
  return be;
}

}  // namespace tessera
