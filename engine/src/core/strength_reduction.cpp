// Strength reduction (strength_reduction.hpp): trials on copies of the initial model.
#include "tessera/core/strength_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "tessera/core/angles.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {

// A friction angle whose tangent is divided by f.
double reduced_friction(double degrees, double f) {
  return std::atan(std::tan(degrees * kDeg) / f) / kDeg;
}

template <class P>
void reduce(P& p, double f) {
  // The nonlinear joint laws: their whole shear strength divided by f.
  if constexpr (std::is_same_v<P, JointProperties>) {
    if (p.impl && p.impl->divides_strength()) {
      p.strength_divisor *= f;
      p.finalize();
      return;
    }
  }
  p.friction = reduced_friction(p.friction, f);
  p.cohesion /= f;
  p.tension /= f;
  if constexpr (std::is_same_v<P, JointProperties>) {
    if (p.residual_friction >= 0.0) p.residual_friction = reduced_friction(p.residual_friction, f);
    p.residual_cohesion /= f;
  }
  // Zones: the plane of weakness and the strain-softening tables too.
  if constexpr (std::is_same_v<P, ZoneProperties>) {
    p.jfriction = reduced_friction(p.jfriction, f);
    p.jcohesion /= f, p.jtension /= f, p.jdilation = std::min(p.jdilation, p.jfriction);
    for (size_t k = 1; k < p.ftable.size(); k += 2) p.ftable[k] = reduced_friction(p.ftable[k], f);
    // Dilation no greater than the reduced friction (a model's own check).
    p.dilation = std::min(p.dilation, p.friction);
    for (size_t k = 1; k < p.dtable.size(); k += 2)
      p.dtable[k] = std::min(p.dtable[k], table_value(p.ftable, p.dtable[k - 1], p.friction));
    for (auto* t : {&p.ctable, &p.ttable})
      for (size_t k = 1; k < t->size(); k += 2) (*t)[k] /= f;
  }
  p.finalize();
}

// The largest displacement of a free block's centroid or a node from the initial model.
double largest_move(const Model& m, const Model& initial) {
  double d = 0.0;
  if (m.dim == 3) {
    const auto& now = m.blocks3.body;
    const auto& then = initial.blocks3.body;
    for (size_t b = 0; b < std::min(now.size(), then.size()); ++b)
      d = std::max(d, (now[b].position - then[b].position).norm());
    const auto &p = m.continuum3.pos, &p0 = initial.continuum3.pos;
    for (size_t n = 0; n < std::min(p.size(), p0.size()); ++n)
      d = std::max(d, (p[n] - p0[n]).norm());
  } else {
    const Blocks &B = m.blocks, &B0 = initial.blocks;
    for (size_t b = 0; b < std::min(B.size(), B0.size()); ++b)
      d = std::max(d, std::hypot(B.x[b] - B0.x[b], B.y[b] - B0.y[b]));
    const auto &p = m.continuum.pos, &p0 = initial.continuum.pos;
    for (size_t n = 0; n < std::min(p.size(), p0.size()); ++n)
      d = std::max(d, (p[n] - p0[n]).norm());
  }
  return d;
}

}  // namespace

namespace {

// Joint sets n..2n-1 become reduced copies of 0..n-1; the table sends every pair to the copies
// except pairs touching an excluded group, which keep the original sets in the original order
// of precedence (the table's later entries win); contacts take their sets afresh.
void reduce_joints_except(Model& m, double f, const std::vector<int>& exclude) {
  const auto n = static_cast<uint32_t>(m.joints.size());
  for (uint32_t j = 0; j < n; ++j) {
    JointProperties copy = m.joints[j];
    reduce(copy, f);
    m.joints.push_back(copy);
  }
  const std::vector<JointAssignment> table = m.joint_table;
  for (JointAssignment& e : m.joint_table) e.joint += n;
  const auto matches = [](int want, int g) { return want < 0 || want == g; };
  for (const JointAssignment& e : table)
    for (int g : exclude) {
      if (matches(e.group_a, g)) m.joint_table.push_back({g, e.group_b, e.joint, e.tag});
      if (matches(e.group_b, g)) m.joint_table.push_back({e.group_a, g, e.joint, e.tag});
    }
  const auto exempt = [&](uint32_t b) {
    return std::find(exclude.begin(), exclude.end(), m.block_group(b)) != exclude.end();
  };
  const auto resolve = [&](uint32_t a, uint32_t b, int tag, uint32_t& joint) {
    const int j = m.joint_for(a, b, tag);
    if (j >= 0)
      joint = static_cast<uint32_t>(j);
    else if (!exempt(a) && !exempt(b))
      joint += n;
  };
  for (size_t i = 0; i < m.contacts.size(); ++i)
    resolve(m.contacts.a[i], m.contacts.b[i], m.contacts.tag[i], m.contacts.joint[i]);
  for (Contact3& c : m.contacts3) resolve(c.a, c.b, c.tag, c.joint);
}

// Zone materials: reduced copies after the originals, given to the zones of blocks outside the
// excluded groups.
template <int D>
void reduce_zones_except(ContinuumT<D>& c, double f, const std::vector<uint8_t>& keep) {
  const auto n = static_cast<uint32_t>(c.materials.size());
  for (uint32_t k = 1; k < n; ++k) {
    ZoneProperties copy = c.materials[k];
    if (copy.impl && copy.model != "null") reduce(copy, f);
    c.materials.push_back(copy);
  }
  for (size_t z = 0; z < c.zone_count(); ++z)
    if (c.material[z] > 0 && !keep[z]) c.material[z] += n - 1;
}

}  // namespace

