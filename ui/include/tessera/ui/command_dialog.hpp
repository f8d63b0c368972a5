// A dialog that builds one script command from a form: a field per keyword, with its unit, so
// that every edit made through a dialog is a command (journalled, undoable, saved with the
// script) and the user learns the script by using the window.
#pragma once

#include <QDialog>
#include <QString>
#include <vector>

class QFormLayout;
class QLineEdit;
class QCheckBox;

namespace tessera::ui {

struct CommandField {
  // Keyword (key=value); "!word": a checkbox that adds the bare word; "#what": a bare value
  // (e.g. the name in "material define NAME ...").
  QString key;
  QString label;  // what the user reads
  QString unit;   // shown after the field, e.g. "Pa", "deg", "m"
  QString value;  // initial text; an empty field is left out of the command
  QString tip;
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
  QString value(const QString& key) const;
  void setValue(const QString& key, const QString& value);

 signals:
  // A field changed (for live previews).
  void changed();

 private:
  QString head_, tail_;
  std::vector<CommandField> fields_;
  std::vector<QLineEdit*> edits_;
  std::vector<QCheckBox*> checks_;
};

}  // namespace tessera::ui
