// Damping (chapter 5.2.4), the same for every degree of freedom in 2D and 3D: local damping
// against the sign of the velocity, adaptive global (viscous) damping servoed to the power of the
// unbalanced forces, kinetic damping (light local damping, and every velocity set to zero at
// each peak of the kinetic energy: step.cpp), or none.
#pragma once

#include <cmath>

namespace tessera {

struct Model;

// The damping of one cycle: local damping's alpha and the global viscosity (1/s).
struct Damping {
  double alpha = 0.0, viscosity = 0.0;
};

// The cycle's damping from the settings; every 10 cycles adaptive global damping servoes its
// viscosity (Cundall 1982) from the power of the unbalanced forces and twice the kinetic energy.
Damping cycle_damping(Model& m, double power, double kin2);
// Whether this cycle servoes the global viscosity (the back end then measures the power).
bool servo_due(const Model& m);

// Sign of a velocity component (zero at rest).
inline double sgn(double v) {
  return (v > 0.0) - (v < 0.0);
}
// A force component with local damping: alpha |f| against the velocity.
inline double locally_damped(double f, double v, double alpha) {
  return f - alpha * std::abs(f) * sgn(v);
}

}  // namespace tessera
