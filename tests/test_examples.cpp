// Every example runs headless through the tessera executable; its results are checked as
// numbers against closed-form estimates, with tolerances, never as text.
#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QProcess>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "support.hpp"

namespace {

struct Run {
  int exit_code = -1;
  QString out, err, dir;
};

// Runs `tessera --batch` on an example into a fresh folder.
Run run_example(const QString& name, const QStringList& extra, QTemporaryDir& dir) {
  QProcess p;
  Run r;
  r.dir = dir.path() + "/" + name;
  p.start(TESSERA_EXE,
          QStringList{"--batch", QString(TESSERA_EXAMPLES) + "/" + name + ".tess", "--out", r.dir} +
              extra);
  p.waitForFinished(600000);
  r.exit_code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  r.out = p.readAllStandardOutput();
  r.err = p.readAllStandardError();
  return r;
}

// Runs `tessera --batch` on a script file into a fresh folder beside it.
Run run_script(const QString& path, int timeout_ms = 600000) {
  QProcess p;
  Run r;
  r.dir = path + "_out";
  p.start(TESSERA_EXE, QStringList{"--batch", path, "--out", r.dir, "--quiet"});
  p.waitForFinished(timeout_ms);
  r.exit_code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  r.out = p.readAllStandardOutput();
  r.err = p.readAllStandardError();
  return r;
}

// Writes text (bytes as they are) to a file in dir; returns its path.
QString write_file(QTemporaryDir& dir, const QString& name, const std::string& text) {
  const QString path = dir.filePath(name);
  std::ofstream(path.toStdString(), std::ios::binary) << text;
  return path;
}

// A figure a script wrote: the size asked for, and a drawing, not a blank page.
// Support drawn purple (elastic) in the plot, left of 2/5 of the width and right of it (to the
// legend, at 3/4): the twin tunnels' left and right.
std::pair<long, long> purple_left_right(const QImage& img) {
  long left = 0, right = 0;
  for (int py = 0; py < img.height(); ++py)
    for (int px = 0; px < img.width() * 3 / 4; ++px) {
      const QColor c = img.pixelColor(px, py);
      if (c.red() > 140 && c.green() < 40 && c.blue() > 140)
        ++(px < img.width() * 2 / 5 ? left : right);
    }
  return {left, right};
}

// Pixels of a figure's plot (left of the legend, at 3/4 of the width) at the top of the force
// ramp (red) and in the support's elastic colour (purple).
std::pair<long, long> red_purple(const QImage& img) {
  long red = 0, purple = 0;
  for (int py = 0; py < img.height(); ++py)
    for (int px = 0; px < img.width() * 3 / 4; ++px) {
      const QColor c = img.pixelColor(px, py);
      red += c.red() > 190 && c.green() < 60 && c.blue() < 60;
      purple += c.red() > 140 && c.green() < 40 && c.blue() > 140;
    }
  return {red, purple};
}

void check_figure(const QString& path, QSize size) {
  QVERIFY2(QFile::exists(path), qPrintable(path));
  QImage img;
  if (path.endsWith(".svg")) {
    QSvgRenderer svg(path);
    QVERIFY(svg.isValid());
    QCOMPARE(svg.viewBoxF().size(), QSizeF(size));
    img = QImage(size, QImage::Format_ARGB32);
    img.fill(Qt::white);
    QPainter p(&img);
    svg.render(&p);
  } else if (path.endsWith(".pdf")) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    QVERIFY(bytes.startsWith("%PDF-") && bytes.contains("%%EOF") && bytes.size() > 2000);
    return;
  } else {
    img = QImage(path);
    QCOMPARE(img.size(), size);
  }
  long coloured = 0;
  for (int y = 0; y < img.height(); y += 4)
    for (int x = 0; x < img.width(); x += 4) coloured += img.pixel(x, y) != qRgb(255, 255, 255);
  const long samples = long(img.width() / 4) * long(img.height() / 4);
  QVERIFY2(coloured > samples / 20,
           qPrintable(QString("%1 of %2 drawn").arg(coloured).arg(samples)));
}

// history.csv as columns by heading.
std::map<std::string, std::vector<double>> read_history(const QString& dir) {
  std::ifstream in((dir + "/history.csv").toStdString());
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> heads;
  for (std::istringstream s(line); std::getline(s, cell, ',');) heads.push_back(cell);
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    for (size_t c = 0; std::getline(s, cell, ',') && c < heads.size(); ++c)
      cols[heads[c]].push_back(cell.empty() ? std::nan("") : std::stod(cell));
  }
  return cols;
}

// Checks a VTK XML PolyData or UnstructuredGrid file: well-formed, and every data array holds as
// many tuples as the piece has points or cells, the connectivity as many as the offsets end at
// (`types`, if given, receives the cell types). Returns the number of cells, or -1 with a message.
long check_vtp(const QString& path, QString& why, std::set<int>* types = nullptr) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return why = "cannot open " + path, -1;
  QXmlStreamReader xml(&f);
  long points = -1, cells = -1, connectivity = -1;
  QString section;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    const auto name = xml.name();
    const auto at = xml.attributes();
    if (name == QLatin1String("Piece")) {
      points = at.value("NumberOfPoints").toLong();
      cells = at.value("NumberOfPolys").toLong() + at.value("NumberOfLines").toLong() +
              at.value("NumberOfVerts").toLong() + at.value("NumberOfCells").toLong();
    } else if (name == QLatin1String("Points") || name == QLatin1String("CellData") ||
               name == QLatin1String("PointData") || name == QLatin1String("Polys") ||
               name == QLatin1String("Lines") || name == QLatin1String("Verts") ||
               name == QLatin1String("Cells")) {
      section = name.toString();
    } else if (name == QLatin1String("DataArray")) {
      const long comps = at.value("NumberOfComponents").toLong();
      const QString array = at.value("Name").toString();
      const QStringList text =
          xml.readElementText().split(QRegularExpression("\\s+"), Qt::SkipEmptyParts);
      const long values = text.size();
      if (array == "connectivity") connectivity = values;
      if (array == "offsets" && section == "Cells" && !text.isEmpty() &&
          text.back().toLong() != connectivity)
        return why = path + ": the offsets end at " + text.back() + ", the connectivity has " +
                     QString::number(connectivity),
               -1;
      if (array == "types" && types)
        for (const QString& t : text) types->insert(t.toInt());
      const long expect = section == "Points"      ? 3 * points
                          : section == "PointData" ? comps * points
                          : section == "CellData"  ? comps * cells
                          : array == "offsets"     ? cells
                          : array == "types"       ? cells
                                                   : -2;
      if (expect != -2 && values != expect)
        return why = QString("%1: %2 has %3 values, expected %4")
                         .arg(path, array)
                         .arg(values)
                         .arg(expect),
               -1;
    }
  }
  if (xml.hasError()) return why = path + ": " + xml.errorString(), -1;
  return cells;
}

// Every DataArray of a VTK XML file as numbers, by name (the points' coordinates as "Points").
std::map<QString, std::vector<double>> read_vtp_arrays(const QString& path) {
  std::map<QString, std::vector<double>> arrays;
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return arrays;
  QXmlStreamReader xml(&f);
  while (!xml.atEnd())
    if (xml.readNextStartElement() && xml.name() == QLatin1String("DataArray")) {
      auto& v = arrays[xml.attributes().value("Name").toString()];
      for (const QString& t :
           xml.readElementText().split(QRegularExpression("\\s+"), Qt::SkipEmptyParts))
        v.push_back(t.toDouble());
    }
  return arrays;
}

