// Editing in the window: undo and redo of commands, and the drawing tools that turn shapes
// drawn in the view into script commands.
#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QToolBar>
#include <cmath>

#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/solver_worker.hpp"
#include "tessera/ui/vtk_view.hpp"

namespace tessera::ui {

void MainWindow::buildEditActions() {
  QMenu* edit = menuBar()->addMenu("&Edit");
  undo_action_ = edit->addAction("&Undo", QKeySequence::Undo, this, &MainWindow::undo);
  redo_action_ = edit->addAction("&Redo", QKeySequence::Redo, this, &MainWindow::redo);
  undo_action_->setObjectName("undo");
  redo_action_->setObjectName("redo");
  QToolBar* bar = addToolBar("Draw");
  bar->setObjectName("draw_toolbar");
  auto* tools = new QActionGroup(this);
  // Clicking the tool that is on keeps it on (Select is the tool that draws nothing).
  tools->setExclusionPolicy(QActionGroup::ExclusionPolicy::Exclusive);
  select_tool_ = bar->addAction("Select");
  select_tool_->setToolTip("Select blocks: click one, or drag a box around their centroids");
  block_tool_ = bar->addAction("Block");
  block_tool_->setToolTip("Draw a block: click its corners, double-click or Enter to finish");
  crack_tool_ = bar->addAction("Crack");
  crack_tool_->setToolTip("Draw a crack: click its points, double-click or Enter to cut");
  for (QAction* a : {select_tool_, block_tool_, crack_tool_}) {
    a->setCheckable(true);
    tools->addAction(a);
    edit->addAction(a);
  }
  connect(tools, &QActionGroup::triggered, this, [this](QAction*) {
    setTool(block_tool_->isChecked()    ? DrawMode::kBlock
            : crack_tool_->isChecked()  ? DrawMode::kCrack
            : select_tool_->isChecked() ? DrawMode::kSelect
                                        : DrawMode::kNone);
  });
  bar->addWidget(new QLabel(" Grid ", bar));
  grid_box_ = new QDoubleSpinBox(bar);
  grid_box_->setRange(0, 1e6);
  grid_box_->setDecimals(3);
  grid_box_->setSuffix(" m");
  grid_box_->setToolTip("Snapping grid spacing (0: none); points also snap to block corners");
  bar->addWidget(grid_box_);
  bar->addWidget(new QLabel(" Group ", bar));
  group_edit_ = new QLineEdit(bar);
  group_edit_->setMaximumWidth(120);
  group_edit_->setToolTip("Group of new blocks (empty: none)");
  bar->addWidget(group_edit_);
  bar->addWidget(new QLabel(" Material ", bar));
  material_box_ = new QComboBox(bar);
  material_box_->setToolTip("Material of new blocks (define materials first)");
  bar->addWidget(material_box_);
  connect(grid_box_, &QDoubleSpinBox::valueChanged, this,
          [this] { view_->setDrawing(view_->drawing().mode(), grid_box_->value()); });
  connect(view_, &VtkView::drawn, this, &MainWindow::onDrawn);
  // The worker keeps at most so many save points: older commands can no longer be undone (the
  // list is trimmed when the command's end is heard).
  connect(worker_, &SolverWorker::undoDepth, this, [this](int depth) { undo_depth_ = depth; });
}

void MainWindow::setTool(DrawMode mode) {
  select_tool_->setChecked(mode == DrawMode::kSelect);
  block_tool_->setChecked(mode == DrawMode::kBlock);
  crack_tool_->setChecked(mode == DrawMode::kCrack);
  view_->setDrawing(mode, grid_box_->value());
  if (mode != DrawMode::kNone) view_->setFocus();
}

void MainWindow::setDrawingDefaults(double grid, const QString& group, const QString& material) {
  grid_box_->setValue(grid);
  group_edit_->setText(group);
  if (material_box_->findText(material) < 0) material_box_->addItem(material);
  material_box_->setCurrentText(material);
}

void MainWindow::onDrawn(DrawMode mode, const QVector<QPointF>& points) {
  Drawing d;
  d.start(mode);
  for (const QPointF& p : points) d.add(Vec2(p.x(), p.y()));
  const std::string line = d.command(group_edit_->text().trimmed().toStdString(),
                                     material_box_->currentText().toStdString());
  if (line.empty()) return;
  // A block drawn before any rounding length is set: a default one first, stated (a hundredth
  // of the block's shortest edge, as a round number), so the drawn shape is not lost.
  if (mode == DrawMode::kBlock && (!shown_ || !(shown_->rounding > 0))) {
    double shortest = 1e300;
    for (qsizetype k = 0; k < points.size(); ++k) {
      const QPointF e = points[(k + 1) % points.size()] - points[k];
      shortest = std::min(shortest, std::hypot(e.x(), e.y()));
    }
    const double d_round = std::pow(10.0, std::floor(std::log10(0.01 * shortest)));
    const QString round = QString("round %1").arg(d_round, 0, 'g', 3);
    console_->append("no rounding length set yet: " + round +
                         " (a hundredth of the block's shortest edge, rounded down); change "
                         "it with 'round D' before drawing",
                     false);
    return runCommands({round, QString::fromStdString(line)});
  }
  runCommand(QString::fromStdString(line));
}

bool MainWindow::canUndo() const {
  return !busy() && !undoable_.isEmpty();
}

bool MainWindow::canRedo() const {
  return !busy() && !redo_.isEmpty();
}

void MainWindow::undo() {
  if (!canUndo()) return;
  running_ = "<undo>";
  setBusy(true);
  QMetaObject::invokeMethod(worker_, "undo", Qt::QueuedConnection);
}

void MainWindow::redo() {
  if (!canRedo()) return;
  redoing_ = true;
  runCommand(redo_.last());
}

void MainWindow::updateEditActions() {
  if (!undo_action_) return;  // not built yet
  undo_action_->setEnabled(canUndo());
  redo_action_->setEnabled(canRedo());
  undo_action_->setText(undoable_.isEmpty() ? "&Undo" : "&Undo " + undoable_.last());
  redo_action_->setText(redo_.isEmpty() ? "&Redo" : "&Redo " + redo_.last());
  // New blocks take a material the model has.
  if (shown_) {
    QStringList names;
    for (const Entry& m : shown_->materials) names << QString::fromStdString(m.name);
    QStringList have;
    for (int i = 0; i < material_box_->count(); ++i) have << material_box_->itemText(i);
    if (names != have) {
      const QString current = material_box_->currentText();
      material_box_->clear();
      material_box_->addItems(names);
      if (names.contains(current)) material_box_->setCurrentText(current);
    }
  }
}

}  // namespace tessera::ui
