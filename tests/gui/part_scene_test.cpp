// SPDX-License-Identifier: MIT
// PartScene under Xvfb: field colours on screen, the scalar bar and the demo part with a field.
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

using ddfcam::gui::ColourMap;
using ddfcam::gui::FieldStyle;
using ddfcam::gui::Layer;
using ddfcam::gui::PartScene;
using ddfcam::gui::VtkView;
using ddfcam::test::colourDistance;
using ddfcam::test::frameStats;
using ddfcam::test::rasterField;

class PartSceneTest : public ddfcam::test::PartSceneTestBase {
  Q_OBJECT

 private slots:
  void linearFieldShowsMapEndsAtPartEnds();
  void scalarBarShowsTitleAndRange();
  void fieldRejectsWrongSizesAndRanges();
  void scalarBarLayoutIsStableWithTranslucentProps();
  void demoPartWithFieldScreenshot();

 private:
  void addDemoOverlays();
};

void PartSceneTest::linearFieldShowsMapEndsAtPartEnds() {
  for (std::size_t budget : {std::size_t{1'000'000}, std::size_t{100}}) {
    showPlane(budget);
    QCOMPARE(geometry_.adaptiveSurface, budget == 100);
    const auto perPoint = rasterField(part_.ddf, [](const Eigen::Vector3d& q) { return q.x(); });
    const auto perVertex =
        ddfcam::ddf::valuesAtSamples(part_.ddf, perPoint, geometry_.surfaceSamples);
    for (ColourMap map : {ColourMap::Viridis, ColourMap::CoolWarm}) {
      scene_->setSurfaceField(perVertex, FieldStyle{map, 0.0, 40.0, "x [mm]"});
      QVERIFY(scene_->isFieldShown());
      // Unlit, full diffuse: the pixel is the map colour itself.
      vtkProperty* property = scene_->actor(Layer::Surface)->GetProperty();
      property->LightingOff();
      property->SetAmbient(0.0);
      property->SetDiffuse(1.0);
      const QImage image = view_->renderImage();
      ddfcam::test::dumpFrame(
          image, QString("part_scene_plane_x_%1_%2").arg(static_cast<int>(map)).arg(budget));
      for (double x : {2.0, 11.0, 20.0, 29.0, 38.0}) {
        const QRgb pixel = pixelAt(image, {x, 15.0, 0.25});
        const auto expected = ddfcam::gui::colourAt(map, x / 40.0);
        QVERIFY2(colourDistance(pixel, expected) <= 8,
                 qPrintable(QString("x %1: pixel %2 %3 %4, expected %5 %6 %7")
                                .arg(x)
                                .arg(qRed(pixel))
                                .arg(qGreen(pixel))
                                .arg(qBlue(pixel))
                                .arg(255 * expected[0])
                                .arg(255 * expected[1])
                                .arg(255 * expected[2])));
      }
      property->LightingOn();
      property->SetAmbient(0.1);
      property->SetDiffuse(0.8);
    }
    // Cleared, the surface is one colour again: left and right ends look alike.
    scene_->clearSurfaceField();
    QVERIFY(!scene_->isFieldShown());
    const QImage plain = view_->renderImage();
    const QRgb left = pixelAt(plain, {2.0, 15.0, 0.25}), right = pixelAt(plain, {38.0, 15.0, 0.25});
    QVERIFY(ddfcam::test::sameColor(left, QColor(right), 12));
  }
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void PartSceneTest::scalarBarShowsTitleAndRange() {
  showPlane(1'000'000);
  const std::vector<float> values(static_cast<std::size_t>(scene_->surfaceVertexCount()), 0.1f);
  QCOMPARE(scene_->surfaceVertexCount(),
           static_cast<long long>(geometry_.surfaceSamples.face.size()));
  // The bar runs along the bottom edge, below the plane (centred, 30 mm high of a ~50 mm fit).
  auto barPixels = [this](const QImage& image) {
    const QColor background = view_->backgroundColor();
    int count = 0;
    for (int y = static_cast<int>(0.86 * image.height()); y < image.height() - 2; ++y)
      for (int x = image.width() / 4; x < 3 * image.width() / 4; ++x)
        if (!ddfcam::test::sameColor(image.pixel(x, y), background)) ++count;
    return count;
  };
  const int before = barPixels(view_->renderImage());
  scene_->setSurfaceField(values, FieldStyle{ColourMap::Magma, -0.5, 2.0, "material removed [mm]"});
  QCOMPARE(scene_->scalarBarTitle(), std::string("material removed [mm]"));
  QCOMPARE(scene_->scalarRange().lo, -0.5);
  QCOMPARE(scene_->scalarRange().hi, 2.0);
  const QImage withBar = view_->renderImage();
  ddfcam::test::dumpFrame(withBar, "part_scene_scalar_bar");
  QCOMPARE(before, 0);
  QVERIFY2(barPixels(withBar) > 200, qPrintable(QString::number(barPixels(withBar))));
  // A second field replaces the first.
  scene_->setSurfaceField(values, FieldStyle{ColourMap::CoolWarm, -1.0, 1.0, "height delta [mm]"});
  QCOMPARE(scene_->scalarBarTitle(), std::string("height delta [mm]"));
  QCOMPARE(scene_->scalarRange().lo, -1.0);
  // New geometry drops the field (its values belonged to the old surface).
  scene_->setGeometry(geometry_.scene);
  QVERIFY(!scene_->isFieldShown());
  QCOMPARE(scene_->scalarBarTitle(), std::string());
  QCOMPARE(barPixels(view_->renderImage()), 0);
}

void PartSceneTest::scalarBarLayoutIsStableWithTranslucentProps() {
  // VTK 9.1 lays a scalar bar out wrongly in the first frame of a renderer with translucent
  // props (labels on the ramp); in the view's annotation layer the first frame is final.
  showPlane(1'000'000);
  ddfcam::gui::OverlayStyle glass;
  glass.surface = true;
  glass.opacity = 0.5;
  const auto tool = ddfcam::planning::makeCylinderTool({}).transformed(
      Eigen::Isometry3d(Eigen::Translation3d(20, 15, 5.5)));
  scene_->setOverlay("tool", ddfcam::gui::toSurfacePolyData(tool), glass);
  view_->renderImage();
  scene_->setSurfaceField(
      std::vector<float>(static_cast<std::size_t>(scene_->surfaceVertexCount()), 0.3f),
      FieldStyle{ColourMap::Viridis, 0.0, 1.0, "material removed [mm]"});
  const QImage first = view_->renderImage();
  const QImage second = view_->renderImage();
  const QRect bar(0, static_cast<int>(0.8 * first.height()), first.width(),
                  first.height() - static_cast<int>(0.8 * first.height()));
  ddfcam::test::dumpFrame(first, "part_scene_translucent_first_frame");
  QVERIFY2(ddfcam::test::changedFraction(first.copy(bar), second.copy(bar)) < 0.001,
           qPrintable(
               QString::number(ddfcam::test::changedFraction(first.copy(bar), second.copy(bar)))));
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void PartSceneTest::fieldRejectsWrongSizesAndRanges() {
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           scene_->setSurfaceField({1.0f}, FieldStyle{}));  // no surface yet
  showPlane(1'000'000);
  const auto count = static_cast<std::size_t>(scene_->surfaceVertexCount());
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           scene_->setSurfaceField(std::vector<float>(count + 1), FieldStyle{}));
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           scene_->setSurfaceField(std::vector<float>(count),
                                                   FieldStyle{ColourMap::Grey, 1.0, 1.0, ""}));
  QVERIFY(!scene_->isFieldShown());
  // The scene's surface polydata is the caller's, untouched: no scalars were added to it.
  scene_->setSurfaceField(std::vector<float>(count, 0.5f), FieldStyle{});
  QVERIFY(geometry_.scene.surface->GetPointData()->GetScalars() == nullptr);
}

