// The 2D back end of the cycle: rounded-corner contacts (interfaces.cpp, detection.cpp) and
// rigid blocks with three degrees of freedom, moved by central differences.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/backend.hpp"
#include "tessera/contact2d/detection.hpp"
#include "tessera/contact2d/interfaces.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/cables.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

namespace {

void prepare2d(Model& m) {
  // Joint properties are asked for by the first contact that needs them (naming its blocks): a
  // single zoned block has none. Contacts need the rounding length.
  if (m.settings.rounding <= 0.0 && m.blocks.size() > 1)
    throw ModelError("the rounding length is not set (use 'round')");
  for (size_t b = 0; b < m.blocks.size(); ++b)
    if (m.blocks.mass[b] <= 0.0 && m.blocks.fixity[b] != kFixAll)
      throw ModelError("block " + std::to_string(m.blocks.id[b]) +
                       " has no mass: give it a material with a density");
  m.blocks.shrink_to_fit();
  if (m.det_x.size() != m.blocks.size()) m.detection_due = true;
  if (m.block_contact_begin.size() != m.blocks.size() + 1) m.build_block_contacts();
}

// Gravity, loads and contact forces, gathered in a fixed order per block from its interfaces'
// sums (Contacts::pair_force, formed by the interfaces stage).
void resultants2d(Model& m) {
  Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const Vec2 g = m.settings.gravity;
  parallel_for(B.size(), [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      double fx = B.mass[b] * g.x() + B.load_fx[b], fy = B.mass[b] * g.y() + B.load_fy[b];
      double mz = B.load_m[b];
      double applied = B.mass[b] * g.norm() +
                       std::sqrt(B.load_fx[b] * B.load_fx[b] + B.load_fy[b] * B.load_fy[b]);
      // On side b: the opposite force, its moment about b's centroid from the one about a's
      // (for side a the arm a - b is zero).
      for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k) {
        const uint32_t p = m.block_contacts[k] >> 1;
        const double sign = Contacts::side_sign(m.block_contacts[k] & 1);
        const Vec2 f = C.pair_force[p];
        const uint32_t a = C.a[C.pair_begin[p]];
        const double dx = B.x[a] - B.x[b], dy = B.y[a] - B.y[b];
        fx += sign * f.x(), fy += sign * f.y();
        mz += sign * (C.pair_moment[p] + (dx * f.y() - dy * f.x()));
        applied += C.pair_load[p];
      }
      B.fx[b] = fx, B.fy[b] = fy, B.moment[b] = mz, B.applied[b] = applied;
    }
  });
  add_reinforcement_forces(m);
}

// Not in 2D: a pair's moment about its second block is formed from the first block's centroid,
// which the step may already have moved.
bool gathers_in_step2d(const Model&) {
  return false;
}

// Joint forces, then the bolts across them, the cables and liners (locally damped in static
// runs).
void joint_forces2d(Model& m) {
  update_interfaces(m);
  update_reinforcement(m);
  const double alpha = m.settings.damping == DampingMode::kNone ? 0.0 : m.settings.local_alpha;
  if (!m.cables.empty()) update_cables(m, alpha);
  if (!m.liners.empty()) update_liners(m, alpha);
}

// Twice the kinetic energy over free degrees of freedom, with the density-scaled inertia.
double motion_energy2d(const Model& m) {
  const Blocks& B = m.blocks;
  const auto& S = m.block_scale;
  return deterministic_sum(B.size(), [&](size_t b) {
    const uint8_t fix = B.fixity[b];
    const double st = S.empty() ? 1.0 : S[b][0], sr = S.empty() ? 1.0 : S[b][1];
    double k = 0.0;
    if (B.inv_mass[b] > 0.0 && !(fix & kFixX)) k += st * B.mass[b] * B.vx[b] * B.vx[b];
    if (B.inv_mass[b] > 0.0 && !(fix & kFixY)) k += st * B.mass[b] * B.vy[b] * B.vy[b];
    if (B.inv_inertia[b] > 0.0 && !(fix & kFixRot))
      k += sr * B.inertia[b] * B.omega[b] * B.omega[b];
    return k;
  });
}

// Power of the unbalanced forces and twice the kinetic energy, over free degrees of freedom.
Power power2d(const Model& m) {
  const Blocks& B = m.blocks;
  Power p;
  p.power = deterministic_sum(B.size(), [&](size_t b) {
    const uint8_t fix = B.fixity[b];
    double w = 0.0;
    if (B.inv_mass[b] > 0.0 && !(fix & kFixX)) w += std::abs(B.fx[b] * B.vx[b]);
    if (B.inv_mass[b] > 0.0 && !(fix & kFixY)) w += std::abs(B.fy[b] * B.vy[b]);
    if (B.inv_inertia[b] > 0.0 && !(fix & kFixRot)) w += std::abs(B.moment[b] * B.omega[b]);
    return w;
  });
  p.kin2 = motion_energy2d(m);
  return p;
}

