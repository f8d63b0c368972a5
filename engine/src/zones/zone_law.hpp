// Pieces of the zone models shared by their files (zone_model.cpp and the models beside it):
// the isotropic elastic increment, Mohr-Coulomb's return, the plane of an anisotropic material,
// the models kept in their own files (engine internal).
#pragma once

#include <array>
#include <cstdint>
#include <numbers>

#include "tessera/core/angles.hpp"
#include "tessera/zones/zone_model.hpp"

namespace tessera::zone_law {

// A Mohr-Coulomb strength: friction and dilation in degrees, cohesion and tension in Pa.
struct Strength {
  double friction = 0, cohesion = 0, tension = 0, dilation = 0;
};

// Isotropic elastic increment: ds = 2G de + (K - 2G/3) tr(de) I (in plane strain dezz = 0).
void elastic_step(double bulk, double shear, const StrainIncrement& de, ZoneStress& s);

// Mohr-Coulomb's correction of a stress that may have left the yield surface (FLAC's return in
// principal axes, non-associated flow, tension cut-off); sets the state's "now" and "past" bits
// and returns false if the stress is inside. `shear_strain`, if given, gets the increment of the
// plastic shear strain measure sqrt(0.5 (de1 - dm)^2 + 0.5 dm^2 + 0.5 (de3 - dm)^2),
// dm = (de1 + de3) / 3, of the shear flow (0 for tension).
bool mohr_coulomb_correct(double bulk, double shear, const Strength& st, ZoneStress& s,
                          uint8_t& state, double* shear_strain = nullptr);

// The models of their own files: softening_model.cpp, ubiquitous_model.cpp, anisotropic_model.cpp.
const ZoneModel& softening_model();
const ZoneModel& ubiquitous_model();
const ZoneModel& anisotropic_model();

// Checks a strain-softening material's tables (pairs, strains increasing from 0 up, values not
// negative, angles below 90 degrees); throws std::invalid_argument naming the fault.
void check_tables(const ZoneProperties& p);
// The axes of a material's plane (of weakness, of isotropy): two in the plane, then its unit
// normal; throws std::invalid_argument if no orientation was given.
std::array<std::array<double, 3>, 3> plane_axes(const ZoneProperties& p);
// A transversely isotropic material's stiffness in x, y, z, and bulk and shear moduli of the
// isotropic material that bounds it (K = l / 3, G = l / 2 with l its largest eigenvalue in
// Mandel's form: that material's stiffness is l I, so no strain is stiffer in it, and the time
// step and masses made from K and G stay stable); throws if the constants are not admissible.
void anisotropic_stiffness(ZoneProperties& p);

}  // namespace tessera::zone_law
