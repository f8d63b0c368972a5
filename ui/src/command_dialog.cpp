// The form of a command dialog and the command it makes.
#include "tessera/ui/command_dialog.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QToolButton>

namespace tessera::ui {

CommandDialog::CommandDialog(const QString& title, const QString& head,
                             const std::vector<CommandField>& fields, QWidget* parent)
    : QDialog(parent), head_(head), fields_(fields) {
  setWindowTitle(title);
  auto* form = new QFormLayout(this);
  for (const CommandField& f : fields_) {
    QLineEdit* edit = nullptr;
    QCheckBox* check = nullptr;
    if (f.key.startsWith('!')) {
      check = new QCheckBox(this);
      check->setChecked(!f.value.isEmpty());
      check->setToolTip(f.tip);
      connect(check, &QCheckBox::toggled, this, &CommandDialog::changed);
      form->addRow(f.label, check);
    } else {
      edit = new QLineEdit(f.value, this);
      edit->setObjectName(f.key);
      edit->setToolTip(f.tip);
      connect(edit, &QLineEdit::textChanged, this, &CommandDialog::changed);
      auto* row = new QHBoxLayout;
      row->addWidget(edit);
      if (!f.choices.isEmpty()) {
        // A list of what exists, filled when the menu opens (setChoices).
        auto* pick = new QToolButton(this);
        pick->setObjectName(f.key + "_choices");
        pick->setText("▾");
        pick->setToolTip("existing " + f.choices);
        pick->setPopupMode(QToolButton::InstantPopup);
        auto* menu = new QMenu(pick);
        const size_t i = edits_.size();
        connect(menu, &QMenu::aboutToShow, this, [this, menu, edit, i] {
          menu->clear();
          if (names_[i].isEmpty()) menu->addAction("(none yet)")->setEnabled(false);
          for (const QString& name : names_[i])
            menu->addAction(name, this, [edit, name] { edit->setText(name); });
        });
        pick->setMenu(menu);
        row->addWidget(pick);
      }
      if (!f.unit.isEmpty()) row->addWidget(new QLabel(f.unit, this));
      form->addRow(f.label, row);
    }
    edits_.push_back(edit);
    checks_.push_back(check);
    names_.emplace_back();
  }
  error_ = new QLabel(this);
  error_->setObjectName("error");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #b00000");
  error_->hide();
  form->addRow(error_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  connect(buttons, &QDialogButtonBox::accepted, this, &CommandDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

void CommandDialog::accept() {
  error_->hide();
  ok_->setEnabled(false);  // until the command has run
  emit submitted();
}

void CommandDialog::showError(const QString& error, int earlier) {
  const QString kept =
      earlier > 0 ? QString(
                        "\nThe failing command was undone; the %1 before it from this dialog "
                        "ran and stay done (Undo takes them back). Correct the fields and "
                        "press OK again.")
                        .arg(earlier)
                  : QString(
                        "\nThe model is as it was before this command: correct the fields "
                        "and press OK again.");
  error_->setText(error + kept);
  error_->show();
  ok_->setEnabled(true);
}

QString CommandDialog::error() const {
  return error_->isHidden() ? QString() : error_->text();
}

void CommandDialog::finish() {
  QDialog::accept();
}

void CommandDialog::setChoices(const QString& kind, const QStringList& names) {
  for (size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].choices == kind) names_[i] = names;
}

QStringList CommandDialog::choices(const QString& key) const {
  for (size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].key == key) return names_[i];
  return {};
}

QString CommandDialog::command() const {
  QString out = head_;
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (checks_[i]) {
      if (checks_[i]->isChecked()) out += " " + fields_[i].key.mid(1);
      continue;
    }
    const QString v = text(i);
    if (v.isEmpty()) continue;
    out += fields_[i].key.startsWith('#') ? " " + v : " " + fields_[i].key + "=" + v;
  }
  if (!tail_.isEmpty()) out += " " + tail_;
  return out;
}

QString CommandDialog::text(size_t i) const {
  // A bare value may be a list of points ("0,0 4,0 4,3"): spaces between them kept, none
  // around commas; a keyword's value has no spaces.
  const QString raw = edits_[i]->text();
  return fields_[i].key.startsWith('#') ? raw.simplified().replace(QRegularExpression(" *, *"), ",")
                                        : raw.trimmed().remove(' ');
}

QString CommandDialog::value(const QString& key) const {
  for (size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].key == key) return edits_[i] ? text(i) : checks_[i]->isChecked() ? "on" : "";
  return {};
}

void CommandDialog::setValue(const QString& key, const QString& value) {
  for (size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].key == key) {
      if (edits_[i]) edits_[i]->setText(value);
      if (checks_[i]) checks_[i]->setChecked(!value.isEmpty());
    }
}

}  // namespace tessera::ui
