// The excavation sequence: stages that each excavate or change something (script commands) and
// then solve to a criterion, edited, reordered and run from a list; each stage's results are
// kept, to step through and export afterwards.
#pragma once

#include <QStringList>
#include <QWidget>
#include <memory>
#include <vector>

#include "tessera/ui/snapshot.hpp"

class QListWidget;

namespace tessera::ui {

struct PlannedStage {
  enum class State { kPending, kRunning, kDone, kFailed };
  QString name;
  QStringList commands;    // e.g. "delete group=heading", "boundary pressure=1e5 joints=tunnel"
  double ratio = 1e-5;     // solve until the unbalanced-force ratio is below this ...
  qint64 cycles = 100000;  // ... or this many cycles have run
  State state = State::kPending;
  std::shared_ptr<const Snapshot> result;  // the model when the stage ended
};

class StagePanel : public QWidget {
  Q_OBJECT
 public:
  explicit StagePanel(QWidget* parent = nullptr);
  void addStage(const PlannedStage& s);
  void removeStage(int i);
  // Moves stage i up (delta -1) or down (+1).
  void moveStage(int i, int delta);
  void setState(int i, PlannedStage::State state, std::shared_ptr<const Snapshot> result = {});
  const std::vector<PlannedStage>& stages() const { return stages_; }
  // The script lines a stage runs: its commands, then its solve.
  static QStringList lines(const PlannedStage& s);
  // Selects stage i in the list (showing its results if it has them).
  void select(int i);
  void clear();
  // The stages not yet run as script comments ("; stage NAME ratio=R cycles=N" and ";   CMD"
  // lines), so a saved script keeps the plan; and the stages read back from such lines (the
  // other lines returned).
  QStringList planComments() const;
  QStringList takePlan(const QStringList& script);

 signals:
  void runRequested();
  void exportRequested();
  // A stage with results was selected: show them.
  void resultChosen(int stage);
  // The plan was changed by the user (added, edited, moved, removed).
  void edited();

 private:
  void refresh();
  // Edits stage i in a dialog (-1: a new stage); false if cancelled.
  bool edit(int i);

  QListWidget* list_;
  std::vector<PlannedStage> stages_;
};

}  // namespace tessera::ui
