// The explicit cycle of 3D rigid blocks (chapter 5.3): common planes, sub-contacts, joint law,
// resultants, damping and motion. solver.hpp's prepare and cycle call these for 3D models.
#pragma once

#include <string>

#include "tessera/model.hpp"

namespace tessera {

// A common-plane candidate and the gap it gives (see contacts3.hpp).
struct PlaneFit {
  uint8_t kind = 0;
  uint32_t ia = 0, ib = 0;
  Vec3 normal = Vec3::UnitZ();
  double gap = -1e300;
  double lo_a = 0.0, hi_b = 0.0;  // support values of a and b along the normal
};
// Support values of block b along n: the least and greatest n . x over its vertices.
double min_dot(const Blocks3& B, uint32_t b, const Vec3& n);
double max_dot(const Blocks3& B, uint32_t b, const Vec3& n);
// The normal and gap of one candidate; the gap is -1e300 for a degenerate one (parallel edges).
PlaneFit evaluate_plane(const Blocks3& B, uint32_t a, uint32_t b, uint8_t kind, uint32_t ia,
                        uint32_t ib);
// The best of every candidate for blocks a and b.
PlaneFit best_plane(const Blocks3& B, uint32_t a, uint32_t b);
// Moves a contact's common plane with its blocks, rebuilds its sub-contacts and runs the joint
// law on each (forces on a; b takes the opposite).
void update_contact3(const Model& m, Contact3& c);

double compute_timestep3(const Model& m);
void prepare3(Model& m);
void cycle3(Model& m);
// Detection pass: bounding boxes swept along x, the common plane of each close pair; keeps the
// state of contacts that persist.
void detect_contacts3(Model& m);
// First pair of blocks overlapping beyond the tolerance, as a message; empty if none.
std::string find_overlap3(const Model& m);
double kinetic_energy3(const Model& m);

}  // namespace tessera
