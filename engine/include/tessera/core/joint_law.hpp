// Joint constitutive laws (chapter 5.2.2): stresses on a contact from its relative displacement.
//
// Laws are small classes registered by name; a joint property set names its law and carries the
// parameters. Stiffnesses and strengths are per unit area of joint; a law works on the forces of
// one contact standing for a size L of joint: a length (2D, unit thickness) or an area (a 3D
// sub-contact). Shear is a vector in the joint plane: two components in 3D, the second zero in
// 2D (where the law reduces exactly to its scalar form). Both force components are incremental
// (dFn = kn L dun, dFs = -ks L dus), so a change of L between cycles never makes a force jump and
// never puts energy into the model. The normal force is held between zero and the total-form
// value kn L un, so it cannot drift from the overlap.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

class JointLaw;

// A contact's state flags (2D contacts and 3D sub-contacts).
enum ContactFlag : uint8_t {
  kBonded = 1,    // cohesion and tensile strength still intact
  kSlipping = 2,  // at the Coulomb limit this cycle
  kTouching = 4,  // overlap or bond: carries force and takes a share of the interface length
  kBroken = 8,    // was bonded and failed, for output
  kNotch = 16,    // a corner touching two faces of a concave block: each contact keeps its face
  kPreload = 32,  // fs holds an in-situ shear stress, made a force at the next law call
};

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
  // law=coulomb-residual: the strength of a bond once it has failed in shear (degrees, Pa; a
  // negative friction means the peak friction). Plain coulomb leaves friction only.
  double residual_friction = -1.0, residual_cohesion = 0.0;
  // Viscous contact damping in the normal and shear directions, as fractions of the critical
  // damping of the two blocks on the contact's springs (0: none; chapter 5.2.4 notes UDEC has
  // none built in). The shear dashpot rests while the contact slips.
  double normal_damping = 0.0, shear_damping = 0.0;
  // law=cy (continuously yielding): stiffnesses kn (sigma_n / sref)^en and ks (sigma_n /
  // sref)^es, the initial friction (degrees; negative: `friction`, the basic angle) decaying to
  // `friction` over the roughness length (m) of plastic shear.
  // Beyond the normal stress smax (Pa; 0: ten times sref) the stiffnesses stop growing.
  double en = 0.0, es = 0.0, sref = 1e6, smax = 0.0, initial_friction = -1.0, roughness = 0.0;
  // law=barton-bandis: JRC, JCS (Pa), Bandis's maximum closure vm (m; kn is the initial normal
  // stiffness), and the shear displacement at peak (m; 0: Barton's (L/500)(JRC/L)^0.33 for the
  // joint length lj, m). `friction` is the residual angle phi_r.
  double jrc = 0.0, jcs = 0.0, vm = 0.0, dpeak = 0.0, lj = 1.0;
  // Barton-Bandis: the largest tangent normal stiffness (Pa/m; 0: ten times kn), beyond which
  // the closure stays linear; the time step uses it.
  double kn_cap = 0.0;
  // Both: their shear strength is divided by this (strength reduction, `solve fos`).
  double strength_divisor = 1.0;
  // Derived when the set is defined.
  double tan_friction = 0.0, tan_dilation = 0.0, tan_residual = 0.0;
  double kn_max = 0.0, ks_max = 0.0;          // the stiffest tangents the law reaches (time step)
  double phi_initial = 0.0, peak_disp = 0.0;  // cy's initial friction, Barton's delta_peak
  const JointLaw* impl = nullptr;
  // The Coulomb laws are called inline by the cycle: 0 coulomb, 1 coulomb-residual, -1 another.
  int8_t inline_coulomb = -1;
  void finalize();  // derives the tangents and binds the law; throws on an unknown law
};

