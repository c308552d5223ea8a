// SPDX-License-Identifier: MIT
// The Segmentation panel under Xvfb: automatic segmentation of z = sin x sin y, region list
// edits with undo/redo, a brush stroke and a lasso driven by mouse events, plan edits.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/region_commands.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/analysis/region_editing.h>
#include <ddfcam/planning/model/project.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QPolygonF>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include <cmath>
#include <numbers>
#include <set>

using ddfcam::gui::RegionEditMode;
using ddfcam::gui::SegmentationPanel;
using ddfcam::planning::Region;

namespace {

constexpr double kPi = std::numbers::pi;

// Mean of the face's raster surface points (computed here, not by the code under test).
Eigen::Vector3d centroid(const ddfcam::ddf::DisplacementField& ddf, int f) {
  const int n = ddf.raster().steps();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) sum += ddf.surfacePoint(f, i, k);
  return sum / static_cast<double>(ddf.pointsPerFace());
}

int faceNear(const ddfcam::ddf::DisplacementField& ddf, double x, double y) {
  int best = 0;
  double bestDistance = 1e300;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Eigen::Vector3d c = centroid(ddf, f);
    const double d = std::hypot(c.x() - x, c.y() - y);
    if (d < bestDistance) bestDistance = d, best = f;
  }
  return best;
}

}  // namespace

class SegmentationPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void automaticSegmentationFindsBumpsPitsAndSaddles();
  void listEditsUndoBitIdentical();
  void brushStrokePaintsFacesUnderTheMouse();
  void lassoAssignsFacesProjectedInside();
  void planEditsAreUndoable();
  void showingAFieldHidesTheRegionColours();

 private:
  QUndoStack& undo() const { return *f_.window->document().undoStack(); }
  SegmentationPanel* panel() { return f_.window->findChild<SegmentationPanel*>(); }
  /// Loads the sin x sin y patch and segments it by curvature type.
  void segmentSinSin();
  QPointF toWidget(const Eigen::Vector3d& world);
};

void SegmentationPanelTest::initTestCase() {
  QVERIFY(openWorkbench(false));
  QVERIFY(panel() != nullptr);
}

void SegmentationPanelTest::init() {
  f_.script.errors.clear();
  segmentSinSin();
}

void SegmentationPanelTest::segmentSinSin() {
  ddfcam::ddf::SinSinParams params;
  params.grid.cellsX = params.grid.cellsY = 12;
  params.grid.m = 9;
  ddfcam::planning::Project p;
  p.partName = "sin x sin y";
  p.part = ddfcam::ddf::sinSinPatch(params).ddf;
  p.tools.push_back(ddfcam::planning::Tool{});
  f_.window->document().reset(std::move(p));
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  view.renderImage();
  panel()->setEditMode(RegionEditMode::None);
  panel()->setSegmentationOptions(ddfcam::gui::SegmentationMethod::CurvatureType, 1e-3, {}, 4);
  QVERIFY(panel()->segment());
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
}

void SegmentationPanelTest::automaticSegmentationFindsBumpsPitsAndSaddles() {
  const auto& regions = project().regions;
  QVERIFY(regions.size() >= 3);
  QCOMPARE(undo().count(), 1);  // the segmentation is one undoable edit
  // A partition of the faces.
  const auto& ddf = *project().part;
  const std::vector<int> index = ddfcam::planning::faceRegionIndex(regions, ddf.faceCount());
  QVERIFY(std::count(index.begin(), index.end(), -1) == 0);
  // Seen from +z (the tool side): bumps at (pi/2, pi/2) and (-pi/2, -pi/2) are convex, pits at
  // (pi/2, -pi/2) and (-pi/2, pi/2) concave, the origin is a saddle (k = +-1).
  const auto kindAt = [&](double x, double y) {
    const std::string& name = regions[index[faceNear(ddf, x, y)]].name;
    return QString::fromStdString(name.substr(0, name.find(' ')));
  };
  QCOMPARE(kindAt(kPi / 2, kPi / 2), QString("convex"));
  QCOMPARE(kindAt(-kPi / 2, -kPi / 2), QString("convex"));
  QCOMPARE(kindAt(kPi / 2, -kPi / 2), QString("concave"));
  QCOMPARE(kindAt(-kPi / 2, kPi / 2), QString("concave"));
  QCOMPARE(kindAt(0.0, 0.0), QString("saddle"));
  // The view shows the regions: colours differ from the plain surface over most of the part.
  auto& view = *f_.window->view();
  const QImage coloured = view.renderImage();
  panel()->viewTool().setColoursVisible(false);
  const QImage plain = view.renderImage();
  panel()->viewTool().setColoursVisible(true);
  QVERIFY(panel()->viewTool().colouredCellCount() > 0);
  ddfcam::test::dumpFrame(coloured, "segmentation_regions");
  ddfcam::test::dumpFrame(plain, "segmentation_plain");
  QVERIFY(ddfcam::test::changedFraction(coloured, plain) > 0.2);
  if (auto* dock = f_.window->findChild<QDockWidget*>("panel_segmentation")) dock->raise();
  QApplication::processEvents();
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "segmentation_window");
}

