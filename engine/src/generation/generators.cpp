#include "tessera/generation/generators.hpp"

#include "tessera/core/block_loads.hpp"
#include "tessera/zones/deformable.hpp"

namespace tessera {

size_t add_running_bond_wall(Model& m, const WallSpec& w) {
  const double rho = w.material >= 0 ? m.materials[static_cast<size_t>(w.material)].density : 0.0;
  const double L = w.brick_length, H = w.brick_height, width = L * w.bricks;
  size_t added = 0;
  for (int c = 0; c < w.courses; ++c) {
    const double y0 = w.origin.y() + H * c, y1 = y0 + H;
    // Joint positions along the course: staggered by half a brick on odd courses.
    std::vector<double> xs{0.0};
    for (int k = 0; k < w.bricks; ++k) xs.push_back(c % 2 ? L * (k + 0.5) : L * (k + 1));
    if (c % 2) xs.push_back(width);
    for (size_t k = 0; k + 1 < xs.size(); ++k) {
      const double x0 = w.origin.x() + xs[k], x1 = w.origin.x() + xs[k + 1];
      m.blocks.add({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, m.settings.rounding, rho, w.group,
                   w.material, {w.bed_tag, w.head_tag, w.bed_tag, w.head_tag});
      ++added;
    }
  }
  m.touch();
  return added;
}

}  // namespace tessera

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include "tessera/contact2d/detection.hpp"
#include "tessera/core/angles.hpp"
#include "tessera/core/random.hpp"
#include "tessera/core/step.hpp"
#include "tessera/support/reinforcement.hpp"

namespace tessera {

namespace {
Vec2 unit(double degrees) {
  return {std::cos(degrees * kDeg), std::sin(degrees * kDeg)};
}

// Adds a polygon in either winding.
size_t add_polygon(Model& m, std::vector<Vec2> pts, int group, int material) {
  if (signed_area(pts) < 0.0) std::reverse(pts.begin(), pts.end());
  const double rho = material >= 0 ? m.materials[static_cast<size_t>(material)].density : 0.0;
  return m.blocks.add(pts, m.settings.rounding, rho, group, material);
}
}  // namespace

size_t add_arch(Model& m, const ArchSpec& a) {
  const double top = 90.0, start = top + a.half_angle, step = 2.0 * a.half_angle / a.voussoirs;
  const double R = a.radius, T = a.thickness;
  size_t added = 0;
  for (int i = 0; i < a.voussoirs; ++i) {
    const Vec2 u0 = unit(start - step * i), u1 = unit(start - step * (i + 1));
    add_polygon(
        m, {a.centre + R * u0, a.centre + R * u1, a.centre + (R + T) * u1, a.centre + (R + T) * u0},
        a.group, a.material);
    ++added;
  }
  if (a.abutment > 0.0) {
    // Each abutment's top is the radial springing joint; its sides go straight down.
    for (const double ang : {start, top - a.half_angle}) {
      const Vec2 p1 = a.centre + R * unit(ang), p2 = a.centre + (R + T) * unit(ang);
      const double base = std::min(p1.y(), p2.y()) - a.abutment;
      add_polygon(m, {p1, p2, Vec2(p2.x(), base), Vec2(p1.x(), base)}, a.abutment_group,
                  a.material);
      ++added;
    }
  }
  m.touch();
  return added;
}

std::vector<CutLine> joint_set_traces(const JointSetSpec& j, const Vec2& lo, const Vec2& hi,
                                      int tag) {
  Random rng(j.seed);
  const Vec2 u = unit(j.angle), n = perp(u);
  // Extent of the box across and along the set.
  double s0 = 1e300, s1 = -1e300, t0 = 1e300, t1 = -1e300;
  for (const Vec2& c : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())}) {
    s0 = std::min(s0, (c - j.origin).dot(n)), s1 = std::max(s1, (c - j.origin).dot(n));
    t0 = std::min(t0, (c - j.origin).dot(u)), t1 = std::max(t1, (c - j.origin).dot(u));
  }
  const double reach = (hi - lo).norm();
  // Refuse what would not fit in memory or time, before drawing anything.
  // (Lines are drawn outwards from the origin, so a far origin counts too.)
  const double lines = std::max(std::abs(s0), std::abs(s1)) / (0.1 * j.spacing);
  const double per_line =
      j.trace > 0.0 ? (t1 - t0 + reach) / (0.05 * j.trace + std::max(j.gap, 0.0)) : 1.0;
  if (lines > 1e5 || lines * per_line > 1e6)
    throw ModelError(
        "the joint set would make more than a million traces: the spacing or trace length is too "
        "small for the blocks it cuts");
  std::vector<CutLine> out;
  // One line of traces at offset s from the origin line.
  auto line = [&](double s) {
    const Vec2 d = unit(rng.normal(j.angle, j.angle_sd));
    const Vec2 base = j.origin + s * n;
    if (j.trace <= 0.0) {
      out.push_back({{base + (t0 - reach) * d, base + (t1 + reach) * d}, tag});
      return;
    }
    // Traces and rock bridges in turn, from a random phase before the box.
    double t = t0 - rng.uniform() * (j.trace + j.gap);
    while (t < t1) {
      const double len = std::max(rng.normal(j.trace, j.trace_sd), 0.05 * j.trace);
      out.push_back({{base + t * d, base + (t + len) * d}, tag});
      t += len + std::max(rng.normal(j.gap, j.gap_sd), 0.0);
    }
  };
  auto next_spacing = [&] {
    return std::max(rng.normal(j.spacing, j.spacing_sd), 0.1 * j.spacing);
  };
  // From the origin line outwards on both sides, in a fixed order.
  for (double s = 0.0; s <= s1; s += next_spacing())
    if (s >= s0) line(s);
  for (double s = -next_spacing(); s >= s0; s -= next_spacing())
    if (s <= s1) line(s);
  return out;
}

