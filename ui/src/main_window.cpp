// Main window layout, actions, and the flow between the solver thread and the view.
#include "tessera/ui/main_window.hpp"

#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDateTime>
#include <QDialog>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTextStream>
#include <QToolBar>
#include <algorithm>
#include <cmath>

#include "tessera/ui/command_dialog.hpp"
#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/figure_writer.hpp"
#include "tessera/ui/history_charts.hpp"
#include "tessera/ui/model_tree.hpp"
#include "tessera/ui/solver_worker.hpp"
#include "tessera/ui/stage_panel.hpp"
#include "tessera/ui/vtk_view.hpp"

namespace tessera::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      worker_(new SolverWorker),
      view_(new VtkView(this)),
      console_(new ConsoleWidget(this)),
      charts_(new HistoryCharts(this)),
      tree_(new ModelTree(this)),
      properties_(new PropertyPanel(this)) {
  setWindowTitle("Tessera");
  qApp->installEventFilter(this);
  setCentralWidget(view_);
  buildActions();
  buildEditActions();
  buildDocks();
  buildStageDock();
  buildModelMenu();
  // The View menu reopens any panel that was closed (each panel's own show/hide action).
  view_menu_->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) view_menu_->addAction(d->toggleViewAction());
  // The solver's thread: commands go to it queued, its log and results come back queued.
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &SolverWorker::logLine, console_, &ConsoleWidget::append);
  connect(worker_, &SolverWorker::started, this, &MainWindow::onStarted);
  connect(worker_, &SolverWorker::finished, this, &MainWindow::onFinished);
  thread_.start();
  // A command typed while the solver runs waits its turn (the line keeps focus, so typing on
  // after Enter loses nothing).
  connect(console_, &ConsoleWidget::command, this, [this](const QString& line) {
    if (!busy()) return runCommand(line);
    pending_.append(line);
    console_->append("queued: " + line + " (runs when the solver is done)", false);
  });
  // Python: the lines of one statement gather until Python says it is complete, then run as
  // one command (journaled as comments, undone as one). Typed while the solver runs, a line
  // stays in the input to send again.
  connect(console_, &ConsoleWidget::python, this, [this](const QString& line) {
    if (busy()) {
      console_->input()->setText(line);
      console_->append("the solver is running: Python waits until it is done (press Enter then)",
                       true);
      return;
    }
    python_lines_.append(line);
    runCommand(kPythonPrefix + python_lines_.join('\n'));
  });
  connect(console_, &ConsoleWidget::statementDropped, this, [this] { python_lines_.clear(); });
  connect(worker_, &SolverWorker::pythonMore, this, [this] {
    running_.clear();
    setBusy(false);
    console_->setContinuation(true);
    // Commands queued meanwhile run now, in order.
    if (!pending_.isEmpty() && stage_running_ < 0) runCommand(pending_.takeFirst());
  });
  // The camera turned: figures of the current view and the caption follow it.
  connect(view_, &VtkView::turned, this, [this](double azimuth, double elevation) {
    options_.azimuth = azimuth, options_.elevation = elevation;
    redraw();
  });
  connect(view_, &VtkView::picked, this, [this](int block, int contact) {
    if (!shown_) return;
    if (contact >= 0)
      properties_->show(QString("contact %1").arg(contact + 1),
                        contact_properties(*shown_, contact));
    else if (block >= 0)
      properties_->show(QString("block %1").arg(shown_->blocks[static_cast<size_t>(block)].id),
                        block_properties(*shown_, block));
  });
  connect(view_, &VtkView::zonePicked, this, [this](int zone) {
    if (shown_ && static_cast<size_t>(zone) < shown_->zones.size())
      properties_->show(QString("zone %1").arg(shown_->zones[size_t(zone)].index + 1),
                        zone_properties(*shown_, zone));
  });
  connect(tree_, &ModelTree::selected, properties_, &PropertyPanel::show);
  // Frames: at most 15 a second, pulled from the worker, never waiting for it.
  connect(&frame_timer_, &QTimer::timeout, this, &MainWindow::frame);
  frame_timer_.start(66);
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  colour_box_->setCurrentText(settings.value("view/colour", "group").toString());
  contacts_box_->setCurrentText(settings.value("view/contacts", "state").toString());
  updateRecent();
  statusBar()->showMessage("Open a model script (File > Open) or type commands in the console");
}

