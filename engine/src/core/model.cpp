#include "tessera/core/model.hpp"

namespace tessera {

int Model::group_index(const std::string& name, bool create) {
  for (size_t i = 0; i < groups.size(); ++i)
    if (groups[i] == name) return static_cast<int>(i);
  if (!create) return -1;
  groups.push_back(name);
  return static_cast<int>(groups.size()) - 1;
}

int Model::material_index(const std::string& name) const {
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

int Model::joint_index(const std::string& name) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

int Model::joint_for(uint32_t a, uint32_t b, int tag) const {
  const int ga = block_group(a), gb = block_group(b);
  // The last assignment that matches either way round wins.
  for (size_t k = joint_table.size(); k-- > 0;) {
    const JointAssignment& j = joint_table[k];
    const auto matches = [](int want, int g) { return want < 0 || want == g; };
    if (j.tag >= 0 && j.tag != tag) continue;
    if ((matches(j.group_a, ga) && matches(j.group_b, gb)) ||
        (matches(j.group_a, gb) && matches(j.group_b, ga)))
      return static_cast<int>(j.joint);
  }
  return -1;
}

std::string Model::block_label(size_t b) const {
  const int g = block_group(b);
  return "block " + std::to_string(dim == 3 ? blocks3.id[b] : blocks.id[b]) + " (group " +
         (g >= 0 ? groups[static_cast<size_t>(g)] : std::string("(none)")) + ")";
}

}  // namespace tessera

namespace tessera {

// The interfaces a block takes part in: 3D contacts, 2D pairs (sides from their first contact).
void Model::build_block_contacts() {
  const size_t n = block_count(), nc = dim == 3 ? contacts3.size() : contacts.pair_count();
  const auto a_of = [&](size_t i) {
    return dim == 3 ? contacts3[i].a : contacts.a[contacts.pair_begin[i]];
  };
  const auto b_of = [&](size_t i) {
    return dim == 3 ? contacts3[i].b : contacts.b[contacts.pair_begin[i]];
  };
  std::vector<uint32_t> count(n + 1, 0);
  for (size_t i = 0; i < nc; ++i) ++count[a_of(i) + 1], ++count[b_of(i) + 1];
  for (size_t b = 0; b < n; ++b) count[b + 1] += count[b];
  block_contact_begin = count;
  block_contacts.assign(count[n], 0);
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (uint32_t i = 0; i < nc; ++i) {
    block_contacts[fill[a_of(i)]++] = i * 2;
    block_contacts[fill[b_of(i)]++] = i * 2 + 1;
  }
}

std::string Model::block_contacts_problem() const {
  const size_t n = block_count(), nc = dim == 3 ? contacts3.size() : contacts.pair_count();
  if (block_contact_begin.size() != n + 1 || block_contact_begin[n] != 2 * nc)
    return "per-block contact lists do not match the contacts";
  for (size_t b = 0; b < n; ++b)
    for (uint32_t k = block_contact_begin[b]; k < block_contact_begin[b + 1]; ++k) {
      const uint32_t i = block_contacts[k] >> 1;
      const bool side_b = block_contacts[k] & 1;
      const uint32_t owner = i >= nc    ? UINT32_MAX
                             : dim == 3 ? (side_b ? contacts3[i].b : contacts3[i].a)
                                        : (side_b ? contacts.b[contacts.pair_begin[i]]
                                                  : contacts.a[contacts.pair_begin[i]]);
      if (owner != b) return "per-block contact list of " + block_label(b) + " is wrong";
    }
  return {};
}

double Model::approx_bytes() const {
  double subs = 0.0;
  for (const Contact3& c : contacts3) subs += static_cast<double>(c.subs.size());
  return 400.0 * double(blocks.size()) + 150.0 * double(blocks.local_vertex.size()) +
         250.0 * double(contacts.size()) + 700.0 * double(blocks3.size()) +
         120.0 * double(blocks3.local_vertex.size()) + 200.0 * double(blocks3.face_vert.size()) +
         250.0 * double(contacts3.size()) + 130.0 * subs + 120.0 * double(continuum.node_count()) +
         100.0 * double(continuum.zone_count()) + 8.0 * double(histories.values.size());
}

}  // namespace tessera
