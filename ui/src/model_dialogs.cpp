// The Model menu: dialogs that write commands (materials, joints, joint sets with a preview of
// the cut, openings, generators, zoning, assignments to the selection, boundary conditions,
// in-situ stress), and the selection they act on.
#include <QAction>
#include <QMenuBar>
#include <QStatusBar>
#include <algorithm>

#include "tessera/generation/generators.hpp"
#include "tessera/ui/command_dialog.hpp"
#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/vtk_view.hpp"

namespace tessera::ui {

namespace {
QString num(double v) {
  return QString::number(v, 'g', 6);
}

// The fields of each dialog: keyword, label, unit, initial value, tip.
struct DialogSpec {
  QString title, head;
  std::vector<CommandField> fields;
  bool on_selection = false;  // the selection's keywords are appended
};

DialogSpec spec(const QString& name) {
  const QString msd = "a mean, or mean,sd for a normal spread";
  if (name == "material")
    return {"Material",
            "material define",
            {{"#name", "Name", "", "rock", "the name scripts and assignments use"},
             {"density", "Density", "kg/m³", "2600", ""},
             {"E", "Young's modulus", "Pa", "", "deformable blocks only"},
             {"nu", "Poisson's ratio", "", "", ""},
             {"model", "Zone model", "", "", "elastic, mohr-coulomb, drucker-prager or null",
              "zone models"},
             {"friction", "Friction angle", "deg", "", ""},
             {"cohesion", "Cohesion", "Pa", "", ""},
             {"tension", "Tensile strength", "Pa", "", ""},
             {"dilation", "Dilation angle", "deg", "", ""}}};
  if (name == "joint")
    return {"Joint properties",
            "joint define",
            {{"#name", "Name", "", "joints", ""},
             {"kn", "Normal stiffness", "Pa/m", "1e10", ""},
             {"ks", "Shear stiffness", "Pa/m", "1e10", ""},
             {"friction", "Friction angle", "deg", "30", ""},
             {"cohesion", "Cohesion", "Pa", "", ""},
             {"tension", "Tensile strength", "Pa", "", ""},
             {"dilation", "Dilation angle", "deg", "", ""}}};
  if (name == "jset")
    return {"Joint set",
            "jset",
            {{"angle", "Angle from x", "deg", "30", msd},
             {"spacing", "Spacing", "m", "1", msd},
             {"trace", "Trace length", "m", "", "empty: traces run through; " + msd},
             {"gap", "Gap (rock bridge)", "m", "", msd},
             {"origin", "A trace through", "x,y m", "", ""},
             {"seed", "Random seed", "", "", ""},
             {"!extend", "Trace ends run to block edges", "", "", ""},
             {"name", "Name", "", "", "the joints' name for properties and selections"}},
            true};
  const CommandField core_name{"name", "Name", "", "", "the opening's joints, e.g. for pressure"};
  const CommandField core{"group", "Group of the core", "", "tunnel",
                          "excavate it with delete group=..."};
  if (name == "tunnel")
    return {"Circular opening",
            "tunnel circle",
            {{"centre", "Centre", "x,y m", "0,0", ""},
             {"radius", "Radius", "m", "1", ""},
             {"segments", "Segments", "", "24", ""},
             core_name,
             core}};
  if (name == "horseshoe")
    return {"Horseshoe opening",
            "tunnel horseshoe",
            {{"centre", "Middle of the floor", "x,y m", "0,0", ""},
             {"width", "Width", "m", "6", ""},
             {"height", "Height", "m", "6", "walls plus the half-circle roof"},
             {"segments", "Roof segments", "", "12", ""},
             core_name,
             core}};
  if (name == "rectangle")
    return {"Rectangular opening",
            "tunnel rectangle",
            {{"#a", "A corner", "x,y m", "0,0", ""},
             {"#b", "The opposite corner", "x,y m", "4,3", ""},
             core_name,
             core}};
  if (name == "region")
    return {"Region (a box to cut)",
            "region",
            {{"#a", "A corner", "x,y m", "0,0", ""},
             {"#b", "The opposite corner", "x,y m", "20,10", ""},
             {"group", "Group", "", "", "", "groups"},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "voronoi")
    return {"Voronoi cells",
            "voronoi",
            {{"size", "Mean cell size", "m", "0.5", ""},
             {"seed", "Random seed", "", "", ""},
             {"name", "Name", "", "", ""}},
            true};
  if (name == "wall")
    return {"Running-bond wall",
            "wall",
            {{"brick", "Brick", "L,H m", "0.4,0.2", ""},
             {"courses", "Courses", "", "10", ""},
             {"bricks", "Bricks per course", "", "8", ""},
             {"origin", "Bottom left", "x,y m", "0,0", ""},
             {"group", "Group", "", "wall", ""},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "arch")
    return {"Arch",
            "arch",
            {{"centre", "Centre of the intrados", "x,y m", "0,0", ""},
             {"radius", "Intrados radius", "m", "2", ""},
             {"thickness", "Ring thickness", "m", "0.3", ""},
             {"voussoirs", "Voussoirs", "", "15", ""},
             {"half_angle", "Half angle", "deg", "90", "90: semicircular"},
             {"abutment", "Abutment height", "m", "", ""},
             {"group", "Group", "", "arch", ""},
             {"material", "Material", "", "", "", "materials"}}};
  if (name == "zones")
    return {"Zones (deformable blocks)",
            "zone generate",
            {{"edge", "Zone edge", "m", "0.5", ""},
             {"fine", "Finer edge near a point", "m", "", ""},
             {"near", "Near", "x,y m", "", ""},
             {"radius", "Within", "m", "", ""},
             {"growth", "Growth away from it", "", "", "e.g. 0.3"},
             {"order", "Zone order", "1 or 2", "", "2: 10-node tetrahedra (3D models)"}},
            true};
  if (name == "boundary")
    return {"Boundary condition on nodes",
            "boundary",
            {{"fix", "Fix", "x, y or xy", "", ""},
             {"stress", "Applied stress", "SXX,SYY,SXY Pa", "", "tension positive"},
             {"pressure", "Pressure", "Pa", "", ""},
             {"joints", "Along joints named", "", "", "e.g. the opening's name", "joint names"}},
            true};
  if (name == "insitu")
    return {"In-situ stress",
            "insitu",
            {{"stress", "Stress", "SXX,SYY,SXY Pa", "-5e6,-10e6,0", "tension positive"},
             {"szz", "Out of plane", "Pa", "", "empty: nu (sxx + syy)"},
             {"ygradient", "Gradient with height", "Pa/m", "", "e.g. k rho g, rho g, 0"},
             {"y0", "Height of the given stress", "m", "", ""}}};
  if (name == "gravity")
    return {"Gravity",
            "gravity",
            {{"#gx", "Along x", "m/s²", "0", ""},
             {"#gy", "Along y", "m/s²", "-9.81", "2D: -9.81 (y up); 3D: 0"},
             {"#gz", "Along z", "m/s²", "", "3D models only: -9.81 (z up)"}}};
  if (name == "damping")
    return {"Damping",
            "damping",
            {{"#mode", "Kind", "", "local",
              "local (static), global (adaptive viscous) or none (dynamic analysis)"},
             {"#value", "Alpha or ratio", "", "",
              "local: alpha (default 0.8); global: the power ratio removed (0.5)"}}};
  if (name == "assign")
    return {"Assign to the selection",
            "",
            {{"group", "Group", "", "", "puts the selected blocks into this group", "groups"},
             {"material", "Material", "", "", "gives them this material", "materials"},
             {"joint", "Joint properties", "", "", "between the selected blocks (needs the group)",
              "joint properties"}}};
  return {};
}

// The 3D forms of the dialogs whose commands differ in 3D (points x,y,z; planes by dip and dip
// direction); the others as in 2D, and none for commands of 2D models only.
DialogSpec spec3(const QString& name) {
  const QString msd = "a mean, or mean,sd for a normal spread";
  const CommandField group{"group", "Group", "", "", "", "groups"};
  const CommandField material{"material", "Material", "", "", "", "materials"};
  const CommandField name_field{"name", "Name", "", "", "the joints' name for properties"};
  if (name == "box")
    return {"Block (box)",
            "block box",
            {{"#a", "A corner", "x,y,z m", "0,0,0", ""},
             {"#b", "The opposite corner", "x,y,z m", "10,10,10", ""},
             group,
             material}};
  if (name == "prism")
    return {"Block (prism)",
            "block prism",
            {{"#base", "Base polygon", "x,y x,y ... m", "0,0 4,0 4,3 0,3",
              "a convex polygon, corners separated by spaces"},
             {"z", "From z to z", "z0,z1 m", "0,2", ""},
             group,
             material}};
  if (name == "region")
    return {"Region (a box to cut)",
            "region",
            {{"#a", "A corner", "x,y,z m", "0,0,0", ""},
             {"#b", "The opposite corner", "x,y,z m", "20,20,20", ""},
             group,
             material}};
  if (name == "crack")
    return {"Crack (a plane)",
            "crack",
            {{"dip", "Dip", "deg", "60", "from horizontal"},
             {"ddir", "Dip direction", "deg", "90", "clockwise from north (+y)"},
             {"origin", "Through", "x,y,z m", "0,0,0", ""},
             {"radius", "Disc radius", "m", "", "empty: the whole plane"},
             name_field},
            true};
  if (name == "jset")
    return {"Joint set",
            "jset",
            {{"dip", "Dip", "deg", "60", msd},
             {"ddir", "Dip direction", "deg", "90", msd},
             {"spacing", "Spacing", "m", "2", msd},
             {"origin", "A plane through", "x,y,z m", "", ""},
             {"persistence", "Persistence", "0 to 1", "", "the share of blocks a plane cuts"},
             {"seed", "Random seed", "", "", ""},
             name_field},
            true};
  const CommandField core{"group", "Group of the core", "", "tunnel",
                          "excavate it with delete group=... (with rounds: group_1, ...)"};
  const CommandField opening{"name", "Name", "", "", "the opening's joints, e.g. for pressure"};
  if (name == "tunnel" || name == "horseshoe") {
    DialogSpec s{name == "tunnel" ? "Circular opening" : "Horseshoe opening",
                 name == "tunnel" ? "tunnel circle" : "tunnel horseshoe",
                 {{"centre", name == "tunnel" ? "Portal centre" : "Middle of the portal floor",
                   "x,y,z m", "0,0,0", ""},
                  {"axis", "Axis", "dx,dy,dz", "0,1,0", "the direction it runs"},
                  {"length", "Length", "m", "10", ""}}};
    if (name == "tunnel")
      s.fields.push_back({"radius", "Radius", "m", "3", ""});
    else
      s.fields.insert(s.fields.end(), {{"width", "Width", "m", "6", ""},
                                       {"height", "Height", "m", "6", "walls plus the roof"}});
    s.fields.insert(s.fields.end(),
                    {{"segments", "Segments", "", name == "tunnel" ? "24" : "12", ""},
                     {"rounds", "Rounds of advance", "", "", "groups G_1 ... G_N"},
                     opening,
                     core,
                     {"!join", "Join the rock around it back into bodies", "", "on", ""}});
    return s;
  }
  if (name == "wall")
    return {"Running-bond wall",
            "wall",
            {{"brick", "Brick", "L,H,W m", "0.6,0.3,0.3", "along x, up z, thick along y"},
             {"courses", "Courses", "", "6", ""},
             {"bricks", "Bricks per course", "", "6", ""},
             {"origin", "Bottom corner", "x,y,z m", "0,0,0", ""},
             {"group", "Group", "", "wall", ""},
             material,
             name_field}};
  if (name == "zones")
    return {"Zones (deformable blocks)",
            "zone generate",
            {{"edge", "Zone edge", "m", "1", ""},
             {"fine", "Finer edge near a point", "m", "", ""},
             {"near", "Near", "x,y,z m", "", ""},
             {"radius", "Within", "m", "", ""},
             {"growth", "Growth away from it", "", "", "e.g. 0.3"},
             {"order", "Zone order", "1 or 2", "", "2: 10-node tetrahedra"}},
            true};
  const CommandField x{"x", "Box: x from, to", "m", "", "nodes inside the box"},
      y{"y", "y from, to", "m", "", ""}, z{"z", "z from, to", "m", "", ""};
  if (name == "boundary")
    return {"Boundary condition on nodes",
            "boundary",
            {{"fix", "Fix", "x, y, z, xy ... xyz", "", ""},
             {"velocity", "Velocity", "vx,vy,vz m/s", "", ""},
             {"stress", "Applied stress", "SXX,SYY,SZZ,SXY,SYZ,SXZ Pa", "", "tension positive"},
             {"pressure", "Pressure", "Pa", "", ""},
             {"joints", "Along joints named", "", "", "e.g. the opening's name", "joint names"},
             x,
             y,
             z}};
  if (name == "insitu")
    return {"In-situ stress",
            "insitu",
            {{"stress", "Stress", "SXX,SYY,SZZ,SXY,SYZ,SXZ Pa", "-10e6,-10e6,-10e6,0,0,0",
              "tension positive"},
             {"zgradient", "Gradient with height", "6 values, Pa/m", "", ""},
             {"z0", "Height of the given stress", "m", "", ""}}};
  if (name == "gravity")
    return {"Gravity",
            "gravity",
            {{"#gx", "Along x", "m/s²", "0", ""},
             {"#gy", "Along y", "m/s²", "0", ""},
             {"#gz", "Along z", "m/s²", "-9.81", "z up"}}};
  if (name == "rectangle" || name == "voronoi" || name == "arch") return {};
  return spec(name);
}

// Commands of one dimension only.
bool three_only(const QString& name) {
  return name == "box" || name == "prism" || name == "crack";
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
  const DialogSpec s = three ? spec3(name) : three_only(name) ? DialogSpec{} : spec(name);
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
    for (const auto& c : shown_->contacts)
      if (!c.joint_set.empty() && !names.contains(QString::fromStdString(c.joint_set)))
        names << QString::fromStdString(c.joint_set);
  }
  d->setChoices("groups", groups);
  d->setChoices("materials", materials);
  d->setChoices("joint properties", joints);
  d->setChoices("joint names", names);
  d->setChoices("zone models", {"elastic", "mohr-coulomb", "drucker-prager", "null"});
  // OK runs the command; the dialog stays open until it has run, and shows its error if it
  // fails (onFinished).
  connect(d, &CommandDialog::submitted, this, [this, d, name] {
    if (busy()) return d->showError("The solver is running: pause or stop it first.");
    waiting_dialog_ = d;
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