std::vector<Vec2> circle_outline(const Vec2& centre, double radius, int segments) {
  std::vector<Vec2> pts;
  for (int i = 0; i < segments; ++i) pts.push_back(centre + radius * unit(360.0 * i / segments));
  return pts;
}

std::vector<Vec2> horseshoe_outline(const Vec2& centre, double width, double height, int segments) {
  const double r = 0.5 * width, wall = std::max(height - r, 0.0);
  std::vector<Vec2> pts{centre + Vec2(-r, 0), centre + Vec2(r, 0)};
  const Vec2 c = centre + Vec2(0, wall);
  for (int i = 0; i <= segments; ++i) pts.push_back(c + r * unit(180.0 * i / segments));
  if (wall <= 0.0) pts.erase(pts.begin() + 2), pts.pop_back();
  return pts;
}

int joint_tag(Model& m, const std::string& name) {
  for (size_t i = 0; i < m.joint_tags.size(); ++i)
    if (m.joint_tags[i] == name) return static_cast<int>(i);
  m.joint_tags.push_back(name);
  return static_cast<int>(m.joint_tags.size()) - 1;
}

// Rebuilds the model's blocks: those not flagged in `in` first, in order, then the new polygons;
// each new block takes group, material, fixity and velocities from its parent. Blocks are
// renumbered and contacts made anew.
static void replace_blocks(Model& m, const Blocks& old, const std::vector<uint8_t>& in,
                           const std::vector<TaggedPolygon>& pieces,
                           const std::vector<size_t>& parents) {
  if (!m.support.empty())
    throw ModelError("cut and join blocks before placing bolts (bolt '" + m.support.bolts[0].name +
                     "' is anchored in the blocks as they are)");
  if (!m.cables.empty())
    throw ModelError("cut and join blocks before placing cables (cable '" +
                     m.cables.cables[0].name + "' is anchored in the blocks as they are)");
  if (!m.liners.empty())
    throw ModelError("cut and join blocks before placing liners (liner '" +
                     m.liners.liners[0].name + "' is anchored in the blocks as they are)");
  // A load stays on a block left whole; a block cut into pieces (or one joined to others, which
  // leaves a piece to one parent only) cannot share out its load.
  std::vector<int> piece_count(old.size(), 0);
  for (size_t p : parents) ++piece_count[p];
  for (size_t b = 0; b < old.size(); ++b)
    if (in[b] && piece_count[b] != 1 && loaded(old, b))
      throw ModelError("cut and join blocks before loading them (block " +
                       std::to_string(old.id[b]) + " carries a load: 'load block=" +
                       std::to_string(old.id[b]) + " fx=0 fy=0 moment=0' takes it off)");
  m.blocks = Blocks{};
  auto copy_state = [&](size_t parent) {
    Blocks& B = m.blocks;
    const size_t b = B.size() - 1;
    B.fixity[b] = old.fixity[parent];
    B.vx[b] = old.vx[parent], B.vy[b] = old.vy[parent], B.omega[b] = old.omega[parent];
    B.fixed_vx[b] = old.fixed_vx[parent], B.fixed_vy[b] = old.fixed_vy[parent];
    B.fixed_omega[b] = old.fixed_omega[parent];
    B.load_fx[b] = old.load_fx[parent], B.load_fy[b] = old.load_fy[parent];
    B.load_m[b] = old.load_m[parent];
  };
  auto density = [&](int mat) {
    return mat >= 0 ? m.materials[static_cast<size_t>(mat)].density : 0.0;
  };
  for (size_t b = 0; b < old.size(); ++b) {
    if (in[b]) continue;
    m.blocks.add(
        old.world_polygon(b), m.settings.rounding, density(old.material[b]), old.group[b],
        old.material[b],
        {old.edge_tag.begin() + old.vert_begin[b], old.edge_tag.begin() + old.vert_begin[b + 1]});
    copy_state(b);
  }
  for (size_t k = 0; k < pieces.size(); ++k) {
    const size_t parent = parents[k];
    m.blocks.add(pieces[k].points, m.settings.rounding, density(old.material[parent]),
                 old.group[parent], old.material[parent], pieces[k].edge_tags);
    copy_state(parent);
  }
  m.contacts.clear();
  m.det_x.clear();
  m.touch();
  m.build_block_contacts();
}

