// One cycle of a 3D model: detection when due, common planes and sub-contacts with the joint
// law, then block resultants, damping and integration (DRL rotation, central differences).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "stage_timer.hpp"
#include "tessera/parallel.hpp"
#include "tessera/solver.hpp"
#include "tessera/solver3.hpp"

namespace tessera {

namespace {

struct Box3 {
  Vec3 lo, hi;
};

std::vector<Box3> block_boxes3(const Blocks3& B, double grow) {
  std::vector<Box3> boxes(B.size());
  for (size_t b = 0; b < B.size(); ++b) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
      lo = lo.cwiseMin(B.world_vertex[v]), hi = hi.cwiseMax(B.world_vertex[v]);
    boxes[b] = {lo - Vec3::Constant(grow), hi + Vec3::Constant(grow)};
  }
  return boxes;
}

// Pairs (lo, hi) whose boxes overlap, sorted: sweep and prune along the axis on which the
// blocks spread most.
std::vector<std::pair<uint32_t, uint32_t>> broad_phase3(const std::vector<Box3>& boxes) {
  const size_t n = boxes.size();
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  if (n < 2) return pairs;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Box3& x : boxes) lo = lo.cwiseMin(x.lo), hi = hi.cwiseMax(x.hi);
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  std::vector<uint32_t> order(n);
  for (uint32_t b = 0; b < n; ++b) order[b] = b;
  std::sort(order.begin(), order.end(), [&](uint32_t p, uint32_t q) {
    return boxes[p].lo[axis] < boxes[q].lo[axis] ||
           (boxes[p].lo[axis] == boxes[q].lo[axis] && p < q);
  });
  for (size_t i = 0; i < n; ++i) {
    const Box3& a = boxes[order[i]];
    for (size_t j = i + 1; j < n && boxes[order[j]].lo[axis] <= a.hi[axis]; ++j) {
      const Box3& b = boxes[order[j]];
      if ((a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all())
        pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

inline double sgn(double v) {
  return (v > 0.0) - (v < 0.0);
}

// An upper bound of the rotation angle between two orientations (2 asin s <= pi s, with s the
// sine of the half angle), cheaper than the angle itself.
double turned(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1) {
  return M_PI * (q0.conjugate() * q1).vec().norm();
}

void build_adjacency3(Model& m) {
  const auto& C = m.contacts3;
  const size_t n = m.blocks3.size();
  std::vector<uint32_t> count(n + 1, 0);
  for (const Contact3& c : C) ++count[c.a + 1], ++count[c.b + 1];
  for (size_t b = 0; b < n; ++b) count[b + 1] += count[b];
  m.block_contact_begin = count;
  m.block_contacts.assign(count[n], 0);
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (uint32_t i = 0; i < C.size(); ++i) {
    m.block_contacts[fill[C[i].a]++] = i * 2;
    m.block_contacts[fill[C[i].b]++] = i * 2 + 1;
  }
}

// Resultants, damping and integration of every block; convergence measures and the checks
// that the run has not diverged.
void move_blocks3(Model& m) {
  Blocks3& B = m.blocks3;
  const Settings& S = m.settings;
  const double dt = m.dt;
  const size_t n = B.size();
  std::vector<double> unbalanced(n, 0.0), drift(n, 0.0), jump(n, 0.0);
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      const double mass = B.body[b].mass;
      Vec3 f = mass * S.gravity3, t = Vec3::Zero();
      double applied = mass * S.gravity3.norm();
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
  });
  // Slave pieces hand their resultants to their masters (in block order: deterministic).
  for (size_t b = 0; b < n; ++b)
    if (B.is_slave(b)) {
      const auto mb = static_cast<size_t>(B.master[b]);
      B.force[mb] += B.force[b], B.torque[mb] += B.torque[b], B.applied[mb] += B.applied[b];
    }
  // Adaptive global damping: as in 2D, on translation and rotation.
  if (S.damping == DampingMode::kAdaptiveGlobal && m.cycle % 10 == 0) {
    const double power = deterministic_sum(n, [&](size_t b) {
      if (B.fixity[b] == kFix3All || B.body[b].mass <= 0.0) return 0.0;
      return B.force[b].cwiseProduct(B.body[b].velocity).cwiseAbs().sum() +
             B.torque[b].cwiseProduct(B.body[b].angular_velocity()).cwiseAbs().sum();
    });
    const double kin2 = deterministic_sum(n, [&](size_t b) {
      if (B.fixity[b] == kFix3All || B.body[b].mass <= 0.0) return 0.0;
      return 2.0 * B.body[b].kinetic_energy();
    });
    servo_global_damping(m, power, kin2);
  }
  const double c_glob = S.damping == DampingMode::kAdaptiveGlobal ? m.global_c : 0.0;
  const double alpha = S.damping == DampingMode::kLocal ? S.local_alpha : 0.0;
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      RigidBody3& body = B.body[b];
      const uint8_t fix = B.fixity[b];
      if (B.is_slave(b)) continue;  // moved with its master below
      if (body.mass <= 0.0 || fix == kFix3All) {
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
        unbalanced[b] = f.norm();
        // Local damping on each component against its velocity; global viscous damping.
        const Vec3 v = body.velocity, w = B.omega[b];
        for (int k = 0; k < 3; ++k) {
          f[k] -= alpha * std::abs(f[k]) * sgn(v[k]);
          t[k] -= alpha * std::abs(t[k]) * sgn(w[k]);
        }
        f -= c_glob * body.mass * v;
        t -= c_glob * body.momentum;
        // Fixed components: no force, the prescribed velocity.
        for (int k = 0; k < 3; ++k)
          if (fix & (1 << k)) f[k] = 0.0, body.velocity[k] = B.fixed_v[b][k];
        if (fix & kFix3Rot) t = Vec3::Zero(), body.momentum = Vec3::Zero();
        step_body(body, f, t, dt);
      }
      B.omega[b] = body.mass > 0.0 && fix != kFix3All ? body.angular_velocity() : B.fixed_w[b];
      B.update_world(b);
      drift[b] = (body.position - m.det_pos3[b]).norm() +
                 B.bound_radius[b] * turned(body.orientation, m.det_q3[b]);
      jump[b] =
          dt * (body.velocity.norm() + B.bound_radius[b] * B.omega[b].norm()) / B.bound_radius[b];
      if (!std::isfinite(jump[b])) jump[b] = 1e300;
    }
  });
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b)
      if (B.is_slave(b)) B.update_world(b);
  });
  size_t free_blocks = 0, worst = 0;
  double max_ub = 0.0, max_drift = 0.0;
  for (size_t b = 0; b < n; ++b) {
    max_drift = std::max(max_drift, drift[b]);
    if (!(jump[b] <= jump[worst])) worst = b;
    if (B.body[b].mass <= 0.0 || (B.fixity[b] & 7) == 7) continue;
    ++free_blocks;
    max_ub = std::max(max_ub, unbalanced[b]);
  }
  const double sum_applied = deterministic_sum(n, [&](size_t b) {
    return B.body[b].mass > 0.0 && (B.fixity[b] & 7) != 7 ? B.applied[b] : 0.0;
  });
  m.max_unbalanced = max_ub;
  m.mean_applied = free_blocks ? sum_applied / static_cast<double>(free_blocks) : 0.0;
  m.ratio = m.mean_applied > 0.0 ? max_ub / m.mean_applied : 0.0;
  if (max_drift > 0.5 * m.tolerance()) m.detection_due = true;
  if (!std::isfinite(max_ub) || !std::isfinite(max_drift) || !(jump[worst] < 0.1))
    throw_diverged(m, B.id[worst]);
}

}  // namespace

