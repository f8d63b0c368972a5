// The console: the run's log, errors in red, and a line where script commands are typed, or
// Python (the "Py" button, in builds with Python): `m` is the window's model.
#pragma once

#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QStringList>
#include <QToolButton>
#include <QWidget>

namespace tessera::ui {

class ConsoleWidget : public QWidget {
  Q_OBJECT
 public:
  explicit ConsoleWidget(QWidget* parent = nullptr);
  // Adds a line: red if `error`, amber if it is a warning.
  void append(const QString& text, bool error);
  QString text() const { return log_->toPlainText(); }
  QLineEdit* input() { return input_; }
  // Python lines instead of commands (the Py button).
  bool pythonMode() const { return python_->isChecked(); }
  void setPythonMode(bool on);
  // The Python statement typed is still open: the prompt shows "..." and an empty line ends it.
  void setContinuation(bool more);

 signals:
  void command(const QString& line);
  // A line of Python, as typed (indentation kept; empty when it ends an open statement).
  void python(const QString& line);
  // The mode changed while a Python statement was open: its lines so far are dropped.
  void statementDropped();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QPlainTextEdit* log_;
  QLineEdit* input_;
  QToolButton* python_;
  QLabel* prompt_;
  bool more_ = false;
  QStringList typed_;  // earlier commands, for the up and down keys
  int recall_ = 0;
};

}  // namespace tessera::ui
