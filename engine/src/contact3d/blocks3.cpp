#include "tessera/contact3d/blocks3.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tessera/core/parallel.hpp"

namespace tessera {

namespace {

// Copies block b of src onto the end of dst.
void append_block(Blocks3& dst, const Blocks3& src, size_t b) {
  dst.body.push_back(src.body[b]);
  dst.omega.push_back(src.omega[b]), dst.rotation.push_back(src.rotation[b]);
  dst.force.push_back(src.force[b]), dst.torque.push_back(src.torque[b]);
  dst.applied.push_back(src.applied[b]), dst.ref.push_back(src.ref[b]);
  dst.ref_q.push_back(src.ref_q[b]);
  dst.fixity.push_back(src.fixity[b]);
  dst.fixed_v.push_back(src.fixed_v[b]), dst.fixed_w.push_back(src.fixed_w[b]);
  dst.load_force.push_back(src.load_force[b]), dst.load_moment.push_back(src.load_moment[b]);
  dst.volume.push_back(src.volume[b]), dst.surface.push_back(src.surface[b]);
  dst.bound_radius.push_back(src.bound_radius[b]);
  dst.group.push_back(src.group[b]), dst.material.push_back(src.material[b]);
  dst.master.push_back(src.master[b]);  // renumbered by the caller
  dst.id.push_back(static_cast<int>(dst.id.size()) + 1);
  dst.deformable.push_back(src.deformable[b]);
  dst.node_begin.push_back(src.node_begin[b]), dst.node_end.push_back(src.node_end[b]);
  dst.zone_begin.push_back(src.zone_begin[b]), dst.zone_end.push_back(src.zone_end[b]);
  const uint32_t v_shift = dst.vert_begin.back() - src.vert_begin[b];
  for (uint32_t v = src.vert_begin[b]; v < src.vert_begin[b + 1]; ++v)
    dst.local_vertex.push_back(src.local_vertex[v]),
        dst.world_vertex.push_back(src.world_vertex[v]),
        dst.vertex_node.push_back(src.vertex_node[v]);
  dst.vert_begin.push_back(static_cast<uint32_t>(dst.local_vertex.size()));
  for (uint32_t f = src.face_begin[b]; f < src.face_begin[b + 1]; ++f) {
    for (uint32_t k = src.fv_begin[f]; k < src.fv_begin[f + 1]; ++k)
      dst.face_vert.push_back(src.face_vert[k] + v_shift);
    dst.fv_begin.push_back(static_cast<uint32_t>(dst.face_vert.size()));
    dst.local_normal.push_back(src.local_normal[f]),
        dst.world_normal.push_back(src.world_normal[f]);
    dst.local_offset.push_back(src.local_offset[f]);
    dst.world_offset.push_back(src.world_offset[f]), dst.face_tag.push_back(src.face_tag[f]);
    for (uint32_t t = src.ftri_begin[f]; t < src.ftri_begin[f + 1]; ++t)
      dst.ftri.push_back(src.ftri[t]);
    dst.ftri_begin.push_back(static_cast<uint32_t>(dst.ftri.size()));
  }
  dst.face_begin.push_back(static_cast<uint32_t>(dst.local_normal.size()));
  for (uint32_t d = src.dir_begin[b]; d < src.dir_begin[b + 1]; ++d)
    dst.local_dir.push_back(src.local_dir[d]), dst.world_dir.push_back(src.world_dir[d]);
  dst.dir_begin.push_back(static_cast<uint32_t>(dst.local_dir.size()));
}

}  // namespace

size_t Blocks3::add(const Polyhedron& p, double density, int group_id, int material_id,
                    const std::vector<int>& face_tags) {
  const SolidProperties s = solid_properties(p);
  // Convex: every vertex on the inner side of every face plane, measured from the centroid,
  // within the round-off of the block's size and of its coordinates (a vertex cut at a northing
  // of 4e6 is off its plane by 1e-9 m).
  double size = 0.0, far = 0.0;
  for (const Vec3& v : p.vertices)
    size = std::max(size, (v - s.centroid).norm()), far = std::max(far, v.cwiseAbs().maxCoeff());
  const double slack = 1e-9 * size + 64.0 * std::numeric_limits<double>::epsilon() * far;
  std::vector<Vec3> normals;
  for (const auto& face : p.faces) {
    const Vec3 n = newell_normal(p.vertices, face);
    const double off = n.dot(p.vertices[face[0]] - s.centroid);
    for (const Vec3& v : p.vertices)
      if (n.dot(v - s.centroid) - off > slack)
        throw std::invalid_argument("the polyhedron is not convex (a vertex lies outside a face)");
    normals.push_back(n);
  }
  const size_t b = size_t(body.size());
  RigidBody3 rb = make_body(s, density);
  body.push_back(rb);
  omega.push_back(Vec3::Zero()), rotation.push_back(Mat3::Identity());
  force.push_back(Vec3::Zero()), torque.push_back(Vec3::Zero()), applied.push_back(0.0);
  ref.push_back(s.centroid), ref_q.push_back(rb.orientation);
  fixity.push_back(0), fixed_v.push_back(Vec3::Zero()), fixed_w.push_back(Vec3::Zero());
  load_force.push_back(Vec3::Zero()), load_moment.push_back(Vec3::Zero());
  volume.push_back(s.volume);
  group.push_back(group_id), material.push_back(material_id);
  id.push_back(static_cast<int>(b) + 1);
  master.push_back(static_cast<int32_t>(b));
  deformable.push_back(0);
  node_begin.push_back(0), node_end.push_back(0), zone_begin.push_back(0), zone_end.push_back(0);
  // Shape in the principal frame about the centroid.
  const Mat3 to_local = rb.orientation.conjugate().toRotationMatrix();
  const uint32_t v0 = vert_begin.back();
  for (const Vec3& v : p.vertices) {
    local_vertex.push_back(to_local * (v - s.centroid));
    world_vertex.push_back(v);
    vertex_node.push_back(-1);
  }
  vert_begin.push_back(static_cast<uint32_t>(local_vertex.size()));
  double area = 0.0;
  std::vector<Vec3> dirs;
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& face = p.faces[f];
    Vec3 twice = Vec3::Zero();
    for (size_t k = 0; k < face.size(); ++k) {
      face_vert.push_back(v0 + face[k]);
      const Vec3& a = p.vertices[face[k]];
      const Vec3& c = p.vertices[face[(k + 1) % face.size()]];
      twice += a.cross(c);
      // Each undirected edge once: from the face that walks it from lower to higher index.
      if (face[k] < face[(k + 1) % face.size()]) {
        const Vec3 d = to_local * (c - a).normalized();
        if (std::none_of(dirs.begin(), dirs.end(),
                         [&](const Vec3& e) { return std::abs(e.dot(d)) > 1.0 - 1e-9; }))
          dirs.push_back(d);
      }
    }
    area += 0.5 * std::abs(twice.dot(normals[f]));
    fv_begin.push_back(static_cast<uint32_t>(face_vert.size()));
    local_normal.push_back(to_local * normals[f]);
    local_offset.push_back(local_normal.back().dot(local_vertex[v0 + face[0]]));
    world_normal.push_back(normals[f]);
    world_offset.push_back(normals[f].dot(p.vertices[face[0]]));
    face_tag.push_back(f < face_tags.size() ? face_tags[f] : -1);
    ftri_begin.push_back(static_cast<uint32_t>(ftri.size()));
  }
  face_begin.push_back(static_cast<uint32_t>(local_normal.size()));
  for (const Vec3& d : dirs) local_dir.push_back(d), world_dir.push_back(Vec3::Zero());
  dir_begin.push_back(static_cast<uint32_t>(local_dir.size()));
  surface.push_back(area);
  bound_radius.push_back(size);
  update_world(b);
  // The vertices as given, so that neighbours cut from one block share them bit for bit.
  for (size_t k = 0; k < p.vertices.size(); ++k) world_vertex[v0 + k] = p.vertices[k];
  return b;
}

