// SPDX-License-Identifier: MIT
// Workbench workflows under Xvfb: colour by a field (scalar bar and histogram against the
// data), picking, jobs and cancel, undo/redo, project save/load and crash recovery.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/panels/pick_panel.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/recovery_manager.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/project.h>

#include <QAction>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

using ddfcam::gui::FieldKind;
using ddfcam::planning::Project;
using ddfcam::planning::projectsEqual;

class WorkflowTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void colourByFieldMatchesScalarBarAndHistogram();
  void pickReturnsKnownFaceAndBarycentrics();
  void cancelledJobLeavesDocumentUnchanged();
  void simulationUndoRedoRoundTrip();
  void projectSaveLoadRoundTrip();
  void recoveryAfterSimulatedCrash();
  void groundPartShowsMaterialRemoved();
  void colourByPrincipalCurvature();
  void clickSeedsAStreamlineThatIsDrawn();

 private:
  QAction* action(const char* name) { return f_.window->findChild<QAction*>(name); }
  template <typename T>
  T* panel() {
    return f_.window->findChild<T*>();
  }
  /// Runs the demo path to completion through the Simulation panel.
  void simulateDemoPath();
};

void WorkflowTest::initTestCase() {
  QVERIFY(openWorkbench(true));
}

void WorkflowTest::init() {
  f_.script.errors.clear();
  // Every test starts from a fresh demo session.
  f_.script.unsaved = ddfcam::gui::UnsavedChoice::Discard;
  QVERIFY(f_.window->openDemo());
  QVERIFY(f_.window->waitForJobs());
  QVERIFY(!f_.window->document().isModified());
}

void WorkflowTest::simulateDemoPath() {
  auto* simulation = panel<ddfcam::gui::SimulationPanel>();
  QVERIFY(simulation != nullptr);
  QVERIFY(simulation->simulatePath(0));
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
}

void WorkflowTest::colourByFieldMatchesScalarBarAndHistogram() {
  auto* fields = panel<ddfcam::gui::FieldsPanel>();
  QVERIFY(fields != nullptr);
  QVERIFY(fields->compute(FieldKind::HeightMm));
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(project().fields.size(), std::size_t{1});
  const auto& ddf = *project().part;
  // Oracle: h |v| at every raster point straight from the field's definition.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<double> perPoint(ddf.topology().pointCount(), std::nan(""));
  const int n = ddf.resolution() - 1;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const auto bary = ddf.rasterBary(i, k);
        const double value = ddf.height(f, i, k) * ddf.vectorAt(f, bary).norm();
        lo = std::min(lo, value);
        hi = std::max(hi, value);
        double& slot = perPoint[ddf.topology().id(f, i, k)];
        if (std::isnan(slot)) slot = value;  // lowest face first, as the histogram counts
      }
  const auto& scene = f_.window->partView().scene();
  QVERIFY(scene.isFieldShown());
  QVERIFY2(QString::fromStdString(scene.scalarBarTitle()).contains("[mm]"),
           scene.scalarBarTitle().c_str());
  // Signed field: the colour range is symmetric about zero and covers the data.
  const auto range = scene.scalarRange();
  QVERIFY(range.lo <= lo + 1e-6 && range.hi >= hi - 1e-6);
  QCOMPARE(range.lo, -range.hi);
  QVERIFY(std::max(std::abs(lo), std::abs(hi)) >= 0.999 * range.hi);

  QCustomPlot* plot = f_.window->plots().plot("Histogram");
  auto* bars = qobject_cast<QCPBars*>(plot->plottable(0));
  QVERIFY(bars != nullptr);
  const int bins = ddfcam::gui::FieldsPanel::kHistogramBins;
  QCOMPARE(bars->data()->size(), bins);
  std::vector<double> expected(bins, 0.0);
  const double width = (range.hi - range.lo) / bins;
  for (double v : perPoint) {
    const int b = std::clamp(static_cast<int>(std::floor((v - range.lo) / width)), 0, bins - 1);
    expected[b] += 1.0;
  }
  for (int b = 0; b < bins; ++b) {
    const auto& bar = *(bars->data()->begin() + b);
    QCOMPARE(bar.key, range.lo + (b + 0.5) * width);
    // Values that fall exactly on a bin edge may land on either side in float arithmetic.
    QVERIFY2(std::abs(bar.value - expected[b]) <= 2.0,
             qPrintable(QString("bin %1: %2 vs %3").arg(b).arg(bar.value).arg(expected[b])));
  }
  double total = 0;
  for (const auto& bar : *bars->data()) total += bar.value;
  QCOMPARE(total, static_cast<double>(perPoint.size()));

  // A fixed range re-colours and re-bins.
  f_.window->partView().setRange(0.0, 0.5);
  QCOMPARE(scene.scalarRange().lo, 0.0);
  QCOMPARE(scene.scalarRange().hi, 0.5);
  // The histogram was redrawn (new bars) over the new range.
  bars = qobject_cast<QCPBars*>(plot->plottable(0));
  QVERIFY(bars != nullptr);
  QCOMPARE(bars->data()->begin()->key, 0.5 / bins / 2);
}

