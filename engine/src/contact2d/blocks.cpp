#include "tessera/contact2d/blocks.hpp"

#include <algorithm>
#include <cmath>

namespace tessera {

size_t Blocks::add(const std::vector<Vec2>& pts, double rounding, double density, int group_id,
                   int material_id, const std::vector<int>& edge_tags) {
  const PolygonProperties props = polygon_properties(pts);
  const std::vector<RoundedCorner> corners = round_corners(pts, rounding);
  const size_t b = size();
  x.push_back(props.centroid.x());
  y.push_back(props.centroid.y());
  theta.push_back(0.0);
  for (auto* v : {&vx, &vy, &omega, &fx, &fy, &moment, &applied, &fixed_vx, &fixed_vy, &fixed_omega,
                  &load_fx, &load_fy, &load_m})
    v->push_back(0.0);
  x_ref.push_back(props.centroid.x());
  y_ref.push_back(props.centroid.y());
  area.push_back(props.area);
  double perim = 0.0, bound = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    perim += (pts[(i + 1) % pts.size()] - pts[i]).norm();
    bound = std::max(bound, (pts[i] - props.centroid).norm());
    local_vertex.push_back(pts[i] - props.centroid);
    local_arc_centre.push_back(corners[i].centre - props.centroid);
    arc_radius.push_back(corners[i].radius);
    round_length.push_back(corners[i].length);
    convex.push_back(corners[i].convex ? 1 : 0);
    const Vec2 e = pts[(i + 1) % pts.size()] - pts[i];
    local_edge_dir.push_back(e / e.norm());
    edge_tag.push_back(i < edge_tags.size() ? edge_tags[i] : -1);
    edge_length.push_back(e.norm());
    world_vertex.push_back(pts[i]);
    world_arc_centre.push_back(corners[i].centre);
    world_edge_dir.push_back(local_edge_dir.back());
    node.push_back(-1);
  }
  vert_begin.push_back(static_cast<uint32_t>(local_vertex.size()));
  all_convex.push_back(
      std::all_of(corners.begin(), corners.end(), [](const RoundedCorner& c) { return c.convex; })
          ? 1
          : 0);
  perimeter.push_back(perim);
  bound_radius.push_back(bound);
  mass.push_back(0.0);
  inertia.push_back(0.0);
  inv_mass.push_back(0.0);
  inv_inertia.push_back(0.0);
  fixity.push_back(kFree);
  deformable.push_back(0);
  group.push_back(group_id);
  material.push_back(material_id);
  id.push_back(id.empty() ? 1 : *std::max_element(id.begin(), id.end()) + 1);
  set_density(b, density);
  return b;
}

void Blocks::set_density(size_t b, double density) {
  // Polar moment per unit area about the centroid, recovered from the local vertices.
  std::vector<Vec2> pts(local_vertex.begin() + vert_begin[b],
                        local_vertex.begin() + vert_begin[b + 1]);
  const PolygonProperties props = polygon_properties(pts);
  mass[b] = density * props.area;
  inertia[b] = density * props.polar_moment;
  refresh_inverse_mass(b);
}

void Blocks::refresh_inverse_mass(size_t b) {
  inv_mass[b] = mass[b] > 0.0 ? 1.0 / mass[b] : 0.0;
  inv_inertia[b] = inertia[b] > 0.0 ? 1.0 / inertia[b] : 0.0;
}

void Blocks::update_world(size_t b) {
  if (deformable[b]) return;
  const double c = std::cos(theta[b]), s = std::sin(theta[b]);
  const double bx = x[b], by = y[b];
  for (uint32_t v = vert_begin[b]; v < vert_begin[b + 1]; ++v) {
    const Vec2& p = local_vertex[v];
    const Vec2& a = local_arc_centre[v];
    const Vec2& e = local_edge_dir[v];
    world_vertex[v] = Vec2(bx + c * p.x() - s * p.y(), by + s * p.x() + c * p.y());
    world_arc_centre[v] = Vec2(bx + c * a.x() - s * a.y(), by + s * a.x() + c * a.y());
    world_edge_dir[v] = Vec2(c * e.x() - s * e.y(), s * e.x() + c * e.y());
  }
}

