// SPDX-License-Identifier: MIT
// ddfcam gui: the "Console" dock showing the library log (ddfcam::log) with timestamps.
#pragma once

#include <ddfcam/log.h>

#include <QDockWidget>
#include <QString>
#include <QTime>

#include <memory>

class QAction;
class QPlainTextEdit;

namespace ddfcam::gui {

/// @brief Dock (objectName "consoleDock", title "Console") with a read-only text view
/// (objectName "consoleText") of timestamped lines "HH:mm:ss.zzz [level] message"; errors are
/// red, warnings amber. Multi-line messages take one line each. The oldest lines are dropped
/// beyond lineLimit().
class ConsoleDock : public QDockWidget {
  Q_OBJECT

 public:
  /// @brief Default number of lines kept.
  static constexpr int kDefaultLineLimit = 5000;

  explicit ConsoleDock(QWidget* parent = nullptr);
  /// @brief Uninstalls the log sink if installLogSink() was called (see there).
  ~ConsoleDock() override;

  /// @brief Appends @p message at @p level, stamped with the current time. UI thread only.
  void appendMessage(LogLevel level, const QString& message);

  /// @brief Makes ddfcam::setLogSink forward every library message, from any thread, to this
  /// dock: the sink stamps the time and posts the message to the UI thread (queued), so
  /// messages of one thread keep their order. Messages still in flight when the dock is
  /// destroyed are dropped. The destructor restores the sink that was installed before,
  /// unless another sink has replaced this one meanwhile (then that one stays).
  /// Calling it twice installs once.
  void installLogSink();

  /// @brief Maximum number of lines kept (default kDefaultLineLimit).
  int lineLimit() const;
  /// @brief Sets the line limit (>= 1; smaller values become 1); excess old lines go now.
  void setLineLimit(int lines);

  /// @brief The whole console text, one line per '\n'-separated line (for tests).
  QString text() const;

  /// @brief The "Clear" action (objectName "consoleClearAction"), also in the context menu.
  QAction* clearAction() const { return clearAction_; }

 public slots:
  /// @brief Removes every line.
  void clear();

 private:
  struct Relay;  // what the installed sink holds of this dock, shared with it
  struct Sink;   // the LogSink functor, a named type so the destructor can recognise it
  void appendStamped(const QTime& time, LogLevel level, const QString& message);
  void uninstallLogSink();

  QPlainTextEdit* text_ = nullptr;
  QAction* clearAction_ = nullptr;
  std::shared_ptr<Relay> relay_;
  LogSink previousSink_;
};

}  // namespace ddfcam::gui
