// One cycle, top to bottom: detection when due, contact geometry and joint law, interface
// lengths and forces, then block resultants, damping and integration.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "stage_timer.hpp"
#include "tessera/contact_geometry.hpp"
#include "tessera/deformable.hpp"
#include "tessera/parallel.hpp"
#include "tessera/solver.hpp"
#include "tessera/solver3.hpp"

namespace tessera {

namespace {

// Velocity of a block's material point p.
inline Vec2 point_velocity(const Blocks& B, uint32_t b, const Vec2& p) {
  return {B.vx[b] - B.omega[b] * (p.y() - B.y[b]), B.vy[b] + B.omega[b] * (p.x() - B.x[b])};
}

// Whether corner v is inside block b at about the overlap's depth: its distance to b's outline
// at least half the overlap (a toe sunk into a soft joint), not at b's edge or vertex.
bool corner_buried(const Blocks& B, uint32_t v, uint32_t b, double overlap) {
  const std::vector<Vec2> poly = B.world_polygon(b);
  const Vec2& p = B.world_vertex[v];
  if (!point_in_polygon(p, poly)) return false;
  for (size_t k = 0; k < poly.size(); ++k)
    if (segment_distance(p, poly[k], poly[(k + 1) % poly.size()]) < 0.5 * overlap) return false;
  return true;
}

// Contact geometry from the current positions: the nearest feature of the other block to each
// corner (searched around last cycle's feature), gap, normal, contact point and chord.
void update_contacts(Model& m) {
  const Blocks& B = m.blocks;
  Contacts& C = m.contacts;
  parallel_for(C.size(), [&](size_t i0, size_t i1) {
    for (size_t i = i0; i < i1; ++i) {
      const uint32_t a = C.a[i], b = C.b[i], v = C.corner[i];
      FeatureHit hit;
      const bool lost = C.kind[i] == kLost;
      const CornerArc arc = corner_arc(B, a, v);
      const double depth = max_contact_depth(B, a, b);
      // A corner in a notch keeps its face: valid or lost, no search.
      if (C.flags[i] & kNotch) {
        if (C.kind[i] == kCornerEdge &&
            edge_feature(B, b, C.feature[i], arc, depth, hit, nullptr)) {
          C.gap[i] = hit.gap, C.normal[i] = hit.normal, C.point[i] = hit.point;
          C.chord[i] = hit.chord;
        } else {
          C.kind[i] = kLost;
          C.gap[i] = std::numeric_limits<double>::infinity();
          C.chord[i] = 0.0;
        }
        continue;
      }
      // Fast path: still well inside the span of the same edge.
      double margin = -1.0;
      if (C.kind[i] == kCornerEdge && edge_feature(B, b, C.feature[i], arc, depth, hit, &margin) &&
          margin > 0.0) {
        C.gap[i] = hit.gap, C.normal[i] = hit.normal, C.point[i] = hit.point,
        C.chord[i] = hit.chord;
        continue;
      }
      const int first = lost ? 0 : local_feature(B, b, C.kind[i], C.feature[i]) - 2;
      const int all = 2 * static_cast<int>(B.vertex_count(b));
      bool found = nearest_feature(B, b, arc, a < b, first, lost ? all : 5, depth, hit);
      // An overlap past the arc's radius is rare and suspect: the whole block is searched for a
      // nearer feature, and it is believed only if the owner's sharp corner is inside b (a toe
      // sunk into a soft joint is; a corner at the tip of a thin sliver of b, measured against
      // the sliver's far side, is not).
      if (found && hit.gap < -arc.radius)
        found = (lost || nearest_feature(B, b, arc, a < b, 0, all, depth, hit)) &&
                (hit.gap >= -arc.radius || corner_buried(B, v, b, -hit.gap));
      if (!found) {
        // The corner has left the reach of every feature: it carries nothing until found again.
        C.kind[i] = kLost;
        C.gap[i] = std::numeric_limits<double>::infinity();
        C.chord[i] = 0.0;
        continue;
      }
      C.kind[i] = hit.kind, C.feature[i] = hit.feature, C.gap[i] = hit.gap;
      C.normal[i] = hit.normal, C.point[i] = hit.point, C.chord[i] = hit.chord;
    }
  });
}

// The stretch of joint a corner stands for when it is alone on its joint line (its neighbour
// has lifted off): the corner as a sharp wedge cut by the other block's surface, each of its two
// edges overlapping up to where it leaves that surface (at most the edge's straight part), and
// half of that extent, since a spring bed under a wedge carries kn o s / 2. Without it the
// length is the arc's chord, which vanishes as the overlap passes 2d, and a toppling block on
// soft joints sinks through its base on its toe. Just after the neighbour lifts, the wedge runs
// the whole face and the length is the share the two had: (w - 2d) / 2.
double wedge_length(const Blocks& B, const Contacts& C, uint32_t i) {
  const uint32_t a = C.a[i], v = C.corner[i];
  const uint32_t vp = B.prev_vertex(a, v);
  const Vec2 nrm = C.normal[i], t = perp(nrm);
  // Depth of the sharp corner below the other block's surface (normals point to the owner).
  const Vec2 surface = C.point[i] - 0.5 * C.gap[i] * nrm;
  const double depth = (surface - B.world_vertex[v]).dot(nrm);
  if (!(depth > 0.0)) return 0.0;
  const uint32_t v0 = B.vert_begin[a], n = B.vertex_count(a);
  const uint32_t next = v0 + (v - v0 + 1) % n;
  double width = 0.0;
  // One edge leaving the corner along u: it rises out of the surface after depth / rise.
  const auto edge = [&](const Vec2& u, double straight) {
    const double rise = u.dot(nrm), cap = std::max(straight, 0.0);
    const double s = rise * cap > depth ? depth / rise : cap;
    width += s * std::abs(u.dot(t));
  };
  edge(B.world_edge_dir[v], B.edge_length[v] - B.round_length[v] - B.round_length[next]);
  edge(-B.world_edge_dir[vp], B.edge_length[vp] - B.round_length[vp] - B.round_length[v]);
  return 0.5 * width;
}

// Shares a joint line's length among its contacts, given as (position along the line, index):
// L = RQ1/2 + RQ2/2 with the neighbours as Q1, Q2, never less than a contact's own chord.
// Contacts closer than `merge` stand at one point (two corners meeting face to face): the
// point's share is split evenly, so that round-off in their order cannot move the length from
// one to the other from cycle to cycle. A line of one point (a corner whose neighbour lifted
// off) has no neighbours to share with: its contacts take their corners' wedge lengths.
void share_length(std::vector<std::pair<double, uint32_t>>& along, double merge, const Blocks& B,
                  Contacts& C) {
  // Insertion sort: a line has a handful of contacts, mostly in order already.
  for (size_t j = 1; j < along.size(); ++j)
    for (size_t q = j; q > 0 && along[q] < along[q - 1]; --q) std::swap(along[q], along[q - 1]);
  const size_t k = along.size();
  // Centre of the group of contacts starting at g0; g1 receives the index past the group.
  auto group = [&](size_t g0, size_t& g1) {
    g1 = g0 + 1;
    double sum = along[g0].first;
    while (g1 < k && along[g1].first - along[g1 - 1].first <= merge) sum += along[g1++].first;
    return sum / static_cast<double>(g1 - g0);
  };
  size_t g0 = 0, g1 = 0;
  double prev = 0.0, centre = k ? group(0, g1) : 0.0;
  if (k && g1 == k) {
    for (size_t j = 0; j < k; ++j) {
      const uint32_t i = along[j].second;
      C.length[i] = std::max(wedge_length(B, C, i) / static_cast<double>(k), C.chord[i]);
    }
    return;
  }
  while (g0 < k) {
    size_t g2 = g1;
    const double next = g1 < k ? group(g1, g2) : centre;
    const double len = 0.5 * ((g0 > 0 ? centre - prev : 0.0) + (next - centre));
    for (size_t j = g0; j < g1; ++j) {
      const uint32_t i = along[j].second;
      C.length[i] = std::max(len / static_cast<double>(g1 - g0), C.chord[i]);
    }
    prev = centre, centre = next, g0 = g1, g1 = g2;
  }
}

// Overlaps beyond this share of the deepest plausible one (a quarter of the smaller block's
// size) stop the run: past it a corner would soon lose its feature and fall through.
constexpr double kOverlapLimit = 0.5;

// Stops the run on contact i, as UDEC's "contact overlap too great" does.
[[noreturn]] void throw_overlap(const Model& m, uint32_t i) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  std::ostringstream msg;
  const uint32_t a = C.a[i], b = C.b[i];
  msg << "contact overlap too great at cycle " << m.cycle << ": " << m.block_label(a) << " and "
      << m.block_label(b) << " overlap by " << -C.gap[i] << " m near x=" << C.point[i].x()
      << ", y=" << C.point[i].y() << " (more than "
      << kOverlapLimit * max_contact_depth(B, C.a[i], C.b[i])
      << " m, an eighth of the smaller block's size; corner " << C.corner[i] - B.vert_begin[a] + 1
      << " of block " << B.id[a] << " against the "
      << (C.kind[i] == kCornerEdge ? "edge from vertex " : "corner ")
      << C.feature[i] - B.vert_begin[b] + 1 << " of block " << B.id[b]
      << "): the joint's normal stiffness is too low "
         "for the load it carries, or the blocks were made overlapping";
  throw ModelError(msg.str());
}

// Per interface: the length of each contact, then the joint law for each contact, giving its
// force. Contacts facing the same way form one joint line (a concave block can touch another
// along two faces); each line shares its length on its own.
void update_interfaces(Model& m) {
  const Blocks& B = m.blocks;
  Contacts& C = m.contacts;
  const double dt = m.dt;
  const double merge = 0.25 * m.settings.rounding;
  const double roundoff = m.roundoff_gap();
  // The first contact (lowest index, whatever the threads) whose overlap is beyond belief.
  std::atomic<uint32_t> too_deep{std::numeric_limits<uint32_t>::max()};
  parallel_for(
      C.pair_count(),
      [&](size_t p0, size_t p1) {
        std::vector<std::pair<double, uint32_t>> along;
        std::vector<uint8_t> placed;
        // Normals point towards the owner: compare them turned to point the same way.
        const auto facing = [&](uint32_t q) {
          return C.a[q] < C.b[q] ? C.normal[q] : Vec2(-C.normal[q]);
        };
        // Contacts of a pair split into joint lines by the way they face (a concave block can
        // touch another along two faces); each line shares its length on its own.
        const auto general_lines = [&](uint32_t c0, uint32_t c1) {
          placed.assign(c1 - c0, 0);
          for (uint32_t i = c0; i < c1; ++i) C.length[i] = 0.0;
          for (uint32_t i = c0; i < c1; ++i) {
            if (C.kind[i] == kLost || placed[i - c0]) continue;
            const Vec2 n0 = facing(i), t = perp(n0);
            along.clear();
            for (uint32_t q = i; q < c1; ++q)
              if (C.kind[q] != kLost && !placed[q - c0] && facing(q).dot(n0) > 0.8) {
                placed[q - c0] = 1;
                along.emplace_back(C.point[q].dot(t), q);
              }
            share_length(along, merge, B, C);
          }
        };
        for (size_t p = p0; p < p1; ++p) {
          const uint32_t c0 = C.pair_begin[p], c1 = C.pair_begin[p + 1];
          // Fast path (convex blocks, nearly every pair): all contacts face one way, so they
          // form one joint line, the same list the general path below would build.
          bool one_line = true;
          Vec2 n_first = Vec2::Zero(), t_first = Vec2::Zero();
          along.clear();
          for (uint32_t i = c0; i < c1 && one_line; ++i) {
            C.length[i] = 0.0;
            if (C.kind[i] == kLost) continue;
            const Vec2 f = facing(i);
            if (along.empty())
              n_first = f, t_first = perp(f);
            else if (!(f.dot(n_first) > 0.8))
              one_line = false;
            along.emplace_back(C.point[i].dot(t_first), i);
          }
          if (one_line) {
            if (!along.empty()) share_length(along, merge, B, C);
          } else {
            general_lines(c0, c1);
          }
          // A node of a deformable block stands for its own stretch of outline at most: a
          // light node alone against a long edge must not take the edge's stiffness.
          // (A pair's contacts can be owned by either block: checked per contact.)
          if (B.deformable[C.a[c0]] || B.deformable[C.b[c0]])
            for (uint32_t i = c0; i < c1; ++i) {
              const uint32_t blk = C.a[i];
              if (!B.deformable[blk]) continue;
              const double own = B.vertex_share(blk, C.corner[i]);
              C.length[i] = std::min(C.length[i], std::max(own, C.chord[i]));
            }
          for (uint32_t i = c0; i < c1; ++i) {
            if (C.kind[i] == kLost) {
              if (C.flags[i] & kBonded)
                C.flags[i] = static_cast<uint8_t>((C.flags[i] & ~kBonded) | kBroken);
              C.flags[i] &= static_cast<uint8_t>(~(kTouching | kSlipping));
              C.fn[i] = 0.0, C.fs[i] = 0.0, C.un_prev[i] = 0.0;
              C.force[i] = Vec2::Zero(), C.force_mag[i] = 0.0;
              continue;
            }
            // Open, unbonded, and open before: nothing to do but remember the opening.
            const double overlap = without_roundoff(-C.gap[i] + C.closure[i], roundoff);
            if (-C.gap[i] > kOverlapLimit * max_contact_depth(B, C.a[i], C.b[i])) {
              uint32_t seen = too_deep.load(std::memory_order_relaxed);
              while (i < seen && !too_deep.compare_exchange_weak(seen, i)) {
              }
            }
            const double un = overlap + C.dilation[i];
            if (un <= 0.0 && C.fn[i] == 0.0 && !(C.flags[i] & (kBonded | kTouching))) {
              C.fs[i] = 0.0, C.un_prev[i] = un, C.force[i] = Vec2::Zero(), C.force_mag[i] = 0.0;
              C.flags[i] &= static_cast<uint8_t>(~kPreload);
              continue;
            }
            // An in-situ shear stress becomes a force once the contact has its length.
            if (C.flags[i] & kPreload) {
              C.fs[i] *= C.length[i];
              C.flags[i] &= static_cast<uint8_t>(~kPreload);
            }
            // Shear displacement increment of a relative to b over the last step.
            const Vec2 n = C.normal[i], tn = perp(n);
            const bool soft = B.deformable[C.a[i]] || B.deformable[C.b[i]];
            const Vec2 dv =
                soft ? Vec2(contact_side_velocity(m, i, false) - contact_side_velocity(m, i, true))
                     : Vec2(point_velocity(B, C.a[i], C.point[i]) -
                            point_velocity(B, C.b[i], C.point[i]));
            const double dus = dv.dot(tn) * dt;
            JointState s{C.fn[i],       C.fs[i],         C.un_prev[i],
                         C.dilation[i], C.shear_disp[i], C.flags[i]};
            const JointProperties& jp = m.joints[C.joint[i]];
            jp.impl->update(jp, C.length[i], overlap, dus, s);
            C.fn[i] = s.fn, C.fs[i] = s.fs, C.un_prev[i] = s.un_prev, C.dilation[i] = s.dilation;
            C.shear_disp[i] = s.shear_disp, C.flags[i] = s.flags;
            C.force[i] = s.fn * n + s.fs * tn;
            C.force_mag[i] = std::abs(s.fn) + std::abs(s.fs);
          }
        }
      },
      64);
  if (const uint32_t i = too_deep.load(); i != std::numeric_limits<uint32_t>::max())
    throw_overlap(m, i);
}

// Sign of a velocity component for local damping (zero at rest).
inline double sgn(double v) {
  return (v > 0.0) - (v < 0.0);
}

// Resultants, damping and central-difference integration of every block.
void move_blocks(Model& m) {
  Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const Settings& S = m.settings;
  const double dt = m.dt;
  const size_t n = B.size();
  const double tol = m.tolerance();
  std::vector<double> unbalanced(n, 0.0), drift(n, 0.0), jump(n, 0.0);
  // Resultants: gravity plus contact forces, gathered in a fixed order per block.
  parallel_for(n, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      double fx = B.mass[b] * S.gravity.x(), fy = B.mass[b] * S.gravity.y(), mz = 0.0;
      double applied = B.mass[b] * S.gravity.norm();
      for (uint32_t k = m.block_contact_begin[b]; k < m.block_contact_begin[b + 1]; ++k) {
        const uint32_t i = m.block_contacts[k] >> 1;
        const double sign = (m.block_contacts[k] & 1) ? -1.0 : 1.0;
        const Vec2 f = sign * C.force[i];
        fx += f.x(), fy += f.y();
        mz += (C.point[i].x() - B.x[b]) * f.y() - (C.point[i].y() - B.y[b]) * f.x();
        applied += C.force_mag[i];
      }
      B.fx[b] = fx, B.fy[b] = fy, B.moment[b] = mz, B.applied[b] = applied;
    }
  });
  // Adaptive global damping: servo the viscosity so that damping absorbs the chosen share of
  // the power of the unbalanced forces (Cundall 1982), adjusted every 10 cycles.
  if (S.damping == DampingMode::kAdaptiveGlobal && m.cycle % 10 == 0) {
    // Power of the unbalanced forces and twice the kinetic energy, over free degrees of freedom.
    const double power = deterministic_sum(n, [&](size_t b) {
      const uint8_t fix = B.fixity[b];
      double p = 0.0;
      if (B.inv_mass[b] > 0.0 && !(fix & kFixX)) p += std::abs(B.fx[b] * B.vx[b]);
      if (B.inv_mass[b] > 0.0 && !(fix & kFixY)) p += std::abs(B.fy[b] * B.vy[b]);
      if (B.inv_inertia[b] > 0.0 && !(fix & kFixRot)) p += std::abs(B.moment[b] * B.omega[b]);
      return p;
    });
    const double kin2 = deterministic_sum(n, [&](size_t b) {
      const uint8_t fix = B.fixity[b];
      double k = 0.0;
      if (B.inv_mass[b] > 0.0 && !(fix & kFixX)) k += B.mass[b] * B.vx[b] * B.vx[b];
      if (B.inv_mass[b] > 0.0 && !(fix & kFixY)) k += B.mass[b] * B.vy[b] * B.vy[b];
      if (B.inv_inertia[b] > 0.0 && !(fix & kFixRot)) k += B.inertia[b] * B.omega[b] * B.omega[b];
      return k;
    });
    servo_global_damping(m, power, kin2);
  }
  const double c_glob = S.damping == DampingMode::kAdaptiveGlobal ? m.global_c : 0.0;
  const double alpha = S.damping == DampingMode::kLocal ? S.local_alpha : 0.0;
  // Damping and integration, one degree of freedom at a time.
  parallel_for(n, [&](size_t b0, size_t b1) {
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
        const double fd = f - alpha * std::abs(f) * sgn(v) - c_glob * mass * v;
        v += dt * fd * inv_m;
      };
      advance(B.fx[b], B.vx[b], B.inv_mass[b], B.mass[b], fix & kFixX, B.fixed_vx[b]);
      advance(B.fy[b], B.vy[b], B.inv_mass[b], B.mass[b], fix & kFixY, B.fixed_vy[b]);
      const double ub_force = ub2;
      advance(B.moment[b], B.omega[b], B.inv_inertia[b], B.inertia[b], fix & kFixRot,
              B.fixed_omega[b]);
      unbalanced[b] = std::sqrt(ub_force);
      B.x[b] += dt * B.vx[b];
      B.y[b] += dt * B.vy[b];
      B.theta[b] += dt * B.omega[b];
      B.update_world(b);
      // Largest vertex displacement since the last detection pass.
      const double dx = B.x[b] - m.det_x[b], dy = B.y[b] - m.det_y[b];
      drift[b] =
          std::sqrt(dx * dx + dy * dy) + B.bound_radius[b] * std::abs(B.theta[b] - m.det_theta[b]);
      // A block that moves a tenth of its size in one step has left explicit dynamics.
      jump[b] = dt *
                (std::sqrt(B.vx[b] * B.vx[b] + B.vy[b] * B.vy[b]) +
                 B.bound_radius[b] * std::abs(B.omega[b])) /
                B.bound_radius[b];
    }
  });
  // Convergence measures over the blocks that move under load.
  size_t free_blocks = 0, worst = 0;
  double max_ub = 0.0, max_drift = 0.0;
  for (size_t b = 0; b < n; ++b) {
    max_drift = std::max(max_drift, drift[b]);
    if (!(jump[b] <= jump[worst])) worst = b;
    if (B.inv_mass[b] == 0.0 || (B.fixity[b] & (kFixX | kFixY)) == (kFixX | kFixY)) continue;
    ++free_blocks;
    max_ub = std::max(max_ub, unbalanced[b]);
  }
  const double sum_applied = deterministic_sum(n, [&](size_t b) {
    const bool moves = B.inv_mass[b] > 0.0 && (B.fixity[b] & (kFixX | kFixY)) != (kFixX | kFixY);
    return moves ? B.applied[b] : 0.0;
  });
  m.max_unbalanced = max_ub;
  m.mean_applied = free_blocks ? sum_applied / static_cast<double>(free_blocks) : 0.0;
  m.ratio = m.mean_applied > 0.0 ? max_ub / m.mean_applied : 0.0;
  // Deformable blocks: the nodes' own cycle, with the contact forces added in between.
  Continuum& zc = m.continuum;
  if (zc.zone_count() > 0) {
    zc.gravity = S.gravity;
    zc.local_damping = alpha;
    zc.dt = dt;
    zone_forces(zc);
    add_contact_forces_to_nodes(m);
    const double node_move = move_nodes(zc);
    update_deformable_world(m);
    // A node that moves half the contact tolerance in one step has left explicit dynamics.
    if (!std::isfinite(node_move) || node_move > 0.5 * tol)
      throw ModelError("the run diverged at cycle " + std::to_string(m.cycle) +
                       ": a node of a deformable block moved " + std::to_string(node_move) +
                       " m in one step (time step too large, or blocks overlapping badly)");
    if (m.det_node.size() != zc.node_count()) m.det_node = zc.pos0;
    for (size_t k = 0; k < zc.node_count(); ++k)
      max_drift = std::max(max_drift, (zc.pos[k] - m.det_node[k]).norm());
    m.ratio = free_blocks ? std::max(m.ratio, zc.ratio) : zc.ratio;
    if (!std::isfinite(zc.ratio)) max_drift = zc.ratio;
  }
  if (max_drift > 0.5 * tol) m.detection_due = true;
  if (!std::isfinite(max_ub) || !std::isfinite(max_drift) || !(jump[worst] < 0.1))
    throw_diverged(m, B.id[worst]);
}

}  // namespace

