// The colour ramp, palette and contact-state colours.
#include "tessera/ui/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace tessera::ui {

Rgb ramp(double t) {
  static constexpr std::array<std::array<double, 3>, 5> stops{{{0.10, 0.20, 0.85},
                                                               {0.00, 0.75, 0.90},
                                                               {0.20, 0.80, 0.20},
                                                               {0.98, 0.85, 0.10},
                                                               {0.85, 0.10, 0.10}}};
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
  const size_t i = std::min(static_cast<size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(i);
  auto mix = [&](int k) {
    const double v = stops[i][k] + f * (stops[i + 1][k] - stops[i][k]);
    return static_cast<uint8_t>(std::lround(255.0 * v));
  };
  return {mix(0), mix(1), mix(2)};
}

Rgb category(int n) {
  static constexpr std::array<Rgb, 10> palette{{{190, 170, 140},
                                                {120, 150, 190},
                                                {200, 130, 90},
                                                {140, 180, 120},
                                                {180, 140, 190},
                                                {210, 190, 100},
                                                {120, 180, 180},
                                                {200, 150, 160},
                                                {160, 160, 160},
                                                {150, 120, 100}}};
  if (n < 0) return {200, 200, 200};
  return palette[static_cast<size_t>(n) % palette.size()];
}

Rgb open_colour() {
  return {150, 150, 150};
}
Rgb elastic_colour() {
  return {20, 40, 140};
}
Rgb slipping_colour() {
  return {220, 20, 20};
}
Rgb bonded_colour() {
  return {20, 120, 40};
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::vector<double> round_ticks(double lo, double hi, int about) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  const double raw = (hi - lo) / std::max(1, about);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * p;
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return ticks;
}

std::string tick_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace tessera::ui
