// SPDX-License-Identifier: MIT
// ddfcam gui: ConsoleDock and the thread-safe log sink that feeds it.
#include <ddfcam/gui/console_dock.h>

#include <QAction>
#include <QFontDatabase>
#include <QMenu>
#include <QMetaObject>
#include <QPlainTextEdit>
#include <QPointer>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextCharFormat>
#include <QTextCursor>

#include <algorithm>
#include <memory>
#include <mutex>

namespace ddfcam::gui {
namespace {

QString levelTag(LogLevel level) {
  switch (level) {
    case LogLevel::Debug:
      return QStringLiteral("[debug]");
    case LogLevel::Info:
      return QStringLiteral("[info]");
    case LogLevel::Warning:
      return QStringLiteral("[warning]");
    case LogLevel::Error:
      return QStringLiteral("[error]");
  }
  return QStringLiteral("[?]");
}

QTextCharFormat levelFormat(LogLevel level, const QPalette& palette) {
  QTextCharFormat format;
  switch (level) {
    case LogLevel::Error:
      format.setForeground(QColor(200, 0, 0));
      break;
    case LogLevel::Warning:
      format.setForeground(QColor(180, 110, 0));
      break;
    case LogLevel::Debug:
      format.setForeground(palette.color(QPalette::PlaceholderText));
      break;
    case LogLevel::Info:
      format.setForeground(palette.color(QPalette::Text));
      break;
  }
  return format;
}

}  // namespace

// The library may call a sink copy after it was uninstalled and from any thread, so the sink
// never touches the dock directly: under the mutex it checks that the dock still exists and
// posts to it. The destructor clears `dock` under the same mutex before the QObject goes, so a
// post never targets a dying object, and Qt drops events still queued for a deleted object.
struct ConsoleDock::Relay {
  std::mutex mutex;
  QPointer<ConsoleDock> dock;

  void post(LogLevel level, const std::string& message) {
    const QTime time = QTime::currentTime();
    QString text = QString::fromStdString(message);
    std::lock_guard lock(mutex);
    if (dock.isNull()) return;
    QMetaObject::invokeMethod(
        dock.data(),
        [guard = dock, time, level, text = std::move(text)] {
          if (guard) guard->appendStamped(time, level, text);
        },
        Qt::QueuedConnection);
  }
};

struct ConsoleDock::Sink {
  std::shared_ptr<Relay> relay;
  void operator()(LogLevel level, const std::string& message) const { relay->post(level, message); }
};

ConsoleDock::ConsoleDock(QWidget* parent) : QDockWidget(QStringLiteral("Console"), parent) {
  setObjectName(QStringLiteral("consoleDock"));
  text_ = new QPlainTextEdit(this);
  text_->setObjectName(QStringLiteral("consoleText"));
  text_->setReadOnly(true);
  text_->setLineWrapMode(QPlainTextEdit::NoWrap);
  text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  text_->setMaximumBlockCount(kDefaultLineLimit);
  clearAction_ = new QAction(QStringLiteral("Clear"), this);
  clearAction_->setObjectName(QStringLiteral("consoleClearAction"));
  connect(clearAction_, &QAction::triggered, this, &ConsoleDock::clear);
  text_->setContextMenuPolicy(Qt::CustomContextMenu);
  connect(text_, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
    std::unique_ptr<QMenu> menu(text_->createStandardContextMenu());
    menu->addSeparator();
    menu->addAction(clearAction_);
    menu->exec(text_->viewport()->mapToGlobal(pos));
  });
  setWidget(text_);
}

ConsoleDock::~ConsoleDock() {
  uninstallLogSink();
}

void ConsoleDock::appendMessage(LogLevel level, const QString& message) {
  appendStamped(QTime::currentTime(), level, message);
}

void ConsoleDock::appendStamped(const QTime& time, LogLevel level, const QString& message) {
  const QString prefix =
      time.toString(QStringLiteral("HH:mm:ss.zzz ")) + levelTag(level) + QLatin1Char(' ');
  const QTextCharFormat format = levelFormat(level, text_->palette());
  QScrollBar* bar = text_->verticalScrollBar();
  const bool atBottom = bar->value() >= bar->maximum();
  QTextCursor cursor(text_->document());
  cursor.beginEditBlock();
  cursor.movePosition(QTextCursor::End);
  QString body = message;
  while (body.endsWith(QLatin1Char('\n'))) body.chop(1);
  for (const QString& line : body.split(QLatin1Char('\n'))) {
    if (!text_->document()->isEmpty()) cursor.insertBlock();
    cursor.insertText(prefix + line, format);
  }
  cursor.endEditBlock();
  // Follow new output only if the user has not scrolled up to read something.
  if (atBottom) bar->setValue(bar->maximum());
}

void ConsoleDock::installLogSink() {
  if (relay_) return;
  relay_ = std::make_shared<Relay>();
  relay_->dock = this;
  previousSink_ = setLogSink(Sink{relay_});
}

void ConsoleDock::uninstallLogSink() {
  if (!relay_) return;
  {
    std::lock_guard lock(relay_->mutex);
    relay_->dock.clear();
  }
  LogSink current = setLogSink(previousSink_);
  const Sink* ours = current.target<Sink>();
  // Someone installed their own sink after ours: theirs stays.
  if (ours == nullptr || ours->relay != relay_) setLogSink(std::move(current));
  relay_.reset();
  previousSink_ = nullptr;
}

int ConsoleDock::lineLimit() const {
  return text_->maximumBlockCount();
}

void ConsoleDock::setLineLimit(int lines) {
  text_->setMaximumBlockCount(std::max(lines, 1));
}

QString ConsoleDock::text() const {
  return text_->toPlainText();
}

void ConsoleDock::clear() {
  text_->clear();
}

}  // namespace ddfcam::gui
