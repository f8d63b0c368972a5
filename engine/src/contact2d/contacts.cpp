#include "tessera/contact2d/contacts.hpp"

namespace tessera {

void Contacts::clear() {
  for_each_array([](auto& v) { v.clear(); });
  pair_begin.assign(1, 0);
}

void Contacts::reserve(size_t n) {
  for_each_array([n](auto& v) { v.reserve(n); });
}

void Contacts::push_from(const Contacts& s, size_t i) {
  a.push_back(s.a[i]), b.push_back(s.b[i]), corner.push_back(s.corner[i]),
      slot.push_back(s.slot[i]);
  kind.push_back(s.kind[i]), feature.push_back(s.feature[i]), flags.push_back(s.flags[i]);
  joint.push_back(s.joint[i]), tag.push_back(s.tag[i]), normal.push_back(s.normal[i]),
      point.push_back(s.point[i]);
  gap.push_back(s.gap[i]), chord.push_back(s.chord[i]), length.push_back(s.length[i]);
  fn.push_back(s.fn[i]), fs.push_back(s.fs[i]), un_prev.push_back(s.un_prev[i]);
  dilation.push_back(s.dilation[i]);
  shear_disp.push_back(s.shear_disp[i]), closure.push_back(s.closure[i]);
  force.push_back(s.force[i]);
  force_mag.push_back(s.force_mag[i]);
}

void Contacts::push_new(uint32_t a_, uint32_t b_, uint32_t corner_, uint8_t slot_, uint32_t joint_,
                        int tag_) {
  tag.push_back(tag_);
  a.push_back(a_), b.push_back(b_), corner.push_back(corner_), slot.push_back(slot_);
  kind.push_back(kLost), feature.push_back(0), flags.push_back(0), joint.push_back(joint_);
  normal.push_back(Vec2::Zero()), point.push_back(Vec2::Zero());
  gap.push_back(0.0), chord.push_back(0.0), length.push_back(0.0);
  fn.push_back(0.0), fs.push_back(0.0), un_prev.push_back(0.0), dilation.push_back(0.0);
  shear_disp.push_back(0.0), closure.push_back(0.0);
  force.push_back(Vec2::Zero());
  force_mag.push_back(0.0);
}

}  // namespace tessera
