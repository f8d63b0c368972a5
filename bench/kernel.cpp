#include "kernel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace tessera::bench {

namespace {
// The hot fields of one contact in one record (64 bytes).
struct Contact {
  uint32_t a, b;
  double px, py;  // contact point
  double nx, ny;  // unit normal from a towards b
  double kn, ks;  // stiffness times the contact's length (N/m per m)
  double mu;      // tan(friction)
  double fn, fs;  // normal (compression positive) and shear force
};

// The hot fields of one block.
struct Body {
  double x, y, vx, vy, w;
  double fx, fy, mz;
  double inv_m, inv_i, gx, gy;  // gravity force m g
};
}  // namespace

KernelResult run_kernel(const Model& m, uint64_t cycles) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  std::vector<Body> body(B.size());
  for (size_t i = 0; i < B.size(); ++i) {
    const bool fixed = B.fixity[i] != 0;
    body[i] = {B.x[i],
               B.y[i],
               0,
               0,
               0,
               0,
               0,
               0,
               fixed ? 0.0 : 1.0 / B.mass[i],
               fixed ? 0.0 : 1.0 / B.inertia[i],
               B.mass[i] * m.settings.gravity.x(),
               B.mass[i] * m.settings.gravity.y()};
  }
  std::vector<Contact> contact;
  contact.reserve(C.size());
  for (size_t c = 0; c < C.size(); ++c) {
    const JointProperties& j = m.joints[C.joint[c]];
    // Tessera's normal points from b towards a; the kernel's from a towards b.
    const double length = std::max(C.length[c], 1e-3);
    contact.push_back({C.a[c], C.b[c], C.point[c].x(), C.point[c].y(), -C.normal[c].x(),
                       -C.normal[c].y(), j.kn * length, j.ks * length, j.tan_friction, 0, 0});
  }
  const double dt = m.dt, alpha = 0.8;
  const auto t0 = std::chrono::steady_clock::now();
  for (uint64_t cycle = 0; cycle < cycles; ++cycle) {
    for (Body& p : body) p.fx = p.gx, p.fy = p.gy, p.mz = 0;
    for (Contact& c : contact) {
      Body &a = body[c.a], &b = body[c.b];
      // Relative velocity of b against a at the contact point, in normal and shear.
      const double rax = c.px - a.x, ray = c.py - a.y, rbx = c.px - b.x, rby = c.py - b.y;
      const double dvx = (b.vx - b.w * rby) - (a.vx - a.w * ray);
      const double dvy = (b.vy + b.w * rbx) - (a.vy + a.w * rax);
      const double dun = (dvx * c.nx + dvy * c.ny) * dt, dus = (-dvx * c.ny + dvy * c.nx) * dt;
      c.fn = std::max(0.0, c.fn - c.kn * dun);
      const double cap = c.mu * c.fn;
      c.fs = std::clamp(c.fs - c.ks * dus, -cap, cap);
      // Force on b (a takes the opposite): compression pushes b along n.
      const double fx = c.fn * c.nx - c.fs * c.ny, fy = c.fn * c.ny + c.fs * c.nx;
      b.fx += fx, b.fy += fy, b.mz += rbx * fy - rby * fx;
      a.fx -= fx, a.fy -= fy, a.mz -= rax * fy - ray * fx;
    }
    for (Body& p : body) {
      // Local damping against the motion, then central differences.
      const auto damped = [&](double f, double v) {
        return f - alpha * std::abs(f) * (v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0);
      };
      p.vx += dt * p.inv_m * damped(p.fx, p.vx);
      p.vy += dt * p.inv_m * damped(p.fy, p.vy);
      p.w += dt * p.inv_i * damped(p.mz, p.w);
      p.x += dt * p.vx, p.y += dt * p.vy;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {1e3 * seconds / static_cast<double>(std::max<uint64_t>(cycles, 1)),
          body.empty() ? 0.0 : body.back().y};
}

}  // namespace tessera::bench
