#include "tessera/core/history.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "tessera/core/model.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

namespace {
// A quantity of block b of a 3D model: rotation is the angle turned since it was made (radians),
// angvel the magnitude of the angular velocity.
// A node of a deformable 3D block (its displacement, velocity, position); no rotation.
double node_value3(const Continuum3& c, HistoryQuantity q, size_t n) {
  switch (q) {
    case HistoryQuantity::kXDisp:
    case HistoryQuantity::kYDisp:
    case HistoryQuantity::kZDisp: {
      const int k = q == HistoryQuantity::kXDisp ? 0 : q == HistoryQuantity::kYDisp ? 1 : 2;
      return c.pos[n][k] - c.pos0[n][k];
    }
    case HistoryQuantity::kXVel:
      return c.vel[n].x();
    case HistoryQuantity::kYVel:
      return c.vel[n].y();
    case HistoryQuantity::kZVel:
      return c.vel[n].z();
    case HistoryQuantity::kXPos:
      return c.pos[n].x();
    case HistoryQuantity::kYPos:
      return c.pos[n].y();
    case HistoryQuantity::kZPos:
      return c.pos[n].z();
    default:
      return 0.0;
  }
}

double history_value3(const Model& m, HistoryQuantity q, size_t b, int32_t node) {
  const Blocks3& B = m.blocks3;
  // A deformable block: its node nearest the point asked for, or the mean of its corners.
  if (node >= 0 && static_cast<size_t>(node) < m.continuum3.node_count())
    return node_value3(m.continuum3, q, static_cast<size_t>(node));
  if (B.deformable[b]) {
    double sum = 0.0;
    for (uint32_t v = B.vert_begin[b]; v < B.vert_begin[b + 1]; ++v)
      sum += node_value3(m.continuum3, q, static_cast<size_t>(B.vertex_node[v]));
    return sum / static_cast<double>(B.vert_begin[b + 1] - B.vert_begin[b]);
  }
  b = static_cast<size_t>(B.master[b]);  // a piece of a concave block moves with its master
  const RigidBody3& body = B.body[b];
  switch (q) {
    case HistoryQuantity::kXDisp:
    case HistoryQuantity::kYDisp:
    case HistoryQuantity::kZDisp: {
      const int k = q == HistoryQuantity::kXDisp ? 0 : q == HistoryQuantity::kYDisp ? 1 : 2;
      return body.position[k] - B.ref[b][k];
    }
    case HistoryQuantity::kXVel:
      return body.velocity.x();
    case HistoryQuantity::kYVel:
      return body.velocity.y();
    case HistoryQuantity::kZVel:
      return body.velocity.z();
    case HistoryQuantity::kXPos:
      return body.position.x();
    case HistoryQuantity::kYPos:
      return body.position.y();
    case HistoryQuantity::kZPos:
      return body.position.z();
    case HistoryQuantity::kRotation:
      return 2.0 * std::acos(std::min(1.0, std::abs(body.orientation.dot(B.ref_q[b]))));
    case HistoryQuantity::kAngVel:
      return body.angular_velocity().norm();
    default:
      return 0.0;
  }
}

struct QuantityName {
  HistoryQuantity q;
  const char* name;
  bool block;
};
constexpr std::array<QuantityName, 34> kNames{{
    {HistoryQuantity::kXDisp, "xdisp", true},
    {HistoryQuantity::kYDisp, "ydisp", true},
    {HistoryQuantity::kXVel, "xvel", true},
    {HistoryQuantity::kYVel, "yvel", true},
    {HistoryQuantity::kRotation, "rotation", true},
    {HistoryQuantity::kAngVel, "angvel", true},
    {HistoryQuantity::kXPos, "xpos", true},
    {HistoryQuantity::kYPos, "ypos", true},
    {HistoryQuantity::kRatio, "ratio", false},
    {HistoryQuantity::kUnbalanced, "unbalanced", false},
    {HistoryQuantity::kKinetic, "kinetic", false},
    {HistoryQuantity::kTime, "time", false},
    {HistoryQuantity::kTimestep, "timestep", false},
    {HistoryQuantity::kZDisp, "zdisp", true},
    {HistoryQuantity::kZVel, "zvel", true},
    {HistoryQuantity::kZPos, "zpos", true},
    {HistoryQuantity::kSxx, "sxx", false},
    {HistoryQuantity::kSyy, "syy", false},
    {HistoryQuantity::kSzz, "szz", false},
    {HistoryQuantity::kSxy, "sxy", false},
    {HistoryQuantity::kSyz, "syz", false},
    {HistoryQuantity::kSxz, "sxz", false},
    {HistoryQuantity::kSigma1, "sigma1", false},
    {HistoryQuantity::kSigma3, "sigma3", false},
    {HistoryQuantity::kBoltAxial, "bolt_axial", false},
    {HistoryQuantity::kBoltShear, "bolt_shear", false},
    {HistoryQuantity::kCableAxial, "cable_axial", false},
    {HistoryQuantity::kCableSlip, "cable_slip", false},
    {HistoryQuantity::kLinerThrust, "liner_thrust", false},
    {HistoryQuantity::kLinerMoment, "liner_moment", false},
    {HistoryQuantity::kLinerPressure, "liner_pressure", false},
    {HistoryQuantity::kSlipping, "slipping", false},
    {HistoryQuantity::kNormalForce, "normal_force", false},
    {HistoryQuantity::kShearForce, "shear_force", false},
}};

// The force between blocks a and b: the sum of their contacts' normal forces, and the size of
// the resultant of what acts on a across the normals (3D: over the sub-contacts).
double pair_force(const Model& m, size_t a, size_t b, bool normal) {
  double fn = 0.0;
  Vec3 shear = Vec3::Zero();
  // f: the force on the contact's first block, n: its normal (towards that block).
  const auto add = [&](uint32_t ca, uint32_t cb, double n_force, const Vec3& f, const Vec3& n) {
    if (!((ca == a && cb == b) || (ca == b && cb == a))) return;
    const double sign = ca == a ? 1.0 : -1.0;
    fn += n_force;
    shear += sign * (f - f.dot(n) * n);
  };
  if (m.dim == 3) {
    for (const Contact3& c : m.contacts3) {
      double sum = 0.0;
      for (const SubContact& s : c.subs) sum += s.fn;
      add(c.a, c.b, sum, c.force, c.normal);
    }
  } else {
    const Contacts& C = m.contacts;
    for (size_t i = 0; i < C.size(); ++i)
      add(C.a[i], C.b[i], C.fn[i], Vec3(C.force(i).x(), C.force(i).y(), 0.0),
          Vec3(C.normal[i].x(), C.normal[i].y(), 0.0));
  }
  return normal ? fn : shear.norm();
}

// A zone's stress component or principal stress (2D: in the plane, as the pictures show).
double zone_value(const ZoneStress& t, HistoryQuantity q, bool three) {
  switch (q) {
    case HistoryQuantity::kSxx:
      return t.xx;
    case HistoryQuantity::kSyy:
      return t.yy;
    case HistoryQuantity::kSzz:
      return t.zz;
    case HistoryQuantity::kSxy:
      return t.xy;
    case HistoryQuantity::kSyz:
      return t.yz;
    case HistoryQuantity::kSxz:
      return t.xz;
    default:
      break;
  }
  double s1 = 0, s3 = 0;
  if (three) {
    const Principal p = principal_3d(t);
    s1 = p.s[0], s3 = p.s[2];
  } else {
    principal_stresses(t, s1, s3);
  }
  return q == HistoryQuantity::kSigma1 ? s1 : s3;
}
}  // namespace

