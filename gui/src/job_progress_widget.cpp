// SPDX-License-Identifier: MIT
// ddfcam gui: JobProgressWidget, the status-bar progress display of background jobs.
#include <ddfcam/gui/job_progress_widget.h>

#include <ddfcam/gui/duration_text.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {
namespace {

constexpr int kBarSteps = 1000;
constexpr int kRefreshMs = 500;  // the label is refreshed at least twice a second
// Below these an estimate of the remaining time is mostly noise.
constexpr double kEstimateAfterS = 1.0;
constexpr double kEstimateAfterFraction = 0.01;


}  // namespace

JobProgressWidget::JobProgressWidget(JobRunner& runner, QWidget* parent)
    : QWidget(parent), runner_(runner) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  label_ = new QLabel(this);
  label_->setObjectName("jobTitleLabel");
  bar_ = new QProgressBar(this);
  bar_->setObjectName("jobProgressBar");
  bar_->setRange(0, kBarSteps);
  bar_->setMaximumWidth(160);
  bar_->setTextVisible(false);
  cancel_ = new QToolButton(this);
  cancel_->setObjectName("jobCancelButton");
  cancel_->setText(tr("Cancel"));
  cancel_->setToolTip(tr("Cancel the running job; the document stays as it was"));
  layout->addWidget(label_);
  layout->addWidget(bar_);
  layout->addWidget(cancel_);

  connect(cancel_, &QToolButton::clicked, this, [this] {
    runner_.cancel();
    cancel_->setEnabled(false);  // one request is enough; the job stops at its next report
    label_->setText(tr("Cancelling %1...").arg(runner_.title()));
  });
  refresh_ = new QTimer(this);
  refresh_->setInterval(kRefreshMs);
  connect(refresh_, &QTimer::timeout, this, &JobProgressWidget::showProgressText);
  connect(&runner_, &JobRunner::started, this, &JobProgressWidget::onStarted);
  connect(&runner_, &JobRunner::progressChanged, this, &JobProgressWidget::onProgress);
  connect(&runner_, &JobRunner::finished, this, &JobProgressWidget::onFinished);
  if (runner_.isRunning()) {
    onStarted(runner_.title());
  } else {
    hide();
  }
}

void JobProgressWidget::onStarted(const QString& title) {
  clock_.start();
  title_ = title;
  fraction_ = 0.0;
  label_->setText(title);
  bar_->setValue(0);
  refresh_->start();
  cancel_->setEnabled(true);
  show();
}

void JobProgressWidget::onProgress(double fraction) {
  if (!std::isfinite(fraction)) return;
  fraction_ = std::clamp(fraction, 0.0, 1.0);
  bar_->setValue(static_cast<int>(std::lround(fraction_ * kBarSteps)));
  showProgressText();
}

void JobProgressWidget::showProgressText() {
  if (!cancel_->isEnabled()) return;  // "Cancelling ..." stays
  const double seconds = static_cast<double>(clock_.elapsed()) / 1000.0;
  QString text = tr("%1: %2 %, %3 elapsed")
                     .arg(title_)
                     .arg(static_cast<int>(std::floor(100.0 * fraction_)))
                     .arg(durationText(seconds));
  // The remaining time at the average rate so far: jobs report evenly spread fractions.
  if (seconds >= kEstimateAfterS && fraction_ >= kEstimateAfterFraction && fraction_ < 1.0)
    text += tr(", about %1 left").arg(durationText(seconds * (1.0 - fraction_) / fraction_));
  label_->setText(text);
}

void JobProgressWidget::onFinished(const QString& title, JobRunner::Outcome outcome) {
  refresh_->stop();
  hide();
  switch (outcome) {
    case JobRunner::Outcome::Completed: {
      const double seconds = static_cast<double>(clock_.elapsed()) / 1000.0;
      emit statusMessage(tr("Done: %1 (%2 s)").arg(title, QString::number(seconds, 'f', 1)));
      break;
    }
    case JobRunner::Outcome::Cancelled:
      emit statusMessage(tr("Cancelled: %1").arg(title));
      break;
    case JobRunner::Outcome::Failed:
      emit statusMessage(tr("Failed: %1").arg(title));
      break;
  }
}

}  // namespace ddfcam::gui
