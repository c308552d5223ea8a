// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: tracer choice (RK4, raster walk, continuous) on the cylinder,
// direction strokes stored in a region plan, and Escape cancelling a brush stroke
// (scallop-tolerance coverage: streamlines_panel_scallop_test.cpp).
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/flow_field_display.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/model/project.h>

#include <QComboBox>
#include <QDockWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using ddfcam::ddf::Vec3;
using ddfcam::gui::GlyphField;
using ddfcam::gui::RegionEditMode;
using ddfcam::gui::SegmentationPanel;
using ddfcam::gui::StreamlinesPanel;
using ddfcam::planning::FlowFieldSource;
using ddfcam::planning::StreamlineMethod;

namespace {

constexpr double kRadius = 10.0;  // cylinder radius, mm
constexpr double kLength = 30.0;  // cylinder length along z, mm

ddfcam::planning::Project cylinderProject() {
  ddfcam::planning::Project project;
  project.partName = "cylinder";
  project.part =
      ddfcam::ddf::cylinderPart(
          {.radiusMm = kRadius, .lengthMm = kLength, .segments = 48, .rings = 12, .m = 9})
          .ddf;
  return project;
}

// The faces of the cylinder whose centre lies at x > 0.
ddfcam::planning::Region frontHalf(const ddfcam::ddf::DisplacementField& ddf) {
  ddfcam::planning::Region half;
  half.name = "front half";
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (ddf.surfacePoint(f, n / 3, n / 3).x() > 0) half.faces.push_back(f);
  return half;
}

std::vector<Vec3> contacts(const ddfcam::planning::ToolPath& path) {
  std::vector<Vec3> out;
  for (const auto& pose : path.poses) out.push_back(pose.contact);
  return out;
}

double angleOf(const Vec3& p) {
  return std::atan2(p.y(), p.x());
}

}  // namespace

class StreamlinesPanelMethodsTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void eachMethodTracesCirclesAndRulings();
  void familyUsesTheChosenMethod();
  void regionStrokesLiveInThePlanAndUndo();
  void regionPlanStrokesDriveTheField();
  void escapeCancelsABrushStroke();

 private:
  StreamlinesPanel& panel() { return *f_.window->findChild<StreamlinesPanel*>(); }
  SegmentationPanel& segmentation() { return *f_.window->findChild<SegmentationPanel*>(); }
  QUndoStack& undo() { return *f_.window->document().undoStack(); }
  ddfcam::gui::PartScene& scene() { return f_.window->partView().scene(); }
};

void StreamlinesPanelMethodsTest::initTestCase() {
  QVERIFY(openWorkbench(false));
}

void StreamlinesPanelMethodsTest::init() {
  f_.script.errors.clear();
  segmentation().setEditMode(RegionEditMode::None);
  panel().setRegion(-1);
  panel().setFieldSource(FlowFieldSource::MaxCurvatureDirection);
  panel().setFieldSmoothing(false);
  panel().setStreamlineMethod(StreamlineMethod::Rk4);
}

