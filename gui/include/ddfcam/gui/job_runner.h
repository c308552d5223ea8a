// SPDX-License-Identifier: MIT
// ddfcam gui: long operations off the UI thread, with progress, cancel and one error report.
#pragma once

#include <ddfcam/gui/user_action.h>
#include <ddfcam/progress.h>

#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>

namespace ddfcam::gui {

/// @brief Work of a job: runs on a worker thread with a progress callback (fraction in [0, 1];
/// returns false once cancel was requested, so ddfcam::reportProgress throws Cancelled). It
/// computes on values it owns (copies) and returns the commit step, which runs on the UI
/// thread only if the work finished, and applies the result (typically Document::push). The
/// work must not touch the document or any widget.
using JobWork = std::function<std::function<void()>(const ProgressCallback& progress)>;

/// @brief Runs one job at a time on a worker thread. Progress is forwarded to the UI thread
/// (progressChanged), cancel() makes the next progress call return false, exceptions of the
/// work or the commit are reported once through the ErrorReporter (unrolled; Cancelled is not
/// an error), and a cancelled or failed job never runs its commit step: the document stays
/// as it was.
class JobRunner : public QObject {
  Q_OBJECT

 public:
  /// @brief How a job ended.
  enum class Outcome { Completed, Cancelled, Failed };
  Q_ENUM(Outcome)

  explicit JobRunner(ErrorReporter reportError, QObject* parent = nullptr);
  /// Cancels a running job and waits for its worker to finish.
  ~JobRunner() override;

  /// @brief Starts @p work titled @p title (e.g. "Simulate path 'demo passes'").
  /// @return false (and nothing started) if a job is already running.
  bool start(const QString& title, JobWork work);
  /// @brief Requests cancellation of the running job (no-op if none).
  void cancel();
  /// @brief True from start() until finished() was emitted.
  bool isRunning() const;
  /// @brief Title of the running job (empty if none).
  QString title() const;
  /// @brief Processes events until the running job finished or @p timeoutMs passed.
  /// @return true if no job is running any more.
  bool waitForFinished(int timeoutMs);

 signals:
  /// @brief A job started.
  void started(const QString& title);
  /// @brief Progress of the running job, in [0, 1] (throttled to ~20 Hz).
  void progressChanged(double fraction);
  /// @brief The job ended: Completed (commit ran), Cancelled or Failed (error reported).
  void finished(const QString& title, ddfcam::gui::JobRunner::Outcome outcome);

 private:
  struct Running;
  void onWorkerDone();

  ErrorReporter reportError_;
  std::shared_ptr<Running> running_;
};

}  // namespace ddfcam::gui
