// The zone constitutive models and their registry.
#include "tessera/zones/zone_model.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "tessera/plugin.hpp"
#include "zone_law.hpp"

namespace tessera {

namespace zone_law {

void elastic_step(double bulk, double shear, const StrainIncrement& de, ZoneStress& s) {
  const double lambda = bulk - 2.0 * shear / 3.0;
  const double vol = de.xx + de.yy + de.zz;
  s.xx += 2.0 * shear * de.xx + lambda * vol;
  s.yy += 2.0 * shear * de.yy + lambda * vol;
  s.zz += 2.0 * shear * de.zz + lambda * vol;
  s.xy += 2.0 * shear * de.xy;
  s.yz += 2.0 * shear * de.yz;
  s.xz += 2.0 * shear * de.xz;
}

namespace {
// Mohr-Coulomb's correction of principal stresses s1 <= s2 <= s3 back onto the yield surface
// (FLAC's formulation): shear yield fs = s1 - s3 Nphi + 2c sqrt(Nphi), tension ft = sigma_t -
// s3, the corrections by the non-associated flow rule with Npsi. Returns false if elastic;
// `gamma` gets the plastic shear strain measure's increment.
bool mohr_coulomb_return(double bulk, double shear, const Strength& p, double& s1, double& s2,
                         double& s3, uint8_t& state, double& gamma) {
  const double sphi = std::sin(p.friction * kDeg), spsi = std::sin(p.dilation * kDeg);
  const double nphi = (1 + sphi) / (1 - sphi), npsi = (1 + spsi) / (1 - spsi);
  const double rn = std::sqrt(nphi);
  // The tensile strength cannot exceed the apex of the shear cone.
  double st = p.tension;
  if (sphi > 0) st = std::min(st, p.cohesion / std::tan(p.friction * kDeg));
  const double a1 = bulk + 4.0 * shear / 3.0, a2 = bulk - 2.0 * shear / 3.0;
  const double fs = s1 - s3 * nphi + 2.0 * p.cohesion * rn;
  const double ft = st - s3;
  gamma = 0;
  if (fs >= 0 && ft >= 0) return false;
  // Which failure: the line h = 0 bisects shear and tension regions near the corner.
  const double alpha_p = std::sqrt(1 + nphi * nphi) + nphi;
  const double sigma_p = st * nphi - 2.0 * p.cohesion * rn;
  const double h = s3 - st + alpha_p * (s1 - sigma_p);
  if (fs < 0 && h <= 0) {
    const double ls = fs / ((a1 - a2 * npsi) - (a2 - a1 * npsi) * nphi);
    s1 -= ls * (a1 - a2 * npsi);
    s2 -= ls * a2 * (1 - npsi);
    s3 -= ls * (a2 - a1 * npsi);
    // Plastic principal strains de1 = ls, de3 = -ls Npsi.
    const double e1 = ls, e3 = -ls * npsi, em = (e1 + e3) / 3.0;
    gamma = std::sqrt(0.5 * (e1 - em) * (e1 - em) + 0.5 * em * em + 0.5 * (e3 - em) * (e3 - em));
    state |= kShearNow | kShearPast;
  } else {
    const double lt = ft / a1;
    s1 += lt * a2;
    s2 += lt * a2;
    s3 += lt * a1;
    state |= kTensionNow | kTensionPast;
  }
  return true;
}
}  // namespace

// Mohr-Coulomb's Nphi, its root and the tensile strength capped at the cone's apex, for the
// strength last asked on this thread (a material's constants; a softening zone's change).
struct ConeConstants {
  double friction = -1, cohesion = -1, tension = -1;
  double nphi = 1, rn = 1, st = 0;
};
const ConeConstants& cone_constants(const Strength& p) {
  thread_local ConeConstants c;
  if (p.friction != c.friction || p.cohesion != c.cohesion || p.tension != c.tension) {
    const double sphi = std::sin(p.friction * kDeg);
    c = {p.friction, p.cohesion, p.tension, (1 + sphi) / (1 - sphi), 0.0, p.tension};
    c.rn = std::sqrt(c.nphi);
    if (sphi > 0) c.st = std::min(c.st, p.cohesion / std::tan(p.friction * kDeg));
  }
  return c;
}

// Whether a 3D stress is surely inside Mohr-Coulomb's surface, by a margin of 1e-6 of the
// stress's size: first from bounds on the principal stresses (mean q, deviator size r: each
// within 2r of q, the extreme two within 2 sqrt(3) r of each other), then from the extreme
// principal stresses in closed form (the trigonometric roots of the characteristic cubic). The
// margin is twenty-five times the closed form's worst error (where two roots meet, acos loses
// half the digits: about 4e-8 of r), so a zone inside by it is elastic in the exact
// decomposition too, and skipping that leaves the results unchanged; nearer zones take the
// full path.
bool surely_elastic(const Strength& p, const ZoneStress& s) {
  const ConeConstants& k = cone_constants(p);
  const double q = (s.xx + s.yy + s.zz) / 3.0;
  const double off = s.xy * s.xy + s.yz * s.yz + s.xz * s.xz;
  const double dx = s.xx - q, dy = s.yy - q, dz = s.zz - q;
  const double r = std::sqrt((dx * dx + dy * dy + dz * dz + 2.0 * off) / 6.0);
  const double margin = 1e-6 * (std::abs(q) + r + p.cohesion * k.rn + std::abs(k.st));
  const double cap = 2.0 * p.cohesion * k.rn, need = margin * (1.0 + k.nphi);
  // fs = s1 - s3 Nphi + cap = (s1 - s3) - s3 (Nphi - 1) + cap, ft = st - s3.
  if (k.nphi >= 1.0 && -2.0 * std::sqrt(3.0) * r - (q + 2.0 * r) * (k.nphi - 1.0) + cap > need &&
      k.st - (q + 2.0 * r) > margin)
    return true;
  double lo = q, hi = q;
  if (r > 0.0) {
    const double det = dx * (dy * dz - s.yz * s.yz) - s.xy * (s.xy * dz - s.yz * s.xz) +
                       s.xz * (s.xy * s.yz - dy * s.xz);
    const double phi = std::acos(std::clamp(0.5 * det / (r * r * r), -1.0, 1.0)) / 3.0;
    hi = q + 2.0 * r * std::cos(phi);
    lo = q + 2.0 * r * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
  }
  return lo - hi * k.nphi + cap > need && k.st - hi > margin;
}

// When z is a principal direction (every 2D zone, in plane strain) the principal stresses are
// the plane's two in closed form and zz; otherwise the symmetric tensor's eigen-decomposition,
// unless the stress is surely elastic. The correction keeps the principal directions.
bool mohr_coulomb_correct(double bulk, double shear, const Strength& st, ZoneStress& s,
                          uint8_t& state, double* shear_strain) {
  double gamma = 0;
  if (s.yz != 0 || s.xz != 0) {
    if (surely_elastic(st, s)) return false;
    const Principal pr = principal_3d(s);
    std::array<double, 3> v = pr.s;
    if (!mohr_coulomb_return(bulk, shear, st, v[0], v[1], v[2], state, gamma)) return false;
    s = from_principal(pr, v);
    if (shear_strain) *shear_strain = gamma;
    return true;
  }
  // Principal stresses: two in the plane, zz out of it.
  double a = 0, b = 0, angle = 0;
  principal_2d(s, a, b, angle);
  std::array<double, 3> sig{a, b, s.zz};
  std::array<int, 3> order{0, 1, 2};  // which of (a, b, zz) is s1, s2, s3
  std::sort(order.begin(), order.end(), [&](int i, int j) { return sig[i] < sig[j]; });
  double s1 = sig[order[0]], s2 = sig[order[1]], s3 = sig[order[2]];
  if (!mohr_coulomb_return(bulk, shear, st, s1, s2, s3, state, gamma)) return false;
  // Back to x, y: the in-plane principal directions are unchanged.
  std::array<double, 3> out{};
  out[order[0]] = s1, out[order[1]] = s2, out[order[2]] = s3;
  const double c = std::cos(angle), sn = std::sin(angle);
  s.xx = out[0] * c * c + out[1] * sn * sn;
  s.yy = out[0] * sn * sn + out[1] * c * c;
  s.xy = (out[0] - out[1]) * c * sn;
  s.zz = out[2];
  if (shear_strain) *shear_strain = gamma;
  return true;
}

}  // namespace zone_law

namespace {

void elastic_step(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s) {
  zone_law::elastic_step(p.bulk, p.shear, de, s);
}

class NullModel final : public ZoneModel {
 public:
  const char* name() const override { return "null"; }
  void update(const ZoneProperties&, const StrainIncrement&, ZoneStress& s,
              uint8_t& state) const override {
    s = ZoneStress{};
    state = 0;
  }
  bool solid() const override { return false; }
};

class ElasticModel final : public ZoneModel {
 public:
  const char* name() const override { return "elastic"; }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    elastic_step(p, de, s);
    state &= kShearPast | kTensionPast;
  }
};

// Mohr-Coulomb with tension cut-off.
class MohrCoulombModel final : public ZoneModel {
 public:
  const char* name() const override { return "mohr-coulomb"; }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    state &= kShearPast | kTensionPast;
    elastic_step(p, de, s);
    zone_law::mohr_coulomb_correct(p.bulk, p.shear, {p.friction, p.cohesion, p.tension, p.dilation},
                                   s, state);
  }
};