CutReport cut_blocks(Model& m, const std::vector<CutLine>& cuts,
                     const std::vector<size_t>& chosen) {
  if (m.cycle > 0) throw ModelError("blocks can be cut only before the first cycle");
  for (const auto& s : m.histories.series)
    if (s.block >= 0)
      throw ModelError("cut blocks before defining block histories (they would be renumbered)");
  for (size_t b = 0; b < m.blocks.size(); ++b)
    if ((chosen.empty() || std::find(chosen.begin(), chosen.end(), b) != chosen.end()) &&
        m.blocks.deformable[b])
      throw ModelError("block " + std::to_string(m.blocks.id[b]) +
                       " is deformable: cut blocks before 'zone generate'");
  const Blocks old = m.blocks;
  std::vector<uint8_t> in(old.size(), chosen.empty() ? 1 : 0);
  for (size_t b : chosen) in[b] = 1;
  std::vector<TaggedPolygon> polys;
  std::vector<size_t> from;
  double size = 0.0;
  // Pieces below the check's area limit (2 d)^2 merge only with pieces of the same group,
  // material and fixity (see SliverMerge).
  const double d = m.settings.rounding;
  SliverMerge merge{4.0 * d * d, {}};
  std::map<std::tuple<int, int, int>, int> kinds;
  for (size_t b = 0; b < old.size(); ++b) {
    size = std::max(size, 2.0 * old.bound_radius[b]);
    if (!in[b]) continue;
    polys.push_back(
        {old.world_polygon(b),
         {old.edge_tag.begin() + old.vert_begin[b], old.edge_tag.begin() + old.vert_begin[b + 1]}});
    from.push_back(b);
    const auto key = std::make_tuple(old.group[b], old.material[b], int(old.fixity[b]));
    merge.kind.push_back(kinds.emplace(key, static_cast<int>(kinds.size())).first->second);
  }
  // The split tag is named only if a split is made.
  const auto named = std::find(m.joint_tags.begin(), m.joint_tags.end(), "split");
  const int split_tag = static_cast<int>(named - m.joint_tags.begin());
  const CutResult r = cut_polygons(polys, cuts, 1e-9 * std::max(size, 1.0), split_tag, merge);
  if (r.splits > 0 && named == m.joint_tags.end()) m.joint_tags.push_back("split");
  std::vector<size_t> parents;
  for (size_t k = 0; k < r.pieces.size(); ++k) parents.push_back(from[r.parent[k]]);
  replace_blocks(m, old, in, r.pieces, parents);
  return {r.slivers_dropped, r.splits, r.slivers_merged, r.slivers_left, merge.min_area};
}