MainWindow::~MainWindow() {
  worker_->stop();
  thread_.quit();
  thread_.wait();
}

void MainWindow::closeEvent(QCloseEvent* e) {
  if (!keepWork()) return e->ignore();
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  settings.setValue("view/colour", colour_box_->currentText());
  settings.setValue("view/contacts", contacts_box_->currentText());
  worker_->stop();
  e->accept();
}

void MainWindow::buildActions() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&Open script…", QKeySequence::Open, this, [this] {
    QSettings settings;
    const QString path = QFileDialog::getOpenFileName(this, "Open model script",
                                                      settings.value("files/dir").toString(),
                                                      "Tessera scripts (*.tess);;All files (*)");
    if (!path.isEmpty()) openScript(path);
  });
  recent_menu_ = file->addMenu("Open &recent");
  file->addAction("&Save script as…", QKeySequence::Save, this, &MainWindow::saveScriptAs);
  file->addAction("Save s&tate as…", QKeySequence("Ctrl+Shift+S"), this, &MainWindow::saveStateAs);
  file->addAction("&Export figure…", QKeySequence("Ctrl+E"), this, &MainWindow::exportDialog);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

  QMenu* run = menuBar()->addMenu("&Run");
  run_action_ = run->addAction("&Solve", QKeySequence("F5"), this, [this] { solve(); });
  step_action_ = run->addAction("S&tep", QKeySequence("F10"), this, [this] { step(0); });
  pause_action_ = run->addAction("&Pause", QKeySequence("F6"));
  pause_action_->setCheckable(true);
  connect(pause_action_, &QAction::toggled, this, &MainWindow::setPaused);
  stop_action_ = run->addAction("St&op", QKeySequence("Shift+F5"), this, &MainWindow::stopRun);
  run->addSeparator();
  run->addAction("&Factor of safety…", this, [this] { openDialog("fos"); });
  QMenu* view = view_menu_ = menuBar()->addMenu("&View");
  view->addAction("&Fit model", QKeySequence("Home"), this, [this] { view_->resetCamera(); });
  // 3D models: the camera's projection, and a plane to look inside.
  QAction* perspective = view->addAction("&Perspective (3D)");
  perspective->setObjectName("perspective");
  perspective->setCheckable(true);
  connect(perspective, &QAction::toggled, this, [this](bool on) {
    options_.perspective = on;  // figures of the current view follow it, the caption says so
    view_->setPerspective(on);
    redraw();
  });
  QAction* see_through = view->addAction("&See-through blocks (3D)");
  see_through->setObjectName("see_through");
  see_through->setCheckable(true);
  connect(see_through, &QAction::toggled, view_, &VtkView::setSeeThrough);
  view->addAction("&Cut plane… (3D)", this, &MainWindow::cutDialog);
  view->addAction("&Remove cut", this, [this] {
    options_.cut = false;
    redraw();
  });

  QToolBar* bar = addToolBar("Run");
  bar->setObjectName("run_toolbar");
  bar->addAction(run_action_);
  bar->addAction(step_action_);
  steps_box_ = new QSpinBox(bar);
  steps_box_->setRange(1, 100000000);
  steps_box_->setValue(1000);
  steps_box_->setToolTip("Cycles per step");
  bar->addWidget(steps_box_);
  bar->addAction(pause_action_);
  bar->addAction(stop_action_);
  QToolBar* show = addToolBar("View");
  show->setObjectName("view_toolbar");
  show->addWidget(new QLabel(" Colour ", show));
  colour_box_ = new QComboBox(show);
  for (const auto& n : colour_by_names()) colour_box_->addItem(QString::fromStdString(n));
  show->addWidget(colour_box_);
  show->addWidget(new QLabel(" Contacts ", show));
  contacts_box_ = new QComboBox(show);
  for (const auto& n : contact_show_names()) contacts_box_->addItem(QString::fromStdString(n));
  contacts_box_->setCurrentText("state");
  show->addWidget(contacts_box_);
  show->addWidget(new QLabel(" Support ", show));
  support_box_ = new QComboBox(show);
  support_box_->addItems({"state", "force"});
  support_box_->setToolTip("Bolts and cables coloured by state, or by axial force");
  show->addWidget(support_box_);
  vectors_box_ = new QCheckBox("Vectors", show);
  show->addWidget(vectors_box_);
  show->addWidget(new QLabel(" Magnify ", show));
  magnify_box_ = new QDoubleSpinBox(show);
  magnify_box_->setRange(0, 1e6);
  magnify_box_->setDecimals(1);
  magnify_box_->setValue(1);
  show->addWidget(magnify_box_);
  // Any view option change redraws the snapshot on screen.
  auto changed = [this] {
    parse_colour_by(colour_box_->currentText().toStdString(), options_.colour);
    parse_contact_show(contacts_box_->currentText().toStdString(), options_.contacts);
    options_.support_force = support_box_->currentText() == "force";
    options_.vectors = vectors_box_->isChecked();
    options_.magnify = magnify_box_->value();
    redraw();
  };
  connect(colour_box_, &QComboBox::currentTextChanged, this, changed);
  connect(contacts_box_, &QComboBox::currentTextChanged, this, changed);
  connect(support_box_, &QComboBox::currentTextChanged, this, changed);
  connect(vectors_box_, &QCheckBox::toggled, this, changed);
  connect(magnify_box_, &QDoubleSpinBox::valueChanged, this, changed);

  cycle_label_ = new QLabel(this);
  ratio_label_ = new QLabel(this);
  speed_label_ = new QLabel(this);
  progress_ = new QProgressBar(this);
  progress_->setMaximumWidth(160);
  progress_->hide();
  for (QWidget* w : {static_cast<QWidget*>(cycle_label_), static_cast<QWidget*>(ratio_label_),
                     static_cast<QWidget*>(speed_label_), static_cast<QWidget*>(progress_)})
    statusBar()->addPermanentWidget(w);
  setBusy(false);
}