// Drucker-Prager (FLAC's form): fs = tau + q_phi sigma - k_phi with tau = sqrt(J2) and sigma
// the mean stress; matched to Mohr-Coulomb in plane strain with associated flow
// (q = 3 tan(phi) / sqrt(9 + 12 tan^2 phi), k = 3c / sqrt(9 + 12 tan^2 phi): the textbook
// sqrt(J2) = alpha I1 + k with I1 = 3 sigma); tension cut-off on the mean stress.
class DruckerPragerModel final : public ZoneModel {
 public:
  const char* name() const override { return "drucker-prager"; }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    state &= kShearPast | kTensionPast;
    elastic_step(p, de, s);
    const double tphi = std::tan(p.friction * kDeg), tpsi = std::tan(p.dilation * kDeg);
    const double qphi = 3 * tphi / std::sqrt(9 + 12 * tphi * tphi);
    const double kphi = 3 * p.cohesion / std::sqrt(9 + 12 * tphi * tphi);
    const double qpsi = 3 * tpsi / std::sqrt(9 + 12 * tpsi * tpsi);
    const double mean = (s.xx + s.yy + s.zz) / 3.0;
    const double dx = s.xx - mean, dy = s.yy - mean, dz = s.zz - mean;
    const double tau =
        std::sqrt(0.5 * (dx * dx + dy * dy + dz * dz) + s.xy * s.xy + s.yz * s.yz + s.xz * s.xz);
    double st = p.tension;
    if (qphi > 0) st = std::min(st, kphi / qphi);
    const double fs = tau + qphi * mean - kphi;
    const double ft = mean - st;
    if (fs <= 0 && ft <= 0) return;
    const double tau_p = kphi - qphi * st;
    const double alpha_p = std::sqrt(1 + qphi * qphi) - qphi;
    const double h = tau - tau_p - alpha_p * (mean - st);
    double new_mean = mean, scale = 1.0;
    if (fs > 0 && h > 0) {
      const double lambda = fs / (p.shear + p.bulk * qphi * qpsi);
      new_mean = mean - p.bulk * qpsi * lambda;
      scale = tau > 0 ? std::max(0.0, (tau - p.shear * lambda) / tau) : 0.0;
      state |= kShearNow | kShearPast;
    } else {
      new_mean = st;
      state |= kTensionNow | kTensionPast;
    }
    s.xx = new_mean + scale * dx;
    s.yy = new_mean + scale * dy;
    s.zz = new_mean + scale * dz;
    s.xy *= scale, s.yz *= scale, s.xz *= scale;
  }
};