// A click seed traced by each method: every contact lies on the cylinder, the k_max line is
// the circle z = z(seed) and the k_min line the ruling at the seed's angle (exact truth).
void StreamlinesPanelMethodsTest::eachMethodTracesCirclesAndRulings() {
  load(cylinderProject());
  ddfcam::ddf::SurfaceLocation seed;
  seed.face = 0;
  seed.bary = Vec3(0.31, 0.33, 0.36);
  const Vec3 seedPoint = project().part->pointAt(0, seed.bary, 0.0);
  struct Case {
    StreamlineMethod method;
    double circleTolMm;  // largest |z - z(seed)| on the k_max line
    double rulingTolMm;  // largest R |angle - angle(seed)| on the k_min line
  };
  // The raster walk moves on raster points: it stays within about half a raster spacing
  // across the line (along z: 30 mm / 12 rings / 8; around: the 48-gon edge / 8).
  const double acrossCircle = kLength / 12 / 8,
               acrossRuling = 2 * kRadius * std::sin(std::numbers::pi / 48) / 8;
  const Case cases[] = {{StreamlineMethod::Rk4, 0.02, 0.02},
                        {StreamlineMethod::RasterWalk, 0.55 * acrossCircle, 0.55 * acrossRuling},
                        {StreamlineMethod::Continuous, 0.02, 0.02}};
  std::vector<std::vector<Vec3>> circles;
  for (const Case& c : cases) {
    panel().setStreamlineMethod(c.method);
    QCOMPARE(panel().streamlineMethod(), c.method);
    for (const FlowFieldSource source :
         {FlowFieldSource::MaxCurvatureDirection, FlowFieldSource::MinCurvatureDirection}) {
      panel().setFieldSource(source);
      const int undoBefore = undo().count();
      QVERIFY(panel().seedAt(seed));
      waitOk();
      QCOMPARE(undo().count(), undoBefore + 1);
      const std::vector<Vec3> line = contacts(project().paths.back());
      QVERIFY(line.size() > 20);
      double offSurface = 0.0, offTruth = 0.0, extent = 0.0;
      for (const Vec3& p : line) {
        offSurface = std::max(offSurface, std::abs(std::hypot(p.x(), p.y()) - kRadius));
        if (source == FlowFieldSource::MaxCurvatureDirection) {
          offTruth = std::max(offTruth, std::abs(p.z() - seedPoint.z()));
        } else {
          const double d = std::remainder(angleOf(p) - angleOf(seedPoint), 2.0 * std::numbers::pi);
          offTruth = std::max(offTruth, kRadius * std::abs(d));
          extent = std::max(extent, std::abs(p.z() - line.front().z()));
        }
      }
      const QString what =
          QString("%1 %2: off surface %3 mm, off truth %4 mm")
              .arg(ddfcam::planning::streamlineMethodName(c.method))
              .arg(source == FlowFieldSource::MaxCurvatureDirection ? "circle" : "ruling")
              .arg(offSurface)
              .arg(offTruth);
      qInfo("%s", qPrintable(what));
      QVERIFY2(offSurface < 2e-3, qPrintable(what));
      const double tol =
          source == FlowFieldSource::MaxCurvatureDirection ? c.circleTolMm : c.rulingTolMm;
      QVERIFY2(offTruth < tol, qPrintable(what));
      if (source == FlowFieldSource::MinCurvatureDirection)
        QVERIFY2(extent > kLength - 0.5, qPrintable(QString::number(extent)));  // end to end
      else
        circles.push_back(line);
    }
  }
  // The methods really differ: the raster walk's points are not RK4's.
  QVERIFY(circles[0] != circles[1]);
  QVERIFY(circles[0] != circles[2]);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusX);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_methods_cylinder");
}

// A family seeded along the transverse line with the continuous and raster-walk methods:
// every line is a ruling.
void StreamlinesPanelMethodsTest::familyUsesTheChosenMethod() {
  load(cylinderProject());
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusX);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, view.rect().center());
  panel().setFieldSource(FlowFieldSource::MinCurvatureDirection);
  for (const StreamlineMethod method :
       {StreamlineMethod::Continuous, StreamlineMethod::RasterWalk}) {
    panel().setStreamlineMethod(method);
    QVERIFY(panel().seedFamily());
    waitOk();
    const auto& path = project().paths.back();
    QVERIFY(path.passStarts.size() >= 5);
    double worst = 0.0;
    for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
      const std::size_t end =
          s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : path.poses.size();
      const double a0 = angleOf(path.poses[path.passStarts[s]].contact);
      for (std::size_t i = path.passStarts[s]; i < end; ++i) {
        const Vec3& p = path.poses[i].contact;
        QVERIFY(std::abs(std::hypot(p.x(), p.y()) - kRadius) < 2e-3);
        worst = std::max(
            worst, kRadius * std::abs(std::remainder(angleOf(p) - a0, 2.0 * std::numbers::pi)));
      }
    }
    qInfo("%s family: %d rulings, worst %g mm off", ddfcam::planning::streamlineMethodName(method),
          int(path.passStarts.size()), worst);
    const double acrossRuling =
        2 * kRadius * std::sin(std::numbers::pi / 48) / 8;  // raster spacing
    QVERIFY2(worst < (method == StreamlineMethod::RasterWalk ? 0.55 * acrossRuling : 0.02),
             qPrintable(QString::number(worst)));
  }
  ddfcam::test::dumpFrame(view.renderImage(), "streamlines_methods_family");
}