void MainWindow::buildDocks() {
  auto dock = [this](const QString& title, QWidget* w, Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(title);
    d->setWidget(w);
    addDockWidget(area, d);
    return d;
  };
  dock("Model", tree_, Qt::LeftDockWidgetArea);
  dock("Properties", properties_, Qt::LeftDockWidgetArea);
  dock("Console", console_, Qt::BottomDockWidgetArea);
  dock("Histories", charts_, Qt::RightDockWidgetArea);
  resize(1400, 900);
}

bool MainWindow::busy() const {
  return worker_->busy() || !running_.isEmpty();
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::KeyPress && watched->isWidgetType() &&
      static_cast<QWidget*>(watched)->window() == this) {
    const int key = static_cast<QKeyEvent*>(event)->key();
    const auto* text = qobject_cast<QLineEdit*>(QApplication::focusWidget());
    if ((key == Qt::Key_Return || key == Qt::Key_Enter) && (!text || text->text().isEmpty()) &&
        view_->finishShape())
      return true;
  }
  return QMainWindow::eventFilter(watched, event);
}

void MainWindow::setBusy(bool b) {
  run_action_->setEnabled(!b);
  step_action_->setEnabled(!b);
  pause_action_->setEnabled(b);
  stop_action_->setEnabled(b);
  if (!b && pause_action_->isChecked()) pause_action_->setChecked(false);
  updateEditActions();
}