void throw_diverged(const Model& m, int block_id) {
  throw ModelError("the run diverged at cycle " + std::to_string(m.cycle) + ": block " +
                   std::to_string(block_id) +
                   " moved more than a tenth of its size in one step (time step too large for "
                   "the joint stiffness, or blocks overlapping badly)");
}

void servo_global_damping(Model& m, double power, double kin2) {
  if (!(kin2 > 0.0)) return;
  const double target = m.settings.global_ratio * power / kin2;
  m.global_c =
      m.global_c <= 0.0 ? target : std::clamp(target, m.global_c / 1.25, m.global_c * 1.25);
}

const char* stage_name(int stage) {
  static const char* const names[] = {"detect", "contacts", "interfaces", "motion"};
  return names[stage];
}

RunOptions& run_options() {
  static RunOptions options{TESSERA_VALIDATE_DEFAULT != 0, nullptr};
  return options;
}

double compute_timestep(const Model& m) {
  if (m.settings.dt_fixed > 0.0) return m.settings.dt_fixed;
  if (m.dim == 3) return compute_timestep3(m);
  double kmax = 0.0;
  for (const JointProperties& j : m.joints) kmax = std::max({kmax, j.kn, j.ks});
  const Blocks& B = m.blocks;
  double dt = std::numeric_limits<double>::infinity();
  // Each block: contact length in touch is at most its perimeter, at most bound_radius away.
  for (size_t b = 0; b < B.size(); ++b) {
    if (B.fixity[b] == kFixAll || kmax <= 0.0) continue;
    const double k = kmax * B.perimeter[b];
    if (B.inv_mass[b] > 0.0) dt = std::min(dt, 2.0 * std::sqrt(B.mass[b] / k));
    if (B.inv_inertia[b] > 0.0)
      dt =
          std::min(dt, 2.0 * std::sqrt(B.inertia[b] / (k * B.bound_radius[b] * B.bound_radius[b])));
  }
  dt = std::min(dt, deformable_timestep(m));
  if (!std::isfinite(dt) || dt >= 1e299) return 1e-3;
  return m.settings.dt_safety * dt;
}

