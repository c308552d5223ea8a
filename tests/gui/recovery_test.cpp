// SPDX-License-Identifier: MIT
// RecoveryManager: autosave after edits only, a simulated crash found and recovered exactly.
#include "gui_test_registry.h"
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/recovery_manager.h>
#include <ddfcam/planning/model/project.h>

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <memory>

using ddfcam::gui::AddFieldCommand;
using ddfcam::gui::Document;
using ddfcam::gui::RecoveryEntry;
using ddfcam::gui::RecoveryManager;
using ddfcam::gui::RecoveryParams;
using ddfcam::gui::SetHeightsCommand;
namespace planning = ddfcam::planning;

namespace {

planning::Project smallProject() {
  ddfcam::ddf::PlanePatchParams params;
  params.cellsX = 3;
  params.cellsY = 2;
  params.m = 5;
  planning::Project project;
  project.partName = "plane";
  project.part = ddfcam::ddf::planePatch(params).ddf;
  project.tools.push_back(planning::Tool{});
  return project;
}

void editField(Document& document, const std::string& name, float value) {
  planning::ScalarField field;
  field.name = name;
  field.values.assign(document.project().part->allHeights().size(), value);
  document.push(std::make_unique<AddFieldCommand>(document, field));
}

QStringList filesIn(const QString& directory) {
  return QDir(directory).entryList(QDir::Files, QDir::Name);
}

}  // namespace

class RecoveryTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    dir_ = std::make_unique<QTemporaryDir>();
    QVERIFY(dir_->isValid());
  }
  void autosaveWritesOnlyAfterEdit();
  void timerAutosavesAndForgetsAfterSave();
  void crashLeavesFileThatIsRecoveredExactly();
  void liveSessionIsNotListed();
  void liveSessionWithOldLockIsNotListed();
  void discardRemovesFiles();
  void corruptRecoveryFileIsReportedAndKept();

 private:
  RecoveryParams params(int intervalMs = 0) const {
    RecoveryParams p;
    p.directory = dir_->path() + "/recovery";
    p.intervalMs = intervalMs;
    return p;
  }
  std::unique_ptr<QTemporaryDir> dir_;
};

void RecoveryTest::autosaveWritesOnlyAfterEdit() {
  Document document;
  document.reset(smallProject());
  RecoveryManager manager(document, params());
  QSignalSpy saved(&manager, &RecoveryManager::autosaved);
  QVERIFY(!manager.autosaveNow());  // freshly opened: nothing to protect
  QVERIFY(!QFile::exists(manager.recoveryFilePath()));

  editField(document, "a", 1.0f);
  QVERIFY(manager.autosaveNow());
  QVERIFY(QFile::exists(manager.recoveryFilePath()));
  QCOMPARE(saved.count(), 1);
  QVERIFY(!manager.autosaveNow());  // no edit since

  document.undoStack()->undo();  // back to the opened state: unmodified
  QVERIFY(!manager.autosaveNow());
  document.undoStack()->redo();  // a new revision of a modified document
  QVERIFY(manager.autosaveNow());
  QCOMPARE(saved.count(), 2);
  manager.discardRecovery();
}

void RecoveryTest::timerAutosavesAndForgetsAfterSave() {
  Document document;
  document.reset(smallProject());
  RecoveryManager manager(document, params(30));
  QSignalSpy saved(&manager, &RecoveryManager::autosaved);
  QTest::qWait(100);
  QCOMPARE(saved.count(), 0);
  editField(document, "a", 1.0f);
  QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 1, 3000);
  QTest::qWait(100);
  QCOMPARE(saved.count(), 1);  // ticks without edits write nothing
  QVERIFY(QFile::exists(manager.recoveryFilePath()));
  document.markSaved(dir_->path() + "/saved.ddfproj");
  // The saved file is newer than the recovery file, which the next tick removes.
  QTRY_VERIFY_WITH_TIMEOUT(!QFile::exists(manager.recoveryFilePath()), 3000);
}

