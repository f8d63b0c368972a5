// The desktop window under Xvfb: runs on the worker thread while the event loop goes on, pixels
// of the rendered view, figure export, and a bad command leaving the model as it was.
#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <algorithm>
#include <thread>

#include "tessera/core/step.hpp"
#include "tessera/script/script.hpp"
#include "tessera/ui/colour_map.hpp"
#include "tessera/ui/command_dialog.hpp"
#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/figure_writer.hpp"
#include "tessera/ui/history_charts.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/model_tree.hpp"
#include "tessera/ui/scene.hpp"
#include "tessera/ui/stage_panel.hpp"
#include "tessera/ui/vtk_view.hpp"

using namespace tessera;
using namespace tessera::ui;

namespace {
// Two blocks side by side in groups left and right, resting on a fixed base (group base).
const char* kTwoBlocks = R"(title "Two blocks"
round 0.005
material define stone density=2500
joint define dry kn=1e9 ks=1e9 friction=30
joint assign dry
block 0,0 4,0 4,1 0,1 group=base material=stone
fix group=base
block 0,1 1.9,1 1.9,3 0,3 group=left material=stone
block 2.1,1 4,1 4,3 2.1,3 group=right material=stone
gravity 0 -9.81
history ydisp block=2
history ratio
history interval 10
)";

// Waits for the window's current command to end; returns whether it succeeded.
bool wait_finished(MainWindow& w, int timeout_ms = 60000) {
  QSignalSpy spy(&w, &MainWindow::commandFinished);
  if (!w.busy()) return true;
  if (!spy.wait(timeout_ms)) return false;
  return spy.takeFirst().at(0).toBool();
}

// Writes a script into the test folder; returns its path (empty if it cannot be written).
QString write_script(const QTemporaryDir& dir, const QString& name, const char* text) {
  const QString path = dir.filePath(name);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(text) < 0) return {};
  return path;
}

// The colour of a framebuffer grab at a model point.
QColor pixel_at(VtkView* view, const QImage& img, double x, double y) {
  const QPoint p = view->pixelOf({x, y});
  const double r = img.devicePixelRatio();
  return img.pixelColor(int(p.x() * r), int(p.y() * r));
}

// Shows the window, opens a script in it and waits until the script has run; false if any
// step fails.
bool open_shown(MainWindow& w, const QString& path) {
  w.show();
  if (!QTest::qWaitForWindowExposed(&w)) return false;
  w.openScript(path);
  return wait_finished(w);
}

// Whether scale values are round: equally spaced by 1, 2 or 5 times a power of ten, each a
// multiple of that step (at least three of them).
bool round_values(const std::vector<double>& t) {
  if (t.size() < 3) return false;
  const double step = t[1] - t[0];
  const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  bool ok = std::abs(m - 1) < 1e-6 || std::abs(m - 2) < 1e-6 || std::abs(m - 5) < 1e-6;
  for (double v : t) ok = ok && std::abs(v / step - std::round(v / step)) < 1e-6;
  return ok;
}

// Opens a script in the window, fits the model and lets it draw; false if the script fails.
bool open_fitted(MainWindow& w, const QString& path) {
  if (!open_shown(w, path)) return false;
  w.view()->resetCamera();
  QTest::qWait(100);
  return true;
}

// The pixels of a frame's model area (right of the 3D triad, left of the colour bars) whose
// colour passes a test.
template <class Is>
std::vector<QPoint> model_pixels(const QImage& img, Is is) {
  std::vector<QPoint> at;
  for (int y = 0; y < img.height(); ++y)
    for (int x = img.width() * 15 / 100; x < img.width() * 8 / 10; ++x)
      if (is(img.pixelColor(x, y))) at.push_back({x, y});
  return at;
}

// Blue-grey: the second group's colour (120,150,190), shaded.
bool blue_grey(const QColor& c) {
  return c.saturation() >= 40 && c.blue() > c.red() + 30;
}

// Orange: the third group's colour (200,130,90), shaded.
bool orange(const QColor& c) {
  return c.saturation() >= 40 && c.red() > c.blue() + 60 && c.red() > c.green() + 35;
}

// The rows of an image from the first to the last holding at least two pixels of a colour
// between columns x0 and x1 (0 if none).
template <class Is>
int rows_spanned(const QImage& img, int x0, int x1, Is is) {
  int first = -1, last = -2;
  for (int y = 0; y < img.height(); ++y) {
    int n = 0;
    for (int x = x0; x < x1; ++x) n += is(img.pixelColor(x, y));
    if (n >= 2) last = y, first = first < 0 ? y : first;
  }
  return last - first + 1;
}

// A wall with a block behind it (seen from the south, the wall hides it).
const char* kWallAndHidden =
    "dimension 3\nmaterial define rock density=2500\n"
    "block box 0,20,0 10,22,10 material=rock group=wall\n"
    "block box 4,24,4 5,25,5 material=rock group=hidden\n";

bool close_to(QColor c, Rgb expected, int tol = 12) {
  return std::abs(c.red() - expected.r) <= tol && std::abs(c.green() - expected.g) <= tol &&
         std::abs(c.blue() - expected.b) <= tol;
}
}  // namespace