int Histories::find(const std::string& label) const {
  for (size_t i = 0; i < series.size(); ++i)
    if (series[i].label == label) return static_cast<int>(i);
  return -1;
}

bool parse_history_quantity(const std::string& word, HistoryQuantity& q, bool& block_quantity) {
  for (const auto& n : kNames)
    if (word == n.name) {
      q = n.q, block_quantity = n.block;
      return true;
    }
  return false;
}

bool is_zone_quantity(HistoryQuantity q) {
  return q >= HistoryQuantity::kSxx && q <= HistoryQuantity::kSigma3;
}

bool is_bolt_quantity(HistoryQuantity q) {
  return q == HistoryQuantity::kBoltAxial || q == HistoryQuantity::kBoltShear;
}

bool is_cable_quantity(HistoryQuantity q) {
  return q == HistoryQuantity::kCableAxial || q == HistoryQuantity::kCableSlip;
}

bool is_contact_quantity(HistoryQuantity q) {
  return q == HistoryQuantity::kNormalForce || q == HistoryQuantity::kShearForce;
}

bool is_liner_quantity(HistoryQuantity q) {
  return q == HistoryQuantity::kLinerThrust || q == HistoryQuantity::kLinerMoment ||
         q == HistoryQuantity::kLinerPressure;
}