void WorkflowTest::pickReturnsKnownFaceAndBarycentrics() {
  const auto& ddf = *project().part;
  auto& view = *f_.window->view();
  // An interior raster point of a face near the part's middle, seen from above.
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  const int n = ddf.resolution() - 1;
  const int face = ddf.faceCount() / 2 + 7;
  const int i = n / 3, k = n / 3;
  const Eigen::Vector3d target = ddf.surfacePoint(face, i, k);
  const QPointF at = view.widgetPosition(target);
  QVERIFY(view.rect().contains(at.toPoint()));
  QSignalSpy picked(&f_.window->partView(), &ddfcam::gui::PartView::picked);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, at.toPoint());
  QCOMPARE(picked.size(), 1);
  const auto result = picked.front().front().value<ddfcam::gui::PickResult>();
  QCOMPARE(result.location.face, face);
  // The click lands within a pixel of the target (rounded to a whole pixel, on a display
  // surface within eps of the DDF): measure what a pixel is here, in mm and in barycentrics.
  const auto f = ddf.faceVertices(face);
  const Eigen::Vector3d p1 = ddf.position(f[0]), p2 = ddf.position(f[1]);
  const double mmPerPixel = 1.0 / (QLineF(view.widgetPosition(target),
                                          view.widgetPosition(target + Eigen::Vector3d::UnitX()))
                                       .length());
  const double shortestEdge = std::min(
      {(p2 - p1).norm(), (ddf.position(f[2]) - p2).norm(), (ddf.position(f[2]) - p1).norm()});
  const double tolMm = 2.0 * mmPerPixel + 0.01;
  QVERIFY2((result.location.point - target).norm() < tolMm,
           qPrintable(QString("%1 mm off, %2 mm per pixel")
                          .arg((result.location.point - target).norm())
                          .arg(mmPerPixel)));
  const Eigen::Vector3d bary = ddf.rasterBary(i, k);
  QVERIFY2((result.location.bary - bary).cwiseAbs().maxCoeff() < 2.0 * tolMm / shortestEdge,
           qPrintable(QString("%1 %2 %3")
                          .arg(result.location.bary.x())
                          .arg(result.location.bary.y())
                          .arg(result.location.bary.z())));
  QVERIFY(std::abs(result.location.bary.sum() - 1.0) < 1e-9);
  // The point reported is on the DDF surface at the reported coordinates.
  QVERIFY(
      (ddf.pointAt(face, result.location.bary, result.location.h) - result.location.point).norm() <
      1e-9);
  QVERIFY(panel<ddfcam::gui::PickPanel>()->text().contains(QString("face %1").arg(face)));
  // The picked point is marked in the view by an arrow (three line cells).
  QCOMPARE(f_.window->partView().scene().overlayCellCount("pick"), 3);
}