void RecoveryTest::crashLeavesFileThatIsRecoveredExactly() {
  const QString original = dir_->path() + "/projects/part.ddfproj";
  planning::Project autosaved;
  QString recoveryFile;
  const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-1);
  {
    Document document;
    document.reset(smallProject(), original);
    auto after = document.project().part->allHeights();
    for (std::size_t i = 0; i < after.size(); i += 3) after[i] = -0.125f * float(i % 7);
    document.push(std::make_unique<SetHeightsCommand>(
        document, "cut", after, planning::SimulationState{"after cut", after}));
    editField(document, "removed", 0.5f);
    RecoveryManager manager(document, params());
    QVERIFY(manager.autosaveNow());
    autosaved = document.project();
    recoveryFile = manager.recoveryFilePath();
    editField(document, "not autosaved", 2.0f);  // lost in the crash
    // The session ends without discardRecovery(): a crash as far as the files tell.
  }
  QVERIFY(QFile::exists(recoveryFile));
  const std::vector<RecoveryEntry> entries = RecoveryManager::findAbandoned(params().directory);
  QCOMPARE(entries.size(), std::size_t{1});
  const RecoveryEntry& entry = entries.front();
  QCOMPARE(entry.recoveryFile, recoveryFile);
  QCOMPARE(entry.originalPath, original);
  QVERIFY(entry.time >= before && entry.time <= QDateTime::currentDateTimeUtc().addSecs(1));

  const planning::Project recovered = RecoveryManager::recover(entry);
  QVERIFY(planning::projectsEqual(recovered, autosaved));
  QVERIFY(!QFile::exists(recoveryFile));
  QCOMPARE(filesIn(params().directory), QStringList());  // sidecar and locks gone too
  QVERIFY(RecoveryManager::findAbandoned(params().directory).empty());

  // The caller's side of the protocol: the document holds it, modified, under its old path.
  Document document;
  document.reset(recovered, entry.originalPath);
  document.markModified();
  QVERIFY(document.isModified());
  QCOMPARE(document.filePath(), original);
}

void RecoveryTest::liveSessionIsNotListed() {
  Document document;
  document.reset(smallProject());
  RecoveryManager live(document, params());
  editField(document, "a", 1.0f);
  QVERIFY(live.autosaveNow());
  QVERIFY(RecoveryManager::findAbandoned(params().directory).empty());
  RecoveryEntry entry{live.recoveryFilePath(), {}, QDateTime::currentDateTimeUtc()};
  QVERIFY_THROWS_EXCEPTION(ddfcam::IoError, RecoveryManager::recover(entry));
  QVERIFY_THROWS_EXCEPTION(ddfcam::IoError, RecoveryManager::discard(entry));
  QVERIFY(QFile::exists(live.recoveryFilePath()));
  live.discardRecovery();
}

void RecoveryTest::liveSessionWithOldLockIsNotListed() {
  // A lock older than QLockFile's stale time (30 s) still belongs to a live session.
  Document document;
  document.reset(smallProject());
  RecoveryManager live(document, params());
  editField(document, "a", 1.0f);
  QVERIFY(live.autosaveNow());
  const QStringList locks = QDir(params().directory).entryList({"session-*.lock"}, QDir::Files);
  QCOMPARE(locks.size(), 1);
  QFile lock(QDir(params().directory).filePath(locks.front()));
  QVERIFY(lock.open(QIODevice::ReadWrite));
  QVERIFY(lock.setFileTime(QDateTime::currentDateTimeUtc().addSecs(-3600),
                           QFileDevice::FileModificationTime));
  lock.close();
  QVERIFY(RecoveryManager::findAbandoned(params().directory).empty());
  QVERIFY(QFile::exists(live.recoveryFilePath()));
  live.discardRecovery();
}

void RecoveryTest::discardRemovesFiles() {
  QString recoveryFile;
  {
    Document document;
    document.reset(smallProject());
    RecoveryManager manager(document, params());
    editField(document, "a", 1.0f);
    QVERIFY(manager.autosaveNow());
    recoveryFile = manager.recoveryFilePath();
    QCOMPARE(filesIn(params().directory).size(), 3);  // lock, project, sidecar
    manager.discardRecovery();
    QVERIFY(!QFile::exists(recoveryFile));
    QCOMPARE(filesIn(params().directory).size(), 1);  // the lock of the live session
  }
  QCOMPARE(filesIn(params().directory), QStringList());
  QVERIFY(RecoveryManager::findAbandoned(params().directory).empty());
}

void RecoveryTest::corruptRecoveryFileIsReportedAndKept() {
  QVERIFY(QDir().mkpath(params().directory));
  const QString path = params().directory + "/recovery-0123abcd.ddfproj";
  {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("DDFPRJ\x1a\n but then nothing sensible");
  }
  const std::vector<RecoveryEntry> entries = RecoveryManager::findAbandoned(params().directory);
  QCOMPARE(entries.size(), std::size_t{1});
  QCOMPARE(entries.front().originalPath, QString());  // no sidecar
  QVERIFY_THROWS_EXCEPTION(ddfcam::IoError, RecoveryManager::recover(entries.front()));
  QVERIFY(QFile::exists(path));
  RecoveryManager::discard(entries.front());
  QVERIFY(!QFile::exists(path));
}

DDFCAM_GUI_TEST_MAIN(RecoveryTest)
#include "recovery_test.moc"