void detect_contacts3(Model& m) {
  const Blocks3& B = m.blocks3;
  const double tol = m.tolerance();
  std::vector<Contact3> next;
  size_t j = 0;
  auto& old = m.contacts3;
  for (const auto& [lo, hi] : broad_phase3(block_boxes3(B, 0.5 * tol))) {
    const auto mlo = static_cast<size_t>(B.master[lo]), mhi = static_cast<size_t>(B.master[hi]);
    // Pieces of one body never touch; nor do two held bodies.
    if (mlo == mhi || (B.fixity[mlo] == kFix3All && B.fixity[mhi] == kFix3All)) continue;
    const PlaneFit fit = best_plane(B, lo, hi);
    if (fit.gap > tol) continue;
    while (j < old.size() && std::make_pair(old[j].a, old[j].b) < std::make_pair(lo, hi)) ++j;
    if (j < old.size() && old[j].a == lo && old[j].b == hi) {
      next.push_back(std::move(old[j]));
    } else {
      Contact3 c;
      c.a = lo, c.b = hi;
      c.tag = fit.kind == kPlaneFaceB   ? B.face_tag[fit.ib]
              : fit.kind == kPlaneFaceA ? B.face_tag[fit.ia]
                                        : -1;
      const int joint = m.joint_for(lo, hi, c.tag);
      if (joint < 0)
        throw ModelError("no joint properties apply to the contact between " + m.block_label(lo) +
                         " and " + m.block_label(hi) + ": use 'joint assign'");
      c.joint = static_cast<uint32_t>(joint);
      c.face_a = B.face_begin[lo], c.face_b = B.face_begin[hi];
      next.push_back(std::move(c));
    }
    Contact3& c = next.back();
    c.kind = fit.kind, c.ia = fit.ia, c.ib = fit.ib;
  }
  m.contacts3 = std::move(next);
  build_adjacency3(m);
  m.det_pos3.resize(B.size()), m.det_q3.resize(B.size());
  for (size_t b = 0; b < B.size(); ++b)
    m.det_pos3[b] = B.body[b].position, m.det_q3[b] = B.body[b].orientation;
  m.detection_due = false;
  ++m.detection_passes;
}

