// SPDX-License-Identifier: MIT
// Smoke test under Xvfb: every action of the main menu, in menu order, on the demo session,
// with every dialog answered "cancel" or a scratch file. Nothing may crash or leave a job
// hanging; errors must come as reported messages.
#include "gui_test_registry.h"
#include "workbench_fixture.h"

#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/vtk_error_monitor.h>

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QtTest/QtTest>

namespace {

/// Every triggerable action reachable from @p menu, depth first, in menu order.
void collectActions(QMenu* menu, QList<QAction*>& out) {
  emit menu->aboutToShow();  // menus that fill themselves on show (recent files)
  for (QAction* action : menu->actions()) {
    if (action->menu())
      collectActions(action->menu(), out);
    else if (!action->isSeparator())
      out << action;
  }
}

}  // namespace

class MenuSmokeTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void walksEveryMenuAction();
};

void MenuSmokeTest::walksEveryMenuAction() {
  ddfcam::gui::VtkErrorMonitor::install();
  ddfcam::test::WorkbenchFixture f;
  QVERIFY(f.open());
  f.script.saveProjectPath = f.dir.filePath("smoke.ddfproj");
  f.script.screenshot =
      ddfcam::gui::ScreenshotRequest{f.dir.filePath("smoke.png"), QSize(320, 240)};
  QList<QAction*> actions;
  for (QAction* top : f.window->menuBar()->actions())
    if (top->menu()) collectActions(top->menu(), actions);
  QVERIFY(actions.size() >= 20);
  QStringList walked;
  for (QAction* action : actions) {
    if (action->objectName() == "actionQuit") continue;  // last, below
    if (!action->isEnabled()) continue;
    walked << (action->objectName().isEmpty() ? action->text() : action->objectName());
    const auto errorsBefore = f.script.errors.size();
    action->trigger();
    QVERIFY2(f.window->waitForJobs(120'000), qPrintable(walked.back()));
    QCoreApplication::processEvents();
    // One user action reports at most one error (caught once, at the action).
    QVERIFY2(f.script.errors.size() <= errorsBefore + 1,
             qPrintable(walked.back() + ": " + f.script.errors.mid(errorsBefore).join(" | ")));
    // Checkable toggles go back, so the following actions see the standard view.
    if (action->isCheckable()) action->trigger();
  }
  qInfo() << "walked" << walked.size() << "actions;" << f.script.errors.size()
          << "reported errors:" << f.script.errors;
  // Reported errors are allowed (e.g. a field needing a design mesh); crashes are not (and
  // nothing is reported twice for one action, checked above).
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);

  // The walk ends with Simulate, an edit after the last save: quitting must ask first;
  // "cancel" keeps the window, "discard" closes it.
  QVERIFY(f.window->document().isModified());
  f.script.unsaved = ddfcam::gui::UnsavedChoice::Cancel;
  f.window->findChild<QAction*>("actionQuit")->trigger();
  QVERIFY(f.window->isVisible());
  f.script.unsaved = ddfcam::gui::UnsavedChoice::Discard;
  f.window->findChild<QAction*>("actionQuit")->trigger();
  QVERIFY(!f.window->isVisible());
}

DDFCAM_GUI_TEST_MAIN(MenuSmokeTest)
#include "menu_smoke_test.moc"