const char* history_quantity_name(HistoryQuantity q) {
  for (const auto& n : kNames)
    if (n.q == q) return n.name;
  return "?";
}

std::string history_quantity_unit(HistoryQuantity q, int dim) {
  switch (q) {
    case HistoryQuantity::kXDisp:
    case HistoryQuantity::kYDisp:
    case HistoryQuantity::kZDisp:
    case HistoryQuantity::kXPos:
    case HistoryQuantity::kYPos:
    case HistoryQuantity::kZPos:
      return "m";
    case HistoryQuantity::kXVel:
    case HistoryQuantity::kYVel:
    case HistoryQuantity::kZVel:
      return "m/s";
    case HistoryQuantity::kRotation:
      return "rad";
    case HistoryQuantity::kAngVel:
      return "rad/s";
    case HistoryQuantity::kRatio:
    case HistoryQuantity::kSlipping:
      return "";
    case HistoryQuantity::kUnbalanced:
      return dim == 3 ? "N" : "N/m";
    case HistoryQuantity::kKinetic:
      return dim == 3 ? "J" : "J/m";
    case HistoryQuantity::kTime:
    case HistoryQuantity::kTimestep:
      return "s";
    case HistoryQuantity::kBoltAxial:
    case HistoryQuantity::kBoltShear:
    case HistoryQuantity::kCableAxial:
      return dim == 3 ? "N" : "N/m";
    case HistoryQuantity::kCableSlip:
      return "m";
    case HistoryQuantity::kNormalForce:
    case HistoryQuantity::kShearForce:
      return dim == 3 ? "N" : "N/m";
    case HistoryQuantity::kLinerThrust:
      return "N/m";
    case HistoryQuantity::kLinerMoment:
      return "N m/m";
    default:
      return "Pa";  // zone stresses
  }
}

std::vector<std::string> history_quantity_names() {
  std::vector<std::string> out;
  for (const auto& n : kNames) out.emplace_back(n.name);
  return out;
}

