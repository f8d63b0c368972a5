// The main window: viewport, model tree, property panel, console and history charts around a
// solver running on its own thread.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <QThread>
#include <QTimer>
#include <deque>
#include <memory>
#include <string>

#include "tessera/io/figure.hpp"
#include "tessera/ui/draw_tool.hpp"
#include "tessera/ui/snapshot.hpp"

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QMenu;
class QMessageBox;
class QProgressBar;
class QSpinBox;

namespace tessera::ui {

class ConsoleWidget;
class HistoryCharts;
class ModelTree;
class PropertyPanel;
class SolverWorker;
class StagePanel;
class CommandDialog;
class VtkView;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a model script: a new model, built and run by the script on the solver's thread.
  void openScript(const QString& path);
  // Runs one line of script as if typed in the console.
  void runCommand(const QString& line);
  void step(int cycles);
  void solve();
  void setPaused(bool paused);
  void stopRun();
  // Writes the current view as a figure (.png, .svg or .pdf) of the given size.
  void exportFigure(const QString& path, int width, int height);
  void setViewOptions(const ViewOptions& o);
  // View > Cut plane (3D): a dialog for the plane (dip, dip direction, a point), which cuts the
  // window's view and the figures exported from it.
  void cutDialog();
  // Undoes the newest command run in the window (not the opened script's lines), or runs the
  // newest undone one again.
  void undo();
  void redo();
  bool canUndo() const;
  bool canRedo() const;
  // A drawing tool in the view (kNone: off); the grid for snapping (0: none); the group and
  // material new blocks get.
  void setTool(DrawMode mode);
  void setDrawingDefaults(double grid, const QString& group, const QString& material);
  // The opened script and every command run since: what "Save script" writes.
  const QStringList& journal() const { return journal_; }
  // The excavation sequence: runs the stages not yet done, in order (stagesFinished at the end);
  // shows a finished stage's results; writes a figure of each finished stage into `dir`
  // (stage_01.png, ...; and stages.mp4 where ffmpeg is installed), returning how many.
  StagePanel* stagePanel() const { return stages_; }
  // The selection (select tool: a click picks a block, a drag a box) as script selection
  // keywords ("block=3", "x=0,2 y=1,4"; empty: none), and the blocks it holds now.
  QString selection() const { return selection_; }
  const std::vector<int>& selectedBlocks() const { return selected_; }
  void selectBox(Vec2 lo, Vec2 hi);
  void selectBlock(int block);
  // Blocks by snapshot index (a box drawn over a 3D view), as `block=ID,ID,...`.
  void selectBlocks(const std::vector<int>& blocks);
  // An outline edge (as the box around it, for boundary commands) or a named joint set.
  void selectEdge(Vec2 a, Vec2 b);
  void selectJoint(const QString& name);
  // Opens one of the Model menu's dialogs by name ("material", "joint", "jset", "tunnel",
  // "horseshoe", "rectangle", "voronoi", "wall", "arch", "zones", "assign", "boundary",
  // "insitu"); OK runs its commands. Cuts and generators preview what they will make.
  CommandDialog* openDialog(const QString& name);
  // Runs lines one after another as commands; stops at the first that fails.
  void runCommands(const QStringList& lines);
  void runStages();
  void showStageResult(int stage);
  int exportStages(const QString& dir, int width, int height);
  // Writes the opened script plus every command that ran since (a failed script's lines after
  // the error commented out): rerun in batch, it rebuilds this model.
  bool saveScript(const QString& path);
  const ViewOptions& viewOptions() const { return options_; }

  bool busy() const;
  // The snapshot on screen now.
  std::shared_ptr<const Snapshot> snapshot() const { return shown_; }
  VtkView* view() const { return view_; }
  ConsoleWidget* console() const { return console_; }
  HistoryCharts* charts() const { return charts_; }
  ModelTree* tree() const { return tree_; }
  PropertyPanel* properties() const { return properties_; }
  // The last error message box, if one is open.
  QMessageBox* errorBox() const { return error_box_; }

