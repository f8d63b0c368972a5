// Console log and command line with recall.
#include "tessera/ui/console_widget.hpp"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QVBoxLayout>

#include "python_console.hpp"

namespace tessera::ui {

ConsoleWidget::ConsoleWidget(QWidget* parent)
    : QWidget(parent),
      log_(new QPlainTextEdit(this)),
      input_(new QLineEdit(this)),
      python_(new QToolButton(this)),
      prompt_(new QLabel(">", this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(log_);
  auto* row = new QHBoxLayout;
  row->addWidget(python_);
  row->addWidget(prompt_);
  row->addWidget(input_);
  layout->addLayout(row);
  python_->setText("Py");
  python_->setObjectName("pythonMode");
  python_->setCheckable(true);
  python_->setToolTip(
      "Python: lines run as at Python's prompt, with m the model (m.blocks.pos, m.cycle(100), "
      "m.command(\"...\"))");
  python_->setVisible(python_console_available());
  connect(python_, &QToolButton::toggled, this, &ConsoleWidget::setPythonMode);
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(20000);
  const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  log_->setFont(mono);
  input_->setFont(mono);
  prompt_->setFont(mono);
  setPythonMode(false);
  input_->installEventFilter(this);
  connect(input_, &QLineEdit::returnPressed, this, [this] {
    // Python keeps its indentation; an empty line ends an open statement.
    const bool py = pythonMode();
    QString line = py ? input_->text() : input_->text().trimmed();
    while (py && line.endsWith(' ')) line.chop(1);
    if (line.trimmed().isEmpty() && !(py && more_)) return;
    if (!line.isEmpty()) typed_.append(line);
    recall_ = static_cast<int>(typed_.size());
    input_->clear();
    if (py)
      emit python(line);
    else
      emit command(line);
  });
}

void ConsoleWidget::setPythonMode(bool on) {
  if (python_->isChecked() != on) return python_->setChecked(on);  // toggles back here
  if (more_) {
    more_ = false;
    append("(the open Python statement is dropped)", false);
    emit statementDropped();
  }
  prompt_->setText(on ? ">>>" : ">");
  input_->setPlaceholderText(
      on ? "Python, with m the model: print(m.blocks.pos), m.cycle(100), m.command(\"solve\")"
         : "Type a command (e.g. step 1000, solve, figure view.png) and press Enter");
}

void ConsoleWidget::setContinuation(bool more) {
  more_ = more;
  prompt_->setText(pythonMode() ? (more ? "..." : ">>>") : ">");
}

void ConsoleWidget::append(const QString& text, bool error) {
  // Errors red, warnings amber, the rest plain.
  const char* colour = error ? "#c00000" : text.contains("warning:") ? "#a06000" : nullptr;
  if (colour)
    log_->appendHtml(QString("<span style='color:%1'>").arg(colour) + text.toHtmlEscaped() +
                     "</span>");
  else
    log_->appendPlainText(text);
}

bool ConsoleWidget::eventFilter(QObject* watched, QEvent* event) {
  if (watched == input_ && event->type() == QEvent::KeyPress && !typed_.isEmpty()) {
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key == Qt::Key_Up || key == Qt::Key_Down) {
      recall_ =
          std::clamp(recall_ + (key == Qt::Key_Up ? -1 : 1), 0, static_cast<int>(typed_.size()));
      input_->setText(recall_ < typed_.size() ? typed_[recall_] : QString());
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

}  // namespace tessera::ui
