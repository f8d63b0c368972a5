// Joint constitutive laws (chapter 5.2.2): stresses on a contact from its relative displacement.
//
// Laws are small classes registered by name; a joint property set names its law and carries the
// parameters. The normal stress is kn times the overlap (the integral of dsigma_n = kn dun for a
// constant kn, which cannot drift); the shear stress is incremental, dtau = -ks dus.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

class JointLaw;

// A named set of joint properties, assigned to contacts between groups.
struct JointProperties {
  std::string name;
  std::string law = "coulomb";
  double kn = 0.0;              // normal stiffness, Pa/m
  double ks = 0.0;              // shear stiffness, Pa/m
  double friction = 0.0;        // degrees
  double cohesion = 0.0;        // Pa
  double tension = 0.0;         // tensile strength, Pa
  double dilation = 0.0;        // degrees
  double dilation_limit = 0.0;  // shear displacement after which dilation stops (0: none)
  // Derived when the set is defined.
  double tan_friction = 0.0, tan_dilation = 0.0;
  const JointLaw* impl = nullptr;
  void finalize();  // derives the tangents and binds the law; throws on an unknown law
};

// The state one law call reads and writes.
struct JointState {
  double sigma_n = 0.0, tau = 0.0, dilation = 0.0, shear_disp = 0.0;
  uint8_t flags = 0;
};

class JointLaw {
 public:
  virtual ~JointLaw() = default;
  virtual const char* name() const = 0;
  // overlap: current overlap (negative gap); dus: shear displacement increment of a relative to b.
  virtual void update(const JointProperties& p, double overlap, double dus, JointState& s) const = 0;
};

// The law registered under a name, or nullptr.
const JointLaw* find_joint_law(const std::string& name);
std::vector<std::string> joint_law_names();

}  // namespace tessera