const NullModel kNull;
const ElasticModel kElastic;
const MohrCoulombModel kMohrCoulomb;
const DruckerPragerModel kDruckerPrager;

// The built-in models (those of other files through their accessors, made on first use).
const std::array<const ZoneModel*, 7>& models() {
  static const std::array<const ZoneModel*, 7> all{&kNull,
                                                   &kElastic,
                                                   &kMohrCoulomb,
                                                   &kDruckerPrager,
                                                   &zone_law::softening_model(),
                                                   &zone_law::ubiquitous_model(),
                                                   &zone_law::anisotropic_model()};
  return all;
}
}  // namespace

void principal_2d(const ZoneStress& s, double& s1, double& s2, double& angle) {
  const double c = 0.5 * (s.xx + s.yy), r = std::hypot(0.5 * (s.xx - s.yy), s.xy);
  s1 = c - r, s2 = c + r;
  // Direction of s1 (the smaller, most compressive).
  angle = 0.5 * std::atan2(-2.0 * s.xy, -(s.xx - s.yy));
}

Principal principal_3d(const ZoneStress& s) {
  Eigen::Matrix3d m;
  m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);  // ascending eigenvalues
  Principal p;
  for (int i = 0; i < 3; ++i) {
    p.s[static_cast<size_t>(i)] = eig.eigenvalues()[i];
    for (int k = 0; k < 3; ++k)
      p.axes[static_cast<size_t>(i)][static_cast<size_t>(k)] = eig.eigenvectors()(k, i);
  }
  return p;
}