// A contact's dashpot forces (compression positive, shear on the owner block) for damping
// ratios of the joint set: c = 2 zeta sqrt(k m_eff) for the contact's spring k = kn (ks) times
// its size, with the pair's effective mass shared in proportion to `share` (the contact's part
// of the pair's joint); `closing` and `sliding` are the normal closing speed and the shear
// velocity of the owner relative to the other block.
struct Dashpot {
  double fn = 0.0, fs = 0.0, fs2 = 0.0;
};
Dashpot contact_dashpot(const struct JointProperties& p, double size, double share, double m_eff,
                        double closing, double sliding, double sliding2, bool slipping);

// The state one law call reads and writes: forces on the owner block (compression positive), the
// normal displacement of the last call, dilation and total shear displacement, flags.
struct JointState {
  double fn = 0.0, fs = 0.0, un_prev = 0.0, dilation = 0.0, shear_disp = 0.0;
  uint8_t flags = 0;
  // Second shear component (3D): force and total displacement.
  double fs2 = 0.0, shear_disp2 = 0.0;
  // Plastic shear displacement travelled (law=cy and barton-bandis: their strength's history).
  double plastic = 0.0;
  // Magnitudes of the shear force and of the total shear displacement.
  double shear() const { return std::sqrt(fs * fs + fs2 * fs2); }
  double shear_travel() const {
    return std::sqrt(shear_disp * shear_disp + shear_disp2 * shear_disp2);
  }
  // Dilation follows the direction of shearing (as 3DEC's): a step of slip (dus, dus2, already
  // in the totals) that takes the joint away from where its shear displacement started opens
  // it, one that brings it back closes it (+1 or -1), so that cyclic shear does not pump it open.
  double dilation_direction(double dus, double dus2) const {
    return dus * shear_disp + dus2 * shear_disp2 >= 0.0 ? 1.0 : -1.0;
  }
  // Adds a dilation increment (signed), never closing the joint past its undilated state.
  void dilate(double increment) { dilation = std::max(0.0, dilation + increment); }
};

class JointLaw {
 public:
  virtual ~JointLaw() = default;
  virtual const char* name() const = 0;
  // size: the contact's share of joint (length or area); overlap: current overlap (negative
  // gap); dus, dus2: shear displacement increment of the owner relative to the other block.
  virtual void update(const JointProperties& p, double size, double overlap, double dus,
                      double dus2, JointState& s) const = 0;
  // The normal displacement that carries a normal stress sigma_n (in-situ closure of a joint).
  // (Defined here: a plug-in links nothing, so every virtual is inline.)
  virtual double closure(const JointProperties& p, double sigma_n) const { return sigma_n / p.kn; }
  // The stiffest normal and shear tangents the law reaches, per unit area (for the time step).
  virtual void stiffness_bounds(const JointProperties& p, double& kn, double& ks) const {
    kn = p.kn, ks = p.ks;
  }
  // Checks the set's parameters of this law; throws std::invalid_argument naming the fault.
  virtual void check(const JointProperties& /*p*/) const {}
  // Whether strength reduction divides the law's whole shear strength (`strength_divisor`)
  // rather than its friction, cohesion and tension parameters.
  virtual bool divides_strength() const { return false; }
  // The 2D form: one shear component.
  void update(const JointProperties& p, double length, double overlap, double dus,
              JointState& s) const {
    update(p, length, overlap, dus, 0.0, s);
  }
};

// An overlap within round-off of zero is zero: a block set exactly on another (a gap of 1e-18 m
// from the arithmetic of its coordinates) is neither in tension nor pressed.
inline double without_roundoff(double overlap, double roundoff) {
  return overlap <= roundoff && overlap >= -roundoff ? 0.0 : overlap;
}

// Open, unbonded and open before (normal displacement un <= 0): the law has nothing to do but
// remember the opening.
inline bool stays_open(double un, double fn, uint8_t flags) {
  return un <= 0.0 && fn == 0.0 && !(flags & (kBonded | kTouching));
}

// The law registered under a name, or nullptr.
const JointLaw* find_joint_law(const std::string& name);
std::vector<std::string> joint_law_names();

}  // namespace tessera
