// Constitutive models of zones, the uniform-strain triangles a deformable block is cut into
// and tetrahedra a deformable block is cut into (§5.2.1, §5.3.1): null, isotropic elastic,
// Mohr-Coulomb with a tension cut-off and non-associated dilation, and Drucker-Prager. One law
// code for both dimensions: it works on the full 3D stress, and a 2D zone is its plane-strain
// case (strain increments with no z components, the out-of-plane stress tracked).
//
// Sign convention of zones: tension positive (as FLAC and UDEC zones; contacts keep compression
// positive). A model takes the stress at the start of a step and a strain increment, and returns
// the new stress, corrected back onto the yield surface when the elastic guess leaves it
// (FLAC's incremental plasticity with the flow rule's closed-form return in principal axes).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

class ZoneModel;

// What a zone is made of. Elastic constants are kept as bulk and shear moduli.
struct ZoneProperties {
  std::string name;
  std::string model = "elastic";
  double density = 0.0;   // kg/m^3
  double bulk = 0.0;      // K, Pa
  double shear = 0.0;     // G, Pa
  double friction = 0.0;  // degrees (Mohr-Coulomb, Drucker-Prager)
  double cohesion = 0.0;  // Pa
  double tension = 0.0;   // tensile strength, Pa (0: none)
  double dilation = 0.0;  // degrees
  const ZoneModel* impl = nullptr;
  // Binds the model and checks the constants; throws std::invalid_argument naming the fault.
  void finalize();
};

// K and G from Young's modulus and Poisson's ratio; throws if nu is not in (-1, 0.5).
void elastic_from_young(double young, double poisson, double& bulk, double& shear);

// Stress (tension positive). In 2D zz is the out-of-plane normal stress and yz = xz = 0.
struct ZoneStress {
  double xx = 0, yy = 0, xy = 0, zz = 0, yz = 0, xz = 0;
};

// Strain increment; the shears are tensor components (half the engineering shear). A 2D zone's
// has zz = yz = xz = 0 (plane strain).
struct StrainIncrement {
  double xx = 0, yy = 0, xy = 0, zz = 0, yz = 0, xz = 0;
};

// Plastic state of a zone, for output: failing now, or failed at some earlier step.
enum ZoneState : uint8_t {
  kShearNow = 1,
  kTensionNow = 2,
  kShearPast = 4,
  kTensionPast = 8,
};

class ZoneModel {
 public:
  virtual ~ZoneModel() = default;
  virtual const char* name() const = 0;
  // Updates the stress for a strain increment and sets the state's "now" bits (keeping "past").
  virtual void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
                      uint8_t& state) const = 0;
  // Whether the zone carries stress and mass at all (false for null zones).
  virtual bool solid() const { return true; }
};

const ZoneModel* find_zone_model(const std::string& name);
std::vector<std::string> zone_model_names();

// Principal stresses in the plane and the angle of the first from x (radians): s1 <= s2.
void principal_2d(const ZoneStress& s, double& s1, double& s2, double& angle);

// The three principal stresses, s[0] <= s[1] <= s[2] (tension positive: s[0] the most
// compressive), and their directions as the columns of `axes`.
struct Principal {
  std::array<double, 3> s{};
  std::array<std::array<double, 3>, 3> axes{};  // axes[i]: the unit direction of s[i]
};
Principal principal_3d(const ZoneStress& s);
// The stress with principal values `s` on the directions of `p` (the inverse of principal_3d).
ZoneStress from_principal(const Principal& p, const std::array<double, 3>& s);

}  // namespace tessera