void SegmentationPanelTest::listEditsUndoBitIdentical() {
  SegmentationPanel& p = *panel();
  const std::vector<Region> start = project().regions;
  const auto roundTrip = [&](std::vector<Region> before, std::vector<Region> after) {  // copies
    QAction* undoAction = f_.window->findChild<QAction*>("actionUndo");
    QAction* redoAction = f_.window->findChild<QAction*>("actionRedo");
    undoAction->trigger();
    QVERIFY(project().regions == before);
    redoAction->trigger();
    QVERIFY(project().regions == after);
  };
  // Rename.
  const int countBefore = undo().count();
  QVERIFY(p.renameRegion(1, "fillet"));
  QCOMPARE(QString::fromStdString(project().regions[1].name), QString("fillet"));
  QCOMPARE(undo().count(), countBefore + 1);
  roundTrip(start, project().regions);
  // Rename by editing the list item, as a person would.
  auto* list = p.findChild<QTreeWidget*>("regionList");
  QVERIFY(list != nullptr);
  QCOMPARE(list->topLevelItemCount(), static_cast<int>(project().regions.size()));
  list->topLevelItem(0)->setText(0, "edited");
  QCOMPARE(QString::fromStdString(project().regions[0].name), QString("edited"));
  QCOMPARE(undo().count(), countBefore + 2);
  // Merge regions 0 and 2: the union of their faces under region 0's name.
  std::vector<Region> before = project().regions;
  p.selectRegions({0, 2});
  QVERIFY(p.mergeSelected());
  QCOMPARE(project().regions.size(), before.size() - 1);
  std::set<int> expected(before[0].faces.begin(), before[0].faces.end());
  expected.insert(before[2].faces.begin(), before[2].faces.end());
  QVERIFY(std::set<int>(project().regions[0].faces.begin(), project().regions[0].faces.end()) ==
          expected);
  QCOMPARE(project().regions[0].name, before[0].name);
  roundTrip(before, project().regions);
  // Split: a region of two opposite corner faces falls into its two faces.
  const int F = project().part->faceCount();
  {
    auto& document = f_.window->document();
    document.push(std::make_unique<ddfcam::gui::SetRegionsCommand>(
        document, "corners",
        ddfcam::planning::assignFaces(project().regions, static_cast<int>(project().regions.size()),
                                      std::vector<int>{0, F - 1}, F, "two corners")));
  }
  before = project().regions;
  const int corners = static_cast<int>(before.size()) - 1;
  p.selectRegions({corners});
  QVERIFY(p.splitSelected());
  QCOMPARE(static_cast<int>(project().regions.size()), corners + 2);
  QCOMPARE(project().regions[corners].faces, std::vector<int>{0});
  QCOMPARE(project().regions[corners + 1].faces, std::vector<int>{F - 1});
  QCOMPARE(project().regions[corners + 1].name, std::string("two corners (2)"));
  QVERIFY(project().regions[corners + 1].color != project().regions[corners].color);
  roundTrip(before, project().regions);
  // Delete.
  before = project().regions;
  p.selectRegions({1});
  QVERIFY(p.deleteSelected());
  QCOMPARE(project().regions.size(), before.size() - 1);
  QVERIFY(project().regions[0] == before[0]);
  roundTrip(before, project().regions);
  // All the way back to the segmentation, then forward again.
  const std::vector<Region> end = project().regions;
  while (undo().index() > 1) undo().undo();
  QVERIFY(project().regions == start);
  while (undo().canRedo()) undo().redo();
  QVERIFY(project().regions == end);
}