class TestGui : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString script_;

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    script_ = dir_.filePath("two_blocks.tess");
    QFile f(script_);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kTwoBlocks);
  }

  // An example opens and runs in the window: its script's step ends, histories are charted.
  void opensAnExample() {
    const QString copy = dir_.filePath("block_on_incline.tess");
    QVERIFY(QFile::copy(QString(TESSERA_EXAMPLES) + "/block_on_incline.tess", copy));
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.openScript(copy);
    QVERIFY(w.busy());
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
    QCOMPARE(w.snapshot()->cycle, uint64_t(8000));
    QCOMPARE(w.charts()->chartCount(), 3);
    // A chart exports for a spreadsheet (the points shown) and for a report (PNG, SVG).
    const QString csv = dir_.filePath("chart.csv"), png = dir_.filePath("chart.png"),
                  svg = dir_.filePath("chart.svg");
    QVERIFY(w.charts()->exportChart(0, csv));
    QFile table(csv);
    QVERIFY(table.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList rows = QString::fromUtf8(table.readAll()).trimmed().split('\n');
    QCOMPARE(rows.size(), w.charts()->pointCount(0) + 1);
    QCOMPARE(rows[0], QString("cycle,xvel_2 [m/s]"));
    // Each y axis names its quantity and unit.
    QCOMPARE(w.charts()->yTitle(0), QString("xvel [m/s]"));
    QCOMPARE(w.charts()->yTitle(2), QString("time [s]"));
    // A chart enlarged in a window of its own, and one history against another (x-y): the
    // x velocity against time, point for point.
    QVERIFY(w.charts()->enlarge(0));
    QCOMPARE(w.charts()->windowCount(), 1);
    QCOMPARE(w.charts()->windowPoints(0).size(), w.charts()->pointCount(0));
    QDialog* xy = w.charts()->plotAgainst(0, 2);
    QVERIFY(xy);
    QCOMPARE(w.charts()->windowCount(), 2);
    const QList<QPointF> against = w.charts()->windowPoints(1),
                         in_cycles = w.charts()->windowPoints(0);
    QCOMPARE(against.size(), in_cycles.size());
    const double dt = w.snapshot()->dt;
    for (qsizetype k = 0; k < against.size(); ++k) {
      QCOMPARE(against[k].y(), in_cycles[k].y());
      QVERIFY(std::abs(against[k].x() - in_cycles[k].x() * dt) < 1e-6 * (1 + against[k].x()));
    }
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      xy->grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/history_xy.png");
    xy->close();
    QTRY_COMPARE(w.charts()->windowCount(), 1);
    QVERIFY(w.charts()->exportChart(0, png));
    const QImage chart(png);
    QVERIFY(chart.width() >= 800 && chart.height() >= 500);
    int drawn = 0;
    for (int y = 0; y < chart.height(); y += 5)
      for (int x = 0; x < chart.width(); x += 5) drawn += chart.pixel(x, y) != qRgb(255, 255, 255);
    QVERIFY(drawn > 200);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      chart.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/history_chart.png");
    QVERIFY(w.charts()->exportChart(0, svg));
    QVERIFY(QSvgRenderer(svg).isValid());
    QVERIFY(!w.charts()->exportChart(0, dir_.filePath("chart.txt")));
    QVERIFY(w.windowTitle().contains("block_on_incline.tess"));
    // The free block slid down the slope: the tree lists its stage, the picture its motion.
    QCOMPARE(w.snapshot()->stages.size(), size_t(1));
    QVERIFY(w.snapshot()->blocks[1].x < w.snapshot()->blocks[1].x_ref - 0.1);
    // Its output goes beside the script, as in batch (vtk interval 2000: 4 snapshots).
    QVERIFY(QDir(dir_.filePath("block_on_incline_out/vtk")).entryList({"*.vtp"}).size() >= 4);
  }

  // Colour-bar labels are round numbers within the range (the window's and the figures' legends
  // both use round_ticks), and one spike does not wash out the contact-force colours: they run
  // to the 98th percentile, and the caption names the largest.
  void scalesAreRoundAndRobust() {
    QCOMPARE(round_ticks(-3.38, 21.5), (std::vector<double>{0, 5, 10, 15, 20}));
    QCOMPARE(round_ticks(0, 1).size(), size_t(6));  // 0, 0.2 ... 1
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
             {-2.61e-06, 3.4e-07}, {1.33, 42.2}, {-7.3e6, -1.1e6}, {0.004, 0.0041}}) {
      const std::vector<double> t = round_ticks(lo, hi);
      QVERIFY2(t.size() >= 3 && t.size() <= 6, qPrintable(QString::number(t.size())));
      QVERIFY(round_values(t));
      const double step = t[1] - t[0];
      for (double v : t) QVERIFY(v >= lo - 1e-9 * step && v <= hi + 1e-9 * step);
    }
    QCOMPARE(tick_text(-2.5e-06), std::string("-2.5e-06"));
    QCOMPARE(tick_text(0.6000000000000001), std::string("0.6"));
    Snapshot s;
    s.lo = Vec2(0, 0), s.hi = Vec2(10, 10);
    for (int i = 0; i < 200; ++i) {
      SnapshotContact c;
      c.point = c.from = c.to = Vec2(0.05 * i, 1);
      c.normal = Vec2(0, 1);
      c.length = 0.05;
      c.flags = kTouching;
      c.fn = i == 7 ? 5.1e8 : 1e6;
      s.contacts.push_back(c);
    }
    ViewOptions o;
    o.contacts = ContactShow::kStress;
    const Scene scene = build_scene(s, o);
    // Normal stresses (MPa): 1e6 N/m on 0.05 m is 20 MPa.
    QCOMPARE(scene.contacts_legend.hi, 20.0);
    QVERIFY(scene.contacts_legend.clipped);
    QVERIFY2(scene.caption.find("largest 1.02e+04") != std::string::npos, scene.caption.c_str());
    QCOMPARE(scene.bars[0].colour, ramp(1.0));  // the ordinary contacts at the top of the scale
  }

  // A liner ring carrying nothing in fixed rock: its caption counts its 26 nodes (not the
  // closing point again: it said 27), none at a capacity, and the nodes open from the rock are
  // drawn elastic and counted as open (they were drawn orange, "yielding"; an independent check).
  void unloadedLinerIsNotYielding() {
    Interpreter in(dir_.filePath("liner_out").toStdString());
    int n = 0;
    for (const char* line :
         {"round 0.01", "material define rock density=2500",
          "joint define j kn=1e10 ks=1e10 friction=30", "joint assign j",
          "region -5,-5 5,5 group=rock material=rock",
          "tunnel circle centre=0,0 radius=1 segments=24 name=t group=t", "delete group=t",
          "fix all", "liner joints=t e=25e9 nu=0.2 thickness=0.2 kn=1e10 ks=1e10 name=L",
          "step 50"})
      in.execute(line, "test", ++n);
    const Model& m = in.model();
    size_t open = 0;
    for (size_t i = 0; i < m.liners.size(); ++i) open += (m.liners.state[i] & kLinerOpen) != 0;
    const Scene scene = build_scene(make_snapshot(m, "", {}), ViewOptions{});
    const std::string want =
        "0 of 26 nodes at a capacity or slipping, " + std::to_string(open) + " open from the rock";
    QVERIFY2(scene.caption.find(want) != std::string::npos, scene.caption.c_str());
    QVERIFY(open > 0);
    int drawn = 0;
    for (const SceneBar& bar : scene.bars)
      if (bar.support >= 0) {
        QCOMPARE(bar.colour, (Rgb{170, 0, 170}));
        ++drawn;
      }
    QCOMPARE(drawn, 26);  // the ring's elements
  }

  // After excavation the opening is empty in the window, as in the batch figures: the pixels at
  // the tunnel's centre and around it, within the radius, are background. The axes are labelled
  // at round values, and the model, zoomed in, stays out of the colour bar's margin.
  // A symmetric jack arch (four voussoirs between fixed skewbacks) is drawn symmetric: the
  // bars are as wide at either end of mirror-image joints. Bars showed each contact's force,
  // and the two corners meeting at one end of a joint share its length (which one makes the
  // contacts depends on the blocks' order), so one joint read as evenly loaded and its mirror
  // as thrust at the extrados (an independent check). Widths now show the normal stress.
  void symmetricArchIsDrawnSymmetric() {
    Interpreter in(dir_.filePath("jack_out").toStdString());
    int n = 0;
    for (const char* line : {"round 0.002", "material define stone density=2000",
                             "joint define dry kn=1e10 ks=1e10 friction=40", "joint assign dry",
                             "block 0,0 0.5,0 0.4425,0.3 -0.15,0.3 group=s material=stone",
                             "block 0.5,0 1,0 1,0.3 0.4425,0.3 group=s material=stone",
                             "block 1,0 1.5,0 1.5575,0.3 1,0.3 group=s material=stone",
                             "block 1.5,0 2,0 2.15,0.3 1.5575,0.3 group=s material=stone",
                             "block -1,-0.5 0,-0.5 0,0 -0.15,0.3 -1,0.3 group=abut material=stone",
                             "block 2,-0.5 3,-0.5 3,0.3 2.15,0.3 2,0 group=abut material=stone",
                             "fix group=abut", "gravity 0 -9.81", "solve ratio=1e-7 cycles=60000"})
      in.execute(line, "test", ++n);
    ViewOptions o;
    o.contacts = ContactShow::kStress;
    const Scene scene = build_scene(make_snapshot(in.model(), "", {}), o);
    // The width of the bar over height y on the joint near x (its midpoint within 0.1 of x).
    const auto width_at = [&](double x, double y) {
      double w = -1.0;
      for (const SceneBar& b : scene.bars) {
        const Vec2 p = 0.5 * (b.corners[0] + b.corners[3]), q = 0.5 * (b.corners[1] + b.corners[2]);
        if (std::abs(0.5 * (p.x() + q.x()) - x) < 0.1 && std::min(p.y(), q.y()) <= y &&
            y <= std::max(p.y(), q.y()))
          w = std::max(w, (b.corners[3] - b.corners[0]).norm());
      }
      return w;
    };
    for (const double y : {0.03, 0.27}) {
      const double left = width_at(0.47, y), right = width_at(1.53, y);
      qInfo("at y = %.2f: %.4g and %.4g", y, left, right);
      QVERIFY(left > 0 && right > 0);
      QVERIFY(std::abs(left / right - 1.0) < 0.1);
    }
    // Thrust at the extrados: wider bars at the top of these joints than at their foot.
    QVERIFY(width_at(0.47, 0.27) > 1.5 * width_at(0.47, 0.03));
  }
  void excavatedOpeningIsEmpty() {
    const QString copy = dir_.filePath("tunnel_jointed.tess");
    QVERIFY(QFile::copy(QString(TESSERA_EXAMPLES) + "/tunnel_jointed.tess", copy));
    MainWindow w;
    QVERIFY(open_fitted(w, copy));
    const QImage img = w.view()->grabFramebuffer();
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      img.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/tunnel_jointed.png");
    int filled = 0;
    for (double r : {0.0, 1.0, 2.0, 2.5})
      for (int k = 0; k < 12; ++k) {
        const double t = k * M_PI / 6;
        const QColor c = pixel_at(w.view(), img, 20 + r * std::cos(t), 20 + r * std::sin(t));
        filled += c != QColor(255, 255, 255);
        if (r == 0) break;
      }
    QCOMPARE(filled, 0);
    // The axes are labelled at round values, and zoomed in on the opening the colour bar's
    // margin stays clear of the model (no rock pixel right of the model's viewport).
    QVERIFY(round_values(w.view()->xTicks()) && round_values(w.view()->yTicks()));
    QCOMPARE(w.view()->xTicks().front(), 0.0);
    QCOMPARE(w.view()->xTicks().back(), 40.0);
    const QPoint centre = w.view()->pixelOf({20, 20});
    for (int i = 0; i < 4; ++i) {
      QWheelEvent wheel(centre, w.view()->mapToGlobal(centre), {}, {0, 120}, Qt::NoButton,
                        Qt::NoModifier, Qt::NoScrollPhase, false);
      QApplication::sendEvent(w.view(), &wheel);
    }
    QTest::qWait(100);
    const QImage zoomed = w.view()->grabFramebuffer();
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      zoomed.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/tunnel_jointed_zoomed.png");
    const Rgb rock = category(0);
    int covered = 0;
    // The strips either side of the colour bar (which shows the rock's colour as its swatch).
    for (int y = 0; y < zoomed.height(); y += 3)
      for (int x = zoomed.width() * 785 / 1000; x < zoomed.width(); x += 3) {
        if (x > zoomed.width() * 80 / 100 && x < zoomed.width() * 975 / 1000) continue;
        const QColor c = zoomed.pixelColor(x, y);
        covered += std::abs(c.red() - rock.r) < 8 && std::abs(c.green() - rock.g) < 8 &&
                   std::abs(c.blue() - rock.b) < 8;
      }
    QCOMPARE(covered, 0);
    QVERIFY(round_values(w.view()->xTicks()) &&
            w.view()->xTicks().back() - w.view()->xTicks().front() < 30);
  }

  // The solve runs on the worker: the event loop (a timer) keeps going during it; stop ends it at
  // a cycle boundary and the model can be stepped on.
  void runsOnWorkerThread() {
    MainWindow w;
    QVERIFY(open_shown(w, script_));
    QVERIFY(w.snapshot());
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    // The UI thread keeps handling events while the solver cycles: a timer on it sees the
    // snapshot's cycle count grow from tick to tick (a blocked loop would see one value), and
    // the snapshots are made on another thread. No clock is read: a busy machine only slows it.
    std::vector<uint64_t> seen_cycles;
    QTimer timer;
    connect(&timer, &QTimer::timeout, [&] {
      const uint64_t c = w.snapshot()->cycle;
      if (seen_cycles.empty() || c > seen_cycles.back()) seen_cycles.push_back(c);
    });
    timer.start(10);
    w.step(100000000);
    QVERIFY(w.busy());
    QTRY_VERIFY_WITH_TIMEOUT(seen_cycles.size() >= 4, 120000);
    timer.stop();
    QVERIFY(w.busy());
    QVERIFY(w.snapshot()->made_on != std::this_thread::get_id());
    const uint64_t seen = w.snapshot()->cycle;
    w.stopRun();
    QVERIFY(wait_finished(w));
    QVERIFY(seen > 0);
    const uint64_t stopped_at = w.snapshot()->cycle;
    QVERIFY(stopped_at > 0 && stopped_at < 100000000);
    QVERIFY(w.charts()->chartCount() == 2 && w.charts()->pointCount(0) > 2);
    // A consistent model: it steps on from where it stopped.
    w.step(10);
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->cycle, stopped_at + 10);
    QVERIFY(w.console()->text().contains("stopped"));
  }

  // Pause holds the solver between cycles; resume lets it go on.
  void pauseHoldsTheSolver() {
    MainWindow w;
    w.show();
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    w.step(100000000);
    QTRY_VERIFY_WITH_TIMEOUT(w.snapshot()->cycle > 0, 60000);
    // Paused, the solver publishes the cycle it holds at and waits: nothing moves after it.
    w.setPaused(true);
    QTRY_VERIFY_WITH_TIMEOUT(w.snapshot()->held, 60000);
    const uint64_t a = w.snapshot()->cycle;
    QTest::qWait(300);
    QCOMPARE(w.snapshot()->cycle, a);
    QVERIFY(w.snapshot()->held && w.busy());
    w.setPaused(false);
    QTRY_VERIFY_WITH_TIMEOUT(w.snapshot()->cycle > a, 60000);
    w.stopRun();
    QVERIFY(wait_finished(w));
  }

  // The view draws each group in its palette colour at the blocks' centres, white outside.
  void framebufferShowsGroupColours() {
    MainWindow w;
    QVERIFY(open_shown(w, script_));
    ViewOptions o;
    o.colour = ColourBy::kGroup;
    o.contacts = ContactShow::kOff;
    w.setViewOptions(o);
    w.view()->resetCamera();
    QTest::qWait(100);
    const QImage img = w.view()->grabFramebuffer();
    QVERIFY(!img.isNull() && img.width() > 100);
    const auto pixel = [&](double x, double y) { return pixel_at(w.view(), img, x, y); };
    // Groups in order of first use: base 0, left 1, right 2.
    QVERIFY2(close_to(pixel(2.0, 0.5), category(0)), qPrintable(pixel(2.0, 0.5).name()));
    QVERIFY2(close_to(pixel(0.95, 2.0), category(1)), qPrintable(pixel(0.95, 2.0).name()));
    QVERIFY2(close_to(pixel(3.05, 2.0), category(2)), qPrintable(pixel(3.05, 2.0).name()));
    QVERIFY(close_to(pixel(2.0, 2.0), Rgb{255, 255, 255}));  // the gap between the blocks
    // Coloured by displacement after a run, the picture changes.
    w.step(200);
    QVERIFY(wait_finished(w));
    o.colour = ColourBy::kDisplacement;
    w.setViewOptions(o);
    QTest::qWait(100);
    const QImage img2 = w.view()->grabFramebuffer();
    QVERIFY(img2 != img);
    // Screenshots for a person to look at, when asked for.
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS")) {
      const QString at = qEnvironmentVariable("TESSERA_TEST_SHOTS");
      img.save(at + "/view_groups.png");
      w.grab().save(at + "/window.png");
    }
    // Picking the left block shows its values.
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({0.95, 2.0}));
    QCOMPARE(w.properties()->heading(), QString("block 2"));
    QCOMPARE(w.properties()->value("group"), QString("left"));
  }

  // A 3D model in the window: the projected faces drawn with their group colours (shaded), a
  // right drag turns the viewpoint and the picture, a click picks the nearest block.
  // A snapshot the solver takes at a progress report, while the 3D cycle lets the vertices of
  // blocks without contacts lag, draws every face where its block is: a falling cube's corners
  // are the body's pose applied to its shape.
  void midRunSnapshotDrawsBlocksWhereTheyAre() {
    const QString path =
        write_script(dir_, "midrun.tess",
                     "dimension 3\ntolerance 0.005\nmaterial define rock density=2500\n"
                     "joint define j kn=1e9 ks=1e9 friction=40\njoint assign j\n"
                     "block box 0,0,-1 1,1,0 material=rock\nfix block=1\n"
                     "block box 0,0,0.5 1,1,1.5 material=rock\ngravity 0 0 -10\n");
    Interpreter in(dir_.filePath("midrun_out").toStdString());
    in.run_file(path.toStdString());
    Model& m = in.model();
    prepare(m);
    std::shared_ptr<Snapshot> snap;
    double centroid = 0.0;
    run_cycles(
        m, 40,
        [&](const Model& now) {
          if (now.cycle != 30) return true;
          snap = std::make_shared<Snapshot>(make_snapshot(now, "", {}));
          centroid = now.blocks3.body[1].position.z();
          return true;
        },
        1);
    QVERIFY(snap);
    // The cube's top in the snapshot against its centroid then; it has fallen far more than that.
    double z_top = -1e300;
    for (const Snapshot::Face3& f : snap->faces3)
      if (f.block == 1)
        for (uint32_t k = f.begin; k < f.end; ++k) z_top = std::max(z_top, snap->points3[k].z());
    qInfo("top at %.9f m, centroid %.9f m", z_top, centroid);
    QVERIFY(1.0 - centroid > 1e-5);
    QVERIFY(std::abs(z_top - (centroid + 0.5)) < 1e-9);
  }

  void showsAndTurnsA3dModel() {
    const QString path = write_script(dir_, "wall3d.tess",
                                      "dimension 3\ntolerance 0.01\n"
                                      "material define stone density=2200\n"
                                      "joint define dry kn=5e10 ks=2e10 friction=35\n"
                                      "joint assign dry\n"
                                      "block box -0.5,-0.3,-0.4 4.1,0.6,0 group=footing "
                                      "material=stone\nfix group=footing\n"
                                      "wall brick=0.6,0.3,0.3 courses=6 bricks=6 group=wall "
                                      "material=stone\ngravity 0 0 -9.81\nstep 50\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    QVERIFY(w.snapshot()->three);
    QCOMPARE(w.snapshot()->blocks.size(), size_t(1 + 6 * 6 + 3));
    // A run moves the same faces: VTK's arrays are updated in place, not rebuilt.
    const size_t in_place = w.view()->updatedInPlace();
    const double z_before = w.snapshot()->blocks.back().z;
    w.runCommand("step 200");
    QVERIFY(wait_finished(w));
    QVERIFY(w.snapshot()->blocks.back().z != z_before);
    QVERIFY(w.view()->updatedInPlace() > in_place);
    // The sub-contacts inside the wall show through translucent blocks.
    auto* see_through = w.findChild<QAction*>("see_through");
    QVERIFY(see_through);
    see_through->trigger();
    QTest::qWait(100);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.view()->grabFramebuffer().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") +
                                       "/view_3d_contacts.png");
    see_through->trigger();
    ViewOptions o = w.viewOptions();
    o.contacts = ContactShow::kOff;
    w.setViewOptions(o);
    w.view()->resetCamera();
    QTest::qWait(100);
    const QImage img = w.view()->grabFramebuffer();
    // The middle of the view is the wall: a shade of its group colour, not background.
    const QColor mid = img.pixelColor(img.width() / 2 - img.width() / 10, img.height() / 2);
    const Rgb wall = category(1);
    qInfo("centre pixel %s, wall colour %d,%d,%d", qPrintable(mid.name()), wall.r, wall.g, wall.b);
    QVERIFY(mid != QColor(255, 255, 255));
    QVERIFY(std::abs(mid.red() * wall.g - mid.green() * wall.r) < 12 * 255);
    const double azimuth = w.viewOptions().azimuth;
    const QPoint c(w.view()->width() / 2, w.view()->height() / 2);
    QTest::mousePress(w.view(), Qt::RightButton, {}, c);
    QMouseEvent move(QEvent::MouseMove, QPointF(c + QPoint(60, 0)), QPointF(c + QPoint(60, 0)),
                     Qt::RightButton, Qt::RightButton, Qt::NoModifier);
    QApplication::sendEvent(w.view(), &move);
    QTest::mouseRelease(w.view(), Qt::RightButton, {}, c + QPoint(60, 0));
    QVERIFY(std::abs(w.viewOptions().azimuth - azimuth) > 10);
    QTest::qWait(100);
    const QImage turned = w.view()->grabFramebuffer();
    QVERIFY(turned != img);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS")) {
      img.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/view_3d.png");
      turned.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/view_3d_turned.png");
    }
  }

  // The window draws 3D models through VTK's depth buffer, not faces sorted by depth: a brick on
  // the far corner of a footing shows whole at the default view (its share of the model's pixels
  // is its silhouette's, 3.01%, less its outlines; painted in depth order the footing's top
  // covered most of it), and a block behind a wall, seen level from the south, has no pixel.
  void windowHidesWhatIsBehindIn3d() {
    // Pixels of the second group's colour (120,150,190, shaded) among all coloured ones, left
    // of the colour bar and right of the triad.
    const auto shares = [](const QImage& img) {
      const auto count = [&](auto is) { return static_cast<long>(model_pixels(img, is).size()); };
      return std::pair<long, long>{count(blue_grey),
                                   count([](const QColor& c) { return c.saturation() >= 40; })};
    };
    const QString path = write_script(dir_, "depth3d.tess",
                                      "dimension 3\nmaterial define rock density=2500\n"
                                      "block box 0,0,0 10,10,1 material=rock group=footing\n"
                                      "block box 8,8,1 9,9,2 material=rock group=brick\n");
    MainWindow w;
    QVERIFY(open_fitted(w, path));
    const auto [brick, model] = shares(w.view()->grabFramebuffer());
    qInfo("brick on the footing: %ld of %ld coloured pixels (%.2f%%, silhouette 3.01%%)", brick,
          model, 100.0 * double(brick) / double(model));
    QVERIFY(model > 5000);
    QVERIFY(std::abs(double(brick) / double(model) - 0.0301) < 0.15 * 0.0301);
    const QString behind = write_script(dir_, "behind3d.tess", kWallAndHidden);
    MainWindow w2;
    QVERIFY(open_shown(w2, behind));
    ViewOptions o = w2.viewOptions();
    o.azimuth = 180, o.elevation = 0;
    w2.setViewOptions(o);
    w2.view()->resetCamera();
    QTest::qWait(100);
    const QImage level = w2.view()->grabFramebuffer();
    const auto [hidden, shown] = shares(level);
    qInfo("block behind the wall: %ld of %ld coloured pixels", hidden, shown);
    QVERIFY(shown > 5000);
    QCOMPARE(hidden, 0L);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      level.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/view_3d_behind.png");
  }

  // The 3D camera: a click picks the block under it through VTK's cell picker (after turning
  // too), the triad shows north, a cut plane opens the wall to what is behind it, and the
  // perspective switch keeps the model in view.
  void threeDCameraPicksAndCuts() {
    const QString path = write_script(dir_, "cut3d.tess", kWallAndHidden);
    MainWindow w;
    QVERIFY(open_shown(w, path));
    ViewOptions o = w.viewOptions();
    o.azimuth = 180, o.elevation = 0;
    w.setViewOptions(o);
    w.view()->resetCamera();
    QTest::qWait(100);
    // The triad's x axis (east, red) in the lower left corner.
    const auto reds = [](const QImage& img) {
      long n = 0;
      for (int y = img.height() * 7 / 10; y < img.height() * 9 / 10; ++y)
        for (int x = 0; x < img.width() * 15 / 100; ++x) {
          const QColor c = img.pixelColor(x, y);
          n += c.red() > 150 && c.green() < 80 && c.blue() < 80;
        }
      return n;
    };
    const QImage before = w.view()->grabFramebuffer();
    QVERIFY(reds(before) > 20);
    // The hidden block's pixels (blue-grey).
    const auto hidden_pixels = [](const QImage& img) { return model_pixels(img, blue_grey); };
    QVERIFY(hidden_pixels(before).empty());
    QSignalSpy picks(w.view(), &VtkView::picked);
    const QPoint middle(w.view()->width() / 2 - w.view()->width() / 10, w.view()->height() / 2);
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, middle);
    QCOMPARE(picks.count(), 1);
    QCOMPARE(picks.takeFirst().at(0).toInt(), 0);  // the wall
    // Cut away everything south of y = 23: the wall goes, the block behind it shows and is
    // picked where it shows.
    o.cut = true, o.cut_dip = 90, o.cut_dip_direction = 180;
    o.cut_point = Vec3(5, 23, 5);
    w.setViewOptions(o);
    QTest::qWait(100);
    const QImage cut = w.view()->grabFramebuffer();
    const std::vector<QPoint> shown = hidden_pixels(cut);
    qInfo("cut open: %zu pixels of the block behind the wall", shown.size());
    QVERIFY(shown.size() > 500);
    QVERIFY(w.view()->scene().caption.find("cut by the plane 90/180") != std::string::npos);
    // The long caption wraps to the window: every line fits, nothing is lost.
    const QString shown_caption = QString::fromStdString(w.view()->captionShown());
    QVERIFY(shown_caption.contains('\n'));
    for (const QString& line : shown_caption.split('\n'))
      QVERIFY2(double(line.size()) <= w.view()->width() / 6.3 + 1, qPrintable(line));
    QCOMPARE(QString(shown_caption).remove(QRegularExpression("\\s")),
             QString::fromStdString(w.view()->scene().caption).remove(QRegularExpression("\\s")));
    const QPoint block = shown[shown.size() / 2] / w.view()->devicePixelRatioF();
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, block);
    QCOMPARE(picks.count(), 1);
    QCOMPARE(picks.takeFirst().at(0).toInt(), 1);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      cut.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/view_3d_cut.png");
    // A figure of the current view keeps the cut and the camera's window: the block, no wall.
    const QString figure = dir_.filePath("cut_view.png");
    w.exportFigure(figure, 800, 600);
    const QImage exported(figure);
    long block_pixels = 0, wall_pixels = 0;
    for (int y = 0; y < exported.height(); ++y)
      for (int x = 0; x < exported.width() * 3 / 4; ++x) {
        const QColor c = exported.pixelColor(x, y);
        if (c.saturation() < 40) continue;
        block_pixels += c.blue() > c.red() + 30;
        wall_pixels += c.red() > c.blue() + 30;
      }
    qInfo("exported cut view: %ld pixels of the block, %ld of the wall", block_pixels, wall_pixels);
    QVERIFY(block_pixels > 500);
    QCOMPARE(wall_pixels, 0L);
    // The View menu's dialog makes the same cut: it offers a vertical plane facing the viewer
    // through the blocks' middle; moved to y = 23, it opens the wall again.
    o.cut = false;
    w.setViewOptions(o);
    QTimer::singleShot(0, [] {
      auto* d = qobject_cast<QDialog*>(QApplication::activeModalWidget());
      QVERIFY(d);
      auto* dir = d->findChild<QDoubleSpinBox*>("dip_direction");
      auto* y = d->findChild<QDoubleSpinBox*>("y");
      QVERIFY(dir && y);
      QCOMPARE(dir->value(), 180.0);
      y->setValue(23);
      d->accept();
    });
    w.cutDialog();
    QVERIFY(w.viewOptions().cut);
    QCOMPARE(w.viewOptions().cut_point.y(), 23.0);
    QCOMPARE(w.viewOptions().cut_dip, 90.0);
    QTest::qWait(100);
    QVERIFY(hidden_pixels(w.view()->grabFramebuffer()).size() > 500);
    // Turned a quarter round by a right drag: still picks what is under the cursor.
    o.cut = false;
    w.setViewOptions(o);
    const QPoint c(w.view()->width() / 2, w.view()->height() / 2);
    QTest::mousePress(w.view(), Qt::RightButton, {}, c);
    for (int k = 1; k <= 5; ++k) {
      const QPointF to(c + QPoint(-45 * k, 0));
      QMouseEvent move(QEvent::MouseMove, to, to, Qt::RightButton, Qt::RightButton, Qt::NoModifier);
      QApplication::sendEvent(w.view(), &move);
    }
    QTest::mouseRelease(w.view(), Qt::RightButton, {}, c + QPoint(-225, 0));
    QCOMPARE(w.viewOptions().azimuth, 270.0);  // 180 + 0.4 per pixel
    QCOMPARE(w.view()->azimuth(), 270.0);
    QTest::qWait(100);
    QVERIFY(reds(w.view()->grabFramebuffer()) > 0);
    // From the west the wall (x = 0 face) is nearest, and the block is beside it, not behind.
    const QImage west = w.view()->grabFramebuffer();
    const std::vector<QPoint> side = hidden_pixels(west);
    QVERIFY(side.size() > 200);
    QTest::mouseClick(w.view(), Qt::LeftButton, {},
                      side[side.size() / 2] / w.view()->devicePixelRatioF());
    QCOMPARE(picks.count(), 1);
    QCOMPARE(picks.takeFirst().at(0).toInt(), 1);
    // A frame arriving while the user turns the camera (as during a run) leaves it where the
    // drag has it; the window learns the view on release.
    const QPoint m0(w.view()->width() / 2, w.view()->height() / 2);
    QTest::mousePress(w.view(), Qt::RightButton, {}, m0);
    QMouseEvent drag(QEvent::MouseMove, QPointF(m0 + QPoint(50, 0)), QPointF(m0 + QPoint(50, 0)),
                     Qt::RightButton, Qt::RightButton, Qt::NoModifier);
    QApplication::sendEvent(w.view(), &drag);
    const double dragged = w.view()->azimuth();
    QVERIFY(std::abs(dragged - 250.0) < 1e-9);  // 270 - 0.4 x 50
    w.setViewOptions(w.viewOptions());          // a frame built for the old view
    QCOMPARE(w.view()->azimuth(), dragged);
    QTest::mouseRelease(w.view(), Qt::RightButton, {}, m0 + QPoint(50, 0));
    QCOMPARE(w.viewOptions().azimuth, dragged);
    // Perspective: the same model, still in view.
    auto* perspective = w.findChild<QAction*>("perspective");
    QVERIFY(perspective);
    perspective->trigger();
    QVERIFY(w.view()->perspective());
    QTest::qWait(100);
    QVERIFY(hidden_pixels(w.view()->grabFramebuffer()).size() > 100);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.view()->grabFramebuffer().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") +
                                       "/view_3d_perspective.png");
    // A 2D model keeps its flat, parallel view whatever the 3D setting.
    MainWindow flat;
    QVERIFY(open_fitted(flat, script_));
    const QPoint flat_at = flat.view()->pixelOf({1.0, 2.0});
    flat.findChild<QAction*>("perspective")->trigger();
    QVERIFY(flat.view()->perspective());
    QCOMPARE(flat.view()->pixelOf({1.0, 2.0}), flat_at);
    flat.view()->resetCamera();
    QCOMPARE(flat.view()->pixelOf({1.0, 2.0}), flat_at);
  }

  // 3D figures in perspective, as View > Perspective shows the window: a row of ten unit cubes
  // along x seen from the west-south-west, the near cube (blue-grey) drawn taller than the far
  // one (orange), as tall in the parallel default. The window's figure has the window's camera
  // (the same ratio as on the screen). Seen from close in front of a wall and above it, the
  // wall's top, edge-on along the line of sight, faces the eye and shows, and the block behind
  // the wall stays hidden. The script keyword is refused in 2D.
  void figuresInPerspective() {
    const QString path = write_script(dir_, "row3d.tess",
                                      "dimension 3\nmaterial define rock density=2500\n"
                                      "block box 1,0,0 9,1,1 material=rock group=row\n"
                                      "block box 0,0,0 1,1,1 material=rock group=near\n"
                                      "block box 9,0,0 10,1,1 material=rock group=far\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    ViewOptions o = w.viewOptions();
    o.azimuth = 240, o.elevation = 20, o.contacts = ContactShow::kOff;
    // The near cube's height over the far one's, left of a figure's legend or in the window's
    // model area.
    const auto ratio = [](const QImage& img, int x0, int x1) {
      return double(rows_spanned(img, x0, x1, blue_grey)) /
             std::max(1, rows_spanned(img, x0, x1, orange));
    };
    const auto figure = [&](const ViewOptions& v, const QString& name) {
      const QString file = dir_.filePath(name);
      write_figure(build_scene(*w.snapshot(), v), file.toStdString(), 1200, 900);
      return QImage(file);
    };
    const double parallel = ratio(figure(o, "row_parallel.png"), 0, 900);
    o.perspective = true;
    const double perspective = ratio(figure(o, "row_perspective.png"), 0, 900);
    qInfo("near cube over far cube: %.3f in parallel, %.3f in perspective", parallel, perspective);
    QVERIFY(std::abs(parallel - 1.0) < 0.05);
    QVERIFY(perspective > 1.4);
    QVERIFY(build_scene(*w.snapshot(), o).caption.find("in perspective") != std::string::npos);
    // The window in perspective (the menu's setting follows the options) and its figure.
    w.setViewOptions(o);
    QVERIFY(w.view()->perspective());
    QVERIFY(w.findChild<QAction*>("perspective")->isChecked());
    w.view()->resetCamera();
    QTest::qWait(100);
    const QImage screen = w.view()->grabFramebuffer();
    const QString exported = dir_.filePath("row_window.png");
    w.exportFigure(exported, 1200, 900);
    const double on_screen = ratio(screen, screen.width() * 15 / 100, screen.width() * 8 / 10);
    const double in_figure = ratio(QImage(exported), 0, 900);
    qInfo("window in perspective: %.3f on the screen, %.3f in its figure", on_screen, in_figure);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS")) {
      screen.save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/view_3d_row_perspective.png");
      QImage(exported).save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/row_window.png");
    }
    QVERIFY(on_screen > 1.4);
    QVERIFY(std::abs(in_figure - on_screen) < 0.1 * on_screen);
    // From 7 m in front of the wall, 2 m above its top, looking level: the top (shaded as
    // edge-on: 0.6 times the wall's colour) shows; the block behind does not.
    const QString behind = write_script(dir_, "behind_perspective.tess", kWallAndHidden);
    MainWindow w2;
    QVERIFY(open_shown(w2, behind));
    ViewOptions close;
    close.azimuth = 180, close.elevation = 0, close.contacts = ContactShow::kOff;
    close.perspective = close.has_camera = true;
    close.focus = Vec3(5, 21, 12), close.distance = 8;
    const QString file = dir_.filePath("wall_perspective.png");
    write_figure(build_scene(*w2.snapshot(), close), file.toStdString(), 1200, 900);
    const QImage img(file);
    const Rgb wall = category(0);
    const Rgb top{static_cast<unsigned char>(std::lround(0.6 * wall.r)),
                  static_cast<unsigned char>(std::lround(0.6 * wall.g)),
                  static_cast<unsigned char>(std::lround(0.6 * wall.b))};
    long hidden = 0, tops = 0, fronts = 0;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < 900; ++x) {
        const QColor c = img.pixelColor(x, y);
        hidden += blue_grey(c);
        tops += close_to(c, top, 3);
        fronts += close_to(c, wall, 3);
      }
    qInfo("close to the wall: %ld pixels of its front, %ld of its top, %ld of the block behind",
          fronts, tops, hidden);
    QVERIFY(fronts > 100000);
    QVERIFY(tops > 5000);
    QCOMPARE(hidden, 0L);
    // The `figure` keyword: 3D models only, on or off.
    ViewOptions v;
    QVERIFY(set_perspective(v, "on", 2).find("2D") != std::string::npos);
    QVERIFY(!v.perspective);
    QVERIFY(!set_perspective(v, "yes", 3).empty());
    QVERIFY(set_perspective(v, "on", 3).empty());
    QVERIFY(v.perspective);
  }

  // A zoned column under gravity coloured by syy: the zones are drawn (one triangle each) in
  // ramp colours, compressive blue at the foot, near zero red at the top; by state, four entries.
  void framebufferShowsZoneStresses() {
    const QString path =
        write_script(dir_, "column.tess",
                     "round 0.01\nmaterial define stone density=2500\n"
                     "material define rock density=2000 E=1e9 nu=0.25\n"
                     "joint define j kn=1e11 ks=1e11 friction=30\njoint assign j\n"
                     "block -1,-1 2,-1 2,0 -1,0 material=stone\nfix x=-1,2 y=-1,0\n"
                     "block 0,0 1,0 1,4 0,4 material=rock\nzone generate edge=0.25 x=0,1 y=0,4\n"
                     "boundary fix=x x=-0.001,0.001\nboundary fix=x x=0.999,1.001\n"
                     "gravity 0 -10\nsolve ratio=1e-5 cycles=100000\n");
    QVERIFY(!path.isEmpty());
    MainWindow w;
    QVERIFY(open_shown(w, path));
    ViewOptions o;
    o.colour = ColourBy::kSyy;
    o.contacts = ContactShow::kOff;
    w.setViewOptions(o);
    w.view()->resetCamera();
    QTest::qWait(100);
    const Scene scene = build_scene(*w.snapshot(), o);
    QCOMPARE(scene.zones.size(), w.snapshot()->zones.size());
    QVERIFY(scene.zones.size() > 100);
    // Each zone a triangle, together the column's 1 x 4 m (squeezed by a hair under gravity).
    double area = 0;
    for (const ScenePolygon& z : scene.zones) {
      QCOMPARE(z.points.size(), size_t(3));
      const Vec2 a = z.points[1] - z.points[0], b = z.points[2] - z.points[0];
      area += 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    }
    QVERIFY2(std::abs(area - 4.0) < 1e-3, qPrintable(QString::number(area)));
    QCOMPARE(QString::fromStdString(scene.blocks_legend.title), QString("syy [MPa]"));
    QVERIFY(scene.blocks_legend.lo < -0.07 && scene.blocks_legend.hi > -0.01);
    const QImage img = w.view()->grabFramebuffer();
    const auto pixel = [&](double x, double y) { return pixel_at(w.view(), img, x, y); };
    const QColor foot = pixel(0.5, 0.05), top = pixel(0.5, 3.95);
    QVERIFY2(foot.blue() > foot.red() + 80, qPrintable(foot.name()));
    QVERIFY2(top.red() > top.blue() + 80, qPrintable(top.name()));
    QVERIFY(!w.view()->contactScaleShown());
    // A click on the column picks the zone there: its stresses, compressive near the foot.
    QSignalSpy zones(w.view(), &VtkView::zonePicked);
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({0.5, 0.3}));
    QCOMPARE(zones.count(), 1);
    const int zone = zones.takeFirst().at(0).toInt();
    const Properties picked = zone_properties(*w.snapshot(), zone);
    QCOMPARE(picked[1].second, std::to_string(w.snapshot()->blocks[1].id));
    QCOMPARE(picked[3].first, std::string("syy"));
    QVERIFY2(std::stod(picked[3].second) < -0.05, picked[3].second.c_str());  // MPa
    // With the contacts coloured by force too, they get a colour bar of their own.
    o.contacts = ContactShow::kStress;
    w.setViewOptions(o);
    QTest::qWait(100);
    QVERIFY(w.view()->contactScaleShown());
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.view()->grabFramebuffer().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") +
                                       "/zones_and_contacts.png");
    o.colour = ColourBy::kZoneState;
    QCOMPARE(build_scene(*w.snapshot(), o).blocks_legend.entries.size(), size_t(4));
  }

  // Figures of the current view: PNG of the asked size, valid SVG and PDF.
  void exportsFigures() {
    MainWindow w;
    w.show();
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    const QString png = dir_.filePath("view.png"), svg = dir_.filePath("view.svg"),
                  pdf = dir_.filePath("view.pdf");
    w.exportFigure(png, 800, 500);
    w.exportFigure(svg, 800, 500);
    w.exportFigure(pdf, 800, 500);
    const QImage img(png);
    QCOMPARE(img.size(), QSize(800, 500));
    QSvgRenderer renderer(svg);
    QVERIFY(renderer.isValid());
    QCOMPARE(renderer.viewBoxF(), QRectF(0, 0, 800, 500));
    QFile f(pdf);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    QVERIFY(bytes.startsWith("%PDF-") && bytes.contains("%%EOF") && bytes.size() > 1000);
  }

  // The session saved as a script reruns in batch to the same model.
  void savedScriptRerunsTheSession() {
    MainWindow w;
    w.show();
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    w.runCommand("step 120");
    QVERIFY(wait_finished(w));
    w.runCommand("blok 1");  // fails: not part of the session
    QVERIFY(!wait_finished(w));
    w.runCommand("fix block=3");
    QVERIFY(wait_finished(w));
    w.step(80);
    QVERIFY(wait_finished(w));
    const QString saved = dir_.filePath("session.tess");
    QVERIFY(w.saveScript(saved));
    QFile f(saved);
    QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(f.readAll());
    QVERIFY(text.startsWith("title \"Two blocks\"") &&
            text.endsWith("step 120\nfix block=3\nstep 80\n"));
    QVERIFY(!text.contains("blok"));
    // Rerun in the window from the saved script: the same blocks at the same cycle.
    const auto before = w.snapshot();
    MainWindow again;
    again.openScript(saved);
    QVERIFY(wait_finished(again));
    QCOMPARE(again.snapshot()->cycle, before->cycle);
    for (size_t b = 0; b < before->blocks.size(); ++b) {
      QCOMPARE(again.snapshot()->blocks[b].x, before->blocks[b].x);
      QCOMPARE(again.snapshot()->blocks[b].y, before->blocks[b].y);
    }
  }

  // Drawing in the view: a block (corners snapped to a block corner and to the grid) and a
  // crack across the base, each a command in the journal; undo and redo step through them; the
  // saved script, run headless, gives the same blocks.
  void drawsBlocksUndoesAndRedoes() {
    const QString path =
        write_script(dir_, "draw.tess",
                     "round 0.005\nmaterial define stone density=2500\n"
                     "joint define dry kn=1e9 ks=1e9 friction=30\njoint assign dry\n"
                     "block 0,0 4,0 4,1 0,1 group=base material=stone\nfix group=base\n"
                     "block 0,1 1.9,1 1.9,3 0,3 group=left material=stone\n");
    QVERIFY(!path.isEmpty());
    MainWindow w;
    QVERIFY(open_shown(w, path));
    w.view()->resetCamera();
    QTest::qWait(50);
    w.setDrawingDefaults(0.25, "top", "stone");
    const auto click = [&](double x, double y) {
      QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({x, y}));
    };
    const auto finish = [&](double x, double y) {
      QTest::mouseDClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({x, y}));
    };
    w.setTool(DrawMode::kBlock);
    click(0.02, 3.01);  // the left block's corner
    click(1.9, 3.0);    // the other corner
    click(1.88, 4.02);  // the grid: 2,4
    finish(0.1, 3.9);   // the grid: 0,4
    QVERIFY(wait_finished(w));
    QCOMPARE(w.journal().last(), QString("block 0,3 1.9,3 2,4 0,4 group=top material=stone"));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    w.setTool(DrawMode::kCrack);
    click(-0.2, 0.5);
    QTest::keyClick(w.view(), Qt::Key_Escape);  // dropped: starts again
    click(-0.2, 0.5);
    click(4.2, 0.5);
    QTest::keyClick(w.view(), Qt::Key_Return);
    QVERIFY(wait_finished(w));
    QCOMPARE(w.journal().last(), QString("crack -0.25,0.5 4.25,0.5"));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(4));
    w.setTool(DrawMode::kNone);
    // Undo twice, redo once: the crack is gone again, the drawn block back.
    QVERIFY(w.canUndo());
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
    QVERIFY(!w.canUndo() && w.canRedo());
    w.redo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    QCOMPARE(w.journal().last(), QString("block 0,3 1.9,3 2,4 0,4 group=top material=stone"));
    // A new command drops what was left to redo.
    QVERIFY(w.canRedo());
    w.runCommand("gravity 0 -9.81");
    QVERIFY(wait_finished(w));
    QVERIFY(!w.canRedo());
    const QString saved = dir_.filePath("drawn.tess");
    QVERIFY(w.saveScript(saved));
    Interpreter batch(dir_.filePath("drawn_out").toStdString());
    batch.run_file(saved.toStdString());
    const Blocks& B = batch.model().blocks;
    QCOMPARE(B.size(), w.snapshot()->blocks.size());
    for (size_t b = 0; b < B.size(); ++b) {
      QCOMPARE(B.x[b], w.snapshot()->blocks[b].x);
      QCOMPARE(B.y[b], w.snapshot()->blocks[b].y);
    }
  }

  // The Undo entry names the command it undoes, whatever ran it (the console, the Step button,
  // a stage), and undoing restores what that command changed.
  void undoNamesWhatItUndoes() {
    MainWindow w;
    QVERIFY(open_shown(w, script_));
    auto* undo = w.findChild<QAction*>("undo");
    QVERIFY(undo);
    const uint64_t cycle = w.snapshot()->cycle;
    w.runCommand("delete group=right");
    QVERIFY(wait_finished(w));
    QCOMPARE(undo->text(), QString("&Undo delete group=right"));
    // The legend names the groups left, not the excavated one (colours stay by group).
    const Legend legend = w.view()->scene().blocks_legend;
    QCOMPARE(legend.entries.size(), size_t(2));
    QCOMPARE(legend.entries[1].first, std::string("left"));
    QCOMPARE(legend.entries[1].second, category(1));
    w.step(50);
    QVERIFY(wait_finished(w));
    QCOMPARE(undo->text(), QString("&Undo step 50"));
    QCOMPARE(w.snapshot()->cycle, cycle + 50);
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->cycle, cycle);  // the step undone, the deletion kept
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
    QCOMPARE(undo->text(), QString("&Undo delete group=right"));
    // A stage's lines are commands like any other.
    PlannedStage stage;
    stage.name = "settle";
    stage.commands = QStringList{"gravity 0 -9.81"};
    stage.ratio = 1e-3, stage.cycles = 30;
    w.stagePanel()->addStage(stage);
    QSignalSpy done(&w, &MainWindow::stagesFinished);
    w.runStages();
    QVERIFY(done.wait(60000));
    QVERIFY(undo->text().startsWith("&Undo solve"));
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(undo->text(), QString("&Undo gravity 0 -9.81"));
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(undo->text(), QString("&Undo delete group=right"));
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    QVERIFY(!w.canUndo());
  }

  // A two-stage sequence from the stage list: each stage's commands and solve run in order and
  // its results are kept; a finished stage can be shown again and exported; a failing stage
  // stops the run and is marked.
  void runsAnExcavationSequence() {
    MainWindow w;
    QVERIFY(open_shown(w, script_));
    PlannedStage remove;
    remove.name = "remove the right block";
    remove.commands = QStringList{"delete group=right"};
    remove.ratio = 1e-4, remove.cycles = 20000;
    PlannedStage prop = remove;
    prop.name = "prop";
    prop.commands = QStringList{"block 2.1,1 4,1 4,2 2.1,2 group=prop material=stone"};
    w.stagePanel()->addStage(remove);
    w.stagePanel()->addStage(prop);
    // The plan is saved with the script (as comments) and comes back when it is opened.
    const QString planned = dir_.filePath("planned.tess");
    QVERIFY(w.saveScript(planned));
    {
      MainWindow other;
      other.openScript(planned);
      QVERIFY(wait_finished(other));
      const auto& back = other.stagePanel()->stages();
      QCOMPARE(back.size(), size_t(2));
      QCOMPARE(back[1].name, prop.name);
      QCOMPARE(back[1].commands, prop.commands);
      QCOMPARE(back[0].ratio, 1e-4);
      QCOMPARE(back[0].cycles, qint64(20000));
      QCOMPARE(other.journal().size(), w.journal().size());
    }
    QSignalSpy done(&w, &MainWindow::stagesFinished);
    w.runStages();
    QVERIFY(done.wait(60000));
    QCOMPARE(done.takeFirst().at(0).toBool(), true);
    const auto& stages = w.stagePanel()->stages();
    QVERIFY(stages[0].state == PlannedStage::State::kDone && stages[0].result);
    QVERIFY(stages[1].state == PlannedStage::State::kDone && stages[1].result);
    QCOMPARE(stages[0].result->blocks.size(), size_t(2));
    QCOMPARE(stages[1].result->blocks.size(), size_t(3));
    QVERIFY(stages[1].result->cycle > stages[0].result->cycle);
    QVERIFY(w.journal().contains("delete group=right"));
    QVERIFY(w.journal().contains("solve ratio=0.0001 cycles=20000"));
    // Back to the first stage's picture, and a figure of each stage.
    w.showStageResult(0);
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
    const QString out = dir_.filePath("stages");
    QCOMPARE(w.exportStages(out, 400, 300), 2);
    QCOMPARE(QImage(out + "/stage_02.png").size(), QSize(400, 300));
    // A stage that fails is marked; the finished ones are not run again.
    PlannedStage bad = remove;
    bad.name = "typo";
    bad.commands = QStringList{"delete group=rigth"};
    w.stagePanel()->addStage(bad);
    w.runStages();
    QVERIFY(done.wait(60000));
    QCOMPARE(done.takeFirst().at(0).toBool(), false);
    QVERIFY(stages[2].state == PlannedStage::State::kFailed);
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
  }

  // Building through dialogs and the selection: a joint set typed into its dialog (previewed
  // A cut shows the section on its plane: the zones it crosses (a zoned block coloured by
  // stress) and a cap across a rigid block, each covering the block's cross-section (1 m² here),
  // and nothing above the plane.
  void cutSectionsCoverTheCrossSection() {
    const QString path = write_script(dir_, "sections.tess",
                                      "dimension 3\nmaterial define rock density=2500 E=1e9 "
                                      "nu=0.25\nblock box 0,0,0 1,1,2 material=rock group=soft\n"
                                      "block box 2,0,0 3,1,2 material=rock group=hard\n"
                                      "zone generate edge=0.3 group=soft\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    ViewOptions o;
    o.colour = ColourBy::kSzz;
    o.cut = true, o.cut_dip = 0, o.cut_dip_direction = 0;
    o.cut_point = Vec3(0, 0, 1.0 / 3.0);
    // The window's scene (world points) and a figure's seen from straight above (elevation 90:
    // the sections, at height 1/3, lie flat on the view plane, so their drawn areas are true).
    o.elevation = 90;
    for (const bool camera : {false, true}) {
      const Scene scene = build_scene(*w.snapshot(), o, camera);
      QVERIFY(scene.caption.find("cut by the plane 0/000") != std::string::npos);
      double area[2] = {0, 0};
      double top = -1;
      for (const ScenePolygon& p : scene.polygons) {
        if (p.block < 0 || p.block > 1) continue;
        bool on_plane = true;
        double twice = 0;
        const size_t n = p.points.size();
        for (size_t k = 0; k < n; ++k) {
          const double z = camera ? p.world[k].z() : p.depth[k];
          top = std::max(top, z);
          on_plane = on_plane && std::abs(z - 1.0 / 3.0) < 1e-9;
          const Vec2 a = p.points[k], b = p.points[(k + 1) % n];
          twice += a.x() * b.y() - a.y() * b.x();
        }
        if (on_plane) area[p.block] += 0.5 * std::abs(twice);
      }
      qInfo(
          "%s: sections of the zoned block %.9f m², of the rigid block %.9f m²; highest point "
          "%.9f",
          camera ? "window" : "figure", area[0], area[1], top);
      QVERIFY(std::abs(area[0] - 1.0) < 1e-9);
      QVERIFY(std::abs(area[1] - 1.0) < 1e-9);
      QVERIFY(top <= 1.0 / 3.0 + 1e-12);
    }
    // A cut along the face between two stacked blocks: the upper one goes whole, face on the
    // plane included, and the lower keeps its top face once (no cap over it).
    const QString stacked = write_script(dir_, "stacked.tess",
                                         "dimension 3\nmaterial define rock density=2500\n"
                                         "block box 0,0,0 1,1,1 material=rock group=low\n"
                                         "block box 0,0,1 1,1,2 material=rock group=high\n");
    MainWindow w2;
    QVERIFY(open_shown(w2, stacked));
    ViewOptions flat;
    flat.cut = true, flat.cut_dip = 0, flat.cut_point = Vec3(0.5, 0.5, 1.0);
    const Scene face = build_scene(*w2.snapshot(), flat, true);
    int on_plane = 0;
    for (const ScenePolygon& p : face.polygons) {
      QVERIFY2(p.block == 0, "nothing of the block above the cut");
      bool flat_on = true;
      for (const Vec3& v : p.world) flat_on = flat_on && std::abs(v.z() - 1.0) < 1e-12;
      on_plane += flat_on;
    }
    QCOMPARE(on_plane, 1);
    // In the window, a click on the zoned block (coloured by szz; the rigid one grey) picks a
    // zone of it through VTK's picker.
    o.cut = false;
    w.setViewOptions(o);
    w.view()->resetCamera();
    QTest::qWait(100);
    const QImage img = w.view()->grabFramebuffer();
    const std::vector<QPoint> zoned =
        model_pixels(img, [](const QColor& c) { return c.saturation() > 60; });
    QVERIFY(zoned.size() > 500);
    QSignalSpy zones(w.view(), &VtkView::zonePicked);
    QTest::mouseClick(w.view(), Qt::LeftButton, {},
                      zoned[zoned.size() / 2] / img.devicePixelRatioF());
    QCOMPARE(zones.count(), 1);
    const auto zone = static_cast<size_t>(zones.takeFirst().at(0).toInt());
    QCOMPARE(w.snapshot()->zones.at(zone).block, 0);
  }

  // A 3D model built through the Model menu's 3D forms: a box, a crack plane and a prism, each
  // previewed before OK and run as a command; a joint set's planes previewed; blocks chosen by
  // a box drawn on the screen become a block list that the dialogs act on.
  void buildsA3dModelThroughDialogs() {
    const QString path = write_script(dir_, "empty3d.tess",
                                      "dimension 3\nmaterial define rock density=2500\n"
                                      "joint define j kn=1e10 ks=1e10 friction=30\n"
                                      "joint assign j\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    QVERIFY(w.snapshot()->three);
    QVERIFY(!w.openDialog("voronoi"));  // 2D models only
    CommandDialog* d = w.openDialog("box");
    QVERIFY(d);
    QCOMPARE(w.view()->previewSegments(), size_t(12));
    d->setValue("#b", "10, 10, 10");
    d->setValue("material", "rock");
    QCOMPARE(d->command(), QString("block box 0,0,0 10,10,10 material=rock"));
    d->accept();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(1));
    QCOMPARE(w.view()->previewSegments(), size_t(0));
    w.view()->resetCamera();
    // A crack plane through the box: its outline within the block previewed.
    d = w.openDialog("crack");
    QVERIFY(d);
    d->setValue("origin", "5,5,5");
    QVERIFY(w.view()->previewSegments() >= 4);
    d->accept();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.journal().last(), QString("crack dip=60 ddir=90 origin=5,5,5"));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
    // A horizontal joint set 4 m apart from z = 1: three planes (z = 1, 5, 9) across the
    // blocks, each a rectangle.
    d = w.openDialog("jset");
    d->setValue("dip", "0"), d->setValue("ddir", "0"), d->setValue("spacing", "4");
    d->setValue("origin", "0,0,1");
    QCOMPARE(w.view()->previewSegments(), size_t(12));
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.view()->grabFramebuffer().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") +
                                       "/jset3d_preview.png");
    d->reject();
    // A prism beside it: the base polygon keeps its spaces.
    d = w.openDialog("prism");
    d->setValue("#base", "20,0  24,0 24, 3 20,3");
    d->setValue("material", "rock");
    QCOMPARE(w.view()->previewSegments(), size_t(12));
    QCOMPARE(d->command(), QString("block prism 20,0 24,0 24,3 20,3 z=0,2 material=rock"));
    d->accept();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    // The select tool's box over the whole view takes every block, as a block list.
    w.view()->resetCamera();
    QTest::qWait(50);
    w.setTool(DrawMode::kSelect);
    const QPoint corner(5, 5), far(w.view()->width() - 5, w.view()->height() - 5);
    QTest::mousePress(w.view(), Qt::LeftButton, {}, corner);
    QTest::mouseMove(w.view(), (corner + far) / 2);
    QTest::mouseMove(w.view(), far);
    QTest::mouseRelease(w.view(), Qt::LeftButton, {}, far);
    QCOMPARE(w.selectedBlocks().size(), size_t(3));
    QCOMPARE(w.selection(), QString("block=1,2,3"));
    d = w.openDialog("zones");
    QVERIFY(d->command().startsWith("zone generate edge=1 block=1,2,3"));
    d->reject();
    // A click on a face picks its block alone (a click on nothing first clears the selection).
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, QPoint(3, 3));
    QVERIFY(w.selectedBlocks().empty());
    QTest::qWait(50);
    const QImage img = w.view()->grabFramebuffer();
    const std::vector<QPoint> model = model_pixels(img, [](const QColor& c) {
      return c.lightness() > 100 && c.lightness() < 245;  // the blocks' grey faces
    });
    QVERIFY(model.size() > 1000);
    QTest::mouseClick(w.view(), Qt::LeftButton, {},
                      model[model.size() / 2] / img.devicePixelRatioF());
    QCOMPARE(w.selectedBlocks().size(), size_t(1));
    QVERIFY(w.selection().startsWith("block="));
    // The wall previews its bricks on its face and its box.
    d = w.openDialog("wall");
    QVERIFY(w.view()->previewSegments() > 12);
    d->reject();
  }

  // Run > Factor of safety: the dialog runs `solve fos`, the console reports the trials and
  // the factor, and the model shown is the one before the trials.
  void factorOfSafetyFromTheRunMenu() {
    const QString path = write_script(
        dir_, "fos.tess",
        "set psi = 20\nset c = cos(psi)\nset s = sin(psi)\nround 0.005\n"
        "material define rock density=2500\njoint define j kn=1e10 ks=1e10 friction=35\n"
        "joint assign j\n"
        "block (-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s) group=slab material=rock\n"
        "block 0,0 c,s (c-s),(s+c) (-s),c material=rock\nfix group=slab\ngravity 0 -9.81\n"
        "solve ratio=1e-6\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    const QList<QAction*> actions = w.findChildren<QAction*>();
    QVERIFY(std::any_of(actions.begin(), actions.end(),
                        [](QAction* a) { return a->text() == "&Factor of safety…"; }));
    QPointer<CommandDialog> d = w.openDialog("fos");
    QVERIFY(d);
    d->setValue("cycles", "3000");
    d->accept();
    QVERIFY(wait_finished(w));
    QTRY_VERIFY(d.isNull() || !d->isVisible());
    qInfo("%s", qPrintable(w.journal().last()));
    QVERIFY(w.journal().last().startsWith("solve fos"));
    QVERIFY(w.journal().last().contains("cycles=3000"));
    QVERIFY(w.console()->text().contains("fos trial 2: fails"));
    QVERIFY(w.console()->text().contains("factor of safety 1.92"));
  }

  // Model > Cable pattern: offers the openings, and its command places grouted cables that the
  // next snapshot draws (3D models: cablesShowThroughTheRockIn3d).
  void cablePatternThroughItsDialog() {
    const QString path = write_script(
        dir_, "cables.tess",
        "round 0.01\nmaterial define rock density=2600\njoint define j kn=1e10 ks=1e10 "
        "friction=30\njoint assign j\nregion -8,-8 8,8 material=rock\njset angle=20 spacing=2\n"
        "tunnel circle centre=0,0 radius=3 name=t group=t\ndelete group=t\nfix all\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    QPointer<CommandDialog> d = w.openDialog("cablepattern");
    QVERIFY(d);
    QVERIFY(d->choices("joints").contains("t"));
    d->setValue("joints", "t");
    d->setValue("spacing", "1");
    d->setValue("length", "4");
    d->setValue("angles", "0,180");
    d->accept();
    QVERIFY(wait_finished(w));
    QVERIFY2(w.journal().last().startsWith("cable pattern joints=t spacing=1 length=4"),
             qPrintable(w.journal().last()));
    QVERIFY(w.openDialog("cable"));
    QPointer<CommandDialog> liner = w.openDialog("liner");
    QVERIFY(liner && liner->choices("joints").contains("t"));
    liner->setValue("joints", "t");
    liner->accept();
    QVERIFY(wait_finished(w));
    QVERIFY2(w.journal().last().startsWith("liner joints=t e=30e9"),
             qPrintable(w.journal().last()));
    // Coloured by axial force, the support has its own scale beside the others.
    QVERIFY(!w.view()->supportScaleShown());
    ViewOptions o;
    o.support_force = true;
    w.setViewOptions(o);
    QVERIFY(w.view()->supportScaleShown());
    const auto caption = [&] {
      return QString::fromStdString(w.view()->captionShown()).replace('\n', ' ');
    };
    QTRY_VERIFY2(caption().contains("cables: coloured by axial force"), qPrintable(caption()));
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/cables_force.png");
  }

  // 3D cables lie inside the rock: the window draws them over it, purple while elastic, from any
  // side; coloured by axial force they take the support's own scale and no purple is left.
  void cablesShowThroughTheRockIn3d() {
    const QString path =
        write_script(dir_, "cables3d.tess",
                     "dimension 3\ntolerance 0.01\nmaterial define rock density=2500\n"
                     "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
                     "block box -2,-2,0 2,2,2 material=rock group=rock\n"
                     "block box -1,-0.5,-0.5 1,0.5,-0.1 material=rock group=plate\nfix group=rock\n"
                     "cable -0.5,0,-0.1 -0.5,0,2 segments=21 ea=1e8 kbond=1e8 sbond=0 head=on\n"
                     "cable 0.5,0,-0.1 0.5,0,2 segments=21 ea=1e8 kbond=1e8 sbond=0 head=on\n"
                     "gravity 0 0 -10\nstep 500\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    const auto purple = [&] {
      QTest::qWait(100);
      return static_cast<long>(model_pixels(w.view()->grabFramebuffer(), [](const QColor& c) {
                                 return c.red() > 140 && c.green() < 40 && c.blue() > 140;
                               }).size());
    };
    w.view()->resetCamera();
    const long front = purple();
    ViewOptions o = w.viewOptions();
    o.azimuth += 90;
    w.setViewOptions(o);
    w.view()->resetCamera();
    const long side = purple();
    qInfo("cable pixels drawn over the rock: %ld, turned a quarter: %ld", front, side);
    QVERIFY(front > 100);
    QVERIFY(side > 100);
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.view()->grabFramebuffer().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") +
                                       "/view_3d_cables.png");
    // Model > Grouted cable in 3D: points x,y,z, no row spacing.
    QPointer<CommandDialog> d = w.openDialog("cable");
    QVERIFY(d);
    d->setValue("#a", "0,0.3,-0.1");
    d->setValue("#b", "0,0.3,2");
    d->setValue("name", "third");
    d->accept();
    QVERIFY(wait_finished(w));
    QVERIFY2(w.journal().last().startsWith("cable 0,0.3,-0.1 0,0.3,2 segments=8"),
             qPrintable(w.journal().last()));
    QVERIFY(!w.journal().last().contains("rowspacing"));
    QCOMPARE(w.snapshot()->bolts.size(), size_t(3));
    o.support_force = true;
    w.setViewOptions(o);
    QVERIFY(w.view()->supportScaleShown());
    QCOMPARE(purple(), 0L);
  }

  // A dialog whose command fails stays open with its fields and shows the error; corrected, it
  // runs and closes. Fields that name things offer what exists.
  void dialogKeepsItsFieldsOnError() {
    const QString path = write_script(dir_, "dialog_error.tess",
                                      "round 0.01\nmaterial define rock density=2600\n"
                                      "block 0,0 1,0 1,1 0,1 material=rock group=stone\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    const qsizetype journal = w.journal().size();
    QPointer<CommandDialog> d = w.openDialog("material");
    QVERIFY(d);
    // Every zone model and joint law the engine has is offered.
    QVERIFY(d->choices("model").contains("strain-softening"));
    QVERIFY(d->choices("model").contains("transversely-isotropic"));
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      d->grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/material_dialog.png");
    {
      QPointer<CommandDialog> joint = w.openDialog("joint");
      QVERIFY(joint && joint->choices("law").contains("barton-bandis"));
      QVERIFY(joint->choices("law").contains("cy"));
      if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
        joint->grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/joint_dialog.png");
      joint->close();
    }
    d->setValue("#name", "soft");
    d->setValue("density", "-5");
    QSignalSpy finished(&w, &MainWindow::commandFinished);
    d->accept();
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.takeFirst().at(0).toBool(), false);
    QVERIFY(d && d->isVisible());
    qInfo("dialog error: %s", qPrintable(d->error()));
    QVERIFY(d->error().contains("density"));
    QCOMPARE(d->value("density"), QString("-5"));
    QCOMPARE(w.journal().size(), journal);
    QVERIFY(!w.errorBox() || !w.errorBox()->isVisible());  // shown in the dialog instead
    d->setValue("density", "2000");
    d->accept();
    QVERIFY(wait_finished(w));
    QTRY_VERIFY(d.isNull() || !d->isVisible());
    QCOMPARE(w.journal().last(), QString("material define soft density=2000"));
    // The assignment dialog offers the materials and groups that exist.
    QPointer<CommandDialog> assign = w.openDialog("assign");
    QVERIFY(assign->choices("material").contains("rock"));
    QVERIFY(assign->choices("material").contains("soft"));
    QVERIFY(assign->findChild<QToolButton*>("material_choices"));
    // Nothing selected: said in the dialog, which stays open.
    assign->setValue("material", "soft");
    assign->accept();
    QVERIFY(assign->isVisible());
    QVERIFY(assign->error().contains("Select blocks"));
    assign->reject();
  }

  // before the cut), a box dragged over two blocks, a group, material and joint properties
  // assigned to them; each step a command; undone; the saved script rebuilds the same model.
  void buildsThroughDialogsAndSelection() {
    const QString path =
        write_script(dir_, "region.tess",
                     "round 0.01\nmaterial define rock density=2600 E=10e9 nu=0.25\n"
                     "material define soft density=2000 E=1e9 nu=0.3\n"
                     "joint define joints kn=1e10 ks=1e10 friction=30\n"
                     "joint define glue kn=1e10 ks=1e10 friction=40 cohesion=1e6 tension=1e6\n"
                     "joint assign joints\nregion 0,0 10,6 group=rock material=rock\n");
    QVERIFY(!path.isEmpty());
    MainWindow w;
    QVERIFY(open_shown(w, path));
    w.view()->resetCamera();
    QTest::qWait(50);
    // Openings and generators preview their outlines; cancelled, nothing runs.
    CommandDialog* opening = w.openDialog("tunnel");
    QCOMPARE(w.view()->previewSegments(), size_t(24));
    opening->setValue("segments", "32");
    QCOMPARE(w.view()->previewSegments(), size_t(32));
    opening->reject();
    QCOMPARE(w.view()->previewSegments(), size_t(0));
    CommandDialog* wall = w.openDialog("wall");
    QCOMPARE(w.view()->previewSegments(), size_t(4 * (5 * 8 + 5 * 9)));  // 10 courses
    wall->reject();
    QCOMPARE(w.journal().size(), 7);
    // Gravity and damping have dialogs of their own.
    CommandDialog* gravity = w.openDialog("gravity");
    QVERIFY(gravity);
    QCOMPARE(gravity->command(), QString("gravity 0 -9.81"));
    gravity->reject();
    CommandDialog* damping = w.openDialog("damping");
    QVERIFY(damping);
    damping->setValue("#mode", "global");
    QCOMPARE(damping->command(), QString("damping global"));
    damping->reject();
    // The joint set dialog, typed into; the traces show before the cut.
    CommandDialog* d = w.openDialog("jset");
    QVERIFY(d);
    auto* angle = d->findChild<QLineEdit*>("angle");
    auto* spacing = d->findChild<QLineEdit*>("spacing");
    QVERIFY(angle && spacing);
    angle->clear(), spacing->clear();
    QTest::keyClicks(angle, "0");
    QTest::keyClicks(spacing, "2");
    QCOMPARE(w.view()->previewSegments(), size_t(4));  // y = 0, 2, 4, 6 across the box
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/jset_preview.png");
    d->accept();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.journal().last(), QString("jset angle=0 spacing=2"));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(3));
    QCOMPARE(w.view()->previewSegments(), size_t(0));
    // A box over the middle and top blocks (centroids at y = 3 and 5).
    w.setTool(DrawMode::kSelect);
    QTest::mousePress(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({-0.5, 2.5}));
    QTest::mouseMove(w.view(), w.view()->pixelOf({5, 4}));
    QTest::mouseMove(w.view(), w.view()->pixelOf({10.5, 6.5}));
    QTest::mouseRelease(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({10.5, 6.5}));
    QCOMPARE(w.selectedBlocks().size(), size_t(2));
    const std::vector<int> chosen = w.selectedBlocks();
    if (qEnvironmentVariableIsSet("TESSERA_TEST_SHOTS"))
      w.grab().save(qEnvironmentVariable("TESSERA_TEST_SHOTS") + "/selection.png");
    QVERIFY(w.selection().startsWith("x=") && w.selection().contains(" y="));
    d = w.openDialog("assign");
    d->setValue("group", "upper");
    d->setValue("material", "soft");
    d->setValue("joint", "glue");
    d->accept();
    QTRY_VERIFY_WITH_TIMEOUT(!w.busy() && w.journal().last().startsWith("joint assign"), 20000);
    QCOMPARE(w.journal().last(), QString("joint assign glue groups=upper,upper"));
    // The selected blocks zoned through the Zones dialog (it acts on the selection).
    d = w.openDialog("zones");
    d->setValue("edge", "1");
    QVERIFY(d->command().startsWith("zone generate edge=1 x="));
    d->accept();
    QVERIFY(wait_finished(w));
    QVERIFY(w.snapshot()->zones.size() > 20);
    // A click on the top edge of the zoned top block selects that outline edge; a stress on it
    // through the Boundary dialog.
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({5, 6.0}));
    QVERIFY2(w.selection().startsWith("x=") && w.selectedBlocks().empty(),
             qPrintable(w.selection()));
    d = w.openDialog("boundary");
    d->setValue("stress", "0,-1e6,0");
    d->accept();
    QVERIFY(wait_finished(w));
    QVERIFY(w.journal().last().startsWith("boundary stress=0,-1e6,0 x="));
    QVERIFY(w.console()->text().contains("boundary stress on 1 edges"));
    // The model tree lists it with the other conditions: two loaded nodes, the resultant the
    // stress times the edge's length (the selection's box around the edge, a hair wider).
    const QStringList xs = w.selection().section(' ', 0, 0).mid(2).split(',');
    const double edge = xs[1].toDouble() - xs[0].toDouble();
    bool listed = false;
    for (const Entry& e : w.snapshot()->conditions)
      if (e.name == "applied stress or pressure (zone nodes)") {
        listed = true;
        QCOMPARE(e.properties[0].second, std::string("2"));
        qInfo("%s: %s %s (edge %.4g m)", e.name.c_str(), e.properties[2].first.c_str(),
              e.properties[2].second.c_str(), edge);
        const double resultant = std::stod(e.properties[2].second);
        QVERIFY(std::abs(resultant + 1e6 * edge) < 1e-4 * 1e6 * edge);
      }
    QVERIFY(listed);
    const Snapshot& s = *w.snapshot();
    const auto& groups = s.groups;
    int upper = 0;
    for (const int b : chosen) {
      const SnapshotBlock& blk = s.blocks[size_t(b)];
      QCOMPARE(QString::fromStdString(groups[size_t(blk.group)]), QString("upper"));
      QCOMPARE(QString::fromStdString(s.materials[size_t(blk.material)].name), QString("soft"));
      ++upper;
    }
    QCOMPARE(upper, 2);
    // The saved script rebuilds it in batch: the same groups and materials.
    const QString saved = dir_.filePath("region_saved.tess");
    QVERIFY(w.saveScript(saved));
    Interpreter batch(dir_.filePath("region_out").toStdString());
    batch.run_file(saved.toStdString());
    const Model& m = batch.model();
    QCOMPARE(m.blocks.size(), s.blocks.size());
    QCOMPARE(m.continuum.zone_count(), s.zones.size());
    for (size_t b = 0; b < m.blocks.size(); ++b) {
      QCOMPARE(m.blocks.group[b], s.blocks[b].group);
      QCOMPARE(m.blocks.material[b], s.blocks[b].material);
      QCOMPARE(bool(m.blocks.deformable[b]), s.blocks[b].deformable);
    }
    // Five undos take the boundary stress, the zones and the assignments back.
    for (int k = 0; k < 5; ++k) {
      w.undo();
      QVERIFY(wait_finished(w));
    }
    for (const int b : chosen)
      QCOMPARE(QString::fromStdString(
                   w.snapshot()->materials[size_t(w.snapshot()->blocks[size_t(b)].material)].name),
               QString("rock"));
  }

  // Enter finishes a shape wherever the focus is (here the console's empty command line), and
  // clicking the tool that is on keeps it on.
  void enterFinishesAShapeAnywhere() {
    const QString path = write_script(dir_, "enter.tess",
                                      "round 0.005\nmaterial define stone density=2500\n"
                                      "block 0,0 4,0 4,1 0,1 material=stone\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    w.view()->resetCamera();
    QTest::qWait(50);
    w.setDrawingDefaults(0.25, "", "stone");
    QAction* crack = nullptr;
    for (QAction* a : w.findChildren<QAction*>())
      if (a->text() == "Crack") crack = a;
    QVERIFY(crack);
    crack->trigger();
    QVERIFY(crack->isChecked());
    crack->trigger();  // clicked again: still on
    QVERIFY(crack->isChecked());
    QCOMPARE(w.view()->drawing().mode(), DrawMode::kCrack);
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({-0.25, 0.5}));
    QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({4.25, 0.5}));
    QLineEdit* line = w.console()->input();
    line->setFocus();
    QTest::keyClick(line, Qt::Key_Return);
    QVERIFY(wait_finished(w));
    QCOMPARE(w.journal().last(), QString("crack -0.25,0.5 4.25,0.5"));
    QCOMPARE(w.snapshot()->blocks.size(), size_t(2));
  }

  // A block drawn in a new model, before any rounding length is set: a default one is set
  // first and said in the console, and the block is made (before, the command failed and the
  // drawn polygon was lost).
  void blockToolInANewModelUsesAStatedRounding() {
    const QString path = write_script(dir_, "empty.tess", "; nothing yet\n");
    MainWindow w;
    QVERIFY(open_shown(w, path));
    w.setDrawingDefaults(0.5, "", "");
    w.view()->resetCamera();
    QTest::qWait(50);
    w.setTool(DrawMode::kBlock);
    for (const Vec2& p : {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1)})
      QTest::mouseClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf(p));
    QTest::mouseDClick(w.view(), Qt::LeftButton, {}, w.view()->pixelOf({0, 1}));
    QTRY_VERIFY_WITH_TIMEOUT(!w.busy() && w.snapshot()->blocks.size() == 1, 20000);
    QVERIFY(w.journal().contains("round 0.01"));
    QCOMPARE(w.journal().last(), QString("block 0,0 2,0 2,1 0,1"));
    QVERIFY(w.console()->text().contains("no rounding length set yet: round 0.01"));
  }

  // A closed panel comes back from the View menu.
  void viewMenuReopensPanels() {
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QDockWidget* console = nullptr;
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
      if (d->windowTitle() == "Console") console = d;
    QVERIFY(console && console->isVisible());
    console->close();
    QVERIFY(!console->isVisible());
    QAction* reopen = nullptr;
    for (QAction* menu : w.menuBar()->actions())
      if (menu->text() == "&View")
        for (QAction* a : menu->menu()->actions())
          if (a->text() == "Console") reopen = a;
    QVERIFY(reopen);
    reopen->trigger();
    QVERIFY(console->isVisible());
  }

  // Commands typed one after another at the console all run: the line keeps its focus while
  // the solver runs, and a command entered meanwhile waits its turn (before, the line was
  // disabled during a run and the second command was lost).
  void typedCommandsAreNotLost() {
    MainWindow w;
    w.show();
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    const uint64_t start = w.snapshot()->cycle;
    QLineEdit* line = w.console()->input();
    line->setFocus();
    QTest::keyClicks(line, "step 300000");
    QTest::keyClick(line, Qt::Key_Return);
    QVERIFY(w.busy());
    QVERIFY(line->isEnabled());
    QTest::keyClicks(line, "step 7");
    QTest::keyClick(line, Qt::Key_Return);
    QVERIFY(wait_finished(w));
    QTRY_VERIFY_WITH_TIMEOUT(!w.busy() && w.snapshot()->cycle == start + 300007, 120000);
    QVERIFY(w.console()->text().contains("queued: step 7"));
    QCOMPARE(line->text(), QString());
  }

  // The console's Python: `m` is the window's model. Printed output reaches the log; a
  // statement over several lines runs when an empty line ends it; an on_cycle callback runs
  // during the window's own step; an exception is shown with the model as it was; Python lines
  // are journaled as comments and undone as one command.
  void pythonConsoleDrivesTheModel() {
    MainWindow w;
    w.show();
    if (w.console()->findChild<QToolButton*>("pythonMode")->isHidden())
      QSKIP("this build has no Python");
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    ConsoleWidget* console = w.console();
    QLineEdit* line = console->input();
    const auto type = [&](const QString& text) {
      line->setText(text);
      QTest::keyClick(line, Qt::Key_Return);
    };
    console->setPythonMode(true);
    type("print('blocks', len(m.blocks.id), 'dim', m.dim)");
    QVERIFY(wait_finished(w));
    QVERIFY(console->text().contains("blocks 3 dim 2"));
    // A function over three lines: nothing runs until the empty line.
    type("def counter(model):");
    QTRY_VERIFY(!w.busy());
    type("    seen.append(model.cycles)");
    QTRY_VERIFY(!w.busy());
    type("");
    QVERIFY(wait_finished(w));
    type("seen = []; m.on_cycle(counter, every=10)");
    QVERIFY(wait_finished(w));
    const uint64_t start = w.snapshot()->cycle;
    console->setPythonMode(false);
    type("step 30");
    QVERIFY(wait_finished(w));
    console->setPythonMode(true);
    type("print('calls', len(seen))");
    QVERIFY(wait_finished(w));
    QVERIFY(console->text().contains("calls 3"));
    // A statement left open when the mode changes is dropped, not glued to the next one.
    type("for k in range(2):");
    QTRY_VERIFY(!w.busy());
    console->setPythonMode(false);
    console->setPythonMode(true);
    type("print('fresh', 2 + 2)");
    QVERIFY(wait_finished(w));
    QVERIFY(console->text().contains("fresh 4"));
    // An exception after a run: the traceback in the log, the model back where it was.
    type("m.cycle(20); 1/0");
    QVERIFY(!wait_finished(w));
    QVERIFY(console->text().contains("ZeroDivisionError: division by zero"));
    QCOMPARE(w.snapshot()->cycle, start + 30);
    QVERIFY(w.errorBox() && w.errorBox()->text().contains("ZeroDivisionError"));
    w.errorBox()->close();
    // A run from Python, journaled as comments, then undone.
    type("m.cycle(5)");
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->cycle, start + 35);
    QVERIFY(w.journal().contains("; python>     seen.append(model.cycles)"));
    QCOMPARE(w.journal().last(), QString("; python> m.cycle(5)"));
    w.undo();
    QVERIFY(wait_finished(w));
    QCOMPARE(w.snapshot()->cycle, start + 30);
    QCOMPARE(w.journal().last(), QString("; python> print('fresh', 2 + 2)"));
  }

  // A bad command and a diverging run: an error in the console and a message, the model as
  // it was before the command.
  void badCommandLeavesModel() {
    MainWindow w;
    w.show();
    w.openScript(script_);
    QVERIFY(wait_finished(w));
    w.step(50);
    QVERIFY(wait_finished(w));
    const auto before = w.snapshot();
    w.runCommand("blok 0,0 1,0 1,1");
    QVERIFY(!wait_finished(w));
    QVERIFY(w.console()->text().contains(
        "<console>:2: unknown command 'blok' (did you mean 'block'?)"));
    QVERIFY(w.errorBox() && w.errorBox()->isVisible());
    // A fixed time step far too large: the run diverges and is rolled back.
    w.runCommand("timestep fixed 0.5");
    QVERIFY(wait_finished(w));
    w.step(1000);
    QVERIFY(!wait_finished(w));
    QVERIFY(w.console()->text().contains("diverged"));
    const auto after = w.snapshot();
    QCOMPARE(after->cycle, before->cycle);
    QCOMPARE(after->blocks.size(), before->blocks.size());
    for (size_t b = 0; b < after->blocks.size(); ++b) {
      QCOMPARE(after->blocks[b].x, before->blocks[b].x);
      QCOMPARE(after->blocks[b].y, before->blocks[b].y);
    }
  }
};

int main(int argc, char** argv) {
  VtkView::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  TestGui t;
  return QTest::qExec(&t, argc, argv);
}

#include "test_gui.moc"
