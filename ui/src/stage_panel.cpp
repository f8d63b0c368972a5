// The stage list: editing, order, state and results of an excavation sequence.
#include "tessera/ui/stage_panel.hpp"

#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleValidator>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QVBoxLayout>

namespace tessera::ui {

StagePanel::StagePanel(QWidget* parent) : QWidget(parent), list_(new QListWidget(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(list_);
  auto* buttons = new QHBoxLayout;
  auto button = [&](const QString& text, const QString& tip, auto slot) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    connect(b, &QPushButton::clicked, this, slot);
    buttons->addWidget(b);
  };
  button("Add", "A new stage: what it excavates or changes, and its solve", [this] { edit(-1); });
  button("Edit", "Edit the selected stage", [this] {
    if (list_->currentRow() >= 0) edit(list_->currentRow());
  });
  button("Remove", "Remove the selected stage", [this] { removeStage(list_->currentRow()); });
  button("Up", "Run the selected stage earlier", [this] { moveStage(list_->currentRow(), -1); });
  button("Down", "Run the selected stage later", [this] { moveStage(list_->currentRow(), 1); });
  layout->addLayout(buttons);
  auto* run = new QHBoxLayout;
  auto* go = new QPushButton("Run stages", this);
  go->setToolTip("Run the stages not yet done, in order, keeping each one's results");
  auto* out = new QPushButton("Export figures…", this);
  out->setToolTip("A figure of each finished stage (and a video where ffmpeg is installed)");
  connect(go, &QPushButton::clicked, this, &StagePanel::runRequested);
  connect(out, &QPushButton::clicked, this, &StagePanel::exportRequested);
  run->addWidget(go);
  run->addWidget(out);
  layout->addLayout(run);
  connect(list_, &QListWidget::currentRowChanged, this, [this](int i) {
    if (i >= 0 && static_cast<size_t>(i) < stages_.size() && stages_[size_t(i)].result)
      emit resultChosen(i);
  });
}

void StagePanel::addStage(const PlannedStage& s) {
  stages_.push_back(s);
  refresh();
  emit edited();
}

void StagePanel::removeStage(int i) {
  if (i < 0 || static_cast<size_t>(i) >= stages_.size()) return;
  stages_.erase(stages_.begin() + i);
  refresh();
  emit edited();
}

void StagePanel::clear() {
  stages_.clear();
  refresh();
}

QStringList StagePanel::planComments() const {
  QStringList out;
  for (const PlannedStage& s : stages_) {
    if (s.state == PlannedStage::State::kDone) continue;
    out << QString("; stage \"%1\" ratio=%2 cycles=%3")
               .arg(s.name)
               .arg(s.ratio, 0, 'g', 6)
               .arg(s.cycles);
    for (const QString& c : s.commands) out << ";   " + c.trimmed();
  }
  return out;
}

QStringList StagePanel::takePlan(const QStringList& script) {
  static const QRegularExpression head(R"re(^; stage "(.*)" ratio=(\S+) cycles=(\d+)\s*$)re");
  QStringList rest;
  PlannedStage* current = nullptr;
  for (const QString& line : script) {
    const auto m = head.match(line);
    if (m.hasMatch()) {
      PlannedStage s;
      s.name = m.captured(1), s.ratio = m.captured(2).toDouble();
      s.cycles = m.captured(3).toLongLong();
      stages_.push_back(s);
      current = &stages_.back();
    } else if (current && line.startsWith(";   ")) {
      current->commands << line.mid(4).trimmed();
    } else {
      current = nullptr;
      rest << line;
    }
  }
  refresh();
  return rest;
}

void StagePanel::moveStage(int i, int delta) {
  const int j = i + delta;
  if (i < 0 || j < 0 || static_cast<size_t>(std::max(i, j)) >= stages_.size()) return;
  std::swap(stages_[size_t(i)], stages_[size_t(j)]);
  refresh();
  list_->setCurrentRow(j);
  emit edited();
}

void StagePanel::setState(int i, PlannedStage::State state, std::shared_ptr<const Snapshot> r) {
  if (i < 0 || static_cast<size_t>(i) >= stages_.size()) return;
  stages_[size_t(i)].state = state;
  if (r) stages_[size_t(i)].result = std::move(r);
  refresh();
}

void StagePanel::select(int i) {
  list_->setCurrentRow(i);
}

QStringList StagePanel::lines(const PlannedStage& s) {
  QStringList out;
  for (const QString& c : s.commands)
    if (!c.trimmed().isEmpty()) out << c.trimmed();
  out << QString("solve ratio=%1 cycles=%2").arg(s.ratio, 0, 'g', 6).arg(s.cycles);
  return out;
}

void StagePanel::refresh() {
  const int row = list_->currentRow();
  const QSignalBlocker quiet(list_);
  list_->clear();
  for (size_t i = 0; i < stages_.size(); ++i) {
    const PlannedStage& s = stages_[i];
    const char* state = s.state == PlannedStage::State::kDone      ? "done"
                        : s.state == PlannedStage::State::kRunning ? "running"
                        : s.state == PlannedStage::State::kFailed  ? "failed"
                                                                   : "to run";
    list_->addItem(QString("%1. %2  [%3]").arg(i + 1).arg(s.name, state));
    list_->item(static_cast<int>(i))->setToolTip(lines(s).join('\n'));
  }
  list_->setCurrentRow(std::min(row, list_->count() - 1));
}

bool StagePanel::edit(int i) {
  PlannedStage s = i >= 0 ? stages_[size_t(i)] : PlannedStage{};
  if (i < 0) s.name = QString("stage %1").arg(stages_.size() + 1);
  QDialog d(this);
  d.setWindowTitle(i < 0 ? "New stage" : "Edit stage");
  auto* form = new QFormLayout(&d);
  auto* name = new QLineEdit(s.name, &d);
  auto* commands = new QPlainTextEdit(s.commands.join('\n'), &d);
  commands->setPlaceholderText("delete group=heading\nboundary pressure=0.2e6 joints=tunnel");
  auto* ratio = new QLineEdit(QString::number(s.ratio, 'g', 6), &d);
  ratio->setValidator(new QDoubleValidator(1e-15, 1.0, 15, ratio));
  auto* cycles = new QSpinBox(&d);
  cycles->setRange(1, 2000000000);
  cycles->setValue(static_cast<int>(s.cycles));
  form->addRow("Name", name);
  form->addRow("Commands (one per line)", commands);
  form->addRow("Solve to ratio", ratio);
  form->addRow("At most (cycles)", cycles);
  auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
  connect(box, &QDialogButtonBox::accepted, &d, &QDialog::accept);
  connect(box, &QDialogButtonBox::rejected, &d, &QDialog::reject);
  form->addRow(box);
  if (d.exec() != QDialog::Accepted) return false;
  s.name = name->text().trimmed().isEmpty() ? s.name : name->text().trimmed();
  s.commands = commands->toPlainText().split('\n', Qt::SkipEmptyParts);
  s.ratio = ratio->text().toDouble();
  s.cycles = cycles->value();
  if (i < 0) {
    stages_.push_back(s);
  } else {
    s.state = PlannedStage::State::kPending, s.result.reset();  // edited: to run again
    stages_[size_t(i)] = s;
  }
  refresh();
  emit edited();
  return true;
}

}  // namespace tessera::ui