void stop2d(Model& m) {
  Blocks& B = m.blocks;
  std::fill(B.vx.begin(), B.vx.end(), 0.0);
  std::fill(B.vy.begin(), B.vy.end(), 0.0);
  std::fill(B.omega.begin(), B.omega.end(), 0.0);
}

// Damping and integration, one degree of freedom at a time (under density scaling with the
// scaled mass and moment of inertia).
void integrate2d(Model& m, const Damping& d, bool /*gather*/, BlockMotion& out) {
  Blocks& B = m.blocks;
  const double dt = m.dt;
  const auto& S = m.block_scale;
  out.reset(B.size());
  parallel_for(B.size(), [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      const uint8_t fix = B.fixity[b];
      double ub2 = 0.0;
      auto advance = [&](double f, double& v, double inv_m, double mass, bool fixed,
                         double v_fixed) {
        if (fixed || inv_m == 0.0) {
          v = fixed ? v_fixed : 0.0;
          return;
        }
        ub2 += f * f;
        const double fd = locally_damped(f, v, d.alpha) - d.viscosity * mass * v;
        v += dt * fd * inv_m;
      };
      double inv_m = B.inv_mass[b], mass = B.mass[b];
      double inv_i = B.inv_inertia[b], inertia = B.inertia[b];
      if (!S.empty()) inv_m /= S[b][0], mass *= S[b][0], inv_i /= S[b][1], inertia *= S[b][1];
      advance(B.fx[b], B.vx[b], inv_m, mass, fix & kFixX, B.fixed_vx[b]);
      advance(B.fy[b], B.vy[b], inv_m, mass, fix & kFixY, B.fixed_vy[b]);
      const double ub_force = ub2;
      advance(B.moment[b], B.omega[b], inv_i, inertia, fix & kFixRot, B.fixed_omega[b]);
      out.unbalanced[b] = std::sqrt(ub_force);
      out.moves[b] = B.inv_mass[b] > 0.0 && (fix & (kFixX | kFixY)) != (kFixX | kFixY);
      out.applied[b] = out.moves[b] ? B.applied[b] : 0.0;
      B.x[b] += dt * B.vx[b];
      B.y[b] += dt * B.vy[b];
      B.theta[b] += dt * B.omega[b];
      B.update_world(b);
      // Largest vertex displacement since the last detection pass.
      const double dx = B.x[b] - m.det_x[b], dy = B.y[b] - m.det_y[b];
      out.drift[b] =
          std::sqrt(dx * dx + dy * dy) + B.bound_radius[b] * std::abs(B.theta[b] - m.det_theta[b]);
      out.jump[b] = dt *
                    (std::sqrt(B.vx[b] * B.vx[b] + B.vy[b] * B.vy[b]) +
                     B.bound_radius[b] * std::abs(B.omega[b])) /
                    B.bound_radius[b];
    }
  });
}

// Each block: the joint length in touch is at most its perimeter, at most bound_radius away.
std::vector<std::array<double, 2>> block_steps2d(const Model& m, double k) {
  const Blocks& B = m.blocks;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 2>> steps(B.size(), {kInf, kInf});
  const std::vector<double> bolts = reinforcement_stiffness(m);
  for (size_t b = 0; b < B.size(); ++b) {
    const double kb = k * B.perimeter[b] + bolts[b];
    if (B.fixity[b] == kFixAll || kb <= 0.0) continue;
    if (B.inv_mass[b] > 0.0) steps[b][0] = 2.0 * std::sqrt(B.mass[b] / kb);
    if (B.inv_inertia[b] > 0.0)
      steps[b][1] = 2.0 * std::sqrt(B.inertia[b] / (kb * B.bound_radius[b] * B.bound_radius[b]));
  }
  return steps;
}

double kinetic_energy2d(const Model& m) {
  const Blocks& B = m.blocks;
  return 0.5 * deterministic_sum(B.size(), [&](size_t b) {
           return B.mass[b] * (B.vx[b] * B.vx[b] + B.vy[b] * B.vy[b]) +
                  B.inertia[b] * B.omega[b] * B.omega[b];
         });
}

}  // namespace

const Backend& backend2d() {
  static const Backend be{.prepare = prepare2d,
                          .detect = detect_contacts,
                          .geometry = update_contact_geometry,
                          .joint_forces = joint_forces2d,
                          .resultants = resultants2d,
                          .gathers_in_step = gathers_in_step2d,
                          .power = power2d,
                          .motion_energy = motion_energy2d,
                          .stop = stop2d,
                          .integrate = integrate2d,
                          .block_steps = block_steps2d,
                          .kinetic_energy = kinetic_energy2d,
                          .find_overlap = find_overlap2d,
                          .validate = validate2d};
  return be;
}

}  // namespace tessera
