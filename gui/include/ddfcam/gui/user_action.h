// SPDX-License-Identifier: MIT
// ddfcam gui: the one place where library errors of a user action are caught and shown.
#pragma once

#include <QString>

class QWidget;

#include <functional>

namespace ddfcam::gui {

/// @brief Shows an error to the user: @p title names the action, @p message is the unrolled
/// exception text. The default implementation is a QMessageBox; tests inject a recorder.
using ErrorReporter = std::function<void(const QString& title, const QString& message)>;

/// @brief An ErrorReporter showing a modal critical QMessageBox over @p parent.
ErrorReporter messageBoxReporter(QWidget* parent);

/// @brief Runs @p action; any std::exception it throws is reported once through @p report
/// with ddfcam::unrollMessage (nested causes included). ddfcam::Cancelled is a normal outcome
/// and is not reported.
/// @return true if @p action completed without throwing.
bool runUserAction(const ErrorReporter& report, const QString& title,
                   const std::function<void()>& action);

}  // namespace ddfcam::gui
