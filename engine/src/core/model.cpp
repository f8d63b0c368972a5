#include "tessera/model.hpp"

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

double Model::tolerance() const {
  return settings.contact_tolerance > 0.0 ? settings.contact_tolerance : settings.rounding;
}

}  // namespace tessera

namespace tessera {

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
