// SPDX-License-Identifier: MIT
// ddfcam gui: JobRunner, one worker thread at a time with throttled progress and cancel.
#include <ddfcam/error.h>
#include <ddfcam/gui/job_runner.h>

#include <QEventLoop>
#include <QMetaObject>
#include <QTimer>

#include <chrono>
#include <cstdint>
#include <exception>
#include <thread>
#include <utility>

namespace ddfcam::gui {
namespace {

// ~20 Hz: smooth enough for a progress bar, rare enough not to flood the UI event queue.
constexpr std::int64_t kProgressIntervalNs = 50'000'000;

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// Runs @p action through runUserAction (one report, Cancelled not reported) and classifies
/// how it ended. Exceptions of other types are turned into an Error so none escapes into Qt.
JobRunner::Outcome runReported(const ErrorReporter& report, const QString& title,
                               const std::function<void()>& action) {
  bool cancelled = false;
  const bool ok = runUserAction(report, title, [&] {
    try {
      action();
    } catch (const Cancelled&) {
      cancelled = true;
      throw;
    } catch (const std::exception&) {
      throw;
    } catch (...) {
      throw Error("unknown exception (not derived from std::exception)");
    }
  });
  if (ok) return JobRunner::Outcome::Completed;
  return cancelled ? JobRunner::Outcome::Cancelled : JobRunner::Outcome::Failed;
}

}  // namespace

/// State of one job, shared between the UI thread and its worker. The worker only touches the
/// atomics, `commit` and `error` (the last two are read by the UI thread after it joined).
struct JobRunner::Running {
  QString title;
  JobWork work;
  std::thread thread;
  std::atomic<bool> cancelRequested{false};
  std::atomic<double> latestFraction{0.0};
  std::atomic<std::int64_t> lastPostNs{0};
  std::function<void()> commit;
  std::exception_ptr error;
};

JobRunner::JobRunner(ErrorReporter reportError, QObject* parent)
    : QObject(parent), reportError_(std::move(reportError)) {}

JobRunner::~JobRunner() {
  // Events the worker posted to this object are discarded with it; the job is not committed.
  if (running_) {
    running_->cancelRequested = true;
    if (running_->thread.joinable()) running_->thread.join();
  }
}

bool JobRunner::start(const QString& title, JobWork work) {
  if (running_) return false;
  auto job = std::make_shared<Running>();
  job->title = title;
  job->work = std::move(work);
  Running* raw = job.get();
  // The progress callback may be called from several threads of the work (e.g. TBB tasks):
  // only atomics are touched, and at most one post wins each interval.
  ProgressCallback progress = [this, raw](double fraction) {
    if (raw->cancelRequested.load()) return false;
    raw->latestFraction.store(fraction);
    const std::int64_t now = nowNs();
    std::int64_t last = raw->lastPostNs.load();
    if (now - last >= kProgressIntervalNs && raw->lastPostNs.compare_exchange_strong(last, now)) {
      QMetaObject::invokeMethod(
          this,
          [this, raw] {
            if (running_.get() == raw) emit progressChanged(raw->latestFraction.load());
          },
          Qt::QueuedConnection);
    }
    return !raw->cancelRequested.load();
  };
  // The worker captures only the raw pointer: the UI thread owns the state and joins the
  // worker before releasing it, so the state never dies on the worker thread. Its events are
  // handled on this thread, so none can arrive before running_ is set below.
  job->thread = std::thread([this, raw, progress = std::move(progress)] {
    try {
      raw->commit = raw->work(progress);
    } catch (...) {
      raw->error = std::current_exception();
    }
    QMetaObject::invokeMethod(
        this,
        [this, raw] {
          if (running_.get() == raw) onWorkerDone();
        },
        Qt::QueuedConnection);
  });
  running_ = std::move(job);
  emit started(title);
  return true;
}

void JobRunner::cancel() {
  if (running_) running_->cancelRequested = true;
}

bool JobRunner::isRunning() const {
  return running_ != nullptr;
}

QString JobRunner::title() const {
  return running_ ? running_->title : QString();
}

bool JobRunner::waitForFinished(int timeoutMs) {
  if (!running_) return true;
  QEventLoop loop;
  QTimer timeout;
  timeout.setSingleShot(true);
  connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
  connect(this, &JobRunner::finished, &loop, &QEventLoop::quit);
  timeout.start(timeoutMs);
  loop.exec();
  return !running_;
}

void JobRunner::onWorkerDone() {
  std::shared_ptr<Running> job = std::move(running_);
  job->thread.join();  // the worker has posted its last event; this returns at once
  Outcome outcome = Outcome::Completed;
  if (job->error) {
    outcome = runReported(reportError_, job->title, [&] { std::rethrow_exception(job->error); });
  } else if (job->cancelRequested.load()) {
    // The work ran to its end after the request, but the user asked to stop: keep the
    // document as it was.
    outcome = Outcome::Cancelled;
  } else if (job->commit) {
    outcome = runReported(reportError_, job->title, job->commit);
  }
  // running_ is already empty, so a slot connected to finished() may start the next job.
  emit finished(job->title, outcome);
}

}  // namespace ddfcam::gui