QJsonObject read_summary(const QString& dir) {
  QFile f(dir + "/summary.json");
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QJsonDocument::fromJson(f.readAll()).object();
}

}  // namespace

class TestExamples : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void brickWallSettlesElastically() {
    const Run r = run_example("brick_wall", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    const QJsonObject s = read_summary(r.dir);
    QVERIFY(s["final_ratio"].toDouble() <= 1e-6);
    QCOMPARE(s["blocks"].toInt(), 79);
    auto h = read_history(r.dir);
    // Joint k from the top carries k courses: settlement = rho g H N (N+1) / (2 kn). The springs
    // sit at the arc centres, a few per cent inside each face, so allow 5%.
    const double expected = 2200 * 9.81 * 0.3 * 12 * 13 / (2 * 5e10);
    const double top = -h["top_settlement"].back();
    qInfo("top settlement %.4e m, estimate %.4e m", top, expected);
    QVERIFY(std::abs(top - expected) < 0.05 * expected);
    QVERIFY(QFile::exists(r.dir + "/vtk/blocks.pvd") && QFile::exists(r.dir + "/vtk/contacts.pvd"));
    // The ParaView files are well-formed and consistent.
    QString why;
    QCOMPARE(check_vtp(r.dir + "/vtk/blocks_0000.vtp", why), 79L);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    QCOMPARE(check_vtp(r.dir + "/vtk/contacts_0000.vtp", why),
             static_cast<long>(s["contacts"].toInt()));
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }
  void brickWallIsTheSameAtTwoThreads() {
    QTemporaryDir other;
    const Run one = run_example("brick_wall", {"--threads", "1"}, dir_);
    const Run two = run_example("brick_wall", {"--threads", "2"}, other);
    QCOMPARE(two.exit_code, 0);
    QFile a(one.dir + "/history.csv"), b(two.dir + "/history.csv");
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(a.readAll(), b.readAll());
  }
  void blockOnInclineAcceleratesAsCoulombSays() {
    const Run r = run_example("block_on_incline", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double t = h["time"].back();
    const double v = std::hypot(h["xvel_2"].back(), h["yvel_2"].back());
    const double a = 9.81 * (std::sin(M_PI / 6) - std::cos(M_PI / 6) * std::tan(M_PI / 9));
    qInfo("speed %.5f m/s after %.4f s, closed form %.5f", v, t, a * t);
    QVERIFY(t > 1.0);
    QVERIFY(std::abs(v - a * t) < 0.01 * a * t);
  }
  void stackTopples() {
    const Run r = run_example("toppling_stack", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    // Once the top block has turned 45 degrees (downhill, counter-clockwise), the stack is
    // turning as one body: the bottom block has turned too, and its foot has not slid (friction
    // 40 > 15 degrees). What happens after the fall is chaotic and not checked.
    const auto& top = h["top_rotation"];
    size_t row = 0;
    while (row < top.size() && top[row] < M_PI / 4) ++row;
    QVERIFY2(row < top.size(), "the stack did not topple");
    const double bottom = h["bottom_rotation"][row], moved = h["xdisp_2"][row];
    // Turning about its downhill toe (at the origin) moves the bottom block's centroid, first at
    // (0.25, 0.5) in the slope frame, by exactly this much.
    const double psi = 15 * M_PI / 180;
    const double cx = 0.25 * std::cos(psi) - 0.5 * std::sin(psi);
    const double cy = 0.25 * std::sin(psi) + 0.5 * std::cos(psi);
    const double pivoted = std::cos(bottom) * cx - std::sin(bottom) * cy - cx;
    qInfo(
        "at 45 degrees of the top block: bottom block turned %.3f rad, moved %.4f m, "
        "pivoting on its toe would move it %.4f m",
        bottom, moved, pivoted);
    QVERIFY(bottom > 0.3);
    QVERIFY(std::abs(moved - pivoted) < 0.02);
  }
  // Bad input found by independent checks (issue 13): each script ends with a message that
  // starts with its file and line, exit status 1 and its results written; never a signal.
  void badInputCorpusEndsWithFileAndLine() {
    const std::string base =
        "round 0.01\nmaterial define rock density=2000\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n";
    const std::string base3 =
        "dimension 3\ntolerance 0.01\nmaterial define rock density=2000\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n";
    const std::vector<std::pair<std::string, std::string>> corpus = {
        {"nesting", "set x = " + std::string(50000, '(') + "1" + std::string(50000, ')') + "\n"},
        {"signs", "set x = " + std::string(50000, '-') + "1\n"},
        {"folder", "call .\n"},
        {"overlap_made", base +
                             "block 0,0 1,0 1,1 0,1 material=rock\nblock 0.5,0 1.5,0 1.5,1 0.5,1 "
                             "material=rock\nstep 1\n"},
        {"duplicate", base + "block 0,0 1,0 1,1 0,1 material=rock\n"
                             "block 0,0 1,0 1,1 0,1 material=rock\nstep 1\n"},
        {"overlap_too_great",
         "round 0.01\nmaterial define rock density=2000\njoint define j kn=1e5 ks=1e5 "
         "friction=40\njoint assign j\nblock -5,-5 5,-5 5,0 -5,0 material=rock\nfix block=1\n"
         "block 0,0 1,0 1,1 0,1 material=rock\ngravity 0 -10\nstep 20000\n"},
        {"no_point", base + "block 0,0 1,0 1,1 0,1 material=rock\nhistory ydisp at=5,5\n"},
        {"join_apart", base3 + "block box 0,0,0 1,1,1 material=rock\n"
                               "block box 3,0,0 4,1,1 material=rock\njoin block=1,2\n"},
        {"bad_state", "restore nonsense.state\n"},
        {"diverges", base + "block 0,-1 2,-1 2,0 0,0 material=rock\nfix block=1\n"
                            "block 0,0 1,0 1,1 0,1 material=rock\ntimestep fixed 1\n"
                            "gravity 0 -10\nstep 100\n"},
        {"unknown_bom", "\xEF\xBB\xBFstpe 10\n"},
        {"bad_title", "title caf\xE9\nround -1\n"},
    };
    // A state file whose block index was overwritten.
    write_file(dir_, "nonsense.state", std::string("TESSERA2") + std::string(64, '\xff'));
    for (const auto& [name, text] : corpus) {
      const QString path = write_file(dir_, QString::fromStdString(name) + ".tess", text);
      const Run r = run_script(path, 120000);
      const QString last = r.err.trimmed().split('\n').last();
      qInfo("%s: exit %d, %s", name.c_str(), r.exit_code, qPrintable(last.left(160)));
      QVERIFY2(r.exit_code == 1, name.c_str());
      QVERIFY2(QRegularExpression("^" + QRegularExpression::escape(path) + ":\\d+: ")
                   .match(last)
                   .hasMatch(),
               name.c_str());
      QVERIFY2(
          QFile::exists(r.dir + "/summary.json") && QFileInfo(r.dir + "/summary.json").size() > 0,
          name.c_str());
      // The summary says the results are partial, and why.
      QFile f(r.dir + "/summary.json");
      QVERIFY(f.open(QIODevice::ReadOnly));
      const QJsonObject summary = QJsonDocument::fromJson(f.readAll()).object();
      QCOMPARE(summary["status"].toString(), QString("error"));
      QCOMPARE(summary["error"].toString(), last);
    }
  }

  // Ctrl-C or SIGTERM in a batch run: it stops at a cycle boundary, writes every result and a
  // state file that 'restore' continues from, says where, and exits 128 + the signal.
  void signalStopsTheRunWithItsResults() {
    const std::string text =
        "round 0.01\nmaterial define rock density=2000\n"
        "joint define j kn=1e9 ks=1e9 friction=30\njoint assign j\n"
        "block 0,-1 2,-1 2,0 0,0 material=rock\nfix block=1\n"
        "block 0,0 1,0 1,1 0,1 material=rock\ngravity 0 -10\nhistory ratio\n"
        "history interval 1000\nvtk\nstep 2000000000\n";
    for (const int sig : {SIGINT, SIGTERM}) {
      const QString path = write_file(dir_, QString("long_%1.tess").arg(sig), text);
      QProcess p;
      const QString out = path + "_out";
      p.start(TESSERA_EXE, QStringList{"--batch", path, "--out", out});
      QVERIFY(p.waitForStarted());
      // Wait until it is past 'vtk' (its folder exists: the handlers are in place), then signal.
      QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(out + "/vtk"), 60000);
      QTest::qWait(300);
      ::kill(static_cast<pid_t>(p.processId()), sig);
      QVERIFY(p.waitForFinished(120000));
      QCOMPARE(p.exitStatus(), QProcess::NormalExit);
      QCOMPARE(p.exitCode(), 128 + sig);
      const QString err = p.readAllStandardError();
      qInfo("%s", qPrintable(err.trimmed()));
      QVERIFY(err.contains(sig == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM"));
      QVERIFY(QFileInfo(out + "/summary.json").size() > 0);
      const QJsonObject stopped = QJsonDocument::fromJson([&] {
                                    QFile f(out + "/summary.json");
                                    f.open(QIODevice::ReadOnly);
                                    return f.readAll();
                                  }())
                                      .object();
      QCOMPARE(stopped["status"].toString(), QString("interrupted"));
      QCOMPARE(stopped["error"].toString(), QString(sig == SIGINT ? "SIGINT" : "SIGTERM"));
      QVERIFY(QFile::exists(out + "/history.csv"));
      QVERIFY(QFile::exists(out + "/vtk/blocks.pvd"));
      QVERIFY(QFile::exists(out + "/interrupted.state"));
      // The state goes on from where it stopped.
      const QString more =
          write_file(dir_, QString("more_%1.tess").arg(sig),
                     "restore " + (out + "/interrupted.state").toStdString() + "\nstep 10\n");
      const Run r = run_script(more);
      QCOMPARE(r.exit_code, 0);
      const auto summary = QJsonDocument::fromJson([&] {
                             QFile f(r.dir + "/summary.json");
                             f.open(QIODevice::ReadOnly);
                             return f.readAll();
                           }())
                               .object();
      QVERIFY(summary["cycles"].toDouble() > 10);
      QCOMPARE(summary["status"].toString(), QString("completed"));
    }
  }

  // SIGTERM while a 3D block is being meshed (a job of a million zones, minutes long) stops the
  // mesher at once: the block is left rigid, and the results and the state are written as for
  // a stop between cycles.
  void signalStopsTheMesher() {
    const QString path = write_file(dir_, "mesh_long.tess",
                                    "dimension 3\nmaterial define rock density=2000 E=1e9 nu=0.25\n"
                                    "block box 0,0,0 8,8,8 material=rock\nvtk\n"
                                    "print \"meshing\"\nzone generate edge=0.16\nstep 10\n");
    QProcess p;
    const QString out = path + "_out";
    p.start(TESSERA_EXE, QStringList{"--batch", path, "--out", out});
    QVERIFY(p.waitForStarted());
    QByteArray said;
    QTRY_VERIFY_WITH_TIMEOUT((said += p.readAllStandardOutput()).contains("meshing"), 60000);
    QTest::qWait(500);  // well into the mesh, which takes far longer
    ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
    QVERIFY(p.waitForFinished(120000));
    said += p.readAllStandardOutput();
    const QString err = p.readAllStandardError();
    qInfo("%s\n%s", said.trimmed().constData(), qPrintable(err.trimmed()));
    QCOMPARE(p.exitCode(), 128 + SIGTERM);
    QVERIFY(said.contains("zone generate stopped while meshing block 1"));
    QVERIFY(err.contains("interrupted by SIGTERM at cycle 0"));
    QVERIFY(QFile::exists(out + "/interrupted.state"));
    QVERIFY(QFileInfo(out + "/summary.json").size() > 0);
  }

  void tunnelStandsThenIsExcavated() {
    const Run r = run_example("tunnel_jointed", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    // Before excavation the model came to rest (the solve's ratio limit was reached) ...
    const auto& ratio = h["ratio"];
    QVERIFY(*std::min_element(ratio.begin(), ratio.end()) <= 1e-5);
    // ... and the crown block history was written through both stages. Under gravity alone the
    // crown only settles: it rose 7.9 mm when the flat corners of the opening's pieces met
    // their neighbours' faces with their arcs' full circles (0.1 m overlaps of blocks that
    // merely touch).
    QVERIFY(h["crown"].size() > 100);
    QVERIFY(*std::max_element(h["crown"].begin(), h["crown"].end()) < 1e-3);
    QVERIFY(QFile::exists(r.dir + "/before.sav"));
    QVERIFY(read_summary(r.dir)["blocks"].toInt() > 100);
    check_figure(r.dir + "/tunnel_displacement.png", QSize(1600, 1200));
    check_figure(r.dir + "/tunnel_contacts.pdf", QSize(1600, 1000));
  }
  void boltsHoldTheRoofWedge() {
    const Run r = run_example("tunnel_bolted", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double free_fall = h["wedge_left"].back(), bolted = h["wedge_right"].back();
    qInfo("unsupported wedge %.3f m, bolted wedge %.3g mm, bolt axial force %.4g N/m", free_fall,
          1e3 * bolted, h["bolt_axial_right-2"].back());
    QVERIFY(free_fall < -0.3);                      // the unsupported wedge falls out
    QVERIFY(std::abs(bolted) < 2e-3);               // the bolts hold theirs within millimetres
    QVERIFY(h["bolt_axial_right-2"].back() > 1e3);  // in tension
    QString why;
    QVERIFY2(check_vtp(r.dir + "/vtk/support_0000.vtp", why) > 0, qPrintable(why));
    check_figure(r.dir + "/tunnel_bolted.png", QSize(1600, 900));
    // The bolts are drawn (purple while elastic) over the right tunnel's roof, and only there.
    const QImage img(r.dir + "/tunnel_bolted.png");
    const auto [left, right] = purple_left_right(img);
    qInfo("bolt pixels: %ld over the left tunnel, %ld over the right", left, right);
    QVERIFY(right > 500);
    QCOMPARE(left, 0L);
  }
  // The same wedges held by grouted cables, which carry the right wedge's weight in tension and
  // are drawn over the right tunnel only.
  void cablesHoldTheRoofWedge() {
    const Run r = run_example("tunnel_cabled", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double free_fall = h["wedge_left"].back(), held = h["wedge_right"].back();
    const double axial = h["cable_axial_right-2"].back();
    qInfo("unsupported wedge %.3f m, cabled wedge %.3g mm, cable axial force %.4g N/m", free_fall,
          1e3 * held, axial);
    QVERIFY(free_fall < -0.3);
    QVERIFY(std::abs(held) < 2e-3);
    QVERIFY(axial > 1e3);
    QString why;
    QVERIFY2(check_vtp(r.dir + "/vtk/support_0000.vtp", why) > 0, qPrintable(why));
    check_figure(r.dir + "/tunnel_cabled.png", QSize(1600, 900));
    const QImage img(r.dir + "/tunnel_cabled.png");
    const auto [left, right] = purple_left_right(img);
    qInfo("cable pixels: %ld over the left tunnel, %ld over the right", left, right);
    QVERIFY(right > 2000);
    QCOMPARE(left, 0L);
    // Coloured by axial force over the crown: the cables across the wedge's joints are red
    // (the top of the scale) where they cross, and none is drawn purple.
    check_figure(r.dir + "/tunnel_cabled_force.png", QSize(1600, 900));
    const auto [red, purple] = red_purple(QImage(r.dir + "/tunnel_cabled_force.png"));
    qInfo("force figure: %ld red pixels, %ld purple", red, purple);
    QVERIFY(red > 100);
    QCOMPARE(purple, 0L);
  }
  // The jointed tunnel dug twice from one saved state: unsupported, the wedge the fault cuts over
  // the crown drops out; bolted, it stays within a millimetre. The script prints both stages'
  // numbers; the ParaView snapshots and figures show which joints slip (red) and the bolts.
  void boltsHoldTheJointedTunnelsCrown() {
    const Run r = run_example("tunnel_support_compare", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    const QRegularExpressionMatch settle =
        QRegularExpression("crown settlement \\(m\\): unsupported (\\S+) bolted (\\S+)")
            .match(r.out);
    const QRegularExpressionMatch slip =
        QRegularExpression("contacts slipping: unsupported (\\d+) bolted (\\d+)").match(r.out);
    QVERIFY2(settle.hasMatch() && slip.hasMatch(), qPrintable(r.out));
    bool ok[4];
    const double free_fall = settle.captured(1).toDouble(&ok[0]);
    const double bolted = settle.captured(2).toDouble(&ok[1]);
    const int free_slipping = slip.captured(1).toInt(&ok[2]);
    const int bolted_slipping = slip.captured(2).toInt(&ok[3]);
    QVERIFY(ok[0] && ok[1] && ok[2] && ok[3]);
    // Snapshot 0 is the end of the unsupported stage, 1 the end of the run (bolted).
    QString why;
    for (const char* f : {"contacts_0000", "contacts_0001", "support_0001"})
      QVERIFY2(check_vtp(r.dir + "/vtk/" + f + ".vtp", why) > 0, qPrintable(why));
    QVERIFY(!QFile::exists(r.dir + "/vtk/support_0000.vtp"));  // no support yet
    const auto support = read_vtp_arrays(r.dir + "/vtk/support_0001.vtp");
    const auto& axial_force = support.at("axial_force");
    const double axial = *std::max_element(axial_force.begin(), axial_force.end());
    // Contacts at their shear strength within 7 m of the tunnel's centre (the bolts' reach).
    long near[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
      const auto c = read_vtp_arrays(r.dir + QString("/vtk/contacts_000%1.vtp").arg(i));
      const auto &p = c.at("Points"), &line = c.at("connectivity"), &state = c.at("state");
      QCOMPARE(line.size(), 2 * state.size());
      for (size_t k = 0; k < state.size(); ++k) {
        const auto a = static_cast<size_t>(line[2 * k]), b = static_cast<size_t>(line[2 * k + 1]);
        const double x = 0.5 * (p[3 * a] + p[3 * b]), y = 0.5 * (p[3 * a + 1] + p[3 * b + 1]);
        near[i] += state[k] == 2 && std::hypot(x - 20, y - 20) < 7;
      }
    }
    qInfo(
        "crown settlement: unsupported %.3f m, bolted %.3g mm; contacts slipping %d and %d, "
        "within 7 m of the opening %ld and %ld; largest bolt force %.4g N/m",
        free_fall, 1e3 * bolted, free_slipping, bolted_slipping, near[0], near[1], axial);
    // Unsupported, the wedge comes loose and falls: 0.38 m in the 0.61 s stepped (local damping
    // leaves about a fifth of g; undamped free fall would be 1.8 m). A wedge caught on the way
    // would stop within millimetres, and no block falls faster than gravity lets it.
    QVERIFY(free_fall > 0.1);
    QVERIFY(free_fall < 1.0);
    // Bolted, it settles as the bolts stretch: 0.38 mm, the loose rock's 48 kN/m (the wedge and
    // the piece left of the fault) on a few crossings of 5e7 N/m each; millimetres at most.
    QVERIFY(bolted > 0.0);
    QVERIFY(bolted < 2e-3);
    // The crown history goes back to before excavation on restore, so it holds the bolted stage:
    // the wedge never came down on the way either.
    auto h = read_history(r.dir);
    QVERIFY(h["crown"].size() > 300);
    for (double y : h["crown"]) QVERIFY(std::abs(y) < 2e-3);
    // The bolts carry the loose rock in tension (1.8e4 N/m at the most loaded crossing; a tenth
    // of the loose rock's weight at least), elastic: below the yield force of 2e5 N/m.
    QVERIFY(axial > 4.8e3);
    QVERIFY(axial < 2e5);
    // The model's `slipping` counts every contact at its shear strength, and a few far from the
    // opening sit at that limit without moving (one in each stage here): no contrast, so the
    // counts are only reported. Around the opening the contrast is one of kind: unsupported, the
    // piece left of the fault, its wedge gone, slides down the cross joint behind it; bolted,
    // nothing there slips.
    QVERIFY(near[0] >= 1);
    QCOMPARE(near[1], 0L);
    // The figures draw that slipping contact red (a thin bar: it presses lightly), and the bolts
    // purple in the bolted figure only; both left of the legend (at 3/4 of the width).
    long red[2] = {0, 0}, purple[2] = {0, 0};
    const QString figures[2] = {"/unsupported.png", "/bolted.png"};
    for (int i = 0; i < 2; ++i) {
      check_figure(r.dir + figures[i], QSize(1600, 1200));
      std::tie(red[i], purple[i]) = red_purple(QImage(r.dir + figures[i]));
    }
    qInfo("slipping (red) pixels: %ld unsupported, %ld bolted; bolt (purple) pixels: %ld, %ld",
          red[0], red[1], purple[0], purple[1]);
    QVERIFY(red[0] > 0);
    QCOMPARE(red[1], 0L);
    QCOMPARE(purple[0], 0L);
    QVERIFY(purple[1] > 2000);
  }
  void rockSlopeWedgeSlidesOnTheBedding() {
    const Run r = run_example("rock_slope", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double dx = h["crest_x"].back(), dy = h["crest_y"].back();
    const double dip = std::atan2(-dy, -dx) * 180 / M_PI;
    qInfo("crest wedge moved %.3f m at %.2f degrees below horizontal; deep block %.2g m",
          std::hypot(dx, dy), dip, h["deep_x"].back());
    // It slides out of the face along the 35 degree bedding; the mass behind stays put.
    QVERIFY(std::hypot(dx, dy) > 0.5);
    QVERIFY(std::abs(dip - 35.0) < 2.0);
    QVERIFY(std::abs(h["deep_x"].back()) < 1e-3);
  }
  void masonryArchStands() {
    const Run r = run_example("masonry_arch", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    QVERIFY(read_summary(r.dir)["final_ratio"].toDouble() <= 1e-6);
    QVERIFY(std::abs(h["crown"].back()) < 5e-4);
    check_figure(r.dir + "/arch_forces.svg", QSize(1200, 800));
  }
  // Voussoirs zoned, self-weight, then a load patch at the left quarter point: that voussoir
  // goes down most, the crown and the right half sway up and right, and nothing runs away.
  void deformableArchCarriesAPointLoad() {
    const Run r = run_example("deformable_arch", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double quarter = h["quarter"].back(), crown = h["crown"].back();
    qInfo("after the load: quarter point %.3e m, crown %.3e m", quarter, crown);
    QVERIFY(quarter < -5e-5 && quarter > -1e-3);
    QVERIFY(crown > 0 && crown < std::abs(quarter));
    QString why;
    QVERIFY2(check_vtp(r.dir + "/vtk/zones_0000.vtp", why) > 500, qPrintable(why));
    check_figure(r.dir + "/deformable_arch.png", QSize(1400, 900));
  }
  // In-situ stress, then top heading and bench: every stage reaches its ratio; the crown settles
  // more than the elastic Kirsch value for an unjointed medium (2.35 mm: a (sv + sh)/(4G) +
  // a (sv - sh)(3 - 4 nu)/(4G)), since joints slip and the rock yields around the opening, but
  // not by more than three times; the side wall converges. Zone figures are drawn.
  void deformableTunnelExcavatedInStages() {
    const Run r = run_example("tunnel_deformable", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    const QJsonObject s = read_summary(r.dir);
    // (The opening's cut leaves a few edges shorter than twice the rounding: warned, not fatal.)
    for (const auto& w : s["warnings"].toArray())
      QVERIFY2(!w.toString().contains("cycle limit"), qPrintable(w.toString()));
    auto h = read_history(r.dir);
    const double crown = h["crown"].back(), wall = h["wall"].back();
    const double g = 20e9 / 2.5, kirsch = 3 * 15e6 / (4 * g) + 3 * 5e6 * 2 / (4 * g);
    qInfo("crown %.3e m (elastic Kirsch %.3e m), wall %.3e m", crown, kirsch, wall);
    QVERIFY(-crown > kirsch && -crown < 3 * kirsch);
    QVERIFY(wall < -1e-4 && wall > crown);
    QString why;
    QVERIFY2(check_vtp(r.dir + "/vtk/zones_0000.vtp", why) > 2000, qPrintable(why));
    check_figure(r.dir + "/tunnel_deformable.png", QSize(1600, 1200));
    check_figure(r.dir + "/tunnel_deformable_state.png", QSize(1600, 1200));
    // The stress picture is zones coloured along the ramp, not one flat colour.
    const QImage img(r.dir + "/tunnel_deformable.png");
    QSet<QRgb> colours;
    for (int y = 100; y < 1000; y += 10)
      for (int x = 50; x < 1150; x += 10) colours.insert(img.pixel(x, y));
    QVERIFY2(colours.size() > 50, qPrintable(QString::number(colours.size())));
  }
  // Every example has its numbers checked above: a new example needs a test here too.
  void brickWall3dSettlesLikeTheColumnEstimate() {
    const Run r = run_example("brick_wall_3d", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    const QJsonObject s = read_summary(r.dir);
    QCOMPARE(s["dimension"].toInt(), 3);
    QCOMPARE(s["blocks"].toInt(), 79);
    QVERIFY(s["final_ratio"].toDouble() <= 1e-6);
    // The bed joints are whole faces in 3D, so the column estimate holds closely.
    auto h = read_history(r.dir);
    const double expected = 2200 * 9.81 * 0.3 * 12 * 13 / (2 * 5e10);
    const double top = -h["top_settlement"].back();
    qInfo("top settlement %.5e m, estimate %.5e m", top, expected);
    QVERIFY(std::abs(top - expected) < 0.01 * expected);
    // ParaView files: every face a polygon, every sub-contact a point, arrays consistent.
    QString why;
    QCOMPARE(check_vtp(r.dir + "/vtk/blocks_0000.vtp", why), 79L * 6);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    QVERIFY(check_vtp(r.dir + "/vtk/contacts_0000.vtp", why) > 4 * s["contacts"].toInt() - 1);
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }
  // 3D figures hide what is behind by a depth buffer. A brick standing on the far corner of a
  // 10 x 10 x 1 m footing, seen from the default view (azimuth 210, elevation 25): sorted face
  // by face (the painter's order) the footing's top, whose centre is nearer the viewer than the
  // brick's faces, was painted over most of the brick. Now the brick shows whole: its share of
  // the drawn pixels is its silhouette's share of the model's, 1.66 of 55.1 m2 (3.01%; less its
  // outlines, within a tenth). Seen
  // from the south, level, a block behind a wall contributes no pixel.
  void threeDFiguresHideWhatIsBehind() {
    const QString script = write_file(dir_, "depth.tess",
                                      "dimension 3\nmaterial define rock density=2500\n"
                                      "block box 0,0,0 10,10,1 material=rock group=footing\n"
                                      "block box 8,8,1 9,9,2 material=rock group=brick\n"
                                      "figure on_footing.png size=1200,900\n"
                                      "delete group=brick\n"
                                      "block box 0,20,0 10,22,10 material=rock group=wall\n"
                                      "block box 4,24,4 5,25,5 material=rock group=hidden\n"
                                      "figure behind_wall.png size=1200,900 view=180,0\n"
                                      "figure cut_open.png size=1200,900 view=180,0 "
                                      "cut=90,180,5,23,5\n");
    const Run r = run_script(script);
    QCOMPARE(r.exit_code, 0);
    // Pixels of one group's colour (shaded: 0.6 to 1 times it) against all coloured ones (not
    // white, not the grey of text and outlines), left of the legend (which starts at 916 pixels:
    // a 264-pixel column and 20-pixel margins). The brick is the second group (120,150,190),
    // the hidden block the fourth (140,180,120): the groups stay after `delete`.
    const auto shares = [](const QImage& img, const auto& is_group) {
      long group = 0, coloured = 0;
      for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < 906; ++x) {
          const QColor c = img.pixelColor(x, y);
          if (c.saturation() < 40) continue;
          ++coloured;
          group += is_group(c);
        }
      return std::pair<long, long>{group, coloured};
    };
    const auto brick_colour = [](const QColor& c) { return c.blue() > c.red() + 30; };
    const auto hidden_colour = [](const QColor& c) {
      return c.green() > c.red() + 15 && c.green() > c.blue() + 25;
    };
    const auto [brick, model] = shares(QImage(r.dir + "/on_footing.png"), brick_colour);
    const double share = double(brick) / double(model);
    qInfo("brick on the footing: %ld of %ld coloured pixels (%.2f%%, its silhouette 3.01%%)", brick,
          model, 100 * share);
    QVERIFY(model > 10000);
    QVERIFY(std::abs(share - 0.0301) < 0.1 * 0.0301);
    const auto [hidden, shown] = shares(QImage(r.dir + "/behind_wall.png"), hidden_colour);
    qInfo("block behind the wall: %ld of %ld coloured pixels", hidden, shown);
    QVERIFY(shown > 10000);
    QCOMPARE(hidden, 0L);
    // Cut by a vertical plane facing the viewer behind the wall (y < 23 cut away): the wall is
    // gone and the block shows whole (the view fitted to it).
    const auto [opened, left] = shares(QImage(r.dir + "/cut_open.png"), hidden_colour);
    qInfo("cut open: %ld of %ld coloured pixels are the block behind the wall", opened, left);
    QVERIFY(opened > 10000);
    QVERIFY(opened >= left - 10);  // antialiased corners of the outline
  }

  void column3dSettlesLikeTheClosedForm() {
    const Run r = run_example("column_3d", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    QVERIFY(r.out.contains("crack bed: 2 -> 3 blocks"));
    const QJsonObject s = read_summary(r.dir);
    QCOMPARE(s["dimension"].toInt(), 3);
    QVERIFY(s["final_ratio"].toDouble() <= 1e-6);
    // rho g H^2 / (2M) in the rock plus the two joints' closures (weight above over kn).
    const double m = 5e9 * 0.75 / (1.25 * 0.5), g = 2600 * 9.81;
    const double rock = g * 16 / (2 * m), base = g * 4 / 1e10, bed = g * 2 / 1e10;
    auto h = read_history(r.dir);
    const double top = -h["top"].back();
    const double closure = h["below_bed"].back() - h["above_bed"].back();
    qInfo("top settlement %.5e m (%.5e), bedding joint closure %.4e m (%.4e)", top,
          rock + base + bed, closure, bed);
    QVERIFY(std::abs(top / (rock + base + bed) - 1) < 0.01);
    QVERIFY(std::abs(closure / bed - 1) < 0.03);
    // The tetrahedra in ParaView: one cell per zone, every array the right length.
    QString why;
    QVERIFY(check_vtp(r.dir + "/vtk/zones_0000.vtu", why) > 1000);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    // The collection lists the run's last snapshot, at the same time as the script's `vtk`
    // (one entry a time).
    QFile pvd(r.dir + "/vtk/zones.pvd");
    QVERIFY(pvd.open(QIODevice::ReadOnly));
    const QByteArray listed = pvd.readAll();
    QVERIFY(listed.contains("zones_0001.vtu") && !listed.contains("zones_0000.vtu"));
    // The figure coloured by szz shows the zones on the column's faces: near zero (red end of
    // the ramp) at the top, most compressive (blue end) at the foot, graded between (many ramp
    // colours, not one per block); the rigid footing grey. Sampled left of the colour bar.
    const QString fig = r.dir + "/column_szz.png";
    check_figure(fig, QSize(900, 1200));
    const QImage img(fig);
    long red = 0, blue = 0, grey = 0;
    double red_y = 0, blue_y = 0;
    std::set<int> ramp;
    for (int py = 0; py < img.height(); py += 3)
      for (int px = 0; px < img.width() * 7 / 10; px += 3) {
        const QColor c = img.pixelColor(px, py);
        if (c.red() > c.blue() + 80) ++red, red_y += py;
        if (c.blue() > c.red() + 80 && c.green() > 40) ++blue, blue_y += py;  // not a contact
        if (c.saturation() > 120) ramp.insert(c.hue() / 10);
        grey += c.saturation() < 10 && c.value() > 100 && c.value() < 230;
      }
    red_y /= static_cast<double>(std::max(red, 1L)),
        blue_y /= static_cast<double>(std::max(blue, 1L));
    qInfo("szz figure: %ld red pixels about y = %.0f, %ld blue about y = %.0f, %zu hues, %ld grey",
          red, red_y, blue, blue_y, ramp.size(), grey);
    QVERIFY(red > 1000 && blue > 1000 && grey > 5000);
    QVERIFY(red_y + img.height() / 5 < blue_y);
    QVERIFY(ramp.size() >= 12);
    // The caption wraps to three lines at this width, all on the page: text near the bottom,
    // none in the last rows (a cut-off line would run into the edge).
    const auto dark_in_rows = [&](int from, int to) {
      long dark = 0;
      for (int py = from; py < to; ++py)
        for (int px = 0; px < img.width(); ++px) dark += qGray(img.pixel(px, py)) < 100;
      return dark;
    };
    QVERIFY(dark_in_rows(img.height() - 60, img.height() - 8) > 100);
    QCOMPARE(dark_in_rows(img.height() - 6, img.height()), 0L);
  }
  void rockWedgeStandsThenSlidesAlongTheIntersection() {
    const Run r = run_example("rock_wedge", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    QVERIFY(r.out.contains("crack B: 2 -> 4 blocks"));
    // Strength reduction at 45 degrees: Hoek & Bray's factor tan 45 / tan 37.22, within the
    // bisection's 0.01 and the model's own error; the mechanism drawn.
    const double fos = read_summary(r.dir)["fos"].toDouble();
    qInfo("factor of safety %.4f (Hoek & Bray %.4f)", fos, 1.0 / std::tan(37.22 * M_PI / 180));
    QVERIFY(std::abs(fos - 1.0 / std::tan(37.22 * M_PI / 180)) < 0.02);
    QVERIFY(r.out.contains("factor of safety 1.3"));
    check_figure(r.dir + "/fos_mechanism.png", QSize(1600, 1000));
    auto h = read_history(r.dir);
    const double x = h["wedge_x"].back(), y = h["wedge_y"].back(), z = h["wedge_z"].back();
    const double d = std::sqrt(x * x + y * y + z * z);
    const double plunge = std::asin(-z / d) * 180 / M_PI;
    const double trend = std::fmod(std::atan2(x, y) * 180 / M_PI + 360, 360);
    qInfo("wedge moved %.4f m, plunge %.2f, trend %.2f", d, plunge, trend);
    // Hoek & Bray: with 30 degrees of friction the wedge accelerates at 1.589 m/s^2 along the
    // line of intersection (plunge 42.46 towards 179.84) for the 1.0754 s of stage 2.
    QVERIFY(std::abs(d - 0.5 * 1.5889 * 1.0754 * 1.0754) < 0.02 * d);
    QVERIFY(std::abs(plunge - 42.46) < 0.5);
    QVERIFY(std::abs(trend - 179.84) < 0.5);
    // Coloured by z displacement: the wedge (down 0.6 m) at the blue end of the ramp, the rock
    // that stays at the red end.
    const QString fig = r.dir + "/wedge_zdisp.png";
    check_figure(fig, QSize(1200, 900));
    const QImage img(fig);
    long blue = 0, red = 0, samples = 0;
    for (int py = 0; py < img.height(); py += 4)
      for (int px = 0; px < img.width() * 3 / 4; px += 4, ++samples) {
        const QColor c = img.pixelColor(px, py);
        blue += c.blue() > c.red() + 80, red += c.red() > c.blue() + 80;
      }
    qInfo("zdisp figure: %ld blue and %ld red of %ld samples", blue, red, samples);
    QVERIFY(blue > samples / 100 && red > samples / 10);
  }
  // 3D cables: the wedge of rock_wedge, which slides out at 30 degrees of friction (0.9 m in a
  // second, rockWedgeStandsThenSlidesAlongTheIntersection), held by four 500 kN cables within
  // millimetres; each cable carries the shortfall in tension where it crosses the wedge's base,
  // below its yield force, and the figure draws the cables over the rock, red at the crossing.
  void cablesHoldTheRockWedgeIn3d() {
    const Run r = run_example("rock_wedge_cabled", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    auto h = read_history(r.dir);
    const double settled = -h["wedge_z"].back(), axial = h["cable_at_joint"].back();
    qInfo("wedge settles %.4g mm; cable force at the wedge's base %.4g kN", 1e3 * settled,
          1e-3 * axial);
    // It came to rest, with no warning (the solve reached its ratio).
    QVERIFY(read_summary(r.dir)["final_ratio"].toDouble() <= 1e-5);
    QVERIFY(read_summary(r.dir)["warnings"].toArray().isEmpty());
    QVERIFY(settled > 0.0 && settled < 0.03);
    QVERIFY(axial > 2e5 && axial < 5e5);  // in tension, below the yield force
    QString why;
    QVERIFY2(check_vtp(r.dir + "/vtk/support_0001.vtp", why) > 0, qPrintable(why));
    const QString fig = r.dir + "/wedge_cables.png";
    check_figure(fig, QSize(1200, 900));
    // Drawn over the rock (which would hide them): reds at the crossings, and no purple (the
    // state colour) when coloured by force.
    const auto [red, purple] = red_purple(QImage(fig));
    qInfo("cable figure: %ld red pixels, %ld purple", red, purple);
    QVERIFY(red > 20);
    QCOMPARE(purple, 0L);
  }
  // 10-node zones in a script: the cantilever's free end deflects as Timoshenko's beam within
  // 2% (-0.8%); the zones go to ParaView as quadratic tetrahedra (cell type 24, ten nodes
  // each); the figure shows the bending stress, tension along the top at the root (red end of
  // the ramp) and compression along the bottom (blue).
  void cantileverOf10NodeZonesBendsAsABeam() {
    const Run r = run_example("cantilever_3d", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    QVERIFY(r.out.contains("10-node tetrahedra"));
    const QJsonObject s = read_summary(r.dir);
    QVERIFY(s["final_ratio"].toDouble() <= 1e-5);
    const double p = 1e4, len = 10, e = 1e9, nu = 0.25, g = e / (2 * (1 + nu));
    const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
    const double beam = p * len * len * len / (3 * e / 12) + p * len / (kappa * g);
    auto h = read_history(r.dir);
    const double tip = -h["tip"].back();
    qInfo("tip deflection %.5g m (beam %.5g m, %+.2f%%)", tip, beam, 100 * (tip / beam - 1));
    QVERIFY(std::abs(tip / beam - 1) < 0.02);
    QVERIFY(h["root_top"].back() > 0);  // tension along the top
    QString why;
    std::set<int> types;
    QVERIFY2(check_vtp(r.dir + "/vtk/zones_0001.vtu", why, &types) > 300, qPrintable(why));
    QCOMPARE(types, std::set<int>{24});
    const QString fig = r.dir + "/cantilever_sxx.png";
    check_figure(fig, QSize(1200, 700));
    const QImage img(fig);
    // Red and blue both near the clamped end (the left fifth), and a spread of ramp colours.
    long red = 0, blue = 0;
    for (int py = 0; py < img.height(); py += 2)
      for (int px = 0; px < img.width() / 5; px += 2) {
        const QColor c = img.pixelColor(px, py);
        red += c.red() > 180 && c.green() < 90 && c.blue() < 90;
        blue += c.blue() > 180 && c.red() < 90 && c.green() < 140;
      }
    qInfo("cantilever figure: %ld red and %ld blue samples at the root", red, blue);
    QVERIFY(red > 20 && blue > 20);
  }
  // The 3D tunnel in jointed Mohr-Coulomb rock, three rounds of advance: every stage solves;
  // the crown settles more after each round (1.7, 2.5, 2.9 mm), in all within 1 to 1.6 times
  // the plane-strain elastic crown displacement of Kirsch's hole in this stress field (2.24 mm;
  // the yielded ring and the boundaries at 4 a add to it); each face extrudes into the opening
  // when its round is dug (the last by about sigma_yy a / E = 1.2 mm); the state figure shows
  // yielded zones around the opening.
  void tunnel3dAdvancesInThreeRounds() {
    const Run r = run_example("tunnel_3d", {}, dir_);
    QCOMPARE(r.exit_code, 0);
    QVERIFY(r.out.contains("smallest dihedral angle"));
    QVERIFY(!r.out.contains("warning"));
    const QJsonObject s = read_summary(r.dir);
    QVERIFY(s["final_ratio"].toDouble() <= 1e-4);
    auto h = read_history(r.dir);
    const std::vector<double>&crown = h["crown"], &face1 = h["face1"], &face2 = h["face2"],
          &face3 = h["face3"];
    QVERIFY(crown.size() > 100);
    // The end of rounds 1 and 2: the last rows in which faces 1 and 2 still exist.
    size_t end1 = 0, end2 = 0;
    for (size_t i = 0; i < crown.size(); ++i) {
      if (!std::isnan(face1[i])) end1 = i;
      if (!std::isnan(face2[i])) end2 = i;
    }
    const double c1 = -crown[end1], c2 = -crown[end2], c3 = -crown.back();
    const double kirsch = 2.24e-3;
    qInfo(
        "crown settles %.3f, %.3f, %.3f mm after rounds 1-3 (Kirsch elastic %.2f mm); faces "
        "%.3f, %.3f, %.3f mm when dug",
        1e3 * c1, 1e3 * c2, 1e3 * c3, 1e3 * kirsch, 1e3 * face1[end1], 1e3 * face2[end2],
        1e3 * face3.back());
    QVERIFY(c1 > 0 && c2 > 1.2 * c1 && c3 > 1.05 * c2);
    QVERIFY(c3 > kirsch && c3 < 1.6 * kirsch);
    QVERIFY(face1[end1] < -0.5e-3 && face2[end2] < -0.5e-3 && face3.back() < -0.5e-3);
    check_figure(r.dir + "/tunnel_3d_sigma1.png", QSize(1600, 1200));
    const QString fig = r.dir + "/tunnel_3d_state.png";
    check_figure(fig, QSize(1600, 1200));
    // Yielded zones (the legend's red and light orange) around the opening: left of the legend.
    const QImage img(fig);
    long yielded = 0;
    for (int py = 0; py < img.height(); py += 2)
      for (int px = 0; px < img.width() * 7 / 10; px += 2) {
        const QColor c = img.pixelColor(px, py);
        yielded += c.red() > 200 && c.blue() < 140 && c.red() - c.blue() > 80;
      }
    qInfo("state figure: %ld yielded samples", yielded);
    QVERIFY(yielded > 500);
  }
  // The Python example through `tessera --batch`: the wedge slides out below Hoek and Bray's
  // limit friction angle (37.2 degrees) and stands above it; a Python error names its line.
  void wedgeFrictionStudyInPython() {
#ifdef TESSERA_PYTHON_MODULE
    QTemporaryDir dir;
    QProcess p;
    const QString out = dir.path() + "/study";
    p.start(TESSERA_EXE, {"--batch", QString(TESSERA_EXAMPLES) + "/wedge_friction_study.py",
                          "--out", out, "--quiet"});
    p.waitForFinished(600000);
    QVERIFY2(p.exitCode() == 0, qPrintable(p.readAllStandardError()));
    std::ifstream csv((out + "/wedge_friction.csv").toStdString());
    std::string line;
    std::getline(csv, line);
    QCOMPARE(QString::fromStdString(line), QString("friction_deg,cycle,displacement_m"));
    std::map<int, double> moved;  // the last sample of each friction angle
    while (std::getline(csv, line)) {
      int phi = 0, cycle = 0;
      double d = 0;
      QCOMPARE(std::sscanf(line.c_str(), "%d,%d,%lf", &phi, &cycle, &d), 3);
      moved[phi] = d;
    }
    QCOMPARE(moved.size(), size_t(6));
    for (const auto& [phi, d] : moved) {
      qInfo("friction %d: the wedge moved %.4f m", phi, d);
      QVERIFY(phi < 37 ? d > 0.01 : d < 1e-4);
    }
    QVERIFY(QFile::exists(out + "/friction_30/history.csv"));
    QVERIFY(QFile::exists(out + "/friction_30/summary.json"));
    const QString bad =
        write_file(dir, "bad.py", "import tessera\nm = tessera.Model()\nm.command('frobnicate')\n");
    const Run r = run_script(bad);
    QCOMPARE(r.exit_code, 1);
    QVERIFY2(r.err.contains(bad + ":3: unknown command 'frobnicate'"), qPrintable(r.err));
#else
    QSKIP("built without the Python module");
#endif
  }
  void everyExampleIsChecked() {
    const QStringList checked{"block_on_incline.tess",
                              "brick_wall.tess",
                              "brick_wall_3d.tess",
                              "cantilever_3d.tess",
                              "column_3d.tess",
                              "deformable_arch.tess",
                              "masonry_arch.tess",
                              "rock_slope.tess",
                              "rock_wedge.tess",
                              "rock_wedge_cabled.tess",
                              "toppling_stack.tess",
                              "tunnel_3d.tess",
                              "tunnel_bolted.tess",
                              "tunnel_cabled.tess",
                              "tunnel_deformable.tess",
                              "tunnel_jointed.tess",
                              "tunnel_support_compare.tess"};
    QStringList found = QDir(TESSERA_EXAMPLES).entryList({"*.tess"}, QDir::Files, QDir::Name);
    QCOMPARE(found, checked);
  }
  // ParaView's collections run forward in time through a `restore` (the abandoned branch's
  // snapshots are no longer listed) and list the run's last snapshot once when an interval one
  // fell on the same cycle; points are written exactly, as a model at map coordinates needs.
  void paraviewFilesRunForwardAndHoldMapCoordinates() {
    QTemporaryDir d;
    const std::string x0 = "500000.123", y0 = "4000000.456";
    const QString path =
        write_file(d, "restore.tess",
                   "round 0.01\nmaterial define rock density=2500\n"
                   "joint define j kn=1e10 ks=1e10 friction=30\njoint assign j\n"
                   "gravity 0 -9.81\nblock " +
                       x0 + "," + y0 + " 500004.123," + y0 + " 500004.123,4000001.456 " + x0 +
                       ",4000001.456 group=base material=rock\n"
                       "fix group=base\nblock 500001.123,4000001.456 500002.123,4000001.456 "
                       "500002.123,4000002.456 500001.123,4000002.456 material=rock\n"
                       "timestep fixed 1e-5\nvtk interval 100\nstep 200\nsave s.state\n"
                       "step 200\nrestore s.state\nstep 200\n");
    const Run r = run_script(path);
    QCOMPARE(r.exit_code, 0);
    QFile pvd(r.dir + "/vtk/blocks.pvd");
    QVERIFY(pvd.open(QIODevice::ReadOnly));
    std::vector<double> times;
    QXmlStreamReader xml(&pvd);
    while (!xml.atEnd())
      if (xml.readNextStartElement() && xml.name() == QLatin1String("DataSet"))
        times.push_back(xml.attributes().value("timestep").toDouble());
    // 1, 2 ms; the restored branch's 3 and 4 ms (files 4 and 6: the end's in place of 5).
    QCOMPARE(times.size(), size_t(4));
    for (size_t i = 0; i < times.size(); ++i)
      QVERIFY(std::abs(times[i] - 1e-3 * static_cast<double>(i + 1)) < 1e-12);
    QVERIFY(pvd.seek(0) && pvd.readAll().contains("blocks_0006.vtp"));
    // The base's first corner, to the digit.
    const auto points = read_vtp_arrays(r.dir + "/vtk/blocks_0000.vtp")["Points"];
    QVERIFY(points.size() >= 3);
    QVERIFY(points[0] == 500000.123 && points[1] == 4000000.456);
  }
  // A command that fails half done (a zoning that zoned block 1, then found block 2 has no
  // elastic constants) is undone before the results are written: they show the model before it.
  void failedCommandIsUndoneInTheResults() {
    QTemporaryDir d;
    const QString path =
        write_file(d, "half.tess",
                   "round 0.01\nmaterial define rock density=2500 E=1e9 nu=0.25\n"
                   "material define stone density=2500\n"
                   "block 0,0 1,0 1,1 0,1 material=rock\n"
                   "block 1,0 2,0 2,1 1,1 material=stone\nzone generate edge=0.5\n");
    const Run r = run_script(path);
    QCOMPARE(r.exit_code, 1);
    QVERIFY2(r.err.contains("half.tess:6: block 2: its material has no elastic constants"),
             qPrintable(r.err));
    const QJsonObject s = read_summary(r.dir);
    QCOMPARE(s["status"].toString(), QString("error"));
    QCOMPARE(s["blocks"].toInt(), 2);
    QVERIFY(QFile::exists(r.dir + "/vtk/blocks_0000.vtp"));
    QVERIFY(!QFile::exists(r.dir + "/vtk/zones_0000.vtp"));
  }
  void badScriptFailsWithItsLine() {
    QTemporaryDir tmp;
    const QString script = tmp.path() + "/bad.tess";
    std::ofstream(script.toStdString())
        << "round 0.01\nmaterial define rock density=2600\nblock 0,0 1,0 1,1 0,1 material=rok\n";
    QProcess p;
    p.start(TESSERA_EXE, {"--batch", script, "--out", tmp.path() + "/out"});
    p.waitForFinished(60000);
    QCOMPARE(p.exitCode(), 1);
    const QString err = p.readAllStandardError();
    QVERIFY2(err.contains(script + ":3: block 1: there is no material 'rok'"), qPrintable(err));
    QVERIFY(err.contains("did you mean 'rock'"));
  }
};

// A QGuiApplication (figures are drawn back to check them) and run_tests, which takes --skip:
// the 3D tunnel example runs as a ctest entry of its own.
int main(int argc, char** argv) {
  QGuiApplication app(argc, argv);
  app.setAttribute(Qt::AA_Use96Dpi, true);
  TestExamples test;
  return tessera::test::run_tests(test, argc, argv);
}
#include "test_examples.moc"
