// The worker's command loop, snapshots and pause.
#include "tessera/ui/solver_worker.hpp"

#include <QDir>
#include <filesystem>
#include <stdexcept>

#include "python_console.hpp"
#include "tessera/io/state_io.hpp"
#include "tessera/script/script.hpp"
#include "tessera/ui/figure_writer.hpp"

namespace tessera::ui {

SolverWorker::SolverWorker() {
  openFile({}, QDir::temp().filePath("tessera_out"));
}

SolverWorker::~SolverWorker() = default;

std::shared_ptr<const Snapshot> SolverWorker::takeSnapshot() {
  std::lock_guard lock(mutex_);
  return std::move(latest_);
}

void SolverWorker::setPaused(bool paused) {
  {
    std::lock_guard lock(mutex_);
    paused_ = paused;
  }
  resume_.notify_all();
}

void SolverWorker::stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    paused_ = false;
  }
  resume_.notify_all();
}

void SolverWorker::publish(bool held) {
  Model& m = interp_->model();
  for (size_t b = 0; b < m.blocks.size(); ++b) m.blocks.update_world(b);
  auto snap = std::make_shared<Snapshot>(make_snapshot(m, interp_->title(), interp_->stages()));
  snap->serial = ++serial_;
  snap->made_on = std::this_thread::get_id();
  snap->held = held;
  {
    std::lock_guard lock(mutex_);
    latest_ = std::move(snap);
  }
  emit snapshotReady();
}

// Called after every cycle on this thread: hands over a snapshot if asked, waits while paused.
void SolverWorker::observe(const Model& m) {
  if (python_) python_->observe(m);
  if (want_snapshot_.exchange(false)) publish();
  if (paused_) {
    publish(true);
    std::unique_lock lock(mutex_);
    resume_.wait(lock, [this] { return !paused_ || stop_; });
  }
}

bool SolverWorker::run(const QString& what, const std::function<void()>& body) {
  stop_ = false;
  busy_ = true;
  emit started(what);
  QString error;
  try {
    body();
  } catch (const std::exception& e) {
    error = QString::fromStdString(e.what());
    emit logLine(error, true);
  }
  if (stop_) emit logLine("stopped", false);
  stop_ = false, paused_ = false;
  busy_ = false;
  publish();
  emit finished(error.isEmpty(), error);
  return error.isEmpty();
}

void SolverWorker::openFile(const QString& path, const QString& outDir) {
  auto log = [this](const std::string& s) { emit logLine(QString::fromStdString(s), false); };
  interp_ = std::make_unique<Interpreter>(outDir.toStdString(), log);
  interp_->set_stop_flag(&stop_);
  interp_->set_rollback(true);
  interp_->set_progress_interval(5.0);
  interp_->set_observer([this](const Model& m) { observe(m); });
  interp_->set_figure_sink(figure_sink());
  console_line_ = 0;
  if (python_) python_->bind(*interp_);
  undo_.clear();
  emit undoDepth(0);
  if (path.isEmpty()) return publish();
  run("open " + path, [&] { interp_->run_file(path.toStdString()); });
}

void SolverWorker::execute(const QString& line) {
  auto before = std::make_unique<SavePoint>(interp_->save_point());
  // One copy of the model serves undo and rollback: the interpreter's own is needed only for
  // 'call', whose lines are rolled back one by one.
  const bool call = line.trimmed().section(' ', 0, 0) == "call";
  interp_->set_rollback(call);
  // The save point is kept before `finished` is emitted, so the window may undo as soon as it
  // hears; a stopped run counts (it changed the model, and the window journals it).
  run(line, [&] {
    emit logLine("> " + line, false);
    try {
      interp_->execute(line.toStdString(), "<console>", ++console_line_);
    } catch (const std::exception&) {
      if (!call) {
        interp_->restore(*before);
        emit logLine("the model is as it was before this command", false);
      }
      throw;
    }
    keepForUndo(std::move(before));
  });
  interp_->set_rollback(true);
}

void SolverWorker::keepForUndo(std::unique_ptr<SavePoint> before) {
  undo_.push_back(std::move(before));
  double bytes = 0;
  for (const auto& p : undo_) bytes += p->model.approx_bytes();
  while (undo_.size() > kUndoDepth || (undo_.size() > 1 && bytes > kUndoBytes)) {
    bytes -= undo_.front()->model.approx_bytes();
    undo_.pop_front();
  }
  emit undoDepth(static_cast<int>(undo_.size()));
}

void SolverWorker::executePython(const QString& source) {
  const std::string text = source.toStdString();
  // Python starts with the first line typed; a build without it says so as the line's error.
  if (!python_) {
    std::string why;
    try {
      python_ = std::make_unique<PythonConsole>(
          [this](const std::string& s, bool error) {
            emit logLine(QString::fromStdString(s), error);
          },
          &stop_);
      python_->bind(*interp_);
    } catch (const std::exception& e) {
      why = e.what();
      python_.reset();
    }
    if (!why.empty()) return (void)run(source, [&] { throw std::runtime_error(why); });
  }
  if (python_->incomplete(text)) return emit pythonMore();
  auto before = std::make_unique<SavePoint>(interp_->save_point());
  // The module's calls keep their own save points: the interpreter's are not needed.
  interp_->set_rollback(false);
  run(source, [&] {
    const QStringList lines = source.split('\n');
    for (int i = 0; i < lines.size(); ++i) emit logLine((i ? "... " : ">>> ") + lines[i], false);
    const std::string error = python_->run(text);
    // Stopped from the window: the model stays where the run stopped, as for a command.
    const bool stopped = stop_ && error.rfind("KeyboardInterrupt", 0) == 0;
    if (!error.empty() && !stopped) {
      interp_->restore(*before);
      python_->rollback();
      emit logLine("the model is as it was before this statement", false);
      throw std::runtime_error("Python: " + error);
    }
    keepForUndo(std::move(before));
  });
  interp_->set_rollback(true);
}

void SolverWorker::undo() {
  run("undo", [&] {
    if (undo_.empty()) throw std::runtime_error("nothing to undo");
    interp_->restore(*undo_.back());
    undo_.pop_back();
    emit undoDepth(static_cast<int>(undo_.size()));
    emit logLine("undone", false);
  });
}

void SolverWorker::saveState(const QString& path) {
  run("save " + path, [&] {
    std::filesystem::path p(path.toStdString());
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    save_state(interp_->model(), p.string());
    emit logLine("saved " + path, false);
  });
}

}  // namespace tessera::ui