void reduce_strength(Model& m, double factor, bool joints, bool zones,
                     const std::vector<int>& exclude) {
  if (exclude.empty()) {
    if (joints)
      for (JointProperties& j : m.joints) reduce(j, factor);
    if (zones) {
      for (Material& mat : m.materials)
        if (!mat.zone.model.empty()) reduce(mat.zone, factor);
      sync_zone_materials(m);
    }
    return;
  }
  if (joints) reduce_joints_except(m, factor, exclude);
  if (!zones) return;
  const auto excluded = [&](int g) {
    return std::find(exclude.begin(), exclude.end(), g) != exclude.end();
  };
  if (m.dim == 3) {
    std::vector<uint8_t> keep(m.continuum3.zone_count(), 0);
    const Blocks3& B = m.blocks3;
    for (size_t b = 0; b < B.size(); ++b)
      if (B.deformable[b] && excluded(B.group[b]))
        for (uint32_t z = B.zone_begin[b]; z < B.zone_end[b]; ++z) keep[z] = 1;
    reduce_zones_except(m.continuum3, factor, keep);
  } else {
    std::vector<uint8_t> keep(m.continuum.zone_count(), 0);
    const std::vector<int> owner = node_owners(m);
    for (size_t z = 0; z < keep.size(); ++z) {
      const int b = owner[m.continuum.zones[z][0]];
      keep[z] = b >= 0 && excluded(m.blocks.group[static_cast<size_t>(b)]);
    }
    reduce_zones_except(m.continuum, factor, keep);
  }
}

FosTrial strength_trial(const Model& initial, double factor, const FosOptions& o, Model& out,
                        const Progress& progress) {
  FosTrial t;
  t.factor = factor;
  out = initial;
  reduce_strength(out, factor, o.joints, o.zones, o.exclude);
  const uint64_t half = o.cycles / 2;
  try {
    SolveResult r = solve(out, o.ratio, half, progress, progress ? 1 : 0);
    t.moved_half = largest_move(out, initial);
    if (!r.converged && !r.stopped) {
      const SolveResult more = solve(out, o.ratio, o.cycles - half, progress, progress ? 1 : 0);
      r.cycles += more.cycles, r.converged = more.converged, r.stopped = more.stopped;
    }
    t.cycles = r.cycles, t.ratio = out.ratio;
    t.moved_end = largest_move(out, initial);
    if (r.stopped) {
      t.stopped = "stopped";
      return t;
    }
    t.stands = r.converged || t.moved_end <= 1.1 * t.moved_half;
  } catch (const ModelError& e) {
    t.stopped = e.what();
    t.moved_end = largest_move(out, initial);
  }
  return t;
}

FosResult factor_of_safety(const Model& initial, const FosOptions& o, const Progress& progress,
                           const std::function<void(const FosTrial&)>& each) {
  FosResult res;
  double lo = 0.0, hi = 0.0;  // a factor that stood, one that failed (0: none yet)
  Model work;
  bool stopped = false;
  const auto trial = [&](double f) {
    const FosTrial t = strength_trial(initial, f, o, work, progress);
    res.trials.push_back(t);
    if (each) each(t);
    if (t.stopped == "stopped") {
      stopped = true;
      return false;
    }
    if (t.stands) {
      lo = std::max(lo, f);
    } else if (hi == 0.0 || f < hi) {
      hi = f;
      res.mechanism = work;
    }
    return t.stands;
  };
  // Bracket: up from 1 by doubling while the model stands, or down by halving while it fails.
  if (trial(1.0)) {
    for (double f = 2.0; !stopped && f <= o.max_factor && trial(f); f *= 2.0) {
    }
  } else {
    for (double f = 0.5; !stopped && f >= 1.0 / o.max_factor && !trial(f); f *= 0.5) {
    }
  }
  res.bracketed = !stopped && lo > 0.0 && hi > 0.0;
  // Bisect to the precision.
  while (res.bracketed && hi - lo > o.precision) {
    trial(0.5 * (lo + hi));
    if (stopped) res.bracketed = false;
  }
  res.factor = lo > 0.0 ? lo : hi;
  return res;
}

}  // namespace tessera
