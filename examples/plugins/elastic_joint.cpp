// An example plug-in: `law=elastic-joint`, a joint that never slips or opens - linear normal and
// shear springs with no strength limit (a glued joint, or a first elastic estimate of a model).
// Built by CMake as a shared library; load it with `model load FILE.so` before
// `joint define NAME kn=.. ks=.. friction=0 law=elastic-joint`.
#include <memory>

#include "tessera/plugin.hpp"

namespace {

class ElasticJoint final : public tessera::JointLaw {
 public:
  const char* name() const override { return "elastic-joint"; }
  void update(const tessera::JointProperties& p, double size, double overlap, double dus,
              double dus2, tessera::JointState& s) const override {
    // Total-form normal force (tension too) and incremental shear forces, on the owner block.
    s.un_prev = overlap;
    s.fn = p.kn * size * overlap;
    s.fs -= p.ks * size * dus;
    s.fs2 -= p.ks * size * dus2;
    s.shear_disp += dus;
    s.shear_disp2 += dus2;
    s.flags = static_cast<uint8_t>((s.flags & ~tessera::kSlipping) | tessera::kTouching);
  }
};

}  // namespace

TESSERA_PLUGIN {
  registry.add_joint_law(std::make_unique<ElasticJoint>());
}
