// SPDX-License-Identifier: MIT
// ddfcam gui: runUserAction and the message-box error reporter.
#include <ddfcam/gui/user_action.h>

#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <QMessageBox>
#include <QPointer>
#include <QWidget>

namespace ddfcam::gui {

ErrorReporter messageBoxReporter(QWidget* parent) {
  QPointer<QWidget> guarded(parent);
  return [guarded](const QString& title, const QString& message) {
    QMessageBox::critical(guarded.data(), title, message);
  };
}

bool runUserAction(const ErrorReporter& report, const QString& title,
                   const std::function<void()>& action) {
  try {
    action();
    return true;
  } catch (const Cancelled&) {
    log(LogLevel::Info, title.toStdString() + ": cancelled");
  } catch (const std::exception& e) {
    const std::string message = unrollMessage(e);
    log(LogLevel::Error, title.toStdString() + ": " + message);
    if (report) report(title, QString::fromStdString(message));
  }
  return false;
}

}  // namespace ddfcam::gui
