// SPDX-License-Identifier: MIT
// PartScene under Xvfb: overlays (add, hide, remove, drawn over the surface) and surface picking.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "part_scene_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <QSignalSpy>
#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

using ddfcam::gui::FieldStyle;
using ddfcam::gui::Layer;
using ddfcam::gui::PartScene;
using ddfcam::gui::VtkView;
using ddfcam::test::colourDistance;

class PartSceneOverlayTest : public ddfcam::test::PartSceneTestBase {
  Q_OBJECT

 private slots:
  void overlaysAddHideAndRemove();
  void overlayIsDrawnOverTheSurface();
  void pickFindsFaceAndPointOfASphere();
  void clickThenPickFindsTheClickedFace();
  void pickMissesBackgroundAndHiddenSurface();
};

void PartSceneOverlayTest::overlaysAddHideAndRemove() {
  showPlane(1'000'000);
  const std::vector<std::vector<Eigen::Vector3d>> paths = {
      {{0, 5, 0.3}, {20, 5, 0.3}, {40, 5, 0.3}}, {{0, 25, 0.3}, {40, 25, 0.3}}};
  scene_->setOverlay("tool path", ddfcam::gui::toPolylinePolyData(paths), {});
  scene_->setOverlay(
      "normals",
      ddfcam::gui::toGlyphPolyData({{10, 10, 0.25}, {30, 10, 0.25}}, {{0, 0, 1}, {0, 0, 1}}, 5.0),
      {});
  ddfcam::gui::OverlayStyle toolStyle;
  toolStyle.surface = true;
  toolStyle.opacity = 0.6;
  const auto tool = ddfcam::planning::makeCylinderTool({}).transformed(
      Eigen::Isometry3d(Eigen::Translation3d(20, 15, 5.5)));
  scene_->setOverlay("tool", ddfcam::gui::toSurfacePolyData(tool), toolStyle);
  QCOMPARE(scene_->overlayNames(), (std::vector<std::string>{"normals", "tool", "tool path"}));
  QCOMPARE(scene_->overlayCellCount("tool path"), 2LL);
  QCOMPARE(scene_->overlayCellCount("normals"), 6LL);
  QCOMPARE(scene_->overlayCellCount("tool"), static_cast<long long>(tool.triangles.size()));
  QVERIFY(scene_->isOverlayVisible("tool"));
  scene_->setOverlayVisible("tool", false);
  QVERIFY(!scene_->isOverlayVisible("tool"));
  // Replacing keeps the visibility; null data is an empty overlay.
  scene_->setOverlay("tool", nullptr, toolStyle);
  QVERIFY(!scene_->isOverlayVisible("tool"));
  QCOMPARE(scene_->overlayCellCount("tool"), 0LL);
  QVERIFY(scene_->removeOverlay("tool"));
  QVERIFY(!scene_->removeOverlay("tool"));
  QVERIFY(!scene_->hasOverlay("tool"));
  QVERIFY(scene_->hasOverlay("normals"));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, scene_->setOverlayVisible("tool", true));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, scene_->overlayCellCount("tool"));
  // Overlays survive new geometry; the scene's own layers are untouched by them.
  scene_->setGeometry(geometry_.scene);
  QCOMPARE(scene_->overlayNames().size(), std::size_t{2});
  QCOMPARE(scene_->cellCount(Layer::Surface), static_cast<long long>(geometry_.surfaceTriangles));
}