std::vector<Vec2> Blocks::world_polygon(size_t b) const {
  return {world_vertex.begin() + vert_begin[b], world_vertex.begin() + vert_begin[b + 1]};
}

void Blocks::set_outline(size_t b, const std::vector<Vec2>& pts, double rounding,
                         const std::vector<int>& edge_tags, const std::vector<int32_t>& nodes) {
  // The new vertex data, made as for a fresh block, spliced in place of the old.
  Blocks fresh;
  fresh.add(pts, rounding, 0.0, -1, -1, edge_tags);
  fresh.node = nodes;
  const Vec2 shift(fresh.x[0] - x[b], fresh.y[0] - y[b]);
  for (Vec2& v : fresh.local_vertex) v += shift;
  for (Vec2& v : fresh.local_arc_centre) v += shift;
  const auto begin = static_cast<std::ptrdiff_t>(vert_begin[b]);
  const auto end = static_cast<std::ptrdiff_t>(vert_begin[b + 1]);
  each_vertex_array(fresh, [&](auto& mine, auto& theirs) {
    mine.erase(mine.begin() + begin, mine.begin() + end);
    mine.insert(mine.begin() + begin, theirs.begin(), theirs.end());
  });
  const auto grow = static_cast<int64_t>(pts.size()) - (end - begin);
  for (size_t k = b + 1; k < vert_begin.size(); ++k)
    vert_begin[k] = static_cast<uint32_t>(static_cast<int64_t>(vert_begin[k]) + grow);
  all_convex[b] = fresh.all_convex[0];
  perimeter[b] = fresh.perimeter[0];
  bound_radius[b] = 0.0;
  for (uint32_t v = vert_begin[b]; v < vert_begin[b + 1]; ++v)
    bound_radius[b] = std::max(bound_radius[b], (world_vertex[v] - Vec2(x[b], y[b])).norm());
}

}  // namespace tessera

namespace tessera {

std::vector<std::vector<double>*> Blocks::block_doubles() {
  return {&x,           &y,       &theta,     &vx,           &vy,       &omega,
          &fx,          &fy,      &moment,    &applied,      &x_ref,    &y_ref,
          &mass,        &inertia, &inv_mass,  &inv_inertia,  &fixed_vx, &fixed_vy,
          &fixed_omega, &area,    &perimeter, &bound_radius, &load_fx,  &load_fy,
          &load_m};
}

void Blocks::shrink_to_fit() {
  for (std::vector<double>* v : block_doubles()) v->shrink_to_fit();
  fixity.shrink_to_fit(), all_convex.shrink_to_fit(), deformable.shrink_to_fit();
  group.shrink_to_fit(), material.shrink_to_fit(), id.shrink_to_fit(), vert_begin.shrink_to_fit();
  each_vertex_array(*this, [](auto& v, auto&) { v.shrink_to_fit(); });
}

std::vector<int> Blocks::remove(const std::vector<uint8_t>& doomed) {
  const size_t n = size();
  std::vector<int> map(n, -1);
  Blocks kept;
  kept.vert_begin = {0};
  // Per-block and per-vertex arrays, copied for the blocks that stay.
  auto src = block_doubles(), dst = kept.block_doubles();
  for (size_t b = 0; b < n; ++b) {
    if (doomed[b]) continue;
    map[b] = static_cast<int>(kept.x.size());
    for (size_t k = 0; k < src.size(); ++k) dst[k]->push_back((*src[k])[b]);
    kept.fixity.push_back(fixity[b]), kept.all_convex.push_back(all_convex[b]);
    kept.deformable.push_back(deformable[b]);
    kept.group.push_back(group[b]), kept.material.push_back(material[b]), kept.id.push_back(id[b]);
    each_vertex_array(kept, [&](auto& from, auto& to) {
      to.insert(to.end(), from.begin() + vert_begin[b], from.begin() + vert_begin[b + 1]);
    });
    kept.vert_begin.push_back(static_cast<uint32_t>(kept.local_vertex.size()));
  }
  *this = std::move(kept);
  return map;
}

}  // namespace tessera
