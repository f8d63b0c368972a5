// Colours for values and categories, shared by the VTK view and figures so both agree.
#pragma once

#include <cstdint>
#include <string>

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

}  // namespace tessera::ui
