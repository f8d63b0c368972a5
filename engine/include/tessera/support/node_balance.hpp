// The out-of-balance of support nodes (cables', liners') in the cycle just run, for the model's
// unbalanced-force ratio: without it, blocks at rest would call the model solved while the
// support's nodes still creep (a cable's grout holding a block its segments, at their cap,
// cannot hold: block and nodes slide on together, the nodes' share unbalanced).
#pragma once

#include <algorithm>
#include <cstddef>

namespace tessera {

struct NodeBalance {
  double max_unbalanced = 0.0, load = 0.0;
  size_t nodes = 0;
  void clear() { *this = NodeBalance{}; }
  // A free node's unbalanced force and the sum of the magnitudes of the forces it carries.
  void add(double unbalanced, double carried) {
    max_unbalanced = std::max(max_unbalanced, unbalanced), load += carried, ++nodes;
  }
  // The largest unbalanced force over the mean force a node carries (0 when none carries any).
  double ratio() const {
    return load > 0.0 ? max_unbalanced * static_cast<double>(nodes) / load : 0.0;
  }
};

}  // namespace tessera