// With a region chosen, each drawn stroke and "clear" is one SetRegionsCommand on its plan.
void StreamlinesPanelMethodsTest::regionStrokesLiveInThePlanAndUndo() {
  auto cylinder = cylinderProject();
  cylinder.regions.push_back(frontHalf(*cylinder.part));
  load(std::move(cylinder));
  panel().setRegion(0);
  QCOMPARE(project().regions[0].plan.flowSource, FlowFieldSource::MaxCurvatureDirection);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusX);
  const int undoBefore = undo().count();
  panel().setDrawDirection(true);
  const QPoint centre = view.rect().center();
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(0, -60));
  for (int dy = -50; dy <= 60; dy += 10) QTest::mouseMove(&view, centre + QPoint(0, dy));
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(0, 60));
  panel().setDrawDirection(false);
  waitOk();
  QCOMPARE(undo().count(), undoBefore + 1);
  const auto& plan = project().regions[0].plan;
  QCOMPARE(plan.strokes.size(), std::size_t{1});
  QCOMPARE(plan.flowSource, FlowFieldSource::UserStrokes);
  QVERIFY(plan.strokes[0].size() >= 5);
  for (const Vec3& p : plan.strokes[0])
    QVERIFY(std::abs(std::hypot(p.x(), p.y()) - kRadius) < 1e-2);
  QCOMPARE(&panel().strokes(), &plan.strokes);
  QCOMPARE(scene().overlayCellCount(StreamlinesPanel::kStrokeOverlay), 1LL);
  // The Segmentation panel's plan editor shows the region's strokes as its flow source.
  segmentation().selectRegions({0});
  auto* source = segmentation().findChild<QComboBox*>("regionFlowSource");
  QVERIFY(source);
  QCOMPARE(source->currentIndex(), static_cast<int>(FlowFieldSource::UserStrokes));
  QCOMPARE(source->currentText(), QString("drawn strokes (1)"));
  // A second stroke (a circle arc), then clear: one step each.
  panel().addStroke(
      {Vec3(kRadius, 0, 5), Vec3(kRadius * std::cos(0.2), kRadius * std::sin(0.2), 5)});
  QCOMPARE(project().regions[0].plan.strokes.size(), std::size_t{2});
  QCOMPARE(scene().overlayCellCount(StreamlinesPanel::kStrokeOverlay), 2LL);
  panel().clearStrokes();
  QVERIFY(project().regions[0].plan.strokes.empty());
  QVERIFY(!scene().hasOverlay(StreamlinesPanel::kStrokeOverlay));
  QCOMPARE(undo().count(), undoBefore + 3);
  ddfcam::test::dumpFrame(view.renderImage(), "streamlines_region_strokes_cleared");
  undo().undo();
  QCOMPARE(project().regions[0].plan.strokes.size(), std::size_t{2});
  QCOMPARE(scene().overlayCellCount(StreamlinesPanel::kStrokeOverlay), 2LL);
  ddfcam::test::dumpFrame(view.renderImage(), "streamlines_region_strokes");
  undo().undo();
  undo().undo();
  QVERIFY(project().regions[0].plan.strokes.empty());
  QCOMPARE(project().regions[0].plan.flowSource, FlowFieldSource::MaxCurvatureDirection);
  QCOMPARE(undo().count() - undo().index(), 3);  // three steps to redo
  // The whole part's strokes stay the panel's own.
  panel().setRegion(-1);
  panel().addStroke({Vec3(kRadius, 0, 0), Vec3(kRadius, 0, 3)});
  QCOMPARE(panel().strokes().size(), std::size_t{1});
  QVERIFY(project().regions[0].plan.strokes.empty());
  panel().clearStrokes();
}

// A region whose plan has UserStrokes along z: the panel's field follows the plan's strokes
// (the default k_max field would run along the circles).
void StreamlinesPanelMethodsTest::regionPlanStrokesDriveTheField() {
  auto cylinder = cylinderProject();
  auto region = frontHalf(*cylinder.part);
  region.plan.flowSource = FlowFieldSource::UserStrokes;
  region.plan.smoothField = false;
  std::vector<Vec3> stroke;
  for (double z = -10.0; z <= 10.0; z += 1.0) stroke.emplace_back(kRadius, 0.0, z);
  region.plan.strokes = {stroke};
  cylinder.regions.push_back(region);
  load(std::move(cylinder));
  panel().setRegion(0);
  QVERIFY(panel().showField());
  waitOk();
  const auto& glyphs = panel().fieldDisplay().glyphs(GlyphField::Flow);
  int near = 0;
  for (std::size_t g = 0; g < glyphs.centres.size(); ++g) {
    double distance = std::numeric_limits<double>::infinity();
    for (const Vec3& p : stroke) distance = std::min(distance, (glyphs.centres[g] - p).norm());
    if (distance > 1.5) continue;
    ++near;
    QVERIFY2(std::abs(glyphs.directions[g].z()) > 0.95,
             qPrintable(QString::number(glyphs.directions[g].z())));
  }
  QVERIFY(near >= 3);
  panel().fieldDisplay().setVisible(GlyphField::Flow, false);
}

