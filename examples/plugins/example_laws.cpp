// An example plug-in of two laws, built by CMake as a shared library; load it with
// `model load FILE.so` before using them:
// - `joint define NAME kn=.. ks=.. friction=0 law=elastic-joint`: a joint that never slips or
//   opens, linear normal and shear springs with no strength limit (a glued joint, or a first
//   elastic estimate of a model);
// - `material define NAME density=.. E=.. nu=.. model=plugin-elastic`: isotropic elasticity, the
//   built-in `elastic` zone model written as a plug-in (the same arithmetic).
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

class PluginElastic final : public tessera::ZoneModel {
 public:
  const char* name() const override { return "plugin-elastic"; }
  void update(const tessera::ZoneProperties& p, const tessera::StrainIncrement& de,
              tessera::ZoneStress& s, uint8_t& state) const override {
    // Hooke's law on the increment (tension positive), with lambda = K - 2G/3.
    const double lambda = p.bulk - 2.0 * p.shear / 3.0;
    const double vol = de.xx + de.yy + de.zz;
    s.xx += 2.0 * p.shear * de.xx + lambda * vol;
    s.yy += 2.0 * p.shear * de.yy + lambda * vol;
    s.zz += 2.0 * p.shear * de.zz + lambda * vol;
    s.xy += 2.0 * p.shear * de.xy;
    s.yz += 2.0 * p.shear * de.yz;
    s.xz += 2.0 * p.shear * de.xz;
    // Never yielding now; what failed before stays marked.
    state &= tessera::kShearPast | tessera::kTensionPast;
  }
};

}  // namespace

TESSERA_PLUGIN {
  registry.add_joint_law(std::make_unique<ElasticJoint>());
  registry.add_zone_model(std::make_unique<PluginElastic>());
}