ZoneStress from_principal(const Principal& p, const std::array<double, 3>& s) {
  // sigma = sum_i s_i a_i a_i^T
  auto part = [&](int r, int c) {
    double v = 0;
    for (size_t i = 0; i < 3; ++i)
      v += s[i] * p.axes[i][static_cast<size_t>(r)] * p.axes[i][static_cast<size_t>(c)];
    return v;
  };
  return {part(0, 0), part(1, 1), part(0, 1), part(2, 2), part(1, 2), part(0, 2)};
}

const ZoneModel* find_zone_model(const std::string& name) {
  for (const ZoneModel* m : models())
    if (name == m->name()) return m;
  return plugin_zone_model(name);
}

std::vector<std::string> zone_model_names() {
  std::vector<std::string> names;
  for (const ZoneModel* m : models()) names.emplace_back(m->name());
  for (std::string& n : plugin_law_names(true)) names.push_back(std::move(n));
  return names;
}

void elastic_from_young(double young, double poisson, double& bulk, double& shear) {
  if (!(young > 0)) throw std::invalid_argument("Young's modulus must be positive");
  if (!(poisson > -1.0 && poisson < 0.5))
    throw std::invalid_argument("Poisson's ratio must be between -1 and 0.5");
  bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  shear = young / (2.0 * (1.0 + poisson));
}

void ZoneProperties::finalize() {
  impl = find_zone_model(model);
  if (!impl) throw std::invalid_argument("'" + model + "' is not a zone model");
  if (!impl->solid()) return;
  if (!(density > 0)) throw std::invalid_argument("zone material '" + name + "' needs a density");
  const bool anisotropic = model == "transversely-isotropic";
  if (anisotropic) zone_law::anisotropic_stiffness(*this);
  if (!(bulk > 0 && shear > 0)) {
    std::ostringstream msg;
    msg << "elastic constants must be positive (bulk modulus K " << bulk << " Pa, shear modulus G "
        << shear << " Pa)";
    throw std::invalid_argument(msg.str());
  }
  const bool softening = model == "strain-softening", ubiquitous = model == "ubiquitous-joint";
  if (model == "mohr-coulomb" || model == "drucker-prager" || softening || ubiquitous) {
    if (!(friction >= 0 && friction < 90) || !(dilation >= 0 && dilation <= friction))
      throw std::invalid_argument("zone material '" + name +
                                  "': friction in [0, 90) and dilation in [0, friction] degrees");
    if (cohesion < 0 || tension < 0)
      throw std::invalid_argument("zone material '" + name +
                                  "': cohesion and tension cannot be negative");
  }
  if (softening) zone_law::check_tables(*this);
  if (ubiquitous) {
    if (!(jfriction >= 0 && jfriction < 90) || !(jdilation >= 0 && jdilation <= jfriction))
      throw std::invalid_argument(
          "zone material '" + name +
          "': jfriction in [0, 90) and jdilation in [0, jfriction] degrees");
    if (jcohesion < 0 || jtension < 0)
      throw std::invalid_argument("zone material '" + name +
                                  "': jcohesion and jtension cannot be negative");
  }
  if (ubiquitous || anisotropic) normal = zone_law::plane_axes(*this)[2];
}

}  // namespace tessera
