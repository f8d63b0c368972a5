// The solver's thread: runs script files, typed commands, steps and solves, and hands snapshots
// of the model to the window while it cycles.
//
// The interpreter lives and runs only on this worker's thread. The window talks to it through
// queued slots (commands) and a few thread-safe calls (snapshot request, pause, stop); it never
// touches the model. Commands run with rollback on, so a failing one leaves the model as it was.
// Each command that succeeds keeps a save point of the interpreter from before it, so it can be
// undone (the newest kUndoDepth of them). Python typed in the console runs here too, on an
// interpreter embedded on this thread.
#pragma once

#include <QObject>
#include <QString>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>

#include "tessera/ui/snapshot.hpp"

namespace tessera {
class Interpreter;
struct SavePoint;
}  // namespace tessera

namespace tessera::ui {

class PythonConsole;

class SolverWorker : public QObject {
  Q_OBJECT
 public:
  SolverWorker();
  ~SolverWorker() override;

  // Thread-safe: asks for a snapshot at the next cycle the solver finishes.
  void requestSnapshot() { want_snapshot_ = true; }
  // Thread-safe: the newest snapshot not yet taken, or null.
  std::shared_ptr<const Snapshot> takeSnapshot();
  // Thread-safe: holds the solver between cycles, or lets it go on.
  void setPaused(bool paused);
  bool paused() const { return paused_; }
  // Thread-safe: ends the running step, solve or script at the next cycle or line.
  void stop();
  bool busy() const { return busy_; }
  // Save points kept for undo: at most this many, and this much memory (roughly) in all.
  static constexpr size_t kUndoDepth = 50;
  static constexpr double kUndoBytes = 1.5e9;

 public slots:
  // A new model from a script file; results go to `outDir`.
  void openFile(const QString& path, const QString& outDir);
  // One line of script typed by the user (or made by a drawing tool or dialog).
  void execute(const QString& line);
  // Python typed in the console (the lines of one statement): `m` is this model. A statement
  // still open is not run: pythonMore() asks for its next line instead of started/finished.
  void executePython(const QString& source);
  // Back to the state before the newest command that can be undone (finished reports it).
  void undo();
  // Saves the model's state (binary, for `restore`).
  void saveState(const QString& path);

 signals:
  void logLine(const QString& text, bool error);
  void started(const QString& what);
  // ok false: `error` names the file, line and fault; the model is as before the command.
  void finished(bool ok, const QString& error);
  void snapshotReady();
  // How many commands can be undone now (emitted before `finished`).
  void undoDepth(int depth);
  // The Python typed so far is a statement still open (executePython).
  void pythonMore();

 private:
  // Runs body as one command; true if it succeeded.
  bool run(const QString& what, const std::function<void()>& body);
  void publish(bool held = false);
  void observe(const Model& m);
  // Keeps the save point from before a command that succeeded, for undo.
  void keepForUndo(std::unique_ptr<SavePoint> before);

  std::unique_ptr<Interpreter> interp_;
  std::atomic<bool> want_snapshot_{false}, paused_{false}, stop_{false}, busy_{false};
  std::mutex mutex_;  // guards latest_ and the pause wait
  std::condition_variable resume_;
  std::shared_ptr<const Snapshot> latest_;
  std::deque<std::unique_ptr<SavePoint>> undo_;
  uint64_t serial_ = 0;
  int console_line_ = 0;
  std::unique_ptr<PythonConsole> python_;  // started by the first Python line
};

}  // namespace tessera::ui