void join_blocks(Model& m, const std::vector<size_t>& chosen) {
  if (m.cycle > 0) throw ModelError("blocks can be joined only before the first cycle");
  if (chosen.size() < 2) throw ModelError("'join' needs at least two blocks");
  for (const auto& s : m.histories.series)
    if (s.block >= 0)
      throw ModelError("join blocks before defining block histories (they would be renumbered)");
  for (size_t b : chosen)
    if (m.blocks.deformable[b])
      throw ModelError("block " + std::to_string(m.blocks.id[b]) +
                       " is deformable: join blocks before 'zone generate'");
  for (size_t b : chosen)
    if (loaded(m.blocks, b))
      throw ModelError("cut and join blocks before loading them (block " +
                       std::to_string(m.blocks.id[b]) + " carries a load)");
  const Blocks old = m.blocks;
  std::vector<uint8_t> in(old.size(), 0);
  std::vector<TaggedPolygon> polys;
  for (size_t b : chosen) {
    in[b] = 1;
    polys.push_back(
        {old.world_polygon(b),
         {old.edge_tag.begin() + old.vert_begin[b], old.edge_tag.begin() + old.vert_begin[b + 1]}});
  }
  std::string why;
  TaggedPolygon joined = join_polygons(polys, why);
  if (joined.points.empty()) throw ModelError("cannot join blocks: " + why);
  replace_blocks(m, old, in, {joined}, {chosen.front()});
}

void delete_blocks(Model& m, const std::vector<size_t>& blocks) {
  Blocks& B = m.blocks;
  std::vector<uint8_t> doomed(B.size(), 0);
  for (size_t b : blocks) doomed[b] = 1;
  const std::vector<uint32_t> old_begin = B.vert_begin;
  const std::vector<int64_t> node_map = drop_deformable(m, doomed);
  const std::vector<int> map = B.remove(doomed);
  remap_reinforcement(m, map, node_map);
  remap_cables(m, map, node_map);
  remap_liners(m, map, node_map);
  // Contacts between blocks that stay, renumbered (their order is kept, so they stay sorted).
  Contacts& C = m.contacts;
  Contacts kept;
  for (size_t i = 0; i < C.size(); ++i) {
    if (map[C.a[i]] < 0 || map[C.b[i]] < 0) continue;
    kept.push_from(C, i);
    const size_t k = kept.size() - 1;
    const auto na = static_cast<uint32_t>(map[C.a[i]]), nb = static_cast<uint32_t>(map[C.b[i]]);
    kept.corner[k] = C.corner[i] - old_begin[C.a[i]] + B.vert_begin[na];
    kept.feature[k] = C.feature[i] - old_begin[C.b[i]] + B.vert_begin[nb];
    kept.a[k] = na, kept.b[k] = nb;
  }
  kept.pair_begin.assign(1, 0);
  for (size_t i = 1; i <= kept.size(); ++i)
    if (i == kept.size() ||
        std::minmax(kept.a[i], kept.b[i]) != std::minmax(kept.a[i - 1], kept.b[i - 1]))
      kept.pair_begin.push_back(static_cast<uint32_t>(i));
  if (kept.size() == 0) kept.pair_begin.assign(1, 0);
  m.contacts = std::move(kept);
  // Verlet references and histories follow the blocks; histories of deleted blocks end.
  auto compact = [&](std::vector<double>& v) {
    if (v.size() != map.size()) return;
    std::vector<double> out;
    for (size_t b = 0; b < map.size(); ++b)
      if (map[b] >= 0) out.push_back(v[b]);
    v = std::move(out);
  };
  compact(m.det_x), compact(m.det_y), compact(m.det_theta);
  for (auto& s : m.histories.series) {
    if (s.block >= 0)
      s.block = map[static_cast<size_t>(s.block)] >= 0 ? map[static_cast<size_t>(s.block)] : -2;
    // The second block of a force between two.
    if (is_contact_quantity(s.quantity) && s.element >= 0)
      s.element =
          map[static_cast<size_t>(s.element)] >= 0 ? map[static_cast<size_t>(s.element)] : -2;
  }
  m.touch();
  m.build_block_contacts();
}

}  // namespace tessera
