// The Model menu: dialogs that write commands (materials, joints, joint sets with a preview of
// the cut, openings, generators, zoning, assignments to the selection, boundary conditions,
// in-situ stress), and the selection they act on.
#include <QAction>
#include <QMenuBar>
#include <QStatusBar>
#include <algorithm>

#include "dialog_specs.hpp"
#include "tessera/core/joint_law.hpp"
#include "tessera/generation/generators.hpp"
#include "tessera/ui/command_dialog.hpp"
#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/vtk_view.hpp"
#include "tessera/zones/zone_model.hpp"

namespace tessera::ui {

namespace {
QString num(double v) {
  return QString::number(v, 'g', 6);
}
}  // namespace

void MainWindow::buildModelMenu() {
  QMenu* model = menuBar()->addMenu("&Model");
  const std::pair<const char*, const char*> items[] = {{"box", "Block (bo&x, 3D)…"},
                                                       {"prism", "Block (&prism, 3D)…"},
                                                       {"region", "R&egion…"},
                                                       {"crack", "&Crack plane (3D)…"},
                                                       {"material", "&Material…"},
                                                       {"joint", "&Joint properties…"},
                                                       {"jset", "Joint &set…"},
                                                       {"tunnel", "Circular &opening…"},
                                                       {"horseshoe", "&Horseshoe opening…"},
                                                       {"rectangle", "&Rectangular opening…"},
                                                       {"voronoi", "&Voronoi cells…"},
                                                       {"wall", "&Wall…"},
                                                       {"arch", "&Arch…"},
                                                       {"zones", "&Zones…"},
                                                       {"bolt", "Rock &bolt…"},
                                                       {"boltpattern", "Bolt &pattern…"},
                                                       {"cable", "Grouted cab&le…"},
                                                       {"cablepattern", "Cable pa&ttern…"},
                                                       {"liner", "&Liner…"},
                                                       {"assign", "Assign to selection…"},
                                                       {"boundary", "&Boundary…"},
                                                       {"insitu", "&In-situ stress…"},
                                                       {"gravity", "&Gravity…"},
                                                       {"damping", "&Damping…"}};
  for (const auto& [name, text] : items) {
    if (QString(name) == "assign" || QString(name) == "gravity") model->addSeparator();
    const QString key = name;
    model->addAction(text, this, [this, key] { openDialog(key); });
  }
  model->addAction("&Fix selection", this, [this] {
    if (selection_.isEmpty()) return console_->append("select blocks first", true);
    runCommand("fix " + selection_);
  });
  model->addAction("&Null zones in the box", this, [this] {
    if (!selection_.startsWith("x="))
      return console_->append("drag a box with the Select tool first", true);
    runCommand("zone null " + selection_);
  });
  connect(view_, &VtkView::boxSelected, this, [this](QPointF lo, QPointF hi) {
    selectBox({lo.x(), lo.y()}, {hi.x(), hi.y()});
  });
  connect(view_, &VtkView::picked, this, [this](int block, int contact) {
    if (view_->drawing().mode() != DrawMode::kSelect) return;
    if (contact >= 0 && shown_)
      return selectJoint(QString::fromStdString(shown_->contacts[size_t(contact)].joint_set));
    selectBlock(block);
  });
  connect(view_, &VtkView::blocksBoxed, this, [this](const QVector<int>& blocks) {
    selectBlocks(std::vector<int>(blocks.begin(), blocks.end()));
  });
  connect(view_, &VtkView::edgePicked, this, [this](int, QPointF a, QPointF b) {
    selectEdge({a.x(), a.y()}, {b.x(), b.y()});
  });
}

void MainWindow::selectBox(Vec2 lo, Vec2 hi) {
  selection_ = QString("x=%1,%2 y=%3,%4").arg(num(lo.x()), num(hi.x()), num(lo.y()), num(hi.y()));
  selected_.clear();
  if (shown_)
    for (size_t b = 0; b < shown_->blocks.size(); ++b) {
      const SnapshotBlock& s = shown_->blocks[b];
      if (s.x >= lo.x() && s.x <= hi.x() && s.y >= lo.y() && s.y <= hi.y())
        selected_.push_back(static_cast<int>(b));
    }
  view_->setHighlight(selected_);
  statusBar()->showMessage(
      QString("%1 block(s) selected: %2").arg(selected_.size()).arg(selection_));
}

void MainWindow::selectBlock(int block) {
  selected_.clear();
  selection_.clear();
  if (shown_ && block >= 0) {
    selected_.push_back(block);
    selection_ = QString("block=%1").arg(shown_->blocks[size_t(block)].id);
  }
  view_->setHighlight(selected_);
  statusBar()->showMessage(selection_.isEmpty() ? "nothing selected" : "selected " + selection_);
}

void MainWindow::selectBlocks(const std::vector<int>& blocks) {
  selected_.clear();
  selection_.clear();
  QStringList ids;
  if (shown_)
    for (int b : blocks)
      if (b >= 0 && static_cast<size_t>(b) < shown_->blocks.size())
        selected_.push_back(b), ids << QString::number(shown_->blocks[size_t(b)].id);
  if (!ids.isEmpty()) selection_ = "block=" + ids.join(',');
  view_->setHighlight(selected_);
  statusBar()->showMessage(
      selection_.isEmpty() ? "nothing selected"
                           : QString("%1 block(s) selected: %2").arg(ids.size()).arg(selection_));
}

void MainWindow::selectEdge(Vec2 a, Vec2 b) {
  // The edge as the box around it, a hair wider, so that boundary commands take its two nodes.
  const double pad = 1e-6 * std::max((b - a).norm(), 1e-3);
  const Vec2 lo = a.cwiseMin(b) - Vec2(pad, pad), hi = a.cwiseMax(b) + Vec2(pad, pad);
  selection_ = QString("x=%1,%2 y=%3,%4").arg(num(lo.x()), num(hi.x()), num(lo.y()), num(hi.y()));
  selected_.clear();
  view_->setHighlight({}, {{a, b}});
  statusBar()->showMessage("selected an outline edge: " + selection_);
}

void MainWindow::selectJoint(const QString& name) {
  selected_.clear();
  selection_ = name.isEmpty() ? QString() : "joints=" + name;
  view_->setHighlight({});
  statusBar()->showMessage(name.isEmpty() ? "this contact lies on no named joint"
                                          : "selected the joints " + name);
}

void MainWindow::runCommands(const QStringList& lines) {
  if (lines.isEmpty() || busy()) return;
  pending_ = lines;
  runCommand(pending_.takeFirst());
}

CommandDialog* MainWindow::openDialog(const QString& name) {
  const bool three = shown_ && shown_->three;
  const DialogSpec s = dialog_spec(name, three);
  if (s.title.isEmpty()) {
    statusBar()->showMessage(QString("There is no %1 in a %2 model").arg(name, three ? "3D" : "2D"),
                             5000);
    return nullptr;
  }
  auto* d = new CommandDialog(s.title, s.head, s.fields, this);
  d->setAttribute(Qt::WA_DeleteOnClose);
  if (s.on_selection) d->setTail(selection_);
  // Cuts and generators show what they will make before OK.
  static const QStringList previewed{"jset", "tunnel", "horseshoe", "rectangle", "voronoi", "wall",
                                     "arch", "box",    "prism",     "region",    "crack"};
  if (previewed.contains(name)) {
    connect(d, &CommandDialog::changed, this, [this, d, name] { preview(name, *d); });
    connect(d, &QDialog::finished, this, [this] { view_->setPreview({}); });
    preview(name, *d);
  }
  // What exists, for the fields that name things.
  QStringList groups, materials, joints, names;
  if (shown_) {
    for (const auto& g : shown_->groups) groups << QString::fromStdString(g);
    for (const auto& m : shown_->materials) materials << QString::fromStdString(m.name);
    for (const auto& j : shown_->joints) joints << QString::fromStdString(j.name);
    // Every joint set, crack and opening (an opening's wall has no contacts once excavated).
    for (const auto& n : shown_->joint_names)
      if (n != "split") names << QString::fromStdString(n);
  }
  d->setChoices("groups", groups);
  d->setChoices("materials", materials);
  d->setChoices("joint properties", joints);
  d->setChoices("joint names", names);
  // The laws the engine knows, plug-ins' included.
  QStringList zone_models, joint_laws;
  for (const std::string& n : zone_model_names()) zone_models << QString::fromStdString(n);
  for (const std::string& n : joint_law_names()) joint_laws << QString::fromStdString(n);
  d->setChoices("zone models", zone_models);
  d->setChoices("joint laws", joint_laws);
  // OK runs the command; the dialog stays open until it has run, and shows its error if it
  // fails (onFinished).
  connect(d, &CommandDialog::submitted, this, [this, d, name] {
    if (busy()) return d->showError("The solver is running: pause or stop it first.");
    waiting_dialog_ = d, waiting_ran_ = 0;
    if (name != "assign") return runCommand(d->command());
    // Assignments: one command each, in order.
    if (selection_.isEmpty()) {
      waiting_dialog_.clear();
      return d->showError("Select blocks first (the Select tool: a click or a box).");
    }
    QStringList lines;
    const QString group = d->value("group"), material = d->value("material"),
                  joint = d->value("joint");
    if (!group.isEmpty()) lines << "group " + group + " " + selection_;
    if (!material.isEmpty()) lines << "material assign " + material + " " + selection_;
    if (!joint.isEmpty() && selection_.startsWith("joints="))
      lines << "joint assign " + joint + " " + selection_;
    else if (!joint.isEmpty() && !group.isEmpty())
      lines << "joint assign " + joint + " groups=" + group + "," + group;
    else if (!joint.isEmpty())
      console_->append("joint properties for a selection need a group to name it", true);
    if (lines.isEmpty()) {
      waiting_dialog_.clear();
      return d->showError("Nothing to assign: give a group, a material or joint properties.");
    }
    runCommands(lines);
  });
  d->open();
  return d;
}

namespace {
// "a" or "a,b" as numbers; false if the first is missing or not a number.
bool numbers(const QString& text, double& a, double& b) {
  const QStringList parts = text.split(',');
  bool ok = false;
  a = parts.value(0).toDouble(&ok);
  if (parts.size() > 1) b = parts[1].toDouble();
  return ok && !text.isEmpty();
}

// A closed outline as segments.
void add_loop(const std::vector<Vec2>& pts, std::vector<std::array<Vec2, 2>>& out) {
  for (size_t k = 0; k < pts.size(); ++k) out.push_back({pts[k], pts[(k + 1) % pts.size()]});
}

void add_cuts(const std::vector<CutLine>& cuts, std::vector<std::array<Vec2, 2>>& out) {
  for (const CutLine& c : cuts)
    for (size_t k = 0; k + 1 < c.points.size(); ++k) out.push_back({c.points[k], c.points[k + 1]});
}
}  // namespace

void MainWindow::preview(const QString& name, const CommandDialog& d) {
  if (shown_ && shown_->three) return preview3(name, d);
  std::vector<std::array<Vec2, 2>> lines;
  double a = 0, b = 0, x = 0, y = 0;
  // The box of the blocks a cut acts on: the selection's, or the whole model's.
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  if (shown_ && !shown_->blocks.empty()) {
    lo = shown_->lo, hi = shown_->hi;
    if (!selected_.empty()) {
      lo = Vec2(1e300, 1e300), hi = -lo;
      for (int blk : selected_) {
        const SnapshotBlock& s = shown_->blocks[size_t(blk)];
        for (uint32_t v = s.vert_begin; v < s.vert_end; ++v) {
          const Vec2 p = shown_vertex(*shown_, s, v, 1.0);
          lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        }
      }
    }
  }
  const double box = (hi - lo).norm();
  if (name == "jset" && box > 0) {
    JointSetSpec j;
    if (numbers(d.value("angle"), j.angle, j.angle_sd) &&
        numbers(d.value("spacing"), j.spacing, j.spacing_sd) && j.spacing > 0 &&
        box / j.spacing < 5000) {
      numbers(d.value("trace"), j.trace, j.trace_sd);
      numbers(d.value("gap"), j.gap, j.gap_sd);
      if (numbers(d.value("origin"), x, y)) j.origin = {x, y};
      if (!d.value("seed").isEmpty()) j.seed = d.value("seed").toULongLong();
      add_cuts(joint_set_traces(j, lo, hi, -1), lines);
    }
  } else if (name == "voronoi" && box > 0) {
    if (numbers(d.value("size"), a, b) && a > 0 && box / a < 700)
      add_cuts(voronoi_traces(lo, hi, a,
                              d.value("seed").isEmpty() ? 1 : d.value("seed").toULongLong(), -1),
               lines);
  } else if (name == "tunnel") {
    if (numbers(d.value("centre"), x, y) && numbers(d.value("radius"), a, b) && a > 0)
      add_loop(circle_outline({x, y}, a, std::clamp(d.value("segments").toInt(), 3, 2000)), lines);
  } else if (name == "horseshoe") {
    double w = 0, h = 0;
    if (numbers(d.value("centre"), x, y) && numbers(d.value("width"), w, b) &&
        numbers(d.value("height"), h, b) && w > 0 && h > w / 2)
      add_loop(horseshoe_outline({x, y}, w, h, std::clamp(d.value("segments").toInt(), 2, 2000)),
               lines);
  } else if (name == "rectangle" || name == "region") {
    double x1 = 0, y1 = 0;
    if (numbers(d.value("#a"), x, y) && numbers(d.value("#b"), x1, y1))
      add_loop({{x, y}, {x1, y}, {x1, y1}, {x, y1}}, lines);
  } else if (name == "wall" || name == "arch") {
    // The generator itself, into a scratch model: the preview is the blocks it will add.
    Model scratch;
    if (name == "wall") {
      WallSpec w;
      const int courses = d.value("courses").toInt(), bricks = d.value("bricks").toInt();
      if (numbers(d.value("brick"), w.brick_length, w.brick_height) && w.brick_length > 0 &&
          w.brick_height > 0 && courses > 0 && bricks > 0 && courses * bricks < 20000) {
        w.courses = courses, w.bricks = bricks;
        if (numbers(d.value("origin"), x, y)) w.origin = {x, y};
        scratch.settings.rounding = 0.01 * std::min(w.brick_length, w.brick_height);
        add_running_bond_wall(scratch, w);
      }
    } else {
      ArchSpec s;
      const int n = d.value("voussoirs").toInt();
      if (numbers(d.value("centre"), x, y) && numbers(d.value("radius"), s.radius, b) &&
          numbers(d.value("thickness"), s.thickness, b) && s.radius > 0 && s.thickness > 0 &&
          n > 0 && n < 5000) {
        s.centre = {x, y}, s.voussoirs = n;
        numbers(d.value("half_angle"), s.half_angle, b);
        numbers(d.value("abutment"), s.abutment, b);
        if (s.half_angle > 0 && s.half_angle <= 90) {
          scratch.settings.rounding = 0.01 * s.thickness;
          add_arch(scratch, s);
        }
      }
    }
    for (size_t k = 0; k < scratch.blocks.size(); ++k)
      add_loop(scratch.blocks.world_polygon(k), lines);
  }
  view_->setPreview(lines);
}

}  // namespace tessera::ui