void MainWindow::openScript(const QString& path) {
  const QFileInfo info(path);
  if (!info.isReadable()) {
    console_->append(path + ": cannot open the script file", true);
    return;
  }
  if (!keepWork()) return;
  if (busy()) worker_->stop();
  dirty_ = false;
  python_lines_.clear(), console_->setContinuation(false);
  script_path_ = info.absoluteFilePath();
  QFile f(script_path_);
  journal_.clear();
  if (f.open(QIODevice::ReadOnly | QIODevice::Text))
    journal_ = QString::fromUtf8(f.readAll()).split('\n');
  if (!journal_.isEmpty() && journal_.back().isEmpty()) journal_.removeLast();
  // A plan of stages saved with the script comes back into the stage list.
  stages_->clear();
  journal_ = stages_->takePlan(journal_);
  const QString out = info.dir().filePath(info.completeBaseName() + "_out");
  setWindowTitle("Tessera - " + info.fileName());
  QSettings().setValue("files/dir", info.absolutePath());
  updateRecent(script_path_);
  fit_next_ = true;
  running_ = "<open>";
  undoable_.clear(), redo_.clear();
  setBusy(true);
  QMetaObject::invokeMethod(worker_, "openFile", Qt::QueuedConnection, Q_ARG(QString, script_path_),
                            Q_ARG(QString, out));
}

void MainWindow::runCommand(const QString& line) {
  if (busy()) {
    console_->append("the solver is running: pause or stop it before typing a command", true);
    return;
  }
  running_ = line;
  setBusy(true);
  if (line.startsWith(kPythonPrefix))
    QMetaObject::invokeMethod(worker_, "executePython", Qt::QueuedConnection,
                              Q_ARG(QString, line.mid(kPythonPrefix.size())));
  else
    QMetaObject::invokeMethod(worker_, "execute", Qt::QueuedConnection, Q_ARG(QString, line));
}

void MainWindow::step(int cycles) {
  runCommand(QString("step %1").arg(cycles > 0 ? cycles : steps_box_->value()));
}

void MainWindow::solve() {
  runCommand("solve");
}

void MainWindow::setPaused(bool paused) {
  worker_->setPaused(paused);
  statusBar()->showMessage(paused ? "paused" : "running");
}

void MainWindow::stopRun() {
  worker_->stop();
}

void MainWindow::onStarted(const QString& what) {
  statusBar()->showMessage(stage_running_ >= 0
                               ? QString::fromStdString(stageTitle(stage_running_)) +
                                     " - running: " + what
                               : "running: " + what);
  progress_->setRange(0, 0);  // busy indicator
  progress_->show();
  speed_cycle_ = step_from_ = shown_ ? shown_->cycle : 0;
  speed_ms_ = QDateTime::currentMSecsSinceEpoch();
}