std::vector<int> Blocks3::remove(const std::vector<uint8_t>& doomed) {
  // A body goes whole: a piece left without its master would keep neither frame nor mass, and a
  // master without a piece would keep the piece's.
  for (size_t b = 0; b < size(); ++b) {
    const auto mb = static_cast<size_t>(master[b]);
    if (doomed[b] != doomed[mb])
      throw std::invalid_argument("blocks " + std::to_string(id[mb]) + " and " +
                                  std::to_string(id[b]) +
                                  " are pieces of one joined body: remove it whole");
  }
  catch_up();  // (the blocks kept are copied as current)
  Blocks3 kept;
  std::vector<int> index(size(), -1);
  for (size_t b = 0; b < size(); ++b) {
    if (doomed[b]) continue;
    index[b] = static_cast<int>(kept.size());
    append_block(kept, *this, b);
    kept.id.back() = id[b];
  }
  for (size_t b = 0; b < kept.size(); ++b)
    kept.master[b] = index[static_cast<size_t>(kept.master[b])];
  *this = std::move(kept);
  return index;
}

void Blocks3::set_density(size_t b, double density) {
  const double old_mass = body[b].mass;
  const double new_mass = density * volume[b];
  // Principal moments scale with the density; a block made with no density gets them anew.
  if (old_mass > 0.0) {
    body[b].principal *= new_mass / old_mass;
    body[b].momentum *= new_mass / old_mass;
  } else {
    Polyhedron p = polyhedron(b);
    const SolidProperties s = solid_properties(p);
    body[b].principal = density * s.principal_moments;
  }
  body[b].mass = new_mass;
}

void Blocks3::update_world(size_t b) {
  update_planes(b);
  update_vertices(b);
}

