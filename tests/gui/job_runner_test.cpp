// SPDX-License-Identifier: MIT
// JobRunner and its status-bar widget: commit on the UI thread, prompt cancel, one error report.
#include "gui_test_registry.h"
#include <ddfcam/error.h>
#include <ddfcam/gui/duration_text.h>
#include <ddfcam/gui/job_progress_widget.h>
#include <ddfcam/gui/job_runner.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QLabel>
#include <QProgressBar>
#include <QSignalSpy>
#include <QThread>
#include <QToolButton>
#include <QtTest/QtTest>

#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <thread>

using ddfcam::gui::JobProgressWidget;
using ddfcam::gui::JobRunner;
using ddfcam::gui::JobWork;

Q_DECLARE_METATYPE(ddfcam::gui::JobRunner::Outcome)

namespace {

/// Work that reports progress every millisecond until it is cancelled (it never ends alone).
JobWork endlessWork(std::atomic<bool>* exited = nullptr) {
  return [exited](const ddfcam::ProgressCallback& progress) -> std::function<void()> {
    struct Flag {
      std::atomic<bool>* flag;
      ~Flag() {
        if (flag) *flag = true;
      }
    } guard{exited};
    for (long i = 0;; ++i) {
      ddfcam::reportProgress(progress, static_cast<double>(i % 1000) / 1000.0);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  };
}

JobRunner::Outcome outcomeOf(const QSignalSpy& finished) {
  return finished.last().at(1).value<JobRunner::Outcome>();
}

}  // namespace

class JobRunnerTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { qRegisterMetaType<JobRunner::Outcome>(); }
  void init() { reports_.clear(); }
  void completedJobCommitsOnceOnUiThread();
  void cancelStopsPromptlyWithoutCommit();
  void progressIsThrottled();
  void throwingJobReportsUnrolledMessageOnce();
  void throwingCommitIsReported();
  void secondStartWhileRunningIsRefused();
  void destructorCancelsAndJoins();
  void widgetShowsAndCancelsJob();
  void widgetShowsElapsedAndRemainingTime();
  void durationsReadLikeAClock();
  void widgetReportsDoneAndFailed();

 private:
  ddfcam::gui::ErrorReporter recorder() {
    return
        [this](const QString& title, const QString& message) { reports_ << title + "|" + message; };
  }
  QStringList reports_;
};

void JobRunnerTest::completedJobCommitsOnceOnUiThread() {
  JobRunner runner(recorder());
  QSignalSpy finished(&runner, &JobRunner::finished);
  std::thread::id workThread;
  QThread* commitThread = nullptr;
  int commits = 0;
  long long sum = 0;
  QVERIFY(runner.start("sum", [&](const ddfcam::ProgressCallback& progress) {
    workThread = std::this_thread::get_id();
    long long s = 0;
    for (int i = 1; i <= 1000; ++i) {
      s += i;
      if (i % 100 == 0) ddfcam::reportProgress(progress, i / 1000.0);
    }
    return std::function<void()>([&, s] {
      commitThread = QThread::currentThread();
      sum = s;
      ++commits;
    });
  }));
  QVERIFY(runner.isRunning());
  QCOMPARE(runner.title(), QString("sum"));
  QVERIFY(runner.waitForFinished(5000));
  QCOMPARE(commits, 1);
  QCOMPARE(sum, 500500LL);
  QCOMPARE(commitThread, qApp->thread());
  QVERIFY(workThread != std::this_thread::get_id());
  QCOMPARE(finished.count(), 1);
  QCOMPARE(outcomeOf(finished), JobRunner::Outcome::Completed);
  QVERIFY(!runner.isRunning());
  QVERIFY(reports_.isEmpty());
}

void JobRunnerTest::cancelStopsPromptlyWithoutCommit() {
  JobRunner runner(recorder());
  QSignalSpy finished(&runner, &JobRunner::finished);
  QSignalSpy progress(&runner, &JobRunner::progressChanged);
  bool committed = false;
  JobWork work = [&, inner = endlessWork()](const ddfcam::ProgressCallback& p) {
    inner(p);
    return std::function<void()>([&] { committed = true; });
  };
  QVERIFY(runner.start("endless", work));
  QVERIFY(progress.wait(2000));  // running and reporting
  QElapsedTimer clock;
  clock.start();
  runner.cancel();
  QVERIFY(runner.waitForFinished(5000));
  const qint64 ms = clock.elapsed();
  QVERIFY2(ms < 1000, qPrintable(QString("cancel took %1 ms").arg(ms)));
  QCOMPARE(finished.count(), 1);
  QCOMPARE(outcomeOf(finished), JobRunner::Outcome::Cancelled);
  QVERIFY(!committed);
  QVERIFY(reports_.isEmpty());  // Cancelled is not an error
}

