// SPDX-License-Identifier: MIT
// Test support: the base of the Qt Test classes that drive one workbench window.
#pragma once

#include "workbench_fixture.h"

#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/planning/model/project.h>

#include <QDockWidget>
#include <QObject>
#include <QtTest/QtTest>

#include <utility>

namespace ddfcam::test {

/// A Qt Test class owning a WorkbenchFixture: the surface format is set before QApplication and
/// every test function must end without a VTK error. (Listed among the sources of each test that
/// derives from it, so AUTOMOC sees the header.)
class WorkbenchTest : public QObject {
  Q_OBJECT

 public:
  /// Called by QTEST_MAIN before QApplication exists.
  static void initMain() { gui::setDefaultSurfaceFormat(); }

 protected:
  /// Installs the VTK error monitor and opens the window (the demo part loaded if @p demo).
  bool openWorkbench(bool demo) {
    gui::VtkErrorMonitor::install();
    return f_.dir.isValid() && f_.open(demo);
  }
  const planning::Project& project() const { return f_.window->document().project(); }
  /// Replaces the document's project and waits for its jobs.
  void load(planning::Project project) {
    f_.window->document().reset(std::move(project));
    QVERIFY(f_.window->waitForJobs());
  }
  /// Raises the dock of the panel with identifier @p id (Panel::id()); false if there is none.
  bool raisePanel(const QString& id) {
    auto* dock = f_.window->findChild<QDockWidget*>("panel_" + id);
    if (dock) dock->raise();
    QApplication::processEvents();
    return dock != nullptr;
  }
  /// Waits for the jobs and checks that no error dialog was shown.
  void waitOk() {
    QVERIFY(f_.window->waitForJobs(60'000));
    QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  }

  WorkbenchFixture f_;

 private slots:
  void cleanup() { QCOMPARE(gui::VtkErrorMonitor::errorCount(), 0); }
};

}  // namespace ddfcam::test