// Escape during a brush stroke: no undo step, the regions and their colours as before. The
// brush circle follows the mouse with the brush radius.
void StreamlinesPanelMethodsTest::escapeCancelsABrushStroke() {
  auto cylinder = cylinderProject();
  cylinder.regions.push_back(frontHalf(*cylinder.part));
  load(std::move(cylinder));
  QVERIFY(raisePanel("segmentation"));
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusY);  // the region (x > 0) on the left
  view.renderImage();
  SegmentationPanel& seg = segmentation();
  seg.selectRegions({0});
  const double radius = 2.0;
  seg.setBrushRadiusMm(radius);
  seg.setEditMode(RegionEditMode::Brush);
  auto& tool = seg.viewTool();
  const auto before = project().regions;
  const long long colouredBefore = tool.colouredCellCount();
  const int undoBefore = undo().count();
  // Hover: the circle lies on the surface point under the mouse, radius as set.
  const QPoint right = view.rect().center() + QPoint(view.width() / 6, 0);
  QTest::mouseMove(&view, right);
  QVERIFY(tool.brushCursorCentre().has_value());
  const auto hit = scene().pickSurface(view, right);
  QVERIFY(hit.has_value());
  // (Within a pixel or two: under a device pixel ratio the event position is rounded.)
  QVERIFY2((*tool.brushCursorCentre() - hit->position).norm() < 0.2,
           qPrintable(QString("%1 %2 %3 vs %4 %5 %6")
                          .arg(tool.brushCursorCentre()->x())
                          .arg(tool.brushCursorCentre()->y())
                          .arg(tool.brushCursorCentre()->z())
                          .arg(hit->position.x())
                          .arg(hit->position.y())
                          .arg(hit->position.z())));
  vtkPolyData* ring = scene().overlayData(ddfcam::gui::RegionViewTool::kBrushCursorOverlay);
  QVERIFY(ring && ring->GetNumberOfPoints() > 16);
  for (vtkIdType i = 0; i < ring->GetNumberOfPoints(); ++i) {
    double p[3];
    ring->GetPoint(i, p);
    QVERIFY(std::abs((Vec3(p[0], p[1], p[2]) - *tool.brushCursorCentre()).norm() - radius) < 1e-9);
  }
  ddfcam::test::dumpFrame(view.renderImage(), "segmentation_brush_cursor");
  // A stroke over the part outside the region, cancelled by Escape before the release.
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, right);
  for (int dy = 10; dy <= 60; dy += 10) QTest::mouseMove(&view, right + QPoint(0, dy));
  QVERIFY(tool.colouredCellCount() > colouredBefore);  // the preview shows painted faces
  ddfcam::test::dumpFrame(view.renderImage(), "segmentation_brush_preview");
  QTest::keyClick(&view, Qt::Key_Escape);
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, right + QPoint(0, 60));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(undo().count(), undoBefore);
  QVERIFY(project().regions == before);
  QCOMPARE(tool.colouredCellCount(), colouredBefore);
  ddfcam::test::dumpFrame(view.renderImage(), "segmentation_brush_cancelled");
  // The same stroke without Escape paints (the cancel was what kept the regions).
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, right);
  for (int dy = 10; dy <= 60; dy += 10) QTest::mouseMove(&view, right + QPoint(0, dy));
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, right + QPoint(0, 60));
  QCOMPARE(undo().count(), undoBefore + 1);
  QVERIFY(project().regions != before);
  seg.setEditMode(RegionEditMode::None);
  QVERIFY(!tool.brushCursorCentre().has_value());
  QVERIFY(!scene().hasOverlay(ddfcam::gui::RegionViewTool::kBrushCursorOverlay));
}

DDFCAM_GUI_TEST_MAIN(StreamlinesPanelMethodsTest)
#include "streamlines_panel_methods_test.moc"