double history_value(const Model& m, const HistorySeries& s) {
  const Blocks& B = m.blocks;
  // A block history whose block was deleted (-2) reads NaN from then on; so does a zone's.
  if (s.block == -2) return std::nan("");
  if (is_bolt_quantity(s.quantity)) {
    const Reinforcement& R = m.support;
    if (s.element < 0 || static_cast<size_t>(s.element) >= R.size()) return std::nan("");
    const auto e = static_cast<size_t>(s.element);
    return s.quantity == HistoryQuantity::kBoltAxial ? R.axial[e] : R.shear[e];
  }
  if (is_cable_quantity(s.quantity)) {
    const auto& axial = m.dim == 3 ? m.cables3.axial : m.cables.axial;
    const auto& slip = m.dim == 3 ? m.cables3.slip : m.cables.slip;
    if (s.element < 0 || static_cast<size_t>(s.element) >= axial.size()) return std::nan("");
    const auto i = static_cast<size_t>(s.element);
    return s.quantity == HistoryQuantity::kCableAxial ? axial[i] : slip[i];
  }
  if (is_liner_quantity(s.quantity)) {
    if (s.element < 0 || static_cast<size_t>(s.element) >= m.liners.size()) return std::nan("");
    const auto i = static_cast<size_t>(s.element);
    if (s.quantity == HistoryQuantity::kLinerPressure) return m.liners.pressure[i];
    return s.quantity == HistoryQuantity::kLinerThrust ? liner_thrust(m.liners, i)
                                                       : liner_moment(m.liners, i);
  }
  if (is_contact_quantity(s.quantity)) {
    if (s.block < 0 || s.element < 0) return std::nan("");
    return pair_force(m, static_cast<size_t>(s.block), static_cast<size_t>(s.element),
                      s.quantity == HistoryQuantity::kNormalForce);
  }
  if (is_zone_quantity(s.quantity)) {
    const auto z = static_cast<size_t>(s.zone);
    if (m.dim == 3)
      return s.zone >= 0 && z < m.continuum3.zone_count()
                 ? zone_value(m.continuum3.stress[z], s.quantity, true)
                 : std::nan("");
    return s.zone >= 0 && z < m.continuum.zone_count()
               ? zone_value(m.continuum.stress[z], s.quantity, false)
               : std::nan("");
  }
  const auto b = static_cast<size_t>(std::max(0, s.block));
  if (m.dim == 3 && s.block >= 0) return history_value3(m, s.quantity, b, s.node);
  // Deformable blocks: a node's displacement, velocity and position, or (for the block as a
  // whole) their means over its outline nodes; no rotation.
  const bool one_node = s.node >= 0 && static_cast<size_t>(s.node) < m.continuum.node_count();
  if (one_node || (s.block >= 0 && B.deformable[b])) {
    const Continuum& c = m.continuum;
    Vec2 u = Vec2::Zero(), v = Vec2::Zero(), p = Vec2::Zero();
    double w = 1.0;
    auto add = [&](size_t n) { u += c.pos[n] - c.pos0[n], v += c.vel[n], p += c.pos[n]; };
    if (one_node) {
      add(static_cast<size_t>(s.node));
    } else {
      for (uint32_t k = B.vert_begin[b]; k < B.vert_begin[b + 1]; ++k)
        add(static_cast<size_t>(B.node[k]));
      w = 1.0 / static_cast<double>(B.vertex_count(b));
    }
    switch (s.quantity) {
      case HistoryQuantity::kXDisp:
        return w * u.x();
      case HistoryQuantity::kYDisp:
        return w * u.y();
      case HistoryQuantity::kXVel:
        return w * v.x();
      case HistoryQuantity::kYVel:
        return w * v.y();
      case HistoryQuantity::kXPos:
        return w * p.x();
      case HistoryQuantity::kYPos:
        return w * p.y();
      case HistoryQuantity::kRotation:
      case HistoryQuantity::kAngVel:
        return 0.0;
      default:
        break;
    }
  }
  switch (s.quantity) {
    case HistoryQuantity::kXDisp:
      return B.x[b] - B.x_ref[b];
    case HistoryQuantity::kYDisp:
      return B.y[b] - B.y_ref[b];
    case HistoryQuantity::kXVel:
      return B.vx[b];
    case HistoryQuantity::kYVel:
      return B.vy[b];
    case HistoryQuantity::kRotation:
      return B.theta[b];
    case HistoryQuantity::kAngVel:
      return B.omega[b];
    case HistoryQuantity::kXPos:
      return B.x[b];
    case HistoryQuantity::kYPos:
      return B.y[b];
    case HistoryQuantity::kRatio:
      return m.ratio;
    case HistoryQuantity::kUnbalanced:
      return m.max_unbalanced;
    case HistoryQuantity::kKinetic:
      return kinetic_energy(m);
    case HistoryQuantity::kTime:
      return m.time;
    case HistoryQuantity::kTimestep:
      return m.dt;
    case HistoryQuantity::kSlipping:
      return static_cast<double>(slipping_contacts(m));
    default:
      break;
  }
  return 0.0;
}

size_t slipping_contacts(const Model& m) {
  size_t n = 0;
  auto slipping = [](uint8_t f) { return (f & kTouching) && (f & kSlipping); };
  for (const uint8_t f : m.contacts.flags) n += slipping(f);
  for (const Contact3& c : m.contacts3)
    for (const SubContact& s : c.subs) n += slipping(s.flags);
  return n;
}

void sample_histories(Model& m, bool force) {
  Histories& h = m.histories;
  if (h.series.empty() || h.interval == 0) return;
  if (!force && m.cycle % h.interval != 0) return;
  if (!h.cycles.empty() && h.cycles.back() == m.cycle) return;
  h.cycles.push_back(m.cycle);
  for (const auto& s : h.series) h.values.push_back(history_value(m, s));
}

void write_histories_csv(const Histories& h, std::ostream& out) {
  out << "cycle";
  for (const auto& s : h.series) out << ',' << s.label;
  out << '\n';
  char buf[32];
  for (size_t r = 0; r < h.rows(); ++r) {
    out << h.cycles[r];
    // No value (a deleted block, a series added later) is an empty cell, as spreadsheets read it.
    for (size_t c = 0; c < h.columns(); ++c) {
      out << ',';
      if (std::isnan(h.at(r, c))) continue;
      std::snprintf(buf, sizeof buf, "%.10g", h.at(r, c));
      out << buf;
    }
    out << '\n';
  }
}

}  // namespace tessera