void PartSceneTest::addDemoOverlays() {
  // Three passes across the part: raster surface points nearest to lines of constant y.
  double b[6];
  geometry_.scene.surface->GetBounds(b);
  std::vector<Eigen::Vector3d> points;
  const int n = part_.ddf.resolution() - 1;
  for (int f = 0; f < part_.ddf.faceCount(); ++f)
    for (int k = 0; k <= n; k += 2)
      for (int i = 0; i + k <= n; i += 2) points.push_back(part_.ddf.surfacePoint(f, i, k));
  std::vector<std::vector<Eigen::Vector3d>> paths;
  for (double s : {0.3, 0.5, 0.7}) {
    const double y = b[2] + s * (b[3] - b[2]);
    std::vector<Eigen::Vector3d> path;
    for (int step = 0; step <= 40; ++step) {
      const Eigen::Vector2d target(b[0] + (0.05 + 0.9 * step / 40.0) * (b[1] - b[0]), y);
      const auto nearest = std::min_element(points.begin(), points.end(), [&](auto& p, auto& q) {
        return (p.template head<2>() - target).squaredNorm() <
               (q.template head<2>() - target).squaredNorm();
      });
      path.push_back(*nearest + Eigen::Vector3d(0, 0, 0.3));
    }
    paths.push_back(std::move(path));
  }
  ddfcam::gui::OverlayStyle pathStyle;
  pathStyle.rgb = {1.0, 0.35, 0.1};
  pathStyle.lineWidth = 3.0;
  scene_->setOverlay("tool paths", ddfcam::gui::toPolylinePolyData(paths), pathStyle);
  std::vector<Eigen::Vector3d> bases, directions;
  for (std::size_t p = 0; p < paths[1].size(); p += 8) {
    bases.push_back(paths[1][p]);
    directions.emplace_back(0, 0, 1);
  }
  ddfcam::gui::OverlayStyle arrowStyle;
  arrowStyle.rgb = {0.95, 0.95, 0.95};
  scene_->setOverlay("normals", ddfcam::gui::toGlyphPolyData(bases, directions, 8.0), arrowStyle);
  ddfcam::planning::CylinderToolParams roll;
  roll.radiusMm = 6.0;
  roll.widthMm = 12.0;
  const Eigen::Vector3d contact = paths[0][20];
  const auto tool = ddfcam::planning::makeCylinderTool(roll).transformed(
      Eigen::Isometry3d(Eigen::Translation3d(contact + Eigen::Vector3d(0, 0, roll.radiusMm))));
  ddfcam::gui::OverlayStyle toolStyle;
  toolStyle.surface = true;
  toolStyle.rgb = {0.75, 0.78, 0.82};
  toolStyle.opacity = 0.7;
  scene_->setOverlay("tool", ddfcam::gui::toSurfacePolyData(tool), toolStyle);
}

