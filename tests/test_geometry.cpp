// Polygon mass properties, validity checks and corner rounding.
#include <QtTest>
#include <cmath>
#include <numbers>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/core/geometry.hpp"

using namespace tessera;

class TestGeometry : public QObject {
  Q_OBJECT
 private slots:
  void rectangleProperties() {
    const std::vector<Vec2> r{{1, 2}, {4, 2}, {4, 4}, {1, 4}};
    const auto p = polygon_properties(r);
    QCOMPARE(p.area, 6.0);
    QVERIFY((p.centroid - Vec2(2.5, 3)).norm() < 1e-12);
    // Polar moment of a b x h rectangle: b h (b^2 + h^2) / 12.
    QVERIFY(std::abs(p.polar_moment - 3 * 2 * (9 + 4) / 12.0) < 1e-12);
  }
  void triangleCentroidFarFromOrigin() {
    const std::vector<Vec2> t{{1e6, 1e6}, {1e6 + 3, 1e6}, {1e6, 1e6 + 3}};
    const auto p = polygon_properties(t);
    QVERIFY(std::abs(p.area - 4.5) < 1e-6);
    QVERIFY((p.centroid - Vec2(1e6 + 1, 1e6 + 1)).norm() < 1e-6);
  }
  void concaveLShape() {
    // L of three unit squares: area 3, centroid at (5/6, 5/6).
    const std::vector<Vec2> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const auto p = polygon_properties(l);
    QVERIFY(std::abs(p.area - 3) < 1e-12);
    QVERIFY((p.centroid - Vec2(5.0 / 6, 5.0 / 6)).norm() < 1e-12);
    const auto c = round_corners(l, 0.1);
    QVERIFY(c[0].convex && !c[3].convex);
  }
  void problemsAreNamed() {
    QVERIFY(polygon_problem({{0, 0}, {1, 0}}).find("at least 3") != std::string::npos);
    QVERIFY(polygon_problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).find("coincide") !=
            std::string::npos);
    QVERIFY(polygon_problem({{0, 0}, {1, 1}, {1, 0}, {0, 1}}).find("cross") != std::string::npos);
    QVERIFY(polygon_problem({{0, 0}, {1, 0}, {2, 0}}).find("no area") != std::string::npos);
    QVERIFY(polygon_problem({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).empty());
  }
  void roundingOfRightAndSharpCorners() {
    const auto sq = round_corners({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1);
    QVERIFY(std::abs(sq[0].radius - 0.1) < 1e-12);
    QVERIFY((sq[0].centre - Vec2(0.1, 0.1)).norm() < 1e-12);
    // Equilateral triangle: interior 60 degrees, radius = d tan(30 deg).
    const double h = std::sqrt(3.0) / 2;
    const auto tri = round_corners({{0, 0}, {1, 0}, {0.5, h}}, 0.1);
    QVERIFY(std::abs(tri[0].radius - 0.1 * std::tan(std::numbers::pi / 6)) < 1e-12);
    // The arc touches both edges: its centre is one radius from each.
    QVERIFY(std::abs(tri[0].centre.y() - tri[0].radius) < 1e-12);
  }
  void roundingLimitedByShortEdges() {
    const auto c = round_corners({{0, 0}, {0.1, 0}, {0.1, 1}, {0, 1}}, 0.5);
    QVERIFY(std::abs(c[0].length - 0.045) < 1e-12);
  }
  void blockMassFromDensity() {
    Blocks b;
    b.add({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.01, 2500, -1, -1);
    QCOMPARE(b.mass[0], 5000.0);
    QVERIFY(std::abs(b.inertia[0] - 5000 * (4 + 1) / 12.0) < 1e-9);
    b.theta[0] = std::numbers::pi / 2;
    b.update_world(0);
    // A quarter turn about the centroid (1, 0.5) takes corner (0,0) to (1.5, -0.5).
    QVERIFY((b.world_vertex[0] - Vec2(1.5, -0.5)).norm() < 1e-12);
  }
};

QTEST_APPLESS_MAIN(TestGeometry)
#include "test_geometry.moc"
