// The form of a command dialog and the command it makes.
#include "tessera/ui/command_dialog.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

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
      if (!f.unit.isEmpty()) row->addWidget(new QLabel(f.unit, this));
      form->addRow(f.label, row);
    }
    edits_.push_back(edit);
    checks_.push_back(check);
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

QString CommandDialog::command() const {
  QString out = head_;
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (checks_[i]) {
      if (checks_[i]->isChecked()) out += " " + fields_[i].key.mid(1);
      continue;
    }
    const QString v = edits_[i]->text().trimmed().remove(' ');
    if (v.isEmpty()) continue;
    out += fields_[i].key.startsWith('#') ? " " + v : " " + fields_[i].key + "=" + v;
  }
  if (!tail_.isEmpty()) out += " " + tail_;
  return out;
}

QString CommandDialog::value(const QString& key) const {
  for (size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].key == key)
      return edits_[i] ? edits_[i]->text().trimmed() : checks_[i]->isChecked() ? "on" : "";
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
