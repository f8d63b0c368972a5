// Cross-reference checks of a 3D model's arrays, run after each cycle when validation is on.
#include <cmath>

#include "core/validation.hpp"
#include "tessera/core/model.hpp"

namespace tessera {

namespace {
bool finite(const Vec3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
}  // namespace

void validate3d(const Model& m) {
  const Blocks3& B = m.blocks3;
  const size_t n = B.size();
  require(B.omega.size() == n && B.force.size() == n && B.fixity.size() == n &&
              B.master.size() == n && B.id.size() == n && B.bound_radius.size() == n &&
              B.rotation.size() == n,
          "block array sizes differ");
  require(B.vert_begin.size() == n + 1 && B.face_begin.size() == n + 1,
          "vertex or face offsets do not match the block count");
  for (size_t b = 0; b < n; ++b) {
    require((B.rotation[b] - B.body_rotation(b)).cwiseAbs().maxCoeff() <= 1e-12, "block", B.id[b],
            "has a rotation that is not its body's");
    require(B.vert_begin[b + 1] - B.vert_begin[b] >= 4, "block", B.id[b],
            "has fewer than 4 vertices");
    require(B.face_begin[b + 1] - B.face_begin[b] >= 4, "block", B.id[b], "has fewer than 4 faces");
    require(B.master[b] >= 0 && static_cast<size_t>(B.master[b]) < n &&
                B.master[static_cast<size_t>(B.master[b])] == B.master[b],
            "block", B.id[b], "names a wrong master body");
    require(finite(B.body[b].position) && finite(B.body[b].velocity), "block", B.id[b],
            "position or velocity is not finite");
  }
  const auto& C = m.contacts3;
  for (size_t i = 0; i < C.size(); ++i) {
    const Contact3& c = C[i];
    require(c.a < c.b && c.b < n, "contact", i, "names a wrong block");
    require(i == 0 || std::make_pair(C[i - 1].a, C[i - 1].b) < std::make_pair(c.a, c.b), "contact",
            i, "is out of order");
    require(c.joint < m.joints.size(), "contact", i, "has no joint properties");
    require(c.face_a >= B.face_begin[c.a] && c.face_a < B.face_begin[c.a + 1] &&
                c.face_b >= B.face_begin[c.b] && c.face_b < B.face_begin[c.b + 1],
            "contact", i, "faces a face of another block");
    require(finite(c.force) && finite(c.torque_a) && finite(c.torque_b), "contact", i,
            "force is not finite");
    for (const SubContact& s : c.subs) {
      require(finite(s.local) && std::isfinite(s.area) && s.area >= 0.0 && finite(s.force),
              "contact", i, "has a sub-contact that is not finite");
      require(s.link >= -1 && s.link < static_cast<int64_t>(c.nodes.size()), "contact", i,
              "has a sub-contact whose node is not listed");
    }
  }
  const std::string lists = m.block_contacts_problem();
  require(lists.empty(), lists.c_str());
}

}  // namespace tessera
