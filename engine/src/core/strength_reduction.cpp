// Strength reduction (strength_reduction.hpp): trials on copies of the initial model.
#include "tessera/core/strength_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "tessera/zones/deformable.hpp"

namespace tessera {

namespace {

constexpr double kDeg = M_PI / 180.0;

// A friction angle whose tangent is divided by f.
double reduced_friction(double degrees, double f) {
  return std::atan(std::tan(degrees * kDeg) / f) / kDeg;
}

template <class P>
void reduce(P& p, double f) {
  p.friction = reduced_friction(p.friction, f);
  p.cohesion /= f;
  p.tension /= f;
  if constexpr (std::is_same_v<P, JointProperties>) {
    if (p.residual_friction >= 0.0) p.residual_friction = reduced_friction(p.residual_friction, f);
    p.residual_cohesion /= f;
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

void reduce_strength(Model& m, double factor, bool joints, bool zones) {
  if (joints)
    for (JointProperties& j : m.joints) reduce(j, factor);
  if (zones) {
    for (Material& mat : m.materials)
      if (!mat.zone.model.empty()) reduce(mat.zone, factor);
    sync_zone_materials(m);
  }
}

FosTrial strength_trial(const Model& initial, double factor, const FosOptions& o, Model& out,
                        const Progress& progress) {
  FosTrial t;
  t.factor = factor;
  out = initial;
  reduce_strength(out, factor, o.joints, o.zones);
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
