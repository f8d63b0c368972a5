// Colours for values and categories, shared by the VTK view and figures so both agree.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::ui {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

// Blue-cyan-green-yellow-red ramp (the rainbow rock engineers read from UDEC plots), t in [0, 1].
Rgb ramp(double t);
// Number of stops the VTK lookup table samples the ramp at.
constexpr int kRampSamples = 256;
// The n-th colour of a ten-colour categorical palette (groups, materials).
Rgb category(int n);
// Contact states.
Rgb open_colour();
Rgb elastic_colour();
Rgb slipping_colour();
Rgb bonded_colour();
// "#rrggbb".
std::string hex(Rgb c);
// Round values for a scale from lo to hi: multiples of 1, 2 or 5 times a power of ten, about
// `about` of them, all within [lo, hi]; and such a value as text ("0.25", "-1.5e+06").
std::vector<double> round_ticks(double lo, double hi, int about = 5);
std::string tick_text(double v);

}  // namespace tessera::ui
