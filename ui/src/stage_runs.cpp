// Running an excavation sequence from the stage list, showing each stage's results, and
// exporting them as figures and a video.
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>

#include "tessera/ui/console_widget.hpp"
#include "tessera/ui/figure_writer.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/stage_panel.hpp"
#include "tessera/ui/vtk_view.hpp"

namespace tessera::ui {

void MainWindow::buildStageDock() {
  stages_ = new StagePanel(this);
  auto* d = new QDockWidget("Stages", this);
  d->setObjectName("Stages");
  d->setWidget(stages_);
  addDockWidget(Qt::RightDockWidgetArea, d);
  connect(stages_, &StagePanel::runRequested, this, &MainWindow::runStages);
  connect(stages_, &StagePanel::edited, this, [this] { dirty_ = true; });
  connect(stages_, &StagePanel::resultChosen, this, &MainWindow::showStageResult);
  connect(stages_, &StagePanel::exportRequested, this, [this] {
    QSettings settings;
    const QString dir = QFileDialog::getExistingDirectory(
        this, "Export stage figures into", settings.value("files/stages").toString());
    if (dir.isEmpty()) return;
    settings.setValue("files/stages", dir);
    exportStages(dir, settings.value("figure/width", 1600).toInt(),
                 settings.value("figure/height", 1000).toInt());
  });
}

void MainWindow::runStages() {
  if (busy()) {
    console_->append("the solver is running: wait or stop it before running the stages", true);
    return;
  }
  stage_queue_.clear();
  const auto& list = stages_->stages();
  for (size_t i = 0; i < list.size(); ++i) {
    if (list[i].state == PlannedStage::State::kDone) continue;
    const QStringList lines = StagePanel::lines(list[i]);
    for (int k = 0; k < lines.size(); ++k)
      stage_queue_.push_back({static_cast<int>(i), lines[k], k + 1 == lines.size()});
  }
  if (stage_queue_.empty()) {
    console_->append("no stage left to run: add one, or edit a finished one to run it again",
                     false);
    emit stagesFinished(true);
    return;
  }
  runNextStageLine();
}

void MainWindow::runNextStageLine() {
  const StageLine next = stage_queue_.front();
  stage_queue_.pop_front();
  if (next.stage != stage_running_) {
    stage_running_ = next.stage;
    stages_->setState(next.stage, PlannedStage::State::kRunning);
    stages_->select(next.stage);
  }
  runCommand(next.line);
  stage_last_ = next.last;
}

void MainWindow::onStageLineFinished(bool ok) {
  const int stage = stage_running_;
  if (!ok) {
    stages_->setState(stage, PlannedStage::State::kFailed);
    stage_queue_.clear();
    stage_running_ = -1;
    console_->append(QString("stage %1 failed: the stages after it were not run").arg(stage + 1),
                     true);
    emit stagesFinished(false);
    return;
  }
  if (stage_last_) stages_->setState(stage, PlannedStage::State::kDone, shown_);
  if (stage_queue_.empty()) {
    stage_running_ = -1;
    statusBar()->showMessage("stages done");
    emit stagesFinished(true);
    return;
  }
  QTimer::singleShot(0, this, &MainWindow::runNextStageLine);
}

std::string MainWindow::stageTitle(int i) const {
  const PlannedStage& s = stages_->stages()[size_t(i)];
  return QString("Stage %1: %2").arg(i + 1).arg(s.name).toStdString();
}

void MainWindow::showStageResult(int i) {
  if (busy() || i < 0 || static_cast<size_t>(i) >= stages_->stages().size()) return;
  const auto& result = stages_->stages()[size_t(i)].result;
  if (!result) return;
  shown_ = result;
  ViewOptions o = options_;
  o.title = stageTitle(i);
  view_->showScene(build_scene(*shown_, o, true));
  statusBar()->showMessage(
      QString("showing the results of stage %1 (cycle %2)").arg(i + 1).arg(shown_->cycle));
}

int MainWindow::exportStages(const QString& dir, int width, int height) {
  QDir().mkpath(dir);
  int written = 0;
  const auto& list = stages_->stages();
  for (size_t i = 0; i < list.size(); ++i) {
    if (!list[i].result) continue;
    ViewOptions o = options_;
    o.title = stageTitle(static_cast<int>(i));
    const QString path =
        QDir(dir).filePath(QString("stage_%1.png").arg(++written, 2, 10, QChar('0')));
    write_figure(build_scene(*list[i].result, o), path.toStdString(), width, height);
  }
  console_->append(QString("%1 stage figure(s) in %2").arg(written).arg(dir), false);
  // A video of the frames, one stage a second, where ffmpeg is installed.
  const QString ffmpeg = QStandardPaths::findExecutable("ffmpeg");
  if (written > 0 && !ffmpeg.isEmpty()) {
    const int code = QProcess::execute(
        ffmpeg, {"-y", "-loglevel", "error", "-framerate", "1", "-i",
                 QDir(dir).filePath("stage_%02d.png"), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                 "-pix_fmt", "yuv420p", QDir(dir).filePath("stages.mp4")});
    console_->append(code == 0 ? "video: " + QDir(dir).filePath("stages.mp4")
                               : "ffmpeg could not make the video",
                     code != 0);
  }
  return written;
}

}  // namespace tessera::ui
