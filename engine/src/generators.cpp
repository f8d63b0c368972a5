#include "tessera/generators.hpp"

namespace tessera {

size_t add_running_bond_wall(Model& m, const WallSpec& w) {
  const double rho = w.material >= 0 ? m.materials[static_cast<size_t>(w.material)].density : 0.0;
  const double L = w.brick_length, H = w.brick_height, width = L * w.bricks;
  size_t added = 0;
  for (int c = 0; c < w.courses; ++c) {
    const double y0 = w.origin.y() + H * c, y1 = y0 + H;
    // Joint positions along the course: staggered by half a brick on odd courses.
    std::vector<double> xs{0.0};
    for (int k = 0; k < w.bricks; ++k) xs.push_back(c % 2 ? L * (k + 0.5) : L * (k + 1));
    if (c % 2) xs.push_back(width);
    for (size_t k = 0; k + 1 < xs.size(); ++k) {
      const double x0 = w.origin.x() + xs[k], x1 = w.origin.x() + xs[k + 1];
      m.blocks.add({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, m.settings.rounding, rho, w.group,
                   w.material);
      ++added;
    }
  }
  m.touch();
  return added;
}

}  // namespace tessera