void SegmentationPanelTest::brushStrokePaintsFacesUnderTheMouse() {
  auto& view = *f_.window->view();
  SegmentationPanel& p = *panel();
  p.selectRegions({0});
  p.setBrushRadiusMm(0.4);
  p.setEditMode(RegionEditMode::Brush);
  const std::vector<Region> before = project().regions;
  const int countBefore = undo().count();
  double cameraBefore[3];
  view.renderer()->GetActiveCamera()->GetPosition(cameraBefore);
  const QPoint c = view.rect().center();
  const std::vector<QPoint> stroke = {c + QPoint(-60, 10), c + QPoint(-30, 15), c + QPoint(0, 20),
                                      c + QPoint(30, 25)};
  // The oracle: the core's brush query at every picked point of the stroke.
  std::set<int> expected;
  for (const QPoint& pos : stroke) {
    const auto hit = f_.window->partView().scene().pickSurface(view, pos);
    QVERIFY(hit.has_value());
    for (int face : ddfcam::planning::facesWithinDistance(*project().part, hit->position, 0.4))
      expected.insert(face);
  }
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, stroke[0]);
  for (std::size_t i = 1; i < stroke.size(); ++i) QTest::mouseMove(&view, stroke[i]);
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, stroke.back());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(undo().count(), countBefore + 1);  // one stroke, one undo step
  const std::vector<int> want(expected.begin(), expected.end());
  QVERIFY(want.size() >= 5);
  QVERIFY(project().regions != before);  // the stroke crossed other regions
  QVERIFY(project().regions ==
          ddfcam::planning::assignFaces(before, 0, want, project().part->faceCount()));
  for (int face : want)
    QVERIFY(std::binary_search(project().regions[0].faces.begin(), project().regions[0].faces.end(),
                               face));
  double cameraAfter[3];
  view.renderer()->GetActiveCamera()->GetPosition(cameraAfter);
  QCOMPARE(cameraAfter[0], cameraBefore[0]);  // the drag painted, it did not rotate
  QCOMPARE(cameraAfter[1], cameraBefore[1]);
  ddfcam::test::dumpFrame(view.renderImage(), "segmentation_brush");
  undo().undo();
  QVERIFY(project().regions == before);
  p.setEditMode(RegionEditMode::None);
}

QPointF SegmentationPanelTest::toWidget(const Eigen::Vector3d& world) {
  auto& view = *f_.window->view();
  vtkRenderer* renderer = view.renderer();
  vtkMatrix4x4* m = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1, 1);
  double in[4] = {world.x(), world.y(), world.z(), 1.0}, out[4];
  m->MultiplyPoint(in, out);
  const int* size = view.renderWindow()->GetSize();
  const double* viewport = renderer->GetViewport();
  const double xd =
      (viewport[0] + (out[0] / out[3] + 1.0) / 2.0 * (viewport[2] - viewport[0])) * size[0];
  const double yd =
      (viewport[1] + (out[1] / out[3] + 1.0) / 2.0 * (viewport[3] - viewport[1])) * size[1];
  const double dpr = view.devicePixelRatioF();
  return {xd / dpr, (size[1] - yd) / dpr};
}