void PartSceneOverlayTest::overlayIsDrawnOverTheSurface() {
  showPlane(1'000'000);
  ddfcam::gui::OverlayStyle red;
  red.rgb = {1.0, 0.0, 0.0};
  red.lineWidth = 5.0;
  // Lying in the surface (z = 0.25): the coincident-topology offset must keep it on top.
  scene_->setOverlay("line", ddfcam::gui::toPolylinePolyData({{{0, 15, 0.25}, {40, 15, 0.25}}}),
                     red);
  const Eigen::Vector3d onLine(13.0, 15.0, 0.25);
  QImage image = view_->renderImage();
  ddfcam::test::dumpFrame(image, "part_scene_overlay_line");
  QVERIFY(colourDistance(pixelAt(image, onLine), red.rgb) <= 8);
  scene_->setOverlayVisible("line", false);
  image = view_->renderImage();
  QVERIFY(colourDistance(pixelAt(image, onLine), red.rgb) > 60);
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void PartSceneOverlayTest::pickFindsFaceAndPointOfASphere() {
  ddfcam::ddf::SphereParams sphere;
  sphere.subdivisions = 1;
  sphere.m = 9;
  part_ = ddfcam::ddf::spherePart(sphere);
  geometry_ = ddfcam::gui::buildPartGeometry(part_.ddf, {});
  QVERIFY(!geometry_.adaptiveSurface);
  scene_->setGeometry(geometry_.scene);
  view_->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  const Eigen::Vector3d towardsCamera = Eigen::Vector3d(1, -1, 1).normalized();
  int tested = 0;
  for (int f = 0; f < part_.ddf.faceCount(); ++f) {
    // Interior raster point (i, j, k) = (2, 3, 3): on face f only, a vertex of the display mesh.
    const Eigen::Vector3d q = part_.ddf.surfacePoint(f, 2, 3);
    if (q.normalized().dot(towardsCamera) < 0.5) continue;  // hidden or grazing
    const auto pick = scene_->pickSurface(*view_, view_->widgetPosition(q));
    QVERIFY2(pick.has_value(), qPrintable(QString("face %1").arg(f)));
    QCOMPARE(pick->face, f);
    QCOMPARE(pick->face, geometry_.surfaceTriangleFace[pick->cell]);
    QVERIFY2((pick->position - q).norm() < 1e-3,
             qPrintable(QString("face %1: %2 mm off").arg(f).arg((pick->position - q).norm())));
    ++tested;
  }
  QVERIFY2(tested >= 10, qPrintable(QString::number(tested)));
  // A scene asked with another view's coordinates is a programming error.
  VtkView other;
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, scene_->pickSurface(other, QPointF(10, 10)));
}

void PartSceneOverlayTest::clickThenPickFindsTheClickedFace() {
  ddfcam::ddf::SphereParams sphere;
  sphere.subdivisions = 1;
  sphere.m = 9;
  part_ = ddfcam::ddf::spherePart(sphere);
  geometry_ = ddfcam::gui::buildPartGeometry(part_.ddf, {});
  scene_->setGeometry(geometry_.scene);
  view_->viewFrom(ddfcam::gui::ViewDirection::PlusY);
  // The face whose centre looks most directly at the camera (+y).
  int best = 0;
  for (int f = 1; f < part_.ddf.faceCount(); ++f)
    if (part_.ddf.surfacePoint(f, 3, 3).y() > part_.ddf.surfacePoint(best, 3, 3).y()) best = f;
  const Eigen::Vector3d q = part_.ddf.surfacePoint(best, 3, 3);
  QSignalSpy spy(view_.get(), &VtkView::clicked);
  QTest::mouseClick(view_.get(), Qt::LeftButton, Qt::NoModifier,
                    view_->widgetPosition(q).toPoint());
  QCOMPARE(spy.count(), 1);
  const auto pick = scene_->pickSurface(*view_, spy.at(0).at(0).toPointF());
  QVERIFY(pick.has_value());
  QCOMPARE(pick->face, best);
  // Whole logical pixels: the hit is within a pixel's width (~0.1 mm here) of the target.
  QVERIFY2((pick->position - q).norm() < 0.2,
           qPrintable(QString::number((pick->position - q).norm())));
}

void PartSceneOverlayTest::pickMissesBackgroundAndHiddenSurface() {
  showPlane(1'000'000);
  QVERIFY(!scene_->pickSurface(*view_, QPointF(1, 1)).has_value());
  const QPointF centre = view_->widgetPosition({20, 15, 0.25});
  const auto hit = scene_->pickSurface(*view_, centre);
  QVERIFY(hit.has_value());
  QVERIFY((hit->position - Eigen::Vector3d(20, 15, 0.25)).norm() < 1e-3);
  // Overlays do not block the surface.
  scene_->setOverlay(
      "box",
      ddfcam::gui::toSurfacePolyData(ddfcam::planning::makeCylinderTool({}).transformed(
          Eigen::Isometry3d(Eigen::Translation3d(20, 15, 6)))),
      {});
  QVERIFY(scene_->pickSurface(*view_, centre).has_value());
  // A field replaces the surface polydata by a coloured copy: picks still find cells and faces.
  scene_->setSurfaceField(
      std::vector<float>(static_cast<std::size_t>(scene_->surfaceVertexCount()), 1.0f),
      FieldStyle{});
  const auto coloured = scene_->pickSurface(*view_, centre);
  QVERIFY(coloured.has_value());
  QCOMPARE(coloured->face, hit->face);
  QCOMPARE(coloured->cell, hit->cell);
  scene_->setVisible(Layer::Surface, false);
  QVERIFY(!scene_->pickSurface(*view_, centre).has_value());
}

DDFCAM_GUI_TEST_MAIN(PartSceneOverlayTest)
#include "part_scene_overlay_test.moc"