void Blocks3::update_planes(size_t b) {
  const Mat3 r = body_rotation(b);
  const Vec3 c = body[static_cast<size_t>(master[b])].position;
  rotation[b] = r;
  // (Through pointers that alias nothing: the stores do not make the compiler reload the rest.)
  const uint32_t f0 = face_begin[b], f1 = face_begin[b + 1];
  const Vec3* __restrict ln = local_normal.data();
  const double* __restrict lo = local_offset.data();
  Vec3* __restrict wn = world_normal.data();
  double* __restrict wo = world_offset.data();
  for (uint32_t f = f0; f < f1; ++f) {
    const Vec3 n = r * ln[f];
    wn[f] = n;
    wo[f] = n.dot(c) + lo[f];
  }
}

void Blocks3::update_vertices(size_t b) const {
  const Mat3& r = rotation[b];  // (refreshed with the face planes, which come first)
  const Vec3& c = body[static_cast<size_t>(master[b])].position;
  for (uint32_t v = vert_begin[b]; v < vert_begin[b + 1]; ++v)
    world_vertex[v] = c + r * local_vertex[v];
  for (uint32_t d = dir_begin[b]; d < dir_begin[b + 1]; ++d) world_dir[d] = r * local_dir[d];
}

void Blocks3::catch_up() const {
  if (!vertices_behind) return;
  parallel_for(size(), [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b)
      if (!deformable[b]) update_vertices(b);
  });
  vertices_behind = false;
}

void Blocks3::join(const std::vector<size_t>& pieces, const std::vector<double>& densities) {
  catch_up();
  // Mass, centroid and inertia about the common centroid (parallel axes).
  double mass = 0.0;
  Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
  std::vector<SolidProperties> props;
  for (size_t i = 0; i < pieces.size(); ++i) {
    props.push_back(solid_properties(polyhedron(pieces[i])));
    const double m = densities[i] * props.back().volume;
    mass += m, centre += m * props.back().centroid;
    momentum += m * body[static_cast<size_t>(master[pieces[i]])].velocity;
  }
  if (!(mass > 0.0)) throw std::invalid_argument("joined blocks need a material with a density");
  centre /= mass;
  // The bodies' loads move to the new centroid, with the moment that keeps them where they act.
  Vec3 load = Vec3::Zero(), load_m = Vec3::Zero();
  for (size_t p : pieces)
    if (!is_slave(p)) {
      load += load_force[p];
      load_m += load_moment[p] + (body[p].position - centre).cross(load_force[p]);
      load_force[p] = load_moment[p] = Vec3::Zero();
    }
  Mat3 inertia = Mat3::Zero();
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Vec3 d = props[i].centroid - centre;
    inertia +=
        densities[i] * (props[i].inertia +
                        props[i].volume * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
  }
  // Principal frame of the whole, right-handed.
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  Mat3 axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) *= -1.0;
  const size_t m0 = pieces.front();
  RigidBody3 rb;
  rb.mass = mass, rb.principal = eig.eigenvalues(), rb.position = centre;
  rb.orientation = Eigen::Quaterniond(axes).normalized();
  rb.velocity = momentum / mass;
  const Mat3 to_local = rb.orientation.conjugate().toRotationMatrix();
  double reach = 0.0;
  for (size_t p : pieces) {
    for (uint32_t v = vert_begin[p]; v < vert_begin[p + 1]; ++v) {
      local_vertex[v] = to_local * (world_vertex[v] - centre);
      reach = std::max(reach, local_vertex[v].norm());
    }
    for (uint32_t f = face_begin[p]; f < face_begin[p + 1]; ++f) {
      local_normal[f] = to_local * world_normal[f];
      local_offset[f] = local_normal[f].dot(local_vertex[face_vert[fv_begin[f]]]);
    }
    for (uint32_t d = dir_begin[p]; d < dir_begin[p + 1]; ++d)
      local_dir[d] = to_local * world_dir[d];
    master[p] = static_cast<int32_t>(m0);
    body[p].mass = 0.0, body[p].velocity = Vec3::Zero(), body[p].momentum = Vec3::Zero();
  }
  body[m0] = rb;
  for (size_t p : pieces) rotation[p] = body_rotation(p);
  ref[m0] = centre, ref_q[m0] = rb.orientation;
  load_force[m0] = load, load_moment[m0] = load_m;
  for (size_t p : pieces) bound_radius[p] = reach;
}

Polyhedron Blocks3::polyhedron(size_t b) const {
  catch_up();
  Polyhedron p;
  const uint32_t v0 = vert_begin[b];
  for (uint32_t v = v0; v < vert_begin[b + 1]; ++v) p.vertices.push_back(world_vertex[v]);
  for (uint32_t f = face_begin[b]; f < face_begin[b + 1]; ++f) {
    std::vector<uint32_t> face;
    for (uint32_t k = fv_begin[f]; k < fv_begin[f + 1]; ++k) face.push_back(face_vert[k] - v0);
    p.faces.push_back(std::move(face));
  }
  return p;
}

bool Blocks3::contains(size_t b, const Vec3& p) const {
  const double eps = 1e-9 * bound_radius[b];
  for (uint32_t f = face_begin[b]; f < face_begin[b + 1]; ++f)
    if (world_normal[f].dot(p) - world_offset[f] > eps) return false;
  return true;
}

}  // namespace tessera
