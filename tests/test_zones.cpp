// Zone constitutive models (elastic, Mohr-Coulomb, Drucker-Prager, null) and zoning of block
// outlines and polyhedra: returns land on the yield surface, plastic flow follows the dilation
// angle, triangles and tetrahedra tile the block exactly.
#include <Eigen/Dense>
#include <QtTest>
#include <atomic>
#include <cmath>
#include <numbers>

#include "tessera/zones/continuum.hpp"
#include "tessera/zones/zone_model.hpp"
#include "tessera/zones/zoning.hpp"
#include "tessera/zones/zoning3.hpp"

using namespace tessera;

namespace {
ZoneProperties material(const std::string& model, double phi = 30, double c = 1e6, double t = 0.5e6,
                        double psi = 0) {
  ZoneProperties p;
  p.name = "rock";
  p.model = model;
  p.density = 2500;
  elastic_from_young(10e9, 0.25, p.bulk, p.shear);
  p.friction = phi, p.cohesion = c, p.tension = t, p.dilation = psi;
  p.finalize();
  return p;
}

// Principal stresses s1 <= s2 <= s3 of a plane-strain stress.
std::array<double, 3> principal(const ZoneStress& s) {
  double a, b, angle;
  principal_2d(s, a, b, angle);
  std::array<double, 3> v{a, b, s.zz};
  std::sort(v.begin(), v.end());
  return v;
}

double nphi(double deg) {
  const double s = std::sin(deg * std::numbers::pi / 180);
  return (1 + s) / (1 - s);
}
}  // namespace

