// Constitutive models of zones, the uniform-strain triangles a deformable block is cut into
// and tetrahedra a deformable block is cut into (§5.2.1, §5.3.1): null, isotropic elastic,
// Mohr-Coulomb with a tension cut-off and non-associated dilation, Drucker-Prager,
// strain-softening Mohr-Coulomb, ubiquitous joints and transversely isotropic elasticity. One law
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
  // Strain-softening: cohesion, friction, dilation and tension as piecewise-linear tables of the
  // plastic shear strain, flat (strain, value, strain, value, ...); empty: the constant above.
  std::vector<double> ctable, ftable, dtable, ttable;
  // Ubiquitous joint: the strength of the plane of weakness (degrees, Pa).
  double jfriction = 0.0, jcohesion = 0.0, jtension = 0.0, jdilation = 0.0;
  // Transversely isotropic elasticity: moduli in the plane of isotropy (1, 2) and normal to it
  // (3); nu13 = -e3/e1 under stress along 1.
  double e1 = 0.0, e3 = 0.0, nu12 = 0.0, nu13 = 0.0, g13 = 0.0;
  // The plane (of weakness, of isotropy): in 2D its angle from x counter-clockwise (jangle), in
  // 3D its dip and dip direction (clockwise from north = +y, z up); `orientation` says which
  // was given: 0 neither, 2 jangle, 3 jdip and jdipdir.
  double jangle = 0.0, jdip = 0.0, jdipdir = 0.0;
  uint8_t orientation = 0;
  // Derived by finalize: the plane's unit normal; a transversely isotropic material's stiffness
  // in x, y, z (Voigt order xx, yy, zz, yz, xz, xy; engineering shears), row by row.
  std::array<double, 3> normal{0.0, 1.0, 0.0};
  std::array<double, 36> stiffness{};
  const ZoneModel* impl = nullptr;
  // Binds the model and checks the constants; throws std::invalid_argument naming the fault.
  void finalize();
};

// A piecewise-linear table (strain, value, ...) at `strain`; the last value beyond its end, the
// first before its start, `constant` if the table is empty.
double table_value(const std::vector<double>& table, double strain, double constant);

// K and G from Young's modulus and Poisson's ratio; throws if nu is not in (-1, 0.5).
void elastic_from_young(double young, double poisson, double& bulk, double& shear);

// Stress (tension positive). In 2D zz is the out-of-plane normal stress and yz = xz = 0.
struct ZoneStress {
  double xx = 0, yy = 0, xy = 0, zz = 0, yz = 0, xz = 0;
};

// A step's spin: the antisymmetric part of the velocity gradient times the step,
// w_ij = (dv_i/dx_j - dv_j/dx_i) dt / 2 (2D: xy only).
struct Spin {
  double xy = 0, yz = 0, xz = 0;
};
// Turns a stress with its material through a step's spin (the Jaumann rate's rotation,
// sigma + W sigma - sigma W): a zone that turns carries its stress round with it, so that a
// rigid rotation leaves the principal stresses as they were, in the material's directions.
inline void rotate_stress(ZoneStress& s, const Spin& w) {
  const ZoneStress o = s;
  s.xx += 2 * (w.xy * o.xy + w.xz * o.xz);
  s.yy += 2 * (w.yz * o.yz - w.xy * o.xy);
  s.zz -= 2 * (w.xz * o.xz + w.yz * o.yz);
  s.xy += w.xy * (o.yy - o.xx) + w.xz * o.yz + w.yz * o.xz;
  s.yz += w.yz * (o.zz - o.yy) - w.xy * o.xz - w.xz * o.xy;
  s.xz += w.xz * (o.zz - o.xx) + w.xy * o.yz - w.yz * o.xy;
}

// The same in the plane (2D: the spin's xy only, and no out-of-plane shear to turn).
inline void rotate_plane_stress(ZoneStress& s, double wxy) {
  const double d = 2 * wxy * s.xy;
  s.xy += wxy * (s.yy - s.xx);
  s.xx += d, s.yy -= d;
}

// The out-of-plane stress of plane strain (ezz = 0) with an in-plane stress `s` from zero:
// nu (sxx + syy), or from a transversely isotropic material's compliance.
double plane_strain_zz(const ZoneProperties& p, const ZoneStress& s);

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
  // The same for a zone with a history, a number it keeps between steps (strain-softening's
  // accumulated plastic shear strain); the zone loops call this one. Models without a history
  // (and plug-ins written before it) need not override it: it forwards to the plain update.
  virtual void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
                      uint8_t& state, double& /*history*/) const {
    update(p, de, s, state);
  }
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
