// Cross-reference checks of the model's arrays, run after each cycle when validation is on.
#include <cmath>

#include "core/validation.hpp"
#include "tessera/contact2d/detection.hpp"

namespace tessera {

void validate2d(const Model& m) {
  const Blocks& B = m.blocks;
  const Contacts& C = m.contacts;
  const size_t n = B.size();
  for (auto* v : {&B.y, &B.theta, &B.vx, &B.vy, &B.omega, &B.mass, &B.inertia})
    require(v->size() == n, "block array sizes differ");
  require(B.vert_begin.size() == n + 1, "vertex offsets do not match the block count");
  for (size_t b = 0; b < n; ++b) {
    require(B.vertex_count(b) >= 3, "block", B.id[b], "has fewer than 3 vertices");
    require(std::isfinite(B.x[b]) && std::isfinite(B.y[b]) && std::isfinite(B.theta[b]), "block",
            B.id[b], "position is not finite");
  }
  require(C.pair_begin.front() == 0 && C.pair_begin.back() == C.size(),
          "interface ranges do not cover the contacts");
  for (size_t p = 0; p < C.pair_count(); ++p)
    for (uint32_t i = C.pair_begin[p]; i < C.pair_begin[p + 1]; ++i)
      require(std::min(C.a[i], C.b[i]) == std::min(C.a[C.pair_begin[p]], C.b[C.pair_begin[p]]) &&
                  std::max(C.a[i], C.b[i]) == std::max(C.a[C.pair_begin[p]], C.b[C.pair_begin[p]]),
              "contact", i, "is outside its interface range");
  for (size_t i = 0; i < C.size(); ++i) {
    require(C.a[i] < n && C.b[i] < n && C.a[i] != C.b[i], "contact", i, "names a wrong block");
    require(C.corner[i] >= B.vert_begin[C.a[i]] && C.corner[i] < B.vert_begin[C.a[i] + 1],
            "contact", i, "corner is not a vertex of its owner");
    if (C.kind[i] != kLost)
      require(C.feature[i] >= B.vert_begin[C.b[i]] && C.feature[i] < B.vert_begin[C.b[i] + 1],
              "contact", i, "faces a feature of another block");
    require(C.joint[i] < m.joints.size(), "contact", i, "has no joint properties");
    require(std::isfinite(C.force(i).x()) && std::isfinite(C.force(i).y()), "contact", i,
            "force is not finite");
  }
  const std::string lists = m.block_contacts_problem();
  require(lists.empty(), lists.c_str());
}

}  // namespace tessera