void JobRunnerTest::progressIsThrottled() {
  JobRunner runner(recorder());
  QSignalSpy progress(&runner, &JobRunner::progressChanged);
  QVERIFY(runner.start("endless", endlessWork()));
  QTest::qWait(500);  // ~500 progress calls on the worker
  runner.cancel();
  QVERIFY(runner.waitForFinished(5000));
  // ~20 Hz over 0.5 s: about 10 forwarded; allow for a slow machine, refuse a flood.
  QVERIFY2(progress.count() >= 2 && progress.count() <= 20,
           qPrintable(QString("%1 progress signals").arg(progress.count())));
  for (const auto& args : progress) {
    const double f = args.at(0).toDouble();
    QVERIFY(f >= 0.0 && f <= 1.0);
  }
}

void JobRunnerTest::throwingJobReportsUnrolledMessageOnce() {
  JobRunner runner(recorder());
  QSignalSpy finished(&runner, &JobRunner::finished);
  bool committed = false;
  QVERIFY(runner.start("load", [&](const ddfcam::ProgressCallback&) -> std::function<void()> {
    try {
      throw ddfcam::InvalidInput("face 7 is degenerate");
    } catch (...) {
      std::throw_with_nested(ddfcam::IoError("cannot convert 'part.stl'"));
    }
    return [&] { committed = true; };
  }));
  QVERIFY(runner.waitForFinished(5000));
  QCOMPARE(reports_.size(), 1);
  const QString report = reports_.front();
  QVERIFY2(report.startsWith("load|cannot convert 'part.stl'"), qPrintable(report));
  QVERIFY2(report.indexOf("face 7 is degenerate") > report.indexOf("part.stl"),
           qPrintable(report));  // outer message first, then its cause
  QCOMPARE(finished.count(), 1);
  QCOMPARE(outcomeOf(finished), JobRunner::Outcome::Failed);
  QVERIFY(!committed);
}

void JobRunnerTest::throwingCommitIsReported() {
  JobRunner runner(recorder());
  QSignalSpy finished(&runner, &JobRunner::finished);
  QVERIFY(runner.start("apply", [](const ddfcam::ProgressCallback&) {
    return std::function<void()>([] { throw ddfcam::InvalidInput("result does not fit"); });
  }));
  QVERIFY(runner.waitForFinished(5000));
  QCOMPARE(reports_, QStringList{"apply|result does not fit"});
  QCOMPARE(outcomeOf(finished), JobRunner::Outcome::Failed);
}

void JobRunnerTest::secondStartWhileRunningIsRefused() {
  JobRunner runner(recorder());
  QSignalSpy started(&runner, &JobRunner::started);
  bool secondRan = false;
  QVERIFY(runner.start("first", endlessWork()));
  QVERIFY(!runner.start("second", [&](const ddfcam::ProgressCallback&) {
    secondRan = true;
    return std::function<void()>();
  }));
  QCOMPARE(runner.title(), QString("first"));
  QCOMPARE(started.count(), 1);
  runner.cancel();
  QVERIFY(runner.waitForFinished(5000));
  QVERIFY(!secondRan);
  // Free again: the next start is accepted.
  QVERIFY(runner.start("third",
                       [](const ddfcam::ProgressCallback&) { return std::function<void()>(); }));
  QVERIFY(runner.waitForFinished(5000));
}

void JobRunnerTest::destructorCancelsAndJoins() {
  std::atomic<bool> exited{false};
  bool committed = false;
  {
    JobRunner runner(recorder());
    JobWork work = [&, inner = endlessWork(&exited)](const ddfcam::ProgressCallback& p) {
      inner(p);
      return std::function<void()>([&] { committed = true; });
    };
    QVERIFY(runner.start("endless", work));
    QTest::qWait(20);
  }
  QVERIFY(exited.load());  // joined: the work has returned before the destructor did
  QCoreApplication::processEvents();
  QVERIFY(!committed);
  QVERIFY(reports_.isEmpty());
}

