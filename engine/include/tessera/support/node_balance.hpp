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
  // An unbalanced force within the node's round-off (its stiffness times the model's round-off
  // length: positions known to round-off give forces known to that) counts as none, so that
  // support carrying nothing is solved rather than judged by its noise over its noise.
  void add(double unbalanced, double carried, double noise) {
    if (unbalanced > noise) max_unbalanced = std::max(max_unbalanced, unbalanced);
    load += carried, ++nodes;
  }
  // The largest unbalanced force over the mean force a node carries, or over the blocks' mean
  // applied force if that is larger (support lightly loaded in a loaded model); 0 when none
  // is unbalanced.
  double ratio(double block_mean_applied) const {
    const double mean =
        std::max(nodes ? load / static_cast<double>(nodes) : 0.0, block_mean_applied);
    return max_unbalanced > 0.0 && mean > 0.0 ? max_unbalanced / mean : 0.0;
  }
};

}  // namespace tessera
