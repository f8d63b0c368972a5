#include "tessera/core/checks.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "tessera/contact2d/detection.hpp"
#include "tessera/contact3d/detection3.hpp"
#include "tessera/core/step.hpp"

namespace tessera {

std::string Finding::text() const {
  if (block == 0) return std::string(error ? "error: " : "warning: ") + message;
  char buf[128];
  if (three)
    std::snprintf(buf, sizeof buf,
                  "%s: block %d at (%.6g, %.6g, %.6g): ", error ? "error" : "warning", block,
                  where.x(), where.y(), where.z());
  else
    std::snprintf(buf, sizeof buf, "%s: block %d at (%.6g, %.6g): ", error ? "error" : "warning",
                  block, where.x(), where.y());
  return buf + message;
}

namespace {
// 3D models: blocks too small or too thin (3 volume / surface) for the contact tolerance, and
// overlapping blocks.
std::vector<Finding> check_geometry3(const Model& m, const CheckLimits& lim) {
  const Blocks3& B = m.blocks3;
  const double d = m.tolerance();
  const double min_volume = lim.min_area > 0.0 ? lim.min_area : 8.0 * d * d * d;
  const double min_thick = lim.min_thickness > 0.0 ? lim.min_thickness : d;
  std::vector<Finding> out;
  char buf[160];
  for (size_t b = 0; b < B.size(); ++b) {
    const Vec3& c = B.body[b].position;
    const double thickness = 3.0 * B.volume[b] / B.surface[b];
    if (B.volume[b] < min_volume) {
      std::snprintf(buf, sizeof buf, "volume %.3g is below the limit %.3g", B.volume[b],
                    min_volume);
      out.push_back({true, B.id[b], c, buf, true});
    } else if (thickness < min_thick) {
      std::snprintf(buf, sizeof buf, "thickness %.3g (3 volume / surface) is below the limit %.3g",
                    thickness, min_thick);
      out.push_back({false, B.id[b], c, buf, true});
    }
  }
  if (const std::string o = find_overlap3(m); !o.empty()) out.push_back({true, 0, {}, o, true});
  return out;
}
}  // namespace

std::vector<Finding> check_geometry(const Model& m, const CheckLimits& lim) {
  if (m.dim == 3) return check_geometry3(m, lim);
  const Blocks& B = m.blocks;
  const double d = m.settings.rounding;
  const double min_area = lim.min_area > 0.0 ? lim.min_area : 4.0 * d * d;
  const double min_thick = lim.min_thickness > 0.0 ? lim.min_thickness : d;
  std::vector<Finding> out;
  auto report = [&](bool error, size_t b, const std::string& msg) {
    out.push_back({error, B.id[b], Vec3(B.x[b], B.y[b], 0.0), msg});
  };
  char buf[160];
  for (size_t b = 0; b < B.size(); ++b) {
    const double thickness = 2.0 * B.area[b] / B.perimeter[b];
    if (B.area[b] < min_area) {
      std::snprintf(buf, sizeof buf, "area %.3g is below the limit %.3g", B.area[b], min_area);
      report(true, b, buf);
    } else if (thickness < min_thick) {
      std::snprintf(buf, sizeof buf, "thickness %.3g (2 area / perimeter) is below the limit %.3g",
                    thickness, min_thick);
      report(false, b, buf);
    }
    const uint32_t v0 = B.vert_begin[b], n = B.vertex_count(b);
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t v = v0 + k, prev = v0 + (k + n - 1) % n;
      if (B.edge_length[v] < 2.0 * d) {
        std::snprintf(buf, sizeof buf,
                      "edge %u is %.3g long, shorter than twice the rounding length %.3g", k + 1,
                      B.edge_length[v], d);
        report(false, b, buf);
      }
      // Interior angle at a convex corner.
      const Vec2 e1 = B.local_edge_dir[prev], e2 = B.local_edge_dir[v];
      const double turn = std::atan2(cross(e1, e2), e1.dot(e2)) * 180.0 / std::numbers::pi;
      if (B.convex[v] && 180.0 - turn < lim.min_angle) {
        std::snprintf(
            buf, sizeof buf,
            "corner %u has an interior angle of %.3g degrees, too sharp to round (limit %.3g)",
            k + 1, 180.0 - turn, lim.min_angle);
        report(false, b, buf);
      }
    }
  }
  if (const std::string o = find_overlap(m); !o.empty()) out.push_back({true, 0, {}, o});
  if (B.size() == 0 || m.joints.empty()) return out;
  // The contacts the first cycle starts from (no bonding side effects; the probe is thrown away).
  Model probe = m;
  probe.cycle = 1;
  try {
    detect_contacts(probe);
  } catch (const ModelError&) {
    return out;  // missing joint properties: the run itself will say so
  }
  // Overlap as the contacts see it: a corner deeper than the tolerance in another block starts
  // the run with a force of kn L times its depth, whatever the outlines say. The outline test
  // above and the contact geometry must agree; the deepest such contact is named.
  const Contacts& C = probe.contacts;
  const double tol = m.tolerance();
  size_t deepest = C.size();
  for (size_t i = 0; i < C.size(); ++i)
    if (C.kind[i] != kLost && C.gap[i] < -tol && (deepest == C.size() || C.gap[i] < C.gap[deepest]))
      deepest = i;
  if (deepest < C.size()) {
    const uint32_t a = C.a[deepest], b = C.b[deepest];
    char msg[320];
    std::snprintf(msg, sizeof msg,
                  "blocks %d and %d overlap by %.3g m at (%.6g, %.6g): corner %u of block %d is "
                  "that deep in block %d, more than the contact tolerance %.3g",
                  B.id[a], B.id[b], -C.gap[deepest], C.point[deepest].x(), C.point[deepest].y(),
                  C.corner[deepest] - B.vert_begin[a] + 1, B.id[a], B.id[b], tol);
    out.push_back({true, 0, {}, msg});
  }
  // Blocks that no chain of contacts joins to a fixed block fall under gravity.
  if (m.settings.gravity.norm() > 0.0) {
    std::vector<size_t> root(B.size());
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](size_t x) {
      while (root[x] != x) x = root[x] = root[root[x]];
      return x;
    };
    for (size_t i = 0; i < probe.contacts.size(); ++i)
      root[find(probe.contacts.a[i])] = find(probe.contacts.b[i]);
    // Bolts and cables hold what they join.
    const Reinforcement& R = m.support;
    for (size_t e = 0; e < R.size(); ++e)
      root[find(static_cast<size_t>(R.side_a[e].block))] =
          find(static_cast<size_t>(R.side_b[e].block));
    const Cables& K = m.cables;
    for (size_t i = 0; i + 1 < K.size(); ++i)
      if (K.cable[i] == K.cable[i + 1])
        root[find(static_cast<size_t>(K.host[i].block))] =
            find(static_cast<size_t>(K.host[i + 1].block));
    const Liners& L = m.liners;
    for (size_t i = 0; i + 1 < L.size(); ++i)
      if (L.liner[i] == L.liner[i + 1])
        root[find(static_cast<size_t>(L.host[i].block))] =
            find(static_cast<size_t>(L.host[i + 1].block));
    std::vector<uint8_t> held(B.size(), 0);
    for (size_t b = 0; b < B.size(); ++b)
      if (B.fixity[b] & (kFixX | kFixY)) held[find(b)] = 1;
    for (size_t b = 0; b < B.size(); ++b)
      if (!held[find(b)])
        report(false, b,
               "nothing holds it up: no chain of contacts or support reaches a fixed block");
  }
  return out;
}

}  // namespace tessera
