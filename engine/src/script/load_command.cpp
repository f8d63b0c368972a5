// The 'load' command: constant forces and moments at the centroids of rigid blocks (2D and 3D),
// like gravity a load every cycle; a table (table=NAME) scales them in time.
#include <algorithm>
#include <cmath>
#include <string>

#include "tessera/script/script.hpp"

namespace tessera {

void Interpreter::cmd_load(Args& a) {
  const auto sel = select(a);
  const bool three = model_.dim == 3;
  // The components given are set; the others keep their value.
  const char* keys3[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  const char* keys2[] = {"fx", "fy", "moment"};
  double value[6] = {};
  bool has[6] = {};
  const int count = three ? 6 : 3;
  bool any = false;
  for (int k = 0; k < count; ++k)
    any |= has[k] = take_num(a, three ? keys3[k] : keys2[k], value[k]);
  done(a);
  if (!any)
    fail(three ? "'load' needs fx=, fy=, fz= (N) or mx=, my=, mz= (N m)"
               : "'load' needs fx=, fy= (N/m) or moment= (N m/m)");
  for (int k = 0; k < count; ++k)
    if (has[k] && !std::isfinite(value[k])) fail("the load's values must be finite");
  const auto& deformable = three ? model_.blocks3.deformable : model_.blocks.deformable;
  const auto& id = three ? model_.blocks3.id : model_.blocks.id;
  for (size_t b : sel)
    if (deformable[b])
      fail("block " + std::to_string(id[b]) +
           " is deformable: load its nodes ('boundary stress', or set_node_force from Python)");
  if (!three) {
    Blocks& B = model_.blocks;
    for (size_t b : sel) {
      if (has[0]) B.load_fx[b] = value[0];
      if (has[1]) B.load_fy[b] = value[1];
      if (has[2]) B.load_m[b] = value[2];
    }
    return;
  }
  // A piece of a joined body: the load acts on the body, at its centroid.
  Blocks3& B = model_.blocks3;
  std::vector<size_t> bodies;
  for (size_t b : sel) bodies.push_back(static_cast<size_t>(B.master[b]));
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  for (size_t b : bodies)
    for (int k = 0; k < 3; ++k) {
      if (has[k]) B.load_force[b][k] = value[k];
      if (has[k + 3]) B.load_moment[b][k] = value[k + 3];
    }
}

}  // namespace tessera