void SegmentationPanelTest::lassoAssignsFacesProjectedInside() {
  auto& view = *f_.window->view();
  SegmentationPanel& p = *panel();
  QVERIFY(p.addRegion());
  const int target = static_cast<int>(project().regions.size()) - 1;
  QCOMPARE(p.selectedRegions(), std::vector<int>{target});
  p.setEditMode(RegionEditMode::Lasso);
  const int countBefore = undo().count();
  const QPoint c = view.rect().center();
  const std::vector<QPoint> ring = {c + QPoint(-80, -60), c + QPoint(40, -90), c + QPoint(90, 0),
                                    c + QPoint(0, 20),    c + QPoint(20, 80),  c + QPoint(-90, 50)};
  QPolygonF polygon;
  for (const QPoint& q : ring) polygon << QPointF(q);
  std::vector<int> expected;
  const auto& ddf = *project().part;
  for (int f = 0; f < ddf.faceCount(); ++f)  // seen from +z every face of the graph faces up
    if (polygon.containsPoint(toWidget(centroid(ddf, f)), Qt::OddEvenFill)) expected.push_back(f);
  QVERIFY(expected.size() > 10);
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, ring[0]);
  for (std::size_t i = 1; i < ring.size(); ++i) {
    QTest::mouseMove(&view, ring[i]);
    if (i == 3) ddfcam::test::dumpFrame(view.renderImage(), "segmentation_lasso_outline");
  }
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, ring.back());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(undo().count(), countBefore + 1);
  QCOMPARE(project().regions[target].faces, expected);
  for (int r = 0; r < target; ++r)
    for (int face : project().regions[r].faces)
      QVERIFY(!std::binary_search(expected.begin(), expected.end(), face));
  ddfcam::test::dumpFrame(view.renderImage(), "segmentation_lasso");
  p.setEditMode(RegionEditMode::None);
}

void SegmentationPanelTest::planEditsAreUndoable() {
  SegmentationPanel& p = *panel();
  p.selectRegions({1});
  const std::vector<Region> before = project().regions;
  ddfcam::planning::RegionPlan plan = before[1].plan;
  plan.tool = 0;
  plan.spacingMode = ddfcam::planning::SpacingMode::ScallopTolerance;
  plan.scallopToleranceMm = 0.004;
  QVERIFY(p.setSelectedPlan(plan));
  QVERIFY(project().regions[1].plan == plan);
  QVERIFY(project().regions[0] == before[0]);
  // Through the editor's widgets: the feed direction combo is one more undo step.
  auto* feed = p.findChild<QComboBox*>("regionFeedSign");
  QVERIFY(feed != nullptr);
  const int countBefore = undo().count();
  feed->setCurrentIndex(1);
  QCOMPARE(undo().count(), countBefore + 1);
  QCOMPARE(project().regions[1].plan.feedSign, -1);
  QCOMPARE(project().regions[1].plan.scallopToleranceMm, 0.004);
  auto* source = p.findChild<QComboBox*>("regionFlowSource");
  source->setCurrentIndex(static_cast<int>(ddfcam::planning::FlowFieldSource::FixedDirection));
  QVERIFY(project().regions[1].plan.flowSource ==
          ddfcam::planning::FlowFieldSource::FixedDirection);
  undo().undo();
  undo().undo();
  QVERIFY(project().regions[1].plan == plan);
  QCOMPARE(feed->currentIndex(), 0);  // the editor follows the undo
  undo().undo();
  QVERIFY(project().regions == before);
}

DDFCAM_GUI_TEST_MAIN(SegmentationPanelTest)
// Region colours are drawn over the surface; a field the user picks must not stay hidden
// under them, and a new segmentation shows the regions again.
void SegmentationPanelTest::showingAFieldHidesTheRegionColours() {
  auto* colours = panel()->findChild<QCheckBox*>("showRegionColours");
  QVERIFY(colours != nullptr);
  QVERIFY(colours->isChecked());
  ddfcam::planning::Project p = project();
  const std::vector<float> heights = p.part->allHeights();
  p.fields.push_back({"height", "", true, heights, {}});
  f_.window->document().reset(std::move(p));
  f_.window->partView().showField("height");
  QVERIFY(!colours->isChecked());
  colours->setChecked(true);  // the user may bring them back over the same field
  f_.window->partView().setColourMap(ddfcam::gui::ColourMap::Viridis);
  QVERIFY(colours->isChecked());
  QVERIFY(panel()->segment());
  QVERIFY(f_.window->waitForJobs());
  QVERIFY(colours->isChecked());
}

#include "segmentation_panel_test.moc"