void WorkflowTest::cancelledJobLeavesDocumentUnchanged() {
  // A long path (the demo passes forty times over) so that the job is surely still running.
  ddfcam::planning::ToolPath longPath = project().paths.front();
  longPath.name = "long path";
  const auto poses = longPath.poses;
  for (int r = 1; r < 40; ++r)
    longPath.poses.insert(longPath.poses.end(), poses.begin(), poses.end());
  f_.window->document().push(
      std::make_unique<ddfcam::gui::AddPathCommand>(f_.window->document(), longPath));
  const Project before = project();
  const auto revision = f_.window->document().revision();

  auto& jobs = f_.window->jobs();
  QSignalSpy progress(&jobs, &ddfcam::gui::JobRunner::progressChanged);
  QSignalSpy finished(&jobs, &ddfcam::gui::JobRunner::finished);
  QVERIFY(panel<ddfcam::gui::SimulationPanel>()->simulatePath(1));
  QVERIFY(jobs.isRunning());
  QTRY_VERIFY_WITH_TIMEOUT(progress.size() > 0, 10'000);
  QElapsedTimer timer;
  timer.start();
  // The status-bar button is what the engineer presses.
  auto* cancel = f_.window->findChild<QAbstractButton*>("jobCancelButton");
  QVERIFY(cancel && cancel->isVisible());
  cancel->click();
  QVERIFY(f_.window->waitForJobs(5'000));
  qInfo("cancel took effect after %lld ms", static_cast<long long>(timer.elapsed()));
  QVERIFY2(timer.elapsed() < 1000, qPrintable(QString::number(timer.elapsed())));
  QCOMPARE(finished.size(), 1);
  QCOMPARE(finished.front().at(1).value<ddfcam::gui::JobRunner::Outcome>(),
           ddfcam::gui::JobRunner::Outcome::Cancelled);
  QVERIFY(f_.script.errors.isEmpty());
  QVERIFY(projectsEqual(project(), before));
  QCOMPARE(f_.window->document().revision(), revision);
}

void WorkflowTest::simulationUndoRedoRoundTrip() {
  const Project stock = project();
  simulateDemoPath();
  const Project ground = project();
  QVERIFY(ground.part->allHeights() != stock.part->allHeights());
  QCOMPARE(ground.states.size(), stock.states.size() + 1);
  QVERIFY(f_.window->document().isModified());
  QVERIFY(f_.window->windowTitle().contains('*'));

  QAction* undo = action("actionUndo");
  QAction* redo = action("actionRedo");
  QVERIFY(undo->isEnabled());
  undo->trigger();
  QVERIFY(projectsEqual(project(), stock));
  QVERIFY(!f_.window->document().isModified());
  redo->trigger();
  QVERIFY(projectsEqual(project(), ground));
  // Restoring the stock state is itself an edit that undoes cleanly.
  QVERIFY(panel<ddfcam::gui::SimulationPanel>()->restoreState(0));
  QVERIFY(project().part->allHeights() == stock.part->allHeights());
  undo->trigger();
  QVERIFY(projectsEqual(project(), ground));
}

void WorkflowTest::projectSaveLoadRoundTrip() {
  simulateDemoPath();
  QVERIFY(panel<ddfcam::gui::FieldsPanel>()->compute(FieldKind::MaterialRemoved));
  QVERIFY(f_.window->waitForJobs());
  const Project saved = project();
  f_.script.saveProjectPath = f_.dir.filePath("session");  // suffix added
  action("actionSaveAs")->trigger();
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const QString file = f_.dir.filePath("session.ddfproj");
  QVERIFY(QFile::exists(file));
  QCOMPARE(f_.window->document().filePath(), file);
  QVERIFY(!f_.window->document().isModified());

  QVERIFY(f_.window->openDemo());
  QVERIFY(f_.window->waitForJobs());
  QVERIFY(!projectsEqual(project(), saved));
  f_.script.openPath = file;
  action("actionOpen")->trigger();
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QVERIFY(projectsEqual(project(), saved));
  QCOMPARE(f_.window->document().filePath(), file);
  QVERIFY(!f_.window->document().isModified());
}

void WorkflowTest::recoveryAfterSimulatedCrash() {
  simulateDemoPath();
  QVERIFY(f_.window->recovery().autosaveNow());
  const Project autosaved = project();
  // A crash: the window goes away without closeEvent (no prompt, no discard of the recovery).
  f_.window.reset();
  f_.script.recoveryChoice = 0;
  QVERIFY(f_.open(/*demo=*/false));
  QCOMPARE(f_.script.offeredRecoveries.size(), 1);
  QVERIFY(projectsEqual(project(), autosaved));
  QVERIFY(f_.window->document().isModified());
  // Recovered once: a second start offers nothing.
  f_.script.recoveryChoice = -1;
  f_.script.offeredRecoveries.clear();
  f_.window->close();
  QVERIFY(f_.open(/*demo=*/false));
  QVERIFY(f_.script.offeredRecoveries.isEmpty());
}

void WorkflowTest::groundPartShowsMaterialRemoved() {
  // The picture of the README: the demo path ground, coloured by the material it removed.
  simulateDemoPath();
  QVERIFY(panel<ddfcam::gui::FieldsPanel>()->compute(FieldKind::MaterialRemoved));
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& field = project().fields.back();
  QCOMPARE(QString::fromStdString(field.name), QString("material removed"));
  // Oracle: the stock state minus the ground heights, times the vector length, per point.
  const auto& ddf = *project().part;
  const auto& stock = project().states.front().heights;
  double removedMax = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k + 1 < ddf.resolution(); ++k) {
      const std::size_t idx =
          static_cast<std::size_t>(f) * ddf.pointsPerFace() + ddf.raster().index(0, k);
      const double expected = (stock[idx] - ddf.heights(f)[ddf.raster().index(0, k)]) *
                              ddf.vectorAt(f, ddf.rasterBary(0, k)).norm();
      QVERIFY(std::abs(field.values[idx] - expected) < 1e-5);
      removedMax = std::max(removedMax, expected);
    }
  // The roll sinks 0.02 mm below the design under 0.2 mm of stock: at least that comes off
  // (more where the straight roll's edges reach into concave parts).
  QVERIFY2(removedMax > 0.2, qPrintable(QString::number(removedMax)));
  QCOMPARE(f_.window->partView().scene().scalarRange().lo, 0.0);
  QVERIFY(!f_.window->partView().scene().isFieldShown() ||
          f_.window->partView().scene().scalarBarTitle() == "material removed [mm]");
  const QSize testSize = f_.window->size();
  f_.window->resize(1280, 820);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  QTest::qWait(100);
  const QImage window = f_.window->grab().toImage();
  ddfcam::test::dumpFrame(window, "workbench");
  QVERIFY(!window.isNull());
  // The other panels, for a look when DDFCAM_GUI_TEST_OUTPUT is set (with a picked point).
  QVERIFY(f_.window->partView().pick(QPointF(f_.window->view()->rect().center())).has_value());
  for (const char* id : {"part", "simulation", "pick"}) {
    auto* dock = f_.window->findChild<QDockWidget*>(QString("panel_") + id);
    QVERIFY(dock != nullptr);
    dock->raise();
    QTest::qWait(50);
    ddfcam::test::dumpFrame(f_.window->grab().toImage(), QString("workbench_") + id);
  }
  f_.window->resize(testSize);
}

void WorkflowTest::colourByPrincipalCurvature() {
  auto* fields = panel<ddfcam::gui::FieldsPanel>();
  for (FieldKind kind : {FieldKind::KMin, FieldKind::KMax}) {
    QVERIFY(fields->compute(kind));
    QVERIFY(f_.window->waitForJobs());
  }
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(project().fields.size(), std::size_t{2});
  const auto& kMin = project().fields[0];
  const auto& kMax = project().fields[1];
  QCOMPARE(QString::fromStdString(kMax.name), QString("k_max"));
  QCOMPARE(QString::fromStdString(kMax.unit), QString("1/mm"));
  // Invariant: k_max >= k_min at every raster point, and the free-form part is curved.
  double largest = 0;
  for (std::size_t i = 0; i < kMax.values.size(); ++i) {
    QVERIFY(kMax.values[i] >= kMin.values[i]);
    largest = std::max(largest, std::abs(static_cast<double>(kMax.values[i])));
  }
  QVERIFY(largest > 1e-3);
  // The last computed field is shown, signed: diverging map, symmetric range, units in the bar.
  const auto& scene = f_.window->partView().scene();
  QCOMPARE(QString::fromStdString(scene.scalarBarTitle()), QString("k_max [1/mm]"));
  QCOMPARE(scene.scalarRange().lo, -scene.scalarRange().hi);
  QCOMPARE(f_.window->partView().fieldDisplay().map, ddfcam::gui::ColourMap::CoolWarm);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "workbench_kmax");

  // Largest non-gouging tool: 1/|k_min| where the surface is concave, capped at the part size.
  QVERIFY(fields->compute(FieldKind::MaxToolRadius));
  QVERIFY(f_.window->waitForJobs());
  const auto& radius = project().fields.back();
  QCOMPARE(QString::fromStdString(radius.unit), QString("mm"));
  const float cap = *std::max_element(radius.values.begin(), radius.values.end());
  QVERIFY(cap > 40.0f && cap < 60.0f);  // the 40 x 30 mm demo part's diagonal
  for (std::size_t i = 0; i < radius.values.size(); ++i) {
    const double k = project().fields[0].values[i];
    const double expected = k < 0 ? std::min(1.0 / -k, static_cast<double>(cap)) : cap;
    QVERIFY2(std::abs(radius.values[i] - expected) <= 1e-4 * expected,
             qPrintable(QString("%1: %2 vs %3").arg(i).arg(radius.values[i]).arg(expected)));
  }
}

void WorkflowTest::clickSeedsAStreamlineThatIsDrawn() {
  auto* streamlines = panel<ddfcam::gui::StreamlinesPanel>();
  QVERIFY(streamlines != nullptr);
  streamlines->setSeedByClick(true);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  const long long drawnBefore = f_.window->partView().scene().overlayCellCount("paths");
  const std::size_t pathsBefore = project().paths.size();
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, view.rect().center());
  QVERIFY(f_.window->waitForJobs());  // the flow field is computed once, as a job
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(project().paths.size(), pathsBefore + 1);
  const auto& path = project().paths.back();
  QVERIFY(path.poses.size() > 20);
  // Drawn: one more poly-line in the path overlay.
  QCOMPARE(f_.window->partView().scene().overlayCellCount("paths"), drawnBefore + 1);
  // The contacts lie on the part (located on some face within a micrometre) and the line is
  // continuous (steps of about a raster spacing).
  const auto& ddf = *project().part;
  for (std::size_t i = 0; i < path.poses.size(); i += 7) {
    bool onSurface = false;
    for (int face = 0; face < ddf.faceCount() && !onSurface; ++face) {
      const auto at = ddfcam::ddf::locateOnFace(ddf, face, path.poses[i].contact);
      onSurface =
          at && at->bary.minCoeff() > -1e-9 && (at->point - path.poses[i].contact).norm() < 1e-3;
    }
    QVERIFY2(onSurface, qPrintable(QString("contact %1").arg(i)));
    if (i > 0) QVERIFY((path.poses[i].contact - path.poses[i - 1].contact).norm() < 0.5);
  }
  // A family along the transverse line through the same pick: several passes w apart.
  QVERIFY(streamlines->seedFamily());
  QVERIFY(f_.window->waitForJobs());
  QCOMPARE(project().paths.size(), pathsBefore + 2);
  QVERIFY(project().paths.back().passStarts.size() >= 5);
  // One undo removes the family again.
  f_.window->findChild<QAction*>("actionUndo")->trigger();
  QCOMPARE(project().paths.size(), pathsBefore + 1);
  streamlines->setSeedByClick(false);
  ddfcam::test::dumpFrame(view.renderImage(), "workbench_streamline");
}

DDFCAM_GUI_TEST_MAIN(WorkflowTest)
#include "workflow_test.moc"
