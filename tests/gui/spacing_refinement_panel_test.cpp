// SPDX-License-Identifier: MIT
// The Path spacing panel under Xvfb: a ball on a plane patch refined to a scallop tolerance;
// the paths meet the tolerance (measured on the produced heights against the plane), their
// count is near the iso-scallop count, iterations are listed and drawn, Apply adds the path
// and the error map as one undo step.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/panels/spacing_refinement_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>

#include <QDockWidget>
#include <QListWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <cmath>

using ddfcam::gui::SpacingRefinementPanel;

namespace {

constexpr double kPlaneZ = 0.25;     // plane height above the support, mm
constexpr double kWidthY = 8.0;      // extent across the feed (x), mm
constexpr double kRadius = 5.0;      // ball radius, mm
constexpr double kTolerance = 0.05;  // scallop tolerance, mm

// Largest height of the produced surface above the plane over the part's interior rows
// (the produced DDF is a z-map: vectors (0, 0, 1) mm).
double maxMaterialLeft(const ddfcam::ddf::DisplacementField& produced) {
  double worst = -1.0;
  for (int f = 0; f < produced.faceCount(); ++f)
    for (int k = 0; k < produced.resolution(); ++k)
      for (int i = 0; i + k < produced.resolution(); ++i)
        worst = std::max(worst, produced.surfacePoint(f, i, k).z() - kPlaneZ);
  return worst;
}

}  // namespace

class SpacingRefinementPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void refinementMeetsTheToleranceNearTheIsoScallopCount();
  void iterationsAreListedAndDrawn();
  void applyAddsPathAndErrorMapInOneUndoStep();

 private:
  SpacingRefinementPanel* panel() { return f_.window->findChild<SpacingRefinementPanel*>(); }
  QUndoStack& undo() const { return *f_.window->document().undoStack(); }
};

void SpacingRefinementPanelTest::initTestCase() {
  QVERIFY(openWorkbench(false));
  QVERIFY(panel() != nullptr);
  ddfcam::ddf::PlanePatchParams plane;
  plane.size = {10.0, kWidthY};
  plane.cellsX = 10;
  plane.cellsY = 8;
  plane.m = 9;  // raster spacing 0.125 mm, a tenth of the expected path spacing
  plane.planeZMm = kPlaneZ;
  ddfcam::planning::Project p;
  p.partName = "plane";
  p.part = ddfcam::ddf::planePatch(plane).ddf;
  p.tools.push_back({.name = "ball R5", .kind = ddfcam::planning::ToolKind::Sphere,
                     .radiusMm = kRadius, .segments = 96});
  load(std::move(p));
  if (auto* dock = f_.window->findChild<QDockWidget*>("panel_spacingRefinement")) dock->raise();
  panel()->setTool(0);
  panel()->setRegion(-1);
  panel()->setFieldSource(ddfcam::planning::FlowFieldSource::FixedDirection);
  panel()->setTolerance(kTolerance);
  QVERIFY(panel()->refine());
  waitOk();
  QVERIFY(panel()->result() != nullptr);
}

void SpacingRefinementPanelTest::refinementMeetsTheToleranceNearTheIsoScallopCount() {
  const auto& r = *panel()->result();
  QVERIFY(r.converged);
  QVERIFY(r.maxErrorMm <= kTolerance);
  // Measured on the produced heights themselves: the plane z = kPlaneZ is the goal.
  const double left = maxMaterialLeft(r.produced);
  QVERIFY2(left <= kTolerance + 1e-4, qPrintable(QString::number(left)));
  // Iso-scallop spacing of a ball on a plane: w = 2 sqrt(2 R h - h^2).
  const double w = 2.0 * std::sqrt(2.0 * kRadius * kTolerance - kTolerance * kTolerance);
  const double analytic = std::ceil(kWidthY / w);
  const double count = static_cast<double>(r.paths.size());
  qInfo("paths %.0f, analytic %.0f, max error %.4f mm", count, analytic, r.maxErrorMm);
  QVERIFY(std::abs(count - analytic) <= std::max(1.0, 0.1 * analytic));
}

void SpacingRefinementPanelTest::iterationsAreListedAndDrawn() {
  const auto& r = *panel()->result();
  auto* list = f_.window->findChild<QListWidget*>("refinementIterationList");
  QVERIFY(list != nullptr);
  QCOMPARE(list->count(), static_cast<int>(r.iterations.size()));
  QVERIFY(panel()->showIteration(0));
  auto& scene = f_.window->partView().scene();
  QVERIFY(scene.hasOverlay(SpacingRefinementPanel::kIterationOverlay));
  QCOMPARE(scene.overlayCellCount(SpacingRefinementPanel::kIterationOverlay),
           static_cast<long long>(r.iterations.front().paths.size()));
  QVERIFY(f_.window->plots().findPlot(SpacingRefinementPanel::kConvergenceTab) != nullptr);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  ddfcam::test::dumpFrame(view.renderImage(), "refinement_iteration");
}

void SpacingRefinementPanelTest::applyAddsPathAndErrorMapInOneUndoStep() {
  const std::size_t paths = project().paths.size(), fields = project().fields.size();
  const int steps = undo().count();
  QVERIFY(panel()->apply());
  QCOMPARE(undo().count(), steps + 1);
  QCOMPARE(project().paths.size(), paths + 1);
  QCOMPARE(project().fields.size(), fields + 1);
  QCOMPARE(project().paths.back().passStarts.size(), panel()->result()->paths.size());
  QCOMPARE(f_.window->partView().fieldDisplay().field,
           std::string(SpacingRefinementPanel::kErrorField));
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "refinement_error_map");
  undo().undo();
  QCOMPARE(project().paths.size(), paths);
  QCOMPARE(project().fields.size(), fields);
}

DDFCAM_GUI_TEST_MAIN(SpacingRefinementPanelTest)
#include "spacing_refinement_panel_test.moc"
