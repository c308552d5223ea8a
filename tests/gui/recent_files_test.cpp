// SPDX-License-Identifier: MIT
// RecentFiles: order, dedup, limit, persistence through a settings file, and its menu.
#include "gui_test_registry.h"
#include <ddfcam/error.h>
#include <ddfcam/gui/recent_files.h>

#include <QAction>
#include <QDir>
#include <QMenu>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <memory>

using ddfcam::gui::RecentFiles;

class RecentFilesTest : public QObject {
  Q_OBJECT

 private slots:
  void init();
  void cleanup() { settings_.reset(); }
  void mostRecentFirstWithoutDuplicates();
  void relativePathsBecomeAbsolute();
  void limitDropsOldest();
  void persistsAcrossInstancesAndSettingsObjects();
  void removeAndClear();
  void rejectsBadArguments();
  void menuEntriesOpenTheirPath();
  void emptyMenuSaysSo();

 private:
  QString file(const QString& name) const { return tmp_.filePath(name); }

  QTemporaryDir tmp_;
  QString iniPath_;
  std::unique_ptr<QSettings> settings_;
};

void RecentFilesTest::init() {
  QVERIFY(tmp_.isValid());
  iniPath_ = tmp_.filePath(QString("settings_%1.ini").arg(QTest::currentTestFunction()));
  settings_ = std::make_unique<QSettings>(iniPath_, QSettings::IniFormat);
}

void RecentFilesTest::mostRecentFirstWithoutDuplicates() {
  RecentFiles recent(settings_.get());
  QCOMPARE(recent.maxEntries(), 8);
  recent.add(file("a.ddf"));
  recent.add(file("b.stl"));
  recent.add(file("c.ddf"));
  recent.add(file("a.ddf"));
  recent.add(tmp_.path() + "/./sub/../b.stl");  // the same file, spelled differently
  QCOMPARE(recent.paths(), QStringList({file("b.stl"), file("a.ddf"), file("c.ddf")}));
}

void RecentFilesTest::relativePathsBecomeAbsolute() {
  RecentFiles recent(settings_.get());
  recent.add("relative/part.ddf");
  QCOMPARE(recent.paths(), QStringList({QDir::current().absoluteFilePath("relative/part.ddf")}));
}

void RecentFilesTest::limitDropsOldest() {
  RecentFiles recent(settings_.get(), 3);
  for (int i = 0; i < 5; ++i) recent.add(file(QString("f%1.ddf").arg(i)));
  QCOMPARE(recent.paths(), QStringList({file("f4.ddf"), file("f3.ddf"), file("f2.ddf")}));
  // A longer list written by a build with a larger limit is cut on reading.
  RecentFiles wider(settings_.get(), 8);
  wider.add(file("f5.ddf"));
  QCOMPARE(wider.paths().size(), 4);
  QCOMPARE(recent.paths(), QStringList({file("f5.ddf"), file("f4.ddf"), file("f3.ddf")}));
}

void RecentFilesTest::persistsAcrossInstancesAndSettingsObjects() {
  {
    RecentFiles first(settings_.get());
    first.add(file("x.ddf"));
    first.add(file("y.ddf"));
    RecentFiles second(settings_.get());
    QCOMPARE(second.paths(), QStringList({file("y.ddf"), file("x.ddf")}));
    second.add(file("x.ddf"));
    QCOMPARE(first.paths(), QStringList({file("x.ddf"), file("y.ddf")}));
  }
  settings_.reset();  // a new session: a fresh QSettings on the same file
  QSettings reopened(iniPath_, QSettings::IniFormat);
  QCOMPARE(reopened.value("recentFiles").toStringList(),
           QStringList({file("x.ddf"), file("y.ddf")}));
  QCOMPARE(RecentFiles(&reopened).paths(), QStringList({file("x.ddf"), file("y.ddf")}));
}

void RecentFilesTest::removeAndClear() {
  RecentFiles recent(settings_.get());
  recent.add(file("a.ddf"));
  recent.add(file("b.ddf"));
  recent.remove(file("missing.ddf"));
  recent.remove(tmp_.path() + "/./a.ddf");
  QCOMPARE(recent.paths(), QStringList({file("b.ddf")}));
  recent.clear();
  QVERIFY(recent.paths().isEmpty());
  recent.add(QString());
  QVERIFY(recent.paths().isEmpty());
}

void RecentFilesTest::rejectsBadArguments() {
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, (void)RecentFiles(nullptr));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, (void)RecentFiles(settings_.get(), 0));
}

void RecentFilesTest::menuEntriesOpenTheirPath() {
  RecentFiles recent(settings_.get());
  recent.add(file("first & last.ddf"));
  recent.add(file("b.stl"));
  recent.add(file("c.ddf"));
  QMenu menu;
  QStringList opened;
  recent.populate(&menu, [&](const QString& path) { opened << path; });
  auto* one = menu.findChild<QAction*>("recentFile1");
  auto* three = menu.findChild<QAction*>("recentFile3");
  QVERIFY(one != nullptr && three != nullptr);
  QCOMPARE(one->text(), QStringLiteral("&1 c.ddf"));
  QCOMPARE(one->toolTip(), file("c.ddf"));
  QCOMPARE(three->text(), QStringLiteral("&3 first && last.ddf"));
  QVERIFY(menu.findChild<QAction*>("recentFile4") == nullptr);
  three->trigger();
  menu.findChild<QAction*>("recentFile2")->trigger();
  QCOMPARE(opened, QStringList({file("first & last.ddf"), file("b.stl")}));

  // Repopulating replaces the entries instead of appending to them.
  recent.populate(&menu, [&](const QString& path) { opened << path; });
  QCOMPARE(menu.actions().size(), 5);  // three files, separator, "Clear list"

  auto* clearEntry = menu.findChild<QAction*>("recentFilesClear");
  QVERIFY(clearEntry != nullptr);
  clearEntry->trigger();
  QVERIFY(recent.paths().isEmpty());
}

void RecentFilesTest::emptyMenuSaysSo() {
  RecentFiles recent(settings_.get());
  QMenu menu;
  recent.populate(&menu, [](const QString&) { QFAIL("nothing to open"); });
  QCOMPARE(menu.actions().size(), 1);
  QAction* empty = menu.actions().front();
  QCOMPARE(empty->objectName(), QStringLiteral("recentFilesEmpty"));
  QCOMPARE(empty->text(), QStringLiteral("No recent files"));
  QVERIFY(!empty->isEnabled());
}

DDFCAM_GUI_TEST_MAIN(RecentFilesTest)
#include "recent_files_test.moc"