void prepare(Model& m) {
  if (m.dim == 3) return prepare3(m);
  if (m.blocks.size() == 0) throw ModelError("the model has no blocks");
  // Joint properties are asked for by the first contact that needs them (naming its blocks): a
  // single zoned block has none. Contacts need the rounding length.
  if (m.settings.rounding <= 0.0 && m.blocks.size() > 1)
    throw ModelError("the rounding length is not set (use 'round')");
  for (size_t b = 0; b < m.blocks.size(); ++b)
    if (m.blocks.mass[b] <= 0.0 && m.blocks.fixity[b] != kFixAll)
      throw ModelError("block " + std::to_string(m.blocks.id[b]) +
                       " has no mass: give it a material with a density");
  if (m.dt_dirty) {
    scale_node_inertia(m);
    m.dt = compute_timestep(m);
    m.dt_dirty = false;
  }
  if (m.det_x.size() != m.blocks.size()) m.detection_due = true;
  if (m.block_contact_begin.size() != m.blocks.size() + 1) build_adjacency(m);
}

void update_contact_geometry(Model& m) {
  update_contacts(m);
}

void cycle(Model& m) {
  if (m.dim == 3) return cycle3(m);
  {
    StageTimer t(kStageDetect);
    if (m.detection_due) detect_contacts(m);
  }
  {
    StageTimer t(kStageContacts);
    update_contacts(m);
  }
  {
    StageTimer t(kStageInterfaces);
    update_interfaces(m);
  }
  {
    StageTimer t(kStageMotion);
    move_blocks(m);
  }
  if (run_options().validate) validate(m);
  m.time += m.dt;
  ++m.cycle;
  if (Profile* p = run_options().profile) ++p->cycles;
  sample_histories(m);
}

double kinetic_energy(const Model& m) {
  if (m.dim == 3) return kinetic_energy3(m);
  const Blocks& B = m.blocks;
  return 0.5 * deterministic_sum(B.size(), [&](size_t b) {
           return B.mass[b] * (B.vx[b] * B.vx[b] + B.vy[b] * B.vy[b]) +
                  B.inertia[b] * B.omega[b] * B.omega[b];
         });
}

uint64_t run_cycles(Model& m, uint64_t n, const Progress& progress, uint64_t every) {
  prepare(m);
  for (uint64_t i = 0; i < n; ++i) {
    cycle(m);
    if (progress && every && (i + 1) % every == 0 && !progress(m)) return i + 1;
  }
  return n;
}

SolveResult solve(Model& m, double ratio, uint64_t max_cycles, const Progress& progress,
                  uint64_t every) {
  prepare(m);
  SolveResult r;
  while (r.cycles < max_cycles) {
    cycle(m);
    ++r.cycles;
    if (m.ratio <= ratio) {
      r.converged = true;
      break;
    }
    if (progress && every && r.cycles % every == 0 && !progress(m)) {
      r.stopped = true;
      break;
    }
  }
  return r;
}

}  // namespace tessera