void MainWindow::onFinished(bool ok, const QString& error) {
  const QString what = running_;
  running_.clear();
  progress_->hide();
  setBusy(false);
  // A Python statement ran (or failed): the prompt starts afresh.
  if (what.startsWith(kPythonPrefix)) python_lines_.clear(), console_->setContinuation(false);
  if (ok && !what.startsWith('<')) {
    // Python goes into the saved script as comments, a line each.
    journal_.append(QString(what).replace("\n", "\n" + kPythonPrefix).split('\n')), dirty_ = true;
    undoable_.append(what);
    // A new command ends the redo list; a redone one moves from it.
    if (redoing_)
      redo_.removeLast();
    else
      redo_.clear();
  }
  if (ok && what == "<undo>" && !undoable_.isEmpty()) {
    redo_.append(undoable_.takeLast());
    // Its journal lines (a Python statement may have several).
    for (qsizetype k = redo_.last().count('\n') + 1; k > 0 && !journal_.isEmpty(); --k)
      journal_.removeLast();
    dirty_ = true;
  }
  redoing_ = false;
  while (undoable_.size() > undo_depth_) undoable_.removeFirst();
  // The Undo and Redo entries name the lists as they are now (setBusy above named them before
  // this command joined them; a snapshot arriving later used to put that right, unless the
  // frame timer had taken it first).
  updateEditActions();
  // A script that failed part way: the lines after the failing one did not run; they stay in
  // the journal as comments, so saving keeps them without pretending they ran.
  if (!ok && what == "<open>") {
    const QString prefix = script_path_ + ":";
    const int line =
        error.startsWith(prefix) ? error.mid(prefix.size()).section(':', 0, 0).toInt() : 0;
    for (int i = std::max(line - 1, 0); line > 0 && i < journal_.size(); ++i)
      journal_[i] = "; not run: " + journal_[i];
  }
  frame();
  // A dialog's command: it closes once its commands have run, or keeps its fields and shows
  // the error.
  const bool in_dialog = !waiting_dialog_.isNull();
  if (in_dialog && !ok) waiting_dialog_->showError(error, waiting_ran_);
  if (in_dialog && ok) ++waiting_ran_;
  if (in_dialog && (!ok || pending_.isEmpty())) {
    if (ok) waiting_dialog_->finish();
    waiting_dialog_.clear();
  }
  if (!ok && in_dialog) {
    statusBar()->showMessage("error: the model is as it was before the failing command");
  } else if (!ok) {
    statusBar()->showMessage("error: the model is as it was before the failing command");
    if (error_box_) error_box_->deleteLater();
    error_box_ = new QMessageBox(QMessageBox::Warning, "Tessera", error, QMessageBox::Ok, this);
    error_box_->setInformativeText("The model is as it was before this command.");
    error_box_->setModal(false);
    error_box_->show();
  } else {
    statusBar()->showMessage("ready");
  }
  emit commandFinished(ok);
  if (stage_running_ >= 0 && !what.startsWith('<')) onStageLineFinished(ok);
  if (!ok && !pending_.isEmpty()) {
    console_->append("not run after the error: " + pending_.join("; "), true);
    pending_.clear();
  }
  if (!pending_.isEmpty() && stage_running_ < 0)
    QTimer::singleShot(0, this, [this] {
      if (!pending_.isEmpty() && !busy()) runCommand(pending_.takeFirst());
    });
}

void MainWindow::frame() {
  if (worker_->busy()) worker_->requestSnapshot();
  if (auto s = worker_->takeSnapshot()) display(std::move(s));
}

void MainWindow::display(std::shared_ptr<const Snapshot> s) {
  const qint64 now = QDateTime::currentMSecsSinceEpoch();
  if (!worker_->busy())
    speed_label_->clear();
  else if (now > speed_ms_ + 500 && s->cycle >= speed_cycle_) {
    speed_label_->setText(
        QString("%1 cycles/s")
            .arg(1000.0 * double(s->cycle - speed_cycle_) / double(now - speed_ms_), 0, 'f', 0));
    speed_cycle_ = s->cycle, speed_ms_ = now;
  }
  // Progress of a step: cycles done of those asked for; a solve shows a busy bar.
  if (running_.startsWith("step ")) {
    const qint64 n = running_.mid(5).trimmed().toLongLong();
    if (n > 0 && s->cycle >= step_from_) {
      progress_->setRange(0, 1000);
      progress_->setValue(int(std::min<qint64>(1000, 1000 * qint64(s->cycle - step_from_) / n)));
    }
  }
  shown_ = std::move(s);
  cycle_label_->setText(QString("cycle %1").arg(shown_->cycle));
  ratio_label_->setText(QString("ratio %1").arg(shown_->ratio, 0, 'e', 2));
  tree_->update(*shown_);
  charts_->update(*shown_);
  redraw(fit_next_ && !shown_->blocks.empty());
  if (!shown_->blocks.empty()) fit_next_ = false;
  updateEditActions();
}

void MainWindow::redraw(bool fit) {
  if (shown_) view_->showScene(build_scene(*shown_, options_, true), fit);
}

void MainWindow::setViewOptions(const ViewOptions& o) {
  options_ = o;
  colour_box_->setCurrentText(QString::fromStdString(colour_by_names()[size_t(o.colour)]));
  contacts_box_->setCurrentText(QString::fromStdString(contact_show_names()[size_t(o.contacts)]));
  support_box_->setCurrentText(o.support_force ? "force" : "state");
  vectors_box_->setChecked(o.vectors);
  magnify_box_->setValue(o.magnify);
  if (auto* perspective = findChild<QAction*>("perspective"))
    perspective->setChecked(o.perspective);  // the view takes it when it changes
  redraw();
}

