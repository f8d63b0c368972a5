// The console: the run's log, errors in red, and a line where script commands are typed.
#pragma once

#include <QLineEdit>
#include <QPlainTextEdit>
#include <QStringList>
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

 signals:
  void command(const QString& line);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QPlainTextEdit* log_;
  QLineEdit* input_;
  QStringList typed_;  // earlier commands, for the up and down keys
  int recall_ = 0;
};

}  // namespace tessera::ui