void PartSceneTest::demoPartWithFieldScreenshot() {
  // What a person sees: the demo part coloured by its height over the design surface.
  part_ = ddfcam::ddf::demoPart();
  geometry_ = ddfcam::gui::buildPartGeometry(part_.ddf, {});
  scene_->setGeometry(geometry_.scene);
  const auto perPoint = rasterField(part_.ddf, [](const Eigen::Vector3d& q) { return q.z(); });
  const auto perVertex =
      ddfcam::ddf::valuesAtSamples(part_.ddf, perPoint, geometry_.surfaceSamples);
  const auto [lo, hi] = std::minmax_element(perVertex.begin(), perVertex.end());
  const auto range = ddfcam::gui::defaultRange(*lo, *hi, false);
  scene_->setSurfaceField(perVertex,
                          FieldStyle{ColourMap::Viridis, range.lo, range.hi, "height z [mm]"});
  addDemoOverlays();
  view_->fitCameraFrom(0.45, -1.0, 0.85, 0.0, 0.0, 1.0);
  const QImage image = view_->renderImage(QSize(800, 600));
  ddfcam::test::dumpFrame(image, "part_scene_demo_field_800x600");
  QCOMPARE(image.size(), QSize(800, 600));
  const auto stats = frameStats(image, view_->backgroundColor());
  QVERIFY(stats.cornersBackground);
  QVERIFY(stats.centreForeground > 0.3);
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

DDFCAM_GUI_TEST_MAIN(PartSceneTest)
#include "part_scene_test.moc"