 signals:
  // A command, file or run ended (ok false: it failed and the model was kept as before).
  void commandFinished(bool ok);
  // A run of the stage list ended (ok false: a stage failed; those after it did not run).
  void stagesFinished(bool ok);

 protected:
  void closeEvent(QCloseEvent* e) override;

 private:
  void buildActions();
  void buildEditActions();  // edit_actions.cpp: undo, redo and the drawing toolbar
  void buildDocks();
  void onDrawn(DrawMode mode, const QVector<QPointF>& points);
  void updateEditActions();
  void buildStageDock();  // stage_runs.cpp
  void runNextStageLine();
  void onStageLineFinished(bool ok);
  std::string stageTitle(int stage) const;
  void buildModelMenu();  // model_dialogs.cpp
  // Draws what a cut or generator dialog will make (model_dialogs.cpp).
  void preview(const QString& name, const CommandDialog& d);
  void preview3(const QString& name, const CommandDialog& d);  // model_previews3.cpp
  void frame();
  void display(std::shared_ptr<const Snapshot> s);
  void redraw(bool fit = false);
  void onStarted(const QString& what);
  void onFinished(bool ok, const QString& error);
  void updateRecent(const QString& added = {});
  bool saveScriptAs();
  // Asks to save commands run since the last save; false if the user cancels.
  bool keepWork();
  void saveStateAs();
  void exportDialog();
  void setBusy(bool busy);
  // Enter finishes a shape being drawn wherever the focus is (unless a text field holds text).
  bool eventFilter(QObject* watched, QEvent* event) override;

  SolverWorker* worker_;
  QThread thread_;
  QTimer frame_timer_;
  VtkView* view_;
  ConsoleWidget* console_;
  HistoryCharts* charts_;
  ModelTree* tree_;
  PropertyPanel* properties_;
  QMessageBox* error_box_ = nullptr;
  // A dialog whose command is running: closed when it succeeds, shown the error if it fails.
  QPointer<CommandDialog> waiting_dialog_;
  int waiting_ran_ = 0;  // its commands that have run
  QComboBox *colour_box_, *contacts_box_, *support_box_;
  QCheckBox* vectors_box_;
  QDoubleSpinBox* magnify_box_;
  QSpinBox* steps_box_;
  QLabel *cycle_label_, *ratio_label_, *speed_label_;
  QProgressBar* progress_;
  QMenu* recent_menu_;
  QMenu* view_menu_ = nullptr;
  QAction *run_action_, *step_action_, *pause_action_, *stop_action_;
  QAction *undo_action_ = nullptr, *redo_action_ = nullptr, *block_tool_ = nullptr,
          *crack_tool_ = nullptr;
  QDoubleSpinBox* grid_box_ = nullptr;
  QLineEdit* group_edit_ = nullptr;
  QComboBox* material_box_ = nullptr;
  ViewOptions options_;
  std::shared_ptr<const Snapshot> shown_;
  QString script_path_;
  QStringList journal_;  // the opened script and every command that ran since: "Save script"
  QString running_;
  uint64_t speed_cycle_ = 0, step_from_ = 0;
  qint64 speed_ms_ = 0;
  bool fit_next_ = true;
  bool dirty_ = false;  // commands ran since the script was opened or saved
  // Commands that can be undone (the newest last, as many as the worker keeps save points for)
  // and those undone, to redo (the newest undone last).
  QStringList undoable_, redo_;
  bool redoing_ = false;
  // The stage run: lines still to run (each with its stage, and whether it ends the stage).
  struct StageLine {
    int stage = -1;
    QString line;
    bool last = false;
  };
  StagePanel* stages_ = nullptr;
  QAction* select_tool_ = nullptr;
  QString selection_;
  std::vector<int> selected_;
  QStringList pending_;  // runCommands' lines still to run
  // The lines of the Python statement being typed (the console's Python mode).
  QStringList python_lines_;
  // What marks Python among the commands run: journaled so, a script reads it as a comment.
  inline static const QString kPythonPrefix = "; python> ";
  std::deque<StageLine> stage_queue_;
  int stage_running_ = -1;
  bool stage_last_ = false;
  int undo_depth_ = 0;  // save points the worker holds
};

}  // namespace tessera::ui
