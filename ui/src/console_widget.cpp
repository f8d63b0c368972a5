// Console log and command line with recall.
#include "tessera/ui/console_widget.hpp"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QVBoxLayout>

namespace tessera::ui {

ConsoleWidget::ConsoleWidget(QWidget* parent)
    : QWidget(parent), log_(new QPlainTextEdit(this)), input_(new QLineEdit(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(log_);
  layout->addWidget(input_);
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(20000);
  const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  log_->setFont(mono);
  input_->setFont(mono);
  input_->setPlaceholderText(
      "Type a command (e.g. step 1000, solve, figure view.png) and press Enter");
  input_->installEventFilter(this);
  connect(input_, &QLineEdit::returnPressed, this, [this] {
    const QString line = input_->text().trimmed();
    if (line.isEmpty()) return;
    typed_.append(line);
    recall_ = static_cast<int>(typed_.size());
    input_->clear();
    emit command(line);
  });
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