class TestZones : public QObject {
  Q_OBJECT
 private slots:
  void elasticConstants() {
    double k, g;
    elastic_from_young(10e9, 0.25, k, g);
    QVERIFY(std::abs(k - 10e9 / 1.5) < 1.0 && std::abs(g - 4e9) < 1.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, elastic_from_young(1e9, 0.5, k, g));
    ZoneProperties p;
    p.model = "mohr-colomb";
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, p.finalize());
  }

  // Constrained (plane strain, one-dimensional) loading: sxx = M exx, syy = szz = lambda exx.
  void elasticUniaxialStrain() {
    const ZoneProperties p = material("elastic");
    ZoneStress s;
    uint8_t state = 0;
    p.impl->update(p, {-1e-4, 0, 0}, s, state);
    const double m = p.bulk + 4 * p.shear / 3, l = p.bulk - 2 * p.shear / 3;
    QVERIFY(std::abs(s.xx + m * 1e-4) < 1e-6 * m * 1e-4);
    QVERIFY(std::abs(s.yy + l * 1e-4) < 1e-6 * m * 1e-4);
    QCOMPARE(s.zz, s.yy);
    QCOMPARE(state, uint8_t(0));
  }

  // Compressing in y from an isotropic stress: once yielding, every step ends on the shear
  // line s1 = s3 Nphi - 2c sqrt(Nphi), and the plastic strain ratio is -Npsi (flow rule).
  void mohrCoulombReturnsToTheSurface() {
    for (double psi : {0.0, 10.0}) {
      const ZoneProperties p = material("mohr-coulomb", 30, 1e6, 0.5e6, psi);
      ZoneStress s{-2e6, -2e6, 0, -2e6};
      uint8_t state = 0;
      bool yielded = false;
      for (int i = 0; i < 200; ++i) {
        const StrainIncrement de{0.2e-5, -1e-5, 0.1e-5};
        ZoneStress trial = s;
        uint8_t ignored = 0;
        material("elastic").impl->update(p, de, trial, ignored);
        p.impl->update(p, de, s, state);
        const auto v = principal(s);
        const double fs = v[0] - v[2] * nphi(30) + 2 * 1e6 * std::sqrt(nphi(30));
        QVERIFY2(fs > -1e-6 * 1e6, qPrintable(QString("fs = %1").arg(fs)));  // never outside
        if (!(state & kShearNow)) continue;
        yielded = true;
        QVERIFY(std::abs(fs) < 1e-6 * 1e6);
        // Plastic strain from the correction (trial - returned), in principal axes of the trial.
        const auto t = principal(trial);
        const double a1 = p.bulk + 4 * p.shear / 3, a2 = p.bulk - 2 * p.shear / 3;
        Eigen::Matrix3d d;
        d << a1, a2, a2, a2, a1, a2, a2, a2, a1;
        const Eigen::Vector3d ep =
            d.inverse() * Eigen::Vector3d(t[0] - v[0], t[1] - v[1], t[2] - v[2]);
        QVERIFY(std::abs(ep[1]) < 1e-9 * std::abs(ep[0]));
        QVERIFY(std::abs(ep[2] / ep[0] + nphi(psi)) < 1e-6);
      }
      QVERIFY(yielded && (state & kShearPast));
    }
  }

  // Stretching: the largest principal stress is held at the tensile strength.
  void mohrCoulombTensionCutOff() {
    const ZoneProperties p = material("mohr-coulomb", 30, 1e6, 0.5e6);
    ZoneStress s;
    uint8_t state = 0;
    for (int i = 0; i < 50; ++i) p.impl->update(p, {1e-5, 0, 0}, s, state);
    QVERIFY(std::abs(principal(s)[2] - 0.5e6) < 1.0);
    QVERIFY(state & kTensionNow);
    // Unloading is elastic again: "now" clears, "past" stays.
    p.impl->update(p, {-1e-6, 0, 0}, s, state);
    QVERIFY(!(state & kTensionNow) && (state & kTensionPast));
  }

  void druckerPragerReturnsToTheSurface() {
    const ZoneProperties p = material("drucker-prager", 30, 1e6, 0.5e6);
    const double tp = std::tan(30 * std::numbers::pi / 180), r = std::sqrt(9 + 12 * tp * tp);
    ZoneStress s{-2e6, -2e6, 0, -2e6};
    uint8_t state = 0;
    for (int i = 0; i < 200; ++i) p.impl->update(p, {0.3e-5, -1e-5, 0}, s, state);
    QVERIFY2(state & kShearNow, qPrintable(QString("state %1 stress %2 %3 %4 %5")
                                               .arg(state)
                                               .arg(s.xx)
                                               .arg(s.yy)
                                               .arg(s.xy)
                                               .arg(s.zz)));
    const double mean = (s.xx + s.yy + s.zz) / 3;
    const double dx = s.xx - mean, dy = s.yy - mean, dz = s.zz - mean;
    const double tau = std::sqrt(0.5 * (dx * dx + dy * dy + dz * dz) + s.xy * s.xy);
    QVERIFY(std::abs(tau + 3 * tp / r * mean - 3 * 1e6 / r) < 1e-6 * 1e6);
  }

  // Stretched equally in x and y, Drucker-Prager holds the mean stress at the tensile strength.
  void druckerPragerTensionCutOff() {
    const ZoneProperties p = material("drucker-prager", 30, 1e6, 0.5e6);
    ZoneStress s;
    uint8_t state = 0;
    for (int i = 0; i < 50; ++i) p.impl->update(p, {1e-5, 1e-5, 0}, s, state);
    QVERIFY(std::abs((s.xx + s.yy + s.zz) / 3 - 0.5e6) < 1.0);
    QVERIFY(state & kTensionNow);
  }

  // One law code for both dimensions: a loading path applied in the plane (z principal: the
  // 2D, closed-form principal axes) and the same path seen in a rotated frame (all six
  // components: the 3D eigen-decomposition) give the same stresses and states, for every model,
  // through elastic loading, shear yield with dilation and tension cut-off.
  void lawsAreTheSameInAnyFrame() {
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                               Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    auto tensor = [](double xx, double yy, double zz, double xy, double yz, double xz) {
      Eigen::Matrix3d m;
      m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
      return m;
    };
    auto of = [&](const ZoneStress& s) { return tensor(s.xx, s.yy, s.zz, s.xy, s.yz, s.xz); };
    auto rotated = [&](const Eigen::Matrix3d& m) { return Eigen::Matrix3d(r * m * r.transpose()); };
    for (const char* model : {"elastic", "mohr-coulomb", "drucker-prager"}) {
      const ZoneProperties p = material(model, 30, 1e6, 0.5e6, 10);
      ZoneStress plane{-2e6, -2e6, 0, -2e6}, turned;
      {
        const Eigen::Matrix3d t = rotated(of(plane));
        turned = {t(0, 0), t(1, 1), t(0, 1), t(2, 2), t(1, 2), t(0, 2)};
      }
      uint8_t state_plane = 0, state_turned = 0;
      int yielded = 0;
      // Compression in y, then stretching in x and y (towards the tension cut-off).
      for (int i = 0; i < 400; ++i) {
        const StrainIncrement de = i < 200 ? StrainIncrement{0.2e-5, -1e-5, 0.1e-5}
                                           : StrainIncrement{1e-5, 0.6e-5, -0.05e-5};
        const Eigen::Matrix3d e = rotated(tensor(de.xx, de.yy, 0, de.xy, 0, 0));
        p.impl->update(p, de, plane, state_plane);
        p.impl->update(p, {e(0, 0), e(1, 1), e(0, 1), e(2, 2), e(1, 2), e(0, 2)}, turned,
                       state_turned);
        const double err = (rotated(of(plane)) - of(turned)).norm();
        QVERIFY2(err < 1e-6 * of(plane).norm(),
                 qPrintable(QString("%1, step %2: %3").arg(model).arg(i).arg(err)));
        QCOMPARE(state_turned, state_plane);
        if (state_plane & (kShearNow | kTensionNow)) ++yielded;
      }
      QVERIFY2((std::string(model) == "elastic") == (yielded == 0), model);
    }
  }

  void nullZonesCarryNothing() {
    ZoneProperties p;
    p.model = "null";
    p.finalize();
    ZoneStress s{1, 2, 3, 4};
    uint8_t state = kShearPast;
    p.impl->update(p, {1, 1, 1}, s, state);
    QVERIFY(s.xx == 0 && s.yy == 0 && s.xy == 0 && s.zz == 0 && !p.impl->solid());
  }

  // Zones tile the outline: areas add up, sizes and angles as asked, corners kept, the same
  // mesh every time.
  void zoningTilesTheBlock() {
    const std::vector<Vec2> l_shape{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}};
    const ZoneMesh m = zone_polygon(l_shape, 0.2);
    double area = 0;
    for (const auto& t : m.triangles) {
      const double a = 0.5 * cross(m.nodes[t[1]] - m.nodes[t[0]], m.nodes[t[2]] - m.nodes[t[0]]);
      QVERIFY(a > 0);
      area += a;
      // No zone outside the L (the notch at x > 1, y > 1).
      const Vec2 c = (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]]) / 3.0;
      QVERIFY(!(c.x() > 1 && c.y() > 1));
    }
    QVERIFY(std::abs(area - 4.0) < 1e-12);
    QVERIFY(m.max_edge <= 0.2 + 1e-9);
    QVERIFY2(m.min_angle >= 20.0, qPrintable(QString::number(m.min_angle)));
    for (const Vec2& corner : l_shape) {
      const auto it = std::find_if(m.nodes.begin(), m.nodes.end(),
                                   [&](const Vec2& n) { return (n - corner).norm() < 1e-12; });
      QVERIFY(it != m.nodes.end() && m.on_boundary[size_t(it - m.nodes.begin())]);
    }
    size_t boundary = 0;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
      const Vec2& n = m.nodes[i];
      const bool on = std::abs(n.x()) < 1e-9 || std::abs(n.y()) < 1e-9 ||
                      std::abs(n.x() - 3) < 1e-9 || std::abs(n.y() - 2) < 1e-9 ||
                      (std::abs(n.x() - 1) < 1e-9 && n.y() >= 1) ||
                      (std::abs(n.y() - 1) < 1e-9 && n.x() >= 1);
      QCOMPARE(bool(m.on_boundary[i]), on);
      boundary += on;
    }
    QVERIFY(boundary >= 50);  // perimeter 10 in edges of at most 0.2
    const ZoneMesh again = zone_polygon(l_shape, 0.2);
    QVERIFY(again.nodes == m.nodes && again.triangles == m.triangles);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, zone_polygon(l_shape, 1e-5, 100000));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             zone_polygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0.1));  // clockwise
  }

  // Tetrahedra tile a concave block (an L prism of two convex pieces): volumes positive and
  // adding up, none in the notch, corners kept, surface nodes on the faces and no others there
  // (the face between the pieces is inside), quality and size as asked, the same mesh every
  // time; graded zones finer near the centre; bad blocks refused.
  void tetrahedraTileTheBlock() {
    const std::vector<Eigen::Vector2d> l_shape{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}};
    const Polyhedron block = prism(l_shape, 0, 1);
    const std::vector<Polyhedron> pieces{prism({{0, 0}, {3, 0}, {3, 1}, {0, 1}}, 0, 1),
                                         prism({{0, 1}, {1, 1}, {1, 2}, {0, 2}}, 0, 1)};
    const double h = 0.25;
    const ZoneMesh3 m = zone_pieces(pieces, h);
    double volume = 0;
    for (const auto& t : m.tets) {
      const std::array<Vec3, 4> p{m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]};
      const double v = (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) / 6.0;
      QVERIFY(v > 0);
      volume += v;
      const Vec3 c = (p[0] + p[1] + p[2] + p[3]) / 4.0;
      QVERIFY(!(c.x() > 1 && c.y() > 1));
    }
    qInfo("%zu tetrahedra, %zu nodes, smallest dihedral %.1f degrees, longest edge %.3f",
          m.tets.size(), m.nodes.size(), m.min_dihedral, m.max_edge);
    QVERIFY(std::abs(volume - 4.0) < 1e-9);
    QVERIFY(m.max_edge <= 2 * h);  // circumradius at most h
    QVERIFY(static_cast<double>(m.tets.size()) > 4.0 / (h * h * h / (6 * std::numbers::sqrt2)) / 2);
    QVERIFY2(m.min_dihedral >= 10.0, qPrintable(QString::number(m.min_dihedral)));
    for (const Vec3& corner : block.vertices) {
      const auto it = std::find_if(m.nodes.begin(), m.nodes.end(),
                                   [&](const Vec3& n) { return (n - corner).norm() < 1e-12; });
      QVERIFY(it != m.nodes.end() && m.on_boundary[size_t(it - m.nodes.begin())]);
    }
    size_t boundary = 0;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
      const Vec3& n = m.nodes[i];
      auto at = [](double a, double b) { return std::abs(a - b) < 1e-9; };
      const bool on = at(n.x(), 0) || at(n.y(), 0) || at(n.x(), 3) || at(n.y(), 2) ||
                      at(n.z(), 0) || at(n.z(), 1) || (at(n.x(), 1) && n.y() >= 1) ||
                      (at(n.y(), 1) && n.x() >= 1);
      QCOMPARE(bool(m.on_boundary[i]), on);
      boundary += on;
    }
    QVERIFY(boundary >= 200);  // surface 18 in triangles of edges at most 2h
    QCOMPARE(min_dihedral_angle({Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)}),
             std::acos(1.0 / 3.0) * 180 / std::numbers::pi);  // the regular tetrahedron's
    const ZoneMesh3 again = zone_pieces(pieces, h);
    QVERIFY(again.nodes == m.nodes && again.tets == m.tets);
    // Graded: edges of 0.2 within 0.5 of a corner of a 4 m cube, growing by 0.5 per metre to 1.
    const ZoneGrading3 grade{Vec3::Zero(), 0.5, 0.2, 0.5};
    const ZoneMesh3 g = zone_pieces({box(Vec3::Zero(), Vec3(4, 4, 4))}, 1.0, 2000000, &grade);
    double near = 0, far = 0;
    int n_near = 0, n_far = 0;
    for (const auto& t : g.tets) {
      const Vec3 c = (g.nodes[t[0]] + g.nodes[t[1]] + g.nodes[t[2]] + g.nodes[t[3]]) / 4.0;
      const double edge = (g.nodes[t[0]] - g.nodes[t[1]]).norm();
      if (c.norm() < 0.7) near += edge, ++n_near;
      if (c.norm() > 3.5) far += edge, ++n_far;
    }
    qInfo("graded: %zu tetrahedra, mean edge %.2f near the corner, %.2f far from it", g.tets.size(),
          near / n_near, far / n_far);
    QVERIFY(n_near > 10 && n_far > 10 && near / n_near < 0.4 && far / n_far > 0.6);
    // Refused: too many zones, faces turned inside out, a surface with a hole.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, zone_pieces(pieces, 1e-3, 100000));
    Polyhedron inverted = pieces[0], open = pieces[0];
    for (auto& f : inverted.faces) std::reverse(f.begin(), f.end());
    open.faces.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, zone_pieces({inverted}, h));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, zone_pieces({open}, h));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, zone_pieces(pieces, 0.0));
  }

  // A plate thinner than its zones (1.5 x 0.05 x 1 m at 0.5 m) is filled: the mesher refines
  // across the thickness, every surface triangle lies in a face of the plate and the volumes add
  // up. (Meshed from their surface, plates 5 cm thick left cells across the thickness out, and
  // zoning failed: "a surface triangle of its zones lies on no face".)
  void thinPlateIsFilled() {
    const ZoneMesh3 m = zone_pieces({box(Vec3::Zero(), Vec3(1.5, 0.05, 1))}, 0.5);
    double volume = 0;
    for (const auto& t : m.tets)
      volume += (m.nodes[t[1]] - m.nodes[t[0]])
                    .cross(m.nodes[t[2]] - m.nodes[t[0]])
                    .dot(m.nodes[t[3]] - m.nodes[t[0]]) /
                6.0;
    int off_faces = 0;
    for (const auto& f : boundary_faces(m)) {
      const Vec3 c = (m.nodes[f[0]] + m.nodes[f[1]] + m.nodes[f[2]]) / 3.0;
      const auto at = [](double a, double b) { return std::abs(a - b) < 1e-12; };
      const bool flat_x = at(m.nodes[f[0]].x(), m.nodes[f[1]].x()) &&
                          at(m.nodes[f[0]].x(), m.nodes[f[2]].x()),
                 flat_y = at(m.nodes[f[0]].y(), m.nodes[f[1]].y()) &&
                          at(m.nodes[f[0]].y(), m.nodes[f[2]].y()),
                 flat_z = at(m.nodes[f[0]].z(), m.nodes[f[1]].z()) &&
                          at(m.nodes[f[0]].z(), m.nodes[f[2]].z());
      const bool on = (flat_x && (at(c.x(), 0) || at(c.x(), 1.5))) ||
                      (flat_y && (at(c.y(), 0) || at(c.y(), 0.05))) ||
                      (flat_z && (at(c.z(), 0) || at(c.z(), 1)));
      off_faces += !on;
    }
    qInfo("%zu tetrahedra, smallest dihedral %.2f degrees, %zu under 5", m.tets.size(),
          m.min_dihedral, m.poor);
    QCOMPARE(off_faces, 0);
    QVERIFY(std::abs(volume - 0.075) < 1e-12);
  }

  // A stop flag set while meshing (a signal, the window's Stop) ends the mesher by
  // ZoningStopped, a single block or a joined body, and leaves nothing behind: the same block
  // meshed afterwards is the same mesh as before.
  void meshingStopsOnItsFlag() {
    const Polyhedron block = box(Vec3::Zero(), Vec3(2, 1, 1));
    const ZoneMesh3 before = zone_pieces({block}, 0.3);
    std::atomic<bool> stop{true};
    const auto stopped = [&](const auto& mesh) {
      try {
        mesh();
      } catch (const ZoningStopped&) {
        return true;
      }
      return false;
    };
    QVERIFY(stopped([&] { zone_pieces({block}, 0.3, 2000000, nullptr, &stop); }));
    QVERIFY(stopped([&] {
      zone_pieces({box(Vec3::Zero(), Vec3(1, 1, 1)), box(Vec3(1, 0, 0), Vec3(2, 1, 1))}, 0.3,
                  2000000, nullptr, &stop);
    }));
    stop = false;
    const ZoneMesh3 after = zone_pieces({block}, 0.3, 2000000, nullptr, &stop);
    QVERIFY(after.nodes == before.nodes && after.tets == before.tets);
  }

  // A joined body (one 2 x 1 x 1 box on two unit boxes: the big one's bottom face meets both
  // small ones', a T where their shared face ends on it) as one conforming mesh: every zone in
  // one piece, each piece's zones filling its volume, nodes shared across the faces between
  // pieces (each face's zone faces on one side are the other side's), every piece's corners
  // nodes, the same mesh every time.
  void piecesMeshAsOneBody() {
    const std::vector<Polyhedron> pieces{box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                         box(Vec3(1, 0, 0), Vec3(2, 1, 1)),
                                         box(Vec3(0, 0, 1), Vec3(2, 1, 2))};
    const double h = 0.3;
    const ZoneMesh3 m = zone_pieces(pieces, h);
    QCOMPARE(m.piece.size(), m.tets.size());
    std::array<double, 3> volume{};
    for (size_t z = 0; z < m.tets.size(); ++z) {
      const auto& t = m.tets[z];
      const std::array<Vec3, 4> p{m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]};
      const double v = (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) / 6.0;
      QVERIFY(v > 0);
      QVERIFY(m.piece[z] < 3);
      QVERIFY(z == 0 || m.piece[z - 1] <= m.piece[z]);  // sorted by piece
      volume[m.piece[z]] += v;
      // The zone lies in its piece.
      const Vec3 c = (p[0] + p[1] + p[2] + p[3]) / 4.0;
      const Vec3 lo = pieces[m.piece[z]].vertices[0], hi = pieces[m.piece[z]].vertices[7];
      QVERIFY((c.array() > lo.array()).all() && (c.array() < hi.array()).all());
    }
    qInfo("%zu tetrahedra, %zu nodes, smallest dihedral %.1f degrees; volumes %.12f %.12f %.12f",
          m.tets.size(), m.nodes.size(), m.min_dihedral, volume[0], volume[1], volume[2]);
    QVERIFY(std::abs(volume[0] - 1) < 1e-9 && std::abs(volume[1] - 1) < 1e-9 &&
            std::abs(volume[2] - 2) < 1e-9);
    QVERIFY(m.min_dihedral >= 5.0);
    for (const Polyhedron& p : pieces)
      for (const Vec3& corner : p.vertices)
        QVERIFY(std::any_of(m.nodes.begin(), m.nodes.end(),
                            [&](const Vec3& n) { return (n - corner).norm() < 1e-9; }));
    // Zone faces on z = 1 seen from below and from above are the same triangles (conforming):
    // the faces of the pieces' zones there, as sorted node triples.
    const auto faces_on_z1 = [&](bool upper) {
      static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
      std::vector<std::array<uint32_t, 3>> out;
      for (size_t z = 0; z < m.tets.size(); ++z) {
        if ((m.piece[z] == 2) != upper) continue;
        for (const auto& f : kFace) {
          std::array<uint32_t, 3> tri{m.tets[z][f[0]], m.tets[z][f[1]], m.tets[z][f[2]]};
          if (std::all_of(tri.begin(), tri.end(),
                          [&](uint32_t n) { return std::abs(m.nodes[n].z() - 1) < 1e-9; })) {
            std::sort(tri.begin(), tri.end());
            out.push_back(tri);
          }
        }
      }
      std::sort(out.begin(), out.end());
      return out;
    };
    const auto below = faces_on_z1(false), above = faces_on_z1(true);
    QVERIFY(static_cast<double>(below.size()) >= 2 * 2 / (h * h));
    QVERIFY(below == above);
    const ZoneMesh3 again = zone_pieces(pieces, h);
    QVERIFY(again.nodes == m.nodes && again.tets == m.tets && again.piece == m.piece);
  }
};

QTEST_APPLESS_MAIN(TestZones)
#include "test_zones.moc"
