// SPDX-License-Identifier: MIT
// The Console dock: messages logged from other threads arrive in order, lines are limited,
// and a dock that is gone drops late messages instead of crashing.
#include "gui_test_registry.h"
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/log.h>

#include <QAction>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QTextBlock>
#include <QtTest/QtTest>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

using ddfcam::LogLevel;
using ddfcam::gui::ConsoleDock;

namespace {

QStringList linesOf(const ConsoleDock& dock) {
  QStringList lines = dock.text().split(QLatin1Char('\n'));
  lines.removeAll(QString());
  return lines;
}

// The message part of a line "HH:mm:ss.zzz [level] message".
QString messageOf(const QString& line) {
  return line.section(QLatin1Char(' '), 2);
}

// Waits (processing events) until @p dock shows @p count lines or 5 s have passed.
bool waitForLines(const ConsoleDock& dock, int count) {
  QDeadlineTimer deadline(5000);
  while (linesOf(dock).size() < count && !deadline.hasExpired()) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  }
  return linesOf(dock).size() == count;
}

}  // namespace

class ConsoleDockTest : public QObject {
  Q_OBJECT

 private slots:
  void cleanup() { ddfcam::setLogSink({}); }
  void linesAreStampedAndTagged();
  void errorsAreRed();
  void multiLineMessageGivesOneLineEach();
  void threadMessagesArriveInOrder();
  void lineLimitDropsOldestLines();
  void clearActionEmptiesTheConsole();
  void destructorRestoresPreviousSink();
  void lateMessagesAfterDeletionAreDropped();
  void deletionWhileThreadsLogDoesNotCrash();
};

void ConsoleDockTest::linesAreStampedAndTagged() {
  ConsoleDock dock;
  QCOMPARE(dock.objectName(), QStringLiteral("consoleDock"));
  QCOMPARE(dock.windowTitle(), QStringLiteral("Console"));
  QVERIFY(dock.findChild<QPlainTextEdit*>("consoleText")->isReadOnly());
  dock.appendMessage(LogLevel::Info, "part loaded");
  dock.appendMessage(LogLevel::Warning, "thin crust");
  const QStringList lines = linesOf(dock);
  QCOMPARE(lines.size(), 2);
  const QRegularExpression info(R"(^\d\d:\d\d:\d\d\.\d\d\d \[info\] part loaded$)");
  QVERIFY2(info.match(lines[0]).hasMatch(), qPrintable(lines[0]));
  QVERIFY(lines[1].endsWith("[warning] thin crust"));
}

void ConsoleDockTest::errorsAreRed() {
  ConsoleDock dock;
  dock.appendMessage(LogLevel::Info, "fine");
  dock.appendMessage(LogLevel::Error, "broken");
  const QTextDocument* document = dock.findChild<QPlainTextEdit*>("consoleText")->document();
  auto colourOf = [&](int block) {
    return document->findBlockByNumber(block).begin().fragment().charFormat().foreground().color();
  };
  const QColor error = colourOf(1);
  QVERIFY2(error.red() > 150 && error.green() < 60 && error.blue() < 60, qPrintable(error.name()));
  QVERIFY(colourOf(0) != error);
}

void ConsoleDockTest::multiLineMessageGivesOneLineEach() {
  ConsoleDock dock;
  dock.appendMessage(LogLevel::Error, "open failed\nfile is truncated\n");
  const QStringList lines = linesOf(dock);
  QCOMPARE(lines.size(), 2);
  QVERIFY(lines[0].endsWith("[error] open failed"));
  QVERIFY(lines[1].endsWith("[error] file is truncated"));
}

void ConsoleDockTest::threadMessagesArriveInOrder() {
  ConsoleDock dock;
  dock.installLogSink();
  constexpr int kCount = 300;
  std::thread worker([] {
    for (int i = 0; i < kCount; ++i) ddfcam::log(LogLevel::Info, "step " + std::to_string(i));
  });
  worker.join();
  QVERIFY(waitForLines(dock, kCount));
  const QStringList lines = linesOf(dock);
  for (int i = 0; i < kCount; ++i) QCOMPARE(messageOf(lines[i]), QString("step %1").arg(i));
}

void ConsoleDockTest::lineLimitDropsOldestLines() {
  ConsoleDock dock;
  QCOMPARE(dock.lineLimit(), ConsoleDock::kDefaultLineLimit);
  dock.setLineLimit(50);
  for (int i = 0; i < 120; ++i) dock.appendMessage(LogLevel::Info, QString("m%1").arg(i));
  const QStringList lines = linesOf(dock);
  QCOMPARE(lines.size(), 50);
  QCOMPARE(messageOf(lines.front()), QStringLiteral("m70"));
  QCOMPARE(messageOf(lines.back()), QStringLiteral("m119"));
}

void ConsoleDockTest::clearActionEmptiesTheConsole() {
  ConsoleDock dock;
  dock.appendMessage(LogLevel::Info, "x");
  QCOMPARE(dock.clearAction()->objectName(), QStringLiteral("consoleClearAction"));
  dock.clearAction()->trigger();
  QVERIFY(dock.text().isEmpty());
  dock.appendMessage(LogLevel::Info, "y");
  QCOMPARE(linesOf(dock).size(), 1);
}

void ConsoleDockTest::destructorRestoresPreviousSink() {
  std::vector<std::string> recorded;
  ddfcam::setLogSink([&](LogLevel, const std::string& m) { recorded.push_back(m); });
  {
    ConsoleDock dock;
    dock.installLogSink();
    dock.installLogSink();  // twice installs once
    ddfcam::log(LogLevel::Info, "to the dock");
    QVERIFY(waitForLines(dock, 1));
  }
  ddfcam::log(LogLevel::Info, "to the recorder");
  QCOMPARE(recorded, std::vector<std::string>({"to the recorder"}));
}

void ConsoleDockTest::lateMessagesAfterDeletionAreDropped() {
  auto dock = std::make_unique<ConsoleDock>();
  dock->installLogSink();
  // A copy of the dock's sink, as a logging thread may still hold it after uninstall.
  ddfcam::LogSink stale = ddfcam::setLogSink({});
  ddfcam::setLogSink(stale);
  ddfcam::log(LogLevel::Info, "queued before deletion");
  dock.reset();
  std::thread worker([&stale] {
    stale(LogLevel::Error, "after deletion");
    ddfcam::log(LogLevel::Error, "after deletion, no sink");
  });
  worker.join();
  QCoreApplication::processEvents();
  QTest::qWait(20);
}

void ConsoleDockTest::deletionWhileThreadsLogDoesNotCrash() {
  auto dock = std::make_unique<ConsoleDock>();
  dock->installLogSink();
  std::atomic<bool> stop{false};
  std::atomic<int> logged{0};
  std::vector<std::thread> workers;
  for (int t = 0; t < 3; ++t) {
    workers.emplace_back([&] {
      while (!stop) {
        ddfcam::log(LogLevel::Debug, "busy");
        ++logged;
        // Bounded pace: the point is concurrency with the deletion, not a flood of events.
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      }
    });
  }
  while (logged < 2000) QCoreApplication::processEvents();
  dock.reset();
  const int atDeletion = logged;
  while (logged < atDeletion + 2000) QCoreApplication::processEvents();
  stop = true;
  for (std::thread& worker : workers) worker.join();
  QCoreApplication::processEvents();
}

DDFCAM_GUI_TEST_MAIN(ConsoleDockTest)
#include "console_dock_test.moc"
