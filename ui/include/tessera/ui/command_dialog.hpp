// A dialog that builds one script command from a form: a field per keyword, with its unit, so
// that every edit made through a dialog is a command (journalled, undoable, saved with the
// script) and the user learns the script by using the window.
#pragma once

#include <QDialog>
#include <QString>
#include <vector>

class QFormLayout;
class QLabel;
class QLineEdit;
class QCheckBox;
class QPushButton;

namespace tessera::ui {

struct CommandField {
  // Keyword (key=value); "!word": a checkbox that adds the bare word; "#what": a bare value
  // (e.g. the name in "material define NAME ...").
  QString key;
  QString label;  // what the user reads
  QString unit;   // shown after the field, e.g. "Pa", "deg", "m"
  QString value;  // initial text; an empty field is left out of the command
  QString tip;
  // What the field names, offered as a list of what exists: "groups", "materials", "joint
  // properties", "joint names" or "zone models" (empty: a free field).
  QString choices = {};
};

class CommandDialog : public QDialog {
  Q_OBJECT
 public:
  // `head`: the command's first words, e.g. "jset" or "tunnel circle".
  CommandDialog(const QString& title, const QString& head, const std::vector<CommandField>& fields,
                QWidget* parent = nullptr);
  // The command the form makes now, with `tail` (e.g. a selection) appended.
  QString command() const;
  void setTail(const QString& tail) { tail_ = tail; }
  // A field's text as it goes into the command.
  QString value(const QString& key) const;
  void setValue(const QString& key, const QString& value);
  // The names a kind of field offers (CommandField::choices).
  void setChoices(const QString& kind, const QStringList& names);
  QStringList choices(const QString& key) const;
  // OK does not close the dialog: it says `submitted`, and the window closes it once the
  // command has run, or shows the command's error here with the fields as they were.
  void accept() override;
  // `earlier`: commands of this dialog that ran before the failing one (they stay done).
  void showError(const QString& error, int earlier = 0);
  QString error() const;
  // Closes the dialog as accepted (the command ran).
  void finish();

 signals:
  // A field changed (for live previews).
  void changed();
  void submitted();

 private:
  QString text(size_t i) const;
  QString head_, tail_;
  std::vector<CommandField> fields_;
  std::vector<QLineEdit*> edits_;
  std::vector<QCheckBox*> checks_;
  std::vector<QStringList> names_;  // per field: the choices offered
  QLabel* error_ = nullptr;
  QPushButton* ok_ = nullptr;
};

}  // namespace tessera::ui