std::string find_overlap3(const Model& m) {
  const Blocks3& B = m.blocks3;
  const double tol = m.tolerance();
  for (const auto& [lo, hi] : broad_phase3(block_boxes3(B, 0.0))) {
    const PlaneFit fit = best_plane(B, lo, hi);
    if (fit.gap < -tol) {
      std::ostringstream s;
      const Vec3& p = B.body[lo].position;
      s << "blocks " << B.id[lo] << " and " << B.id[hi] << " overlap by " << -fit.gap
        << " m (near x=" << p.x() << ", y=" << p.y() << ", z=" << p.z() << ")";
      return s.str();
    }
  }
  return {};
}

double compute_timestep3(const Model& m) {
  double kmax = 0.0;
  for (const JointProperties& j : m.joints) kmax = std::max({kmax, j.kn, j.ks});
  const Blocks3& B = m.blocks3;
  double dt = std::numeric_limits<double>::infinity();
  // Each body: the joint area in touch is at most its surface (all its pieces'), at most
  // bound_radius away.
  std::vector<double> surface(B.size(), 0.0);
  for (size_t b = 0; b < B.size(); ++b) surface[static_cast<size_t>(B.master[b])] += B.surface[b];
  for (size_t b = 0; b < B.size(); ++b) {
    if (B.fixity[b] == kFix3All || kmax <= 0.0 || B.body[b].mass <= 0.0 || B.is_slave(b)) continue;
    const double k = kmax * surface[b];
    const double r = B.bound_radius[b];
    dt = std::min(dt, 2.0 * std::sqrt(B.body[b].mass / k));
    dt = std::min(dt, 2.0 * std::sqrt(B.body[b].principal.minCoeff() / (k * r * r)));
  }
  if (!std::isfinite(dt)) return 1e-3;
  return m.settings.dt_safety * dt;
}

void prepare3(Model& m) {
  const Blocks3& B = m.blocks3;
  if (B.size() == 0) throw ModelError("the model has no blocks");
  // Joint properties are asked for by the first contact that needs them, naming its blocks.
  if (m.tolerance() <= 0.0 && B.size() > 1)
    throw ModelError("the contact tolerance is not set (use 'tolerance T' or 'round D')");
  for (size_t b = 0; b < B.size(); ++b)
    if (B.body[b].mass <= 0.0 && B.fixity[b] != kFix3All && !B.is_slave(b))
      throw ModelError("block " + std::to_string(B.id[b]) +
                       " has no mass: give it a material with a density");
  // Angular velocities from the momenta (a script may have set either).
  for (size_t b = 0; b < B.size(); ++b)
    m.blocks3.omega[b] = B.body[b].mass > 0.0 && B.fixity[b] != kFix3All
                             ? B.body[b].angular_velocity()
                             : B.fixed_w[b];
  if (m.dt_dirty) {
    m.dt = compute_timestep(m);
    m.dt_dirty = false;
  }
  if (m.det_pos3.size() != B.size()) m.detection_due = true;
  if (m.block_contact_begin.size() != B.size() + 1) build_adjacency3(m);
}

void cycle3(Model& m) {
  {
    StageTimer t(kStageDetect);
    if (m.detection_due) detect_contacts3(m);
  }
  {
    StageTimer t(kStageContacts);
    parallel_for(
        m.contacts3.size(),
        [&](size_t c0, size_t c1) {
          for (size_t i = c0; i < c1; ++i) update_contact3(m, m.contacts3[i]);
        },
        64);
  }
  {
    StageTimer t(kStageMotion);
    move_blocks3(m);
  }
  m.time += m.dt;
  ++m.cycle;
  if (Profile* p = run_options().profile) ++p->cycles;
  sample_histories(m);
}

double kinetic_energy3(const Model& m) {
  const Blocks3& B = m.blocks3;
  return deterministic_sum(B.size(), [&](size_t b) {
    return B.fixity[b] == kFix3All ? 0.0 : B.body[b].kinetic_energy();
  });
}

}  // namespace tessera
