#include "tessera/generation/generators3.hpp"

#include <cmath>
#include <stdexcept>

#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/core/block_loads.hpp"
#include "tessera/core/step.hpp"
#include "tessera/zones/deformable3.hpp"

namespace tessera {

namespace {
// Cables are anchored in the blocks as they are: cut and join first.
void no_cables_yet(const Model& m) {
  if (!m.cables3.empty())
    throw ModelError("cut and join blocks before placing cables (cable '" +
                     m.cables3.cables[0].name + "' is anchored in the blocks as they are)");
}
}  // namespace

size_t add_block3(Model& m, const Polyhedron& p, int group, int material,
                  const std::vector<int>& face_tags) {
  const double density = material >= 0 ? m.materials[static_cast<size_t>(material)].density : 0.0;
  const size_t b = m.blocks3.add(p, density, group, material, face_tags);
  m.touch();
  return b;
}

namespace {

// The selected blocks as pieces to cut (with their indices in `owner`).
std::vector<CutBlock> cut_input3(const Model& m, const std::vector<size_t>& selection,
                                 std::vector<size_t>& owner) {
  const Blocks3& B = m.blocks3;
  std::vector<uint8_t> chosen(B.size(), selection.empty() ? 1 : 0);
  for (size_t b : selection) chosen[b] = 1;
  std::vector<CutBlock> input;
  for (size_t b = 0; b < B.size(); ++b) {
    if (!chosen[b]) continue;
    if (B.deformable[b])
      throw std::invalid_argument("block " + std::to_string(B.id[b]) +
                                  " is deformable: cut blocks before 'zone generate'");
    CutBlock c;
    c.poly = B.polyhedron(b);
    c.face_tags.assign(B.face_tag.begin() + B.face_begin[b],
                       B.face_tag.begin() + B.face_begin[b + 1]);
    input.push_back(std::move(c));
    owner.push_back(b);
  }
  return input;
}

// Replaces each block cut into more than one piece by its pieces (a piece labelled L joins
// group label_group[L]); returns the number of blocks added. With `rock`, the unlabelled pieces
// of each block cut: their new block indices, one list per block.
size_t replace_cut3(Model& m, const std::vector<size_t>& owner, const std::vector<CutBlock>& pieces,
                    const std::vector<int>& label_group,
                    std::vector<std::vector<size_t>>* rock = nullptr) {
  no_cables_yet(m);
  Blocks3& B = m.blocks3;
  const auto group_of = [&](const CutBlock& p, int parent_group) {
    return p.label >= 0 ? label_group[static_cast<size_t>(p.label)] : parent_group;
  };
  // Keep the blocks no plane split; then the pieces of those that were.
  std::vector<size_t> piece_count(owner.size(), 0);
  for (const CutBlock& p : pieces) ++piece_count[p.parent];
  // A load cannot be shared out among pieces (checked before anything changes).
  for (size_t i = 0; i < owner.size(); ++i) {
    const size_t b = owner[i];
    if (piece_count[i] > 1 && B.master[b] == static_cast<int32_t>(b) && loaded(B, b))
      throw ModelError("cut blocks before loading them (block " + std::to_string(B.id[b]) +
                       " carries a load: 'load block=" + std::to_string(B.id[b]) +
                       " fx=0 fy=0 fz=0 mx=0 my=0 mz=0' takes it off)");
  }
  for (const CutBlock& p : pieces)
    if (piece_count[p.parent] == 1)
      B.group[owner[p.parent]] = group_of(p, B.group[owner[p.parent]]);
  if (pieces.size() == owner.size()) return 0;
  std::vector<uint8_t> doomed(B.size(), 0);
  for (size_t i = 0; i < owner.size(); ++i)
    if (piece_count[i] > 1) doomed[owner[i]] = 1;
  const Blocks3 old = B;
  std::vector<int> map = B.remove(doomed);
  for (size_t b = 0; b < B.size(); ++b) B.id[b] = static_cast<int>(b) + 1;
  size_t added = 0;
  for (const CutBlock& p : pieces) {
    const size_t parent = owner[p.parent];
    if (piece_count[p.parent] < 2) continue;
    const size_t b =
        add_block3(m, p.poly, group_of(p, old.group[parent]), old.material[parent], p.face_tags);
    B.fixity[b] = old.fixity[parent];
    B.fixed_v[b] = old.fixed_v[parent], B.fixed_w[b] = old.fixed_w[parent];
    B.body[b].velocity = old.body[parent].velocity;
    if (rock && p.label < 0) {
      if (rock->size() <= p.parent) rock->resize(owner.size());
      (*rock)[p.parent].push_back(b);
    }
    ++added;
  }
  // Histories of cut blocks end; contacts are found afresh.
  for (auto& s : m.histories.series) {
    if (s.block >= 0)
      s.block = map[static_cast<size_t>(s.block)] >= 0 ? map[static_cast<size_t>(s.block)] : -2;
    // The second block of a force between two.
    if (is_contact_quantity(s.quantity) && s.element >= 0)
      s.element =
          map[static_cast<size_t>(s.element)] >= 0 ? map[static_cast<size_t>(s.element)] : -2;
  }
  m.contacts3.clear();
  m.det_pos3.clear(), m.det_q3.clear();
  m.block_contact_begin.clear();
  m.touch();
  return added;
}

}  // namespace

size_t cut_model3(Model& m, const std::vector<size_t>& selection,
                  const std::vector<JointPlane>& planes) {
  std::vector<size_t> owner;
  const std::vector<CutBlock> input = cut_input3(m, selection, owner);
  return replace_cut3(m, owner, cut_blocks(input, planes), {});
}

size_t tunnel_model3(Model& m, const std::vector<size_t>& selection, const Opening3& o,
                     const std::vector<int>& round_groups, bool join) {
  std::vector<size_t> owner;
  const std::vector<CutBlock> input = cut_input3(m, selection, owner);
  const std::vector<CutBlock> pieces = cut_opening(input, o);
  // Joining needs each body's mass: refused before anything is cut.
  std::vector<size_t> rock_count(owner.size(), 0);
  for (const CutBlock& p : pieces) rock_count[p.parent] += p.label < 0;
  for (size_t i = 0; join && i < owner.size(); ++i) {
    const int k = m.blocks3.material[owner[i]];
    if (rock_count[i] > 1 && !(k >= 0 && m.materials[static_cast<size_t>(k)].density > 0.0))
      throw std::invalid_argument("block " + std::to_string(m.blocks3.id[owner[i]]) +
                                  " has no density: give it a material before joining its rock");
  }
  std::vector<std::vector<size_t>> rock;
  const size_t added = replace_cut3(m, owner, pieces, round_groups, &rock);
  // The rock each block keeps around the opening, one body again (no fictitious joints).
  if (join)
    for (const std::vector<size_t>& body : rock)
      if (body.size() > 1) join_blocks3(m, body);
  return added;
}

void add_wall3(Model& m, const WallSpec3& w) {
  for (int k = 0; k < w.courses; ++k) {
    const double z0 = w.origin.z() + k * w.height;
    // Brick ends along the course: every second course starts and ends with a half brick.
    std::vector<double> ends{0.0};
    const bool offset = k % 2 == 1;
    if (offset) ends.push_back(0.5 * w.length);
    for (int i = 0; i < (offset ? w.bricks - 1 : w.bricks); ++i)
      ends.push_back(ends.back() + w.length);
    if (offset) ends.push_back(ends.back() + 0.5 * w.length);
    for (size_t i = 0; i + 1 < ends.size(); ++i) {
      const Vec3 lo(w.origin.x() + ends[i], w.origin.y(), z0);
      const Vec3 hi(w.origin.x() + ends[i + 1], w.origin.y() + w.width, z0 + w.height);
      const Polyhedron p = box(lo, hi);
      // Bed joints on the faces across z, head joints across x.
      std::vector<int> tags;
      const SolidProperties s = solid_properties(p);
      for (const auto& face : p.faces) {
        Vec3 c = Vec3::Zero();
        for (uint32_t v : face) c += p.vertices[v];
        c /= static_cast<double>(face.size());
        const Vec3 d = (c - s.centroid).cwiseAbs();
        tags.push_back(d.z() > 0.49 * w.height            ? w.bed_tag
                       : d.x() > 0.49 * (hi.x() - lo.x()) ? w.head_tag
                                                          : -1);
      }
      add_block3(m, p, w.group, w.material, tags);
    }
  }
}

std::vector<size_t> whole_bodies3(const Blocks3& B, const std::vector<size_t>& blocks) {
  std::vector<uint8_t> body(B.size(), 0);
  for (size_t b : blocks) body[static_cast<size_t>(B.master[b])] = 1;
  std::vector<size_t> out;
  for (size_t b = 0; b < B.size(); ++b)
    if (body[static_cast<size_t>(B.master[b])]) out.push_back(b);
  return out;
}

void join_blocks3(Model& m, const std::vector<size_t>& blocks) {
  no_cables_yet(m);
  Blocks3& B = m.blocks3;
  const std::vector<size_t> pieces = whole_bodies3(B, blocks);
  std::vector<double> densities;
  for (size_t b : pieces) {
    if (B.deformable[b])
      throw std::invalid_argument("block " + std::to_string(B.id[b]) +
                                  " is deformable: join blocks before 'zone generate'");
    const int k = B.material[b];
    densities.push_back(k >= 0 ? m.materials[static_cast<size_t>(k)].density : 0.0);
    if (!(densities.back() > 0.0))
      throw std::invalid_argument("block " + std::to_string(B.id[b]) +
                                  " has no density: give it a material before joining");
  }
  // Sub-contact points ride in the frame of block a's body, which the join changes: they cross
  // it in world axes.
  std::vector<Vec3> at;
  for (const Contact3& c : m.contacts3)
    for (const SubContact& s : c.subs) at.push_back(world_point(B, c, s));
  B.join(pieces, densities);
  size_t k = 0;
  for (Contact3& c : m.contacts3)
    for (SubContact& s : c.subs) s.local = frame_point(B, c, at[k++]);
  // Contacts between pieces of the new body go; the rest are found again.
  std::vector<Contact3> kept;
  for (Contact3& c : m.contacts3)
    if (B.master[c.a] != B.master[c.b]) kept.push_back(std::move(c));
  m.contacts3 = std::move(kept);
  m.block_contact_begin.clear();
  m.touch();
}

void delete_blocks3(Model& m, const std::vector<size_t>& selected) {
  Blocks3& B = m.blocks3;
  const std::vector<size_t> blocks = whole_bodies3(B, selected);
  std::vector<uint8_t> doomed(B.size(), 0);
  for (size_t b : blocks) doomed[b] = 1;
  const std::vector<uint32_t> old_face = B.face_begin;
  const std::vector<int64_t> node_map = drop_deformable3(m, doomed);
  const std::vector<int> map = B.remove(doomed);
  // Contacts between blocks that stay, renumbered (their order is kept, so they stay sorted).
  std::vector<Contact3> kept;
  for (Contact3& c : m.contacts3) {
    if (map[c.a] < 0 || map[c.b] < 0) continue;
    const auto na = static_cast<uint32_t>(map[c.a]), nb = static_cast<uint32_t>(map[c.b]);
    const auto shift_face = [&](uint32_t f, uint32_t from, uint32_t to) {
      return f - old_face[from] + B.face_begin[to];
    };
    c.face_a = shift_face(c.face_a, c.a, na), c.face_b = shift_face(c.face_b, c.b, nb);
    if (c.kind == kPlaneFaceA) c.ia = shift_face(c.ia, c.a, na);
    if (c.kind == kPlaneFaceB) c.ib = shift_face(c.ib, c.b, nb);
    // Edge directions and vertex keys are renumbered too: the next pass finds the plane anew.
    if (c.kind == kPlaneEdges) m.detection_due = true;
    for (SubContact& s : c.subs) s.key = 0;
    c.drift = 1e300;  // node numbers changed: the sub-contacts are built afresh
    c.a = na, c.b = nb;
    kept.push_back(std::move(c));
  }
  m.contacts3 = std::move(kept);
  std::vector<Vec3> pos;
  std::vector<Eigen::Quaterniond> q;
  for (size_t b = 0; b < map.size() && m.det_pos3.size() == map.size(); ++b)
    if (map[b] >= 0) pos.push_back(m.det_pos3[b]), q.push_back(m.det_q3[b]);
  m.det_pos3 = std::move(pos), m.det_q3 = std::move(q);
  remap_cables3(m, map, node_map);
  for (auto& s : m.histories.series) {
    if (s.block >= 0)
      s.block = map[static_cast<size_t>(s.block)] >= 0 ? map[static_cast<size_t>(s.block)] : -2;
    // The second block of a force between two.
    if (is_contact_quantity(s.quantity) && s.element >= 0)
      s.element =
          map[static_cast<size_t>(s.element)] >= 0 ? map[static_cast<size_t>(s.element)] : -2;
  }
  m.touch();
  m.block_contact_begin.clear();
}

}  // namespace tessera