void JobRunnerTest::widgetShowsAndCancelsJob() {
  QWidget statusBar;
  JobRunner runner(recorder());
  auto* widget = new JobProgressWidget(runner, &statusBar);
  QSignalSpy messages(widget, &JobProgressWidget::statusMessage);
  statusBar.show();
  QVERIFY(widget->isHidden());

  QVERIFY(runner.start("Simulate path 'demo'", endlessWork()));
  QVERIFY(widget->isVisible());
  auto* bar = widget->findChild<QProgressBar*>();
  QVERIFY(bar);
  QCOMPARE(bar->maximum(), 1000);
  QTRY_VERIFY_WITH_TIMEOUT(bar->value() > 0, 3000);
  auto* cancel = widget->findChild<QToolButton*>("jobCancelButton");
  QVERIFY(cancel);
  QTest::mouseClick(cancel, Qt::LeftButton);
  QVERIFY(runner.waitForFinished(5000));
  QVERIFY(widget->isHidden());
  QCOMPARE(messages.count(), 1);
  QCOMPARE(messages.last().at(0).toString(), QString("Cancelled: Simulate path 'demo'"));
}

void JobRunnerTest::widgetShowsElapsedAndRemainingTime() {
  QWidget statusBar;
  JobRunner runner(recorder());
  auto* widget = new JobProgressWidget(runner, &statusBar);
  statusBar.show();
  // Work that reaches a quarter after 1.2 s and then waits to be cancelled: at the average
  // rate so far, three times the elapsed time remains.
  QVERIFY(runner.start("long", [](const ddfcam::ProgressCallback& p) {
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1200))
      if (!p(0.0)) throw ddfcam::Cancelled();
    while (p(0.25)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    throw ddfcam::Cancelled();
    return std::function<void()>([] {});
  }));
  auto* label = widget->findChild<QLabel*>("jobTitleLabel");
  QTRY_VERIFY_WITH_TIMEOUT(label->text().contains("25 %"), 5000);
  QTest::qWait(600);  // the refresh timer moves the elapsed time on without new progress
  const QString text = label->text();
  QVERIFY2(text.startsWith("long: 25 %, 0:0") && text.contains(" elapsed, about 0:0"),
           qPrintable(text));
  // "about m:ss left" is three times the elapsed seconds: 1.8 s here, more on a loaded
  // machine (a single digit of seconds up to 3.3 s elapsed).
  const int left = text.section("about 0:0", 1).left(1).toInt();
  QVERIFY2(left >= 3 && left <= 9, qPrintable(text));
  runner.cancel();
  QVERIFY(runner.waitForFinished(5000));
}

void JobRunnerTest::durationsReadLikeAClock() {
  using ddfcam::gui::durationText;
  QCOMPARE(durationText(7.2), QString("0:07"));
  QCOMPARE(durationText(750.0), QString("12:30"));
  QCOMPARE(durationText(3599.4), QString("59:59"));
  QCOMPARE(durationText(3723.0), QString("1:02:03"));
  QCOMPARE(durationText(-3.0), QString("0:00"));
}

void JobRunnerTest::widgetReportsDoneAndFailed() {
  QWidget statusBar;
  JobRunner runner(recorder());
  auto* widget = new JobProgressWidget(runner, &statusBar);
  QSignalSpy messages(widget, &JobProgressWidget::statusMessage);
  statusBar.show();

  QVERIFY(runner.start("quick", [](const ddfcam::ProgressCallback&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(120));
    return std::function<void()>();
  }));
  QVERIFY(runner.waitForFinished(5000));
  const QString done = messages.last().at(0).toString();
  QVERIFY2(QRegularExpression(R"(^Done: quick \(0\.[1-9] s\)$)").match(done).hasMatch(),
           qPrintable(done));

  QVERIFY(runner.start("broken", [](const ddfcam::ProgressCallback&) -> std::function<void()> {
    throw ddfcam::IoError("disk full");
  }));
  QVERIFY(runner.waitForFinished(5000));
  QCOMPARE(messages.last().at(0).toString(), QString("Failed: broken"));
  QCOMPARE(reports_, QStringList{"broken|disk full"});
  QVERIFY(widget->isHidden());
}

DDFCAM_GUI_TEST_MAIN(JobRunnerTest)
#include "job_runner_test.moc"
