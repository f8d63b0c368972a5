#include "tessera/core/insitu.hpp"

#include "tessera/contact2d/detection.hpp"
#include "tessera/contact2d/interfaces.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

ZoneStress StressField::at(double y) const {
  const double d = y - y0;
  return {base.xx + gradient.xx * d, base.yy + gradient.yy * d, base.xy + gradient.xy * d,
          base.zz + gradient.zz * d};
}

size_t preload_contacts(Model& m, const StressField& field) {
  prepare(m);
  if (m.detection_due) detect_contacts(m);
  update_contact_geometry(m);
  Contacts& C = m.contacts;
  const double shut = 1e-3 * m.tolerance();
  size_t loaded = 0;
  for (size_t i = 0; i < C.size(); ++i) {
    const double kn = m.joints[C.joint[i]].kn;
    if (C.kind[i] == kLost || C.gap[i] > shut || !(kn > 0.0)) continue;
    const ZoneStress s = field.at(C.point[i].y());
    // Traction on block a, whose outward normal is -n: t = -sigma n (compression positive).
    const Vec2 n = C.normal[i], t = perp(n);
    const Vec2 sn(s.xx * n.x() + s.xy * n.y(), s.xy * n.x() + s.yy * n.y());
    const double normal = -n.dot(sn), shear = -t.dot(sn);
    if (normal <= 0.0) continue;
    // Closure measured from the drawn gap, so that the next law call gives exactly normal * L.
    C.closure[i] = normal / kn + C.gap[i];
    C.un_prev[i] = C.dilation[i];
    C.fn[i] = 0.0;
    C.fs[i] = shear;
    C.flags[i] |= kPreload;
    ++loaded;
  }
  return loaded;
}

}  // namespace tessera
