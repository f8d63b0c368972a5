#include "tessera/core/insitu.hpp"

#include "tessera/contact2d/detection.hpp"
#include "tessera/contact2d/interfaces.hpp"
#include "tessera/contact3d/detection3.hpp"
#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

ZoneStress StressField::at(double v) const {
  const double d = v - y0;
  return {base.xx + gradient.xx * d, base.yy + gradient.yy * d, base.xy + gradient.xy * d,
          base.zz + gradient.zz * d, base.yz + gradient.yz * d, base.xz + gradient.xz * d};
}

namespace {
size_t preload_contacts3(Model& m, const StressField& field) {
  if (m.detection_due) detect_contacts3(m);
  for (Contact3& c : m.contacts3) update_plane3(m, c);
  const double shut = 1e-3 * m.tolerance();
  size_t loaded = 0;
  for (Contact3& c : m.contacts3) {
    const JointProperties& jp = m.joints[c.joint];
    if (!(jp.kn > 0.0)) continue;
    const Vec3 n = c.normal;
    bool any = false;
    for (SubContact& s : c.subs) {
      if (s.gap > shut) continue;
      const ZoneStress t = field.at(world_point(m.blocks3, c, s).z());
      // Traction on block a, whose outward normal is -n: -sigma n (compression positive).
      const Vec3 sn(t.xx * n.x() + t.xy * n.y() + t.xz * n.z(),
                    t.xy * n.x() + t.yy * n.y() + t.yz * n.z(),
                    t.xz * n.x() + t.yz * n.y() + t.zz * n.z());
      const double normal = -n.dot(sn);
      if (normal <= 0.0) continue;
      s.closure = jp.impl->closure(jp, normal) + s.gap;
      s.un_prev = s.dilation, s.fn = 0.0;
      const Vec3 shear = s.area * (-sn - normal * n);
      s.fs = shear.dot(c.t1), s.fs2 = shear.dot(c.t2());
      any = true;
    }
    loaded += any;
  }
  return loaded;
}
}  // namespace

size_t preload_contacts(Model& m, const StressField& field) {
  prepare(m);
  if (m.dim == 3) return preload_contacts3(m, field);
  if (m.detection_due) detect_contacts(m);
  update_contact_geometry(m);
  Contacts& C = m.contacts;
  const double shut = 1e-3 * m.tolerance();
  size_t loaded = 0;
  for (size_t i = 0; i < C.size(); ++i) {
    const JointProperties& jp = m.joints[C.joint[i]];
    if (C.kind[i] == kLost || C.gap[i] > shut || !(jp.kn > 0.0)) continue;
    const ZoneStress s = field.at(C.point[i].y());
    // Traction on block a, whose outward normal is -n: t = -sigma n (compression positive).
    const Vec2 n = C.normal[i], t = perp(n);
    const Vec2 sn(s.xx * n.x() + s.xy * n.y(), s.xy * n.x() + s.yy * n.y());
    const double normal = -n.dot(sn), shear = -t.dot(sn);
    if (normal <= 0.0) continue;
    // Closure measured from the drawn gap, so that the next law call gives exactly normal * L.
    C.hold(C.closure);
    C.closure[i] = jp.impl->closure(jp, normal) + C.gap[i];
    C.un_prev[i] = C.dilation[i];
    C.fn[i] = 0.0;
    C.fs[i] = shear;
    C.flags[i] |= kPreload;
    ++loaded;
  }
  return loaded;
}

}  // namespace tessera
