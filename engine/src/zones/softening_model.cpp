// Strain-softening Mohr-Coulomb (FLAC's strain-softening model): Mohr-Coulomb's return with
// cohesion, friction, dilation and tension read from tables of the zone's accumulated plastic
// shear strain, taken at the start of each step and the strain added after the correction.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "zone_law.hpp"

namespace tessera {

double table_value(const std::vector<double>& table, double strain, double constant) {
  if (table.size() < 2) return constant;
  if (strain <= table[0]) return table[1];
  // The segment holding `strain`: linear between its ends.
  for (size_t k = 2; k + 1 < table.size(); k += 2)
    if (strain <= table[k]) {
      const double x0 = table[k - 2], y0 = table[k - 1], x1 = table[k], y1 = table[k + 1];
      return y0 + (y1 - y0) * (strain - x0) / (x1 - x0);
    }
  return table.back();
}

namespace zone_law {

void check_tables(const ZoneProperties& p) {
  const auto check = [&](const std::vector<double>& t, const char* key, bool angle) {
    const std::string what = "zone material '" + p.name + "': " + key;
    if (t.empty()) return;
    if (t.size() % 2 != 0 || t.size() < 2)
      throw std::invalid_argument(what + " needs pairs strain,value (" + std::to_string(t.size()) +
                                  " numbers given)");
    for (size_t k = 0; k < t.size(); k += 2) {
      if (!(t[k] >= 0)) throw std::invalid_argument(what + "'s plastic strains cannot be negative");
      if (k > 0 && !(t[k] > t[k - 2]))
        throw std::invalid_argument(what + "'s plastic strains must increase (" +
                                    std::to_string(t[k - 2]) + " then " + std::to_string(t[k]) +
                                    ")");
      if (!(t[k + 1] >= 0)) throw std::invalid_argument(what + "'s values cannot be negative");
      if (angle && !(t[k + 1] < 90))
        throw std::invalid_argument(what + "'s angles must be below 90 degrees");
    }
  };
  check(p.ctable, "ctable", false), check(p.ftable, "ftable", true);
  check(p.dtable, "dtable", true), check(p.ttable, "ttable", false);
}

namespace {
class SofteningModel final : public ZoneModel {
 public:
  const char* name() const override { return "strain-softening"; }
  // Without a history (a caller that keeps none): the strength at no plastic strain.
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s,
              uint8_t& state) const override {
    double history = 0;
    update(p, de, s, state, history);
  }
  void update(const ZoneProperties& p, const StrainIncrement& de, ZoneStress& s, uint8_t& state,
              double& history) const override {
    state &= kShearPast | kTensionPast;
    elastic_step(p.bulk, p.shear, de, s);
    // The strength at the plastic shear strain so far, then the strain of this correction.
    const Strength st{
        table_value(p.ftable, history, p.friction), table_value(p.ctable, history, p.cohesion),
        table_value(p.ttable, history, p.tension), table_value(p.dtable, history, p.dilation)};
    double gamma = 0;
    if (mohr_coulomb_correct(p.bulk, p.shear, st, s, state, &gamma)) history += gamma;
  }
};
}  // namespace

const ZoneModel& softening_model() {
  static const SofteningModel model;
  return model;
}

}  // namespace zone_law
}  // namespace tessera