void MainWindow::exportFigure(const QString& path, int width, int height) {
  if (!shown_) throw std::runtime_error("there is no model to draw");
  ViewOptions o = options_;
  o.has_window = true;
  view_->visibleWindow(o.lo, o.hi);
  // 3D: the window's camera, so that a perspective figure shows what the window shows.
  if (shown_->three) o.has_camera = true, view_->camera3(o.focus, o.distance);
  write_figure(build_scene(*shown_, o), path.toStdString(), width, height);
  console_->append("figure " + path, false);
}

void MainWindow::exportDialog() {
  QSettings settings;
  const QString path = QFileDialog::getSaveFileName(
      this, "Export figure", settings.value("files/figure", "figure.png").toString(),
      "PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)");
  if (path.isEmpty()) return;
  settings.setValue("files/figure", path);
  QDialog d(this);
  d.setWindowTitle("Figure size");
  auto* w = new QSpinBox(&d);
  auto* h = new QSpinBox(&d);
  for (QSpinBox* s : {w, h}) s->setRange(16, 16384);
  w->setValue(settings.value("figure/width", 1600).toInt());
  h->setValue(settings.value("figure/height", 1000).toInt());
  auto* ok = new QPushButton("Export", &d);
  auto* layout = new QHBoxLayout(&d);
  layout->addWidget(new QLabel("width", &d));
  layout->addWidget(w);
  layout->addWidget(new QLabel("height", &d));
  layout->addWidget(h);
  layout->addWidget(ok);
  connect(ok, &QPushButton::clicked, &d, &QDialog::accept);
  if (d.exec() != QDialog::Accepted) return;
  settings.setValue("figure/width", w->value());
  settings.setValue("figure/height", h->value());
  try {
    exportFigure(path, w->value(), h->value());
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "Tessera", e.what());
  }
}

bool MainWindow::saveScript(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
  QTextStream out(&f);
  for (const QString& line : journal_) out << line << '\n';
  for (const QString& line : stages_->planComments()) out << line << '\n';
  out.flush();
  if (f.error() != QFileDevice::NoError) return false;
  dirty_ = false;
  console_->append("saved the script (" + QString::number(journal_.size()) + " lines) to " + path,
                   false);
  return true;
}

bool MainWindow::saveScriptAs() {
  const QString path =
      QFileDialog::getSaveFileName(this, "Save script", script_path_, "Tessera scripts (*.tess)");
  if (path.isEmpty()) return false;
  if (saveScript(path)) return true;
  QMessageBox::warning(this, "Tessera", "cannot write " + path);
  return false;
}

bool MainWindow::keepWork() {
  if (!dirty_) return true;
  const auto answer = QMessageBox::question(
      this, "Tessera", "Commands were run since the script was opened or saved. Save them?",
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save) return saveScriptAs();
  return answer == QMessageBox::Discard;
}

void MainWindow::saveStateAs() {
  const QString path =
      QFileDialog::getSaveFileName(this, "Save state", {}, "Tessera state (*.sav)");
  if (path.isEmpty() || busy()) return;
  running_ = "<save>";
  setBusy(true);
  QMetaObject::invokeMethod(worker_, "saveState", Qt::QueuedConnection, Q_ARG(QString, path));
}

void MainWindow::updateRecent(const QString& added) {
  QSettings settings;
  QStringList recent = settings.value("files/recent").toStringList();
  if (!added.isEmpty()) {
    recent.removeAll(added);
    recent.prepend(added);
    while (recent.size() > 8) recent.removeLast();
    settings.setValue("files/recent", recent);
  }
  recent_menu_->clear();
  for (const QString& path : recent)
    recent_menu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openScript(path); })
        ->setToolTip(path);
  recent_menu_->setEnabled(!recent.isEmpty());
}

}  // namespace tessera::ui
