// SPDX-License-Identifier: MIT
// ddfcam gui: the status-bar view of a JobRunner: title, progress bar and a cancel button.
#pragma once

#include <ddfcam/gui/job_runner.h>

#include <QElapsedTimer>
#include <QString>
#include <QWidget>

class QLabel;
class QProgressBar;
class QTimer;
class QToolButton;

namespace ddfcam::gui {

/// @brief A small widget for the status bar observing a JobRunner: a label with the job's
/// title, a QProgressBar over 0..1000 and a Cancel QToolButton (objectName "jobCancelButton").
/// Hidden while no job runs. When a job ends it emits statusMessage() with "Done: <title>
/// (1.2 s)", "Cancelled: <title>" or "Failed: <title>" for the window's status bar.
class JobProgressWidget : public QWidget {
  Q_OBJECT

 public:
  /// @param runner the observed runner; must outlive the widget.
  explicit JobProgressWidget(JobRunner& runner, QWidget* parent = nullptr);

 signals:
  /// @brief One line about the job that just ended (see the class description).
  void statusMessage(const QString& message);

 private:
  void onStarted(const QString& title);
  void onProgress(double fraction);
  void onFinished(const QString& title, JobRunner::Outcome outcome);
  void showProgressText();

  JobRunner& runner_;
  QLabel* label_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QToolButton* cancel_ = nullptr;
  QElapsedTimer clock_;
  QTimer* refresh_ = nullptr;  ///< keeps the elapsed time moving between progress reports
  QString title_;
  double fraction_ = 0.0;
};

}  // namespace ddfcam::gui
