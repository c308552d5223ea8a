// SPDX-License-Identifier: MIT
// PartScene under Xvfb: fields drawn at raster resolution on a coarse adaptive display mesh.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "part_scene_fixture.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/adapters/raster_texture_atlas.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>

#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkProperty.h>

#include <cmath>
#include <vector>

using ddfcam::gui::ColourMap;
using ddfcam::gui::FieldStyle;
using ddfcam::gui::Layer;
using ddfcam::test::colourDistance;
using ddfcam::test::rasterField;

class PartSceneRasterFieldTest : public ddfcam::test::PartSceneTestBase {
  Q_OBJECT

 private slots:
  void narrowBandShowsOnACoarseMesh();
  void toleranceBandKeepsOneColourPerRasterPoint();
  void clearingRestoresThePlainSurface();
  void rejectsSurfacesWithoutRasterPositions();
  void demoPartAtRasterResolutionScreenshot();

 private:
  /// The 40 x 30 mm plane drawn adaptively (a flat face needs two triangles, whose corners all
  /// lie on support vertices, 2 mm apart), unlit so that a pixel is its texel's colour.
  void showCoarsePlane();
  /// Values v at the raster points of the column x = 21 mm (raster spacing 0.5 mm; the
  /// nearest display vertices are at x = 20 and 22), 0 elsewhere.
  std::vector<float> column(double v) const {
    return rasterField(part_.ddf, [v](const Eigen::Vector3d& q) {
      return std::abs(q.x() - 21.0) < 0.1 ? v : 0.0;
    });
  }
  QString describe(QRgb pixel) const {
    return QString("%1 %2 %3").arg(qRed(pixel)).arg(qGreen(pixel)).arg(qBlue(pixel));
  }
};

void PartSceneRasterFieldTest::showCoarsePlane() {
  showPlane(100);
  QVERIFY(geometry_.adaptiveSurface);
  QVERIFY(scene_->showsRasterFields());
  QVERIFY(geometry_.surfaceTriangles <= 4 * 600);
  vtkProperty* property = scene_->actor(Layer::Surface)->GetProperty();
  property->LightingOff();
  property->SetAmbient(0.0);
  property->SetDiffuse(1.0);
}

void PartSceneRasterFieldTest::narrowBandShowsOnACoarseMesh() {
  showCoarsePlane();
  const std::vector<float> values = column(1.0f);
  const FieldStyle style{ColourMap::Viridis, 0.0, 1.0, "band [1]"};
  // Per display vertex the band vanishes: every vertex lies off it.
  scene_->setSurfaceField(
      ddfcam::ddf::valuesAtSamples(part_.ddf, values, geometry_.surfaceSamples), style);
  QVERIFY(scene_->rasterFieldAtlas() == nullptr);
  const QImage perVertex = view_->renderImage();
  const auto low = ddfcam::gui::colourAt(ColourMap::Viridis, 0.0);
  const auto high = ddfcam::gui::colourAt(ColourMap::Viridis, 1.0);
  QVERIFY2(colourDistance(pixelAt(perVertex, {21.0, 15.0, 0.25}), low) <= 8,
           qPrintable(describe(pixelAt(perVertex, {21.0, 15.0, 0.25}))));

  scene_->setSurfaceRasterField(values, style);
  QVERIFY(scene_->isFieldShown());
  QVERIFY(scene_->rasterFieldAtlas() != nullptr);
  QCOMPARE(scene_->scalarBarTitle(), std::string("band [1]"));
  QCOMPARE(scene_->scalarRange().hi, 1.0);
  const QImage image = view_->renderImage();
  ddfcam::test::dumpFrame(image, "part_scene_raster_field_band");
  // At the band's raster points (every 0.5 mm along y) the pixel is the band's colour; half a
  // raster step to either side it is the background value's.
  for (double y : {3.0, 9.5, 15.0, 21.5, 27.0}) {
    const QRgb on = pixelAt(image, {21.0, y, 0.25});
    QVERIFY2(colourDistance(on, high) <= 8, qPrintable(QString("y %1: %2").arg(y).arg(describe(on))));
    for (double x : {20.5, 21.5}) {
      const QRgb off = pixelAt(image, {x, y, 0.25});
      QVERIFY2(colourDistance(off, low) <= 8, qPrintable(describe(off)));
    }
  }
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void PartSceneRasterFieldTest::toleranceBandKeepsOneColourPerRasterPoint() {
  showCoarsePlane();
  FieldStyle style{ColourMap::Viridis, -0.1, 0.1, "deviation [mm]"};
  style.band = ddfcam::planning::ToleranceBand{-0.01, 0.01};
  scene_->setSurfaceRasterField(column(-0.05f), style);
  const QImage image = view_->renderImage();
  ddfcam::test::dumpFrame(image, "part_scene_raster_field_overcut");
  const auto overcut = ddfcam::gui::toleranceColourAt(-0.05, -0.1, 0.1, *style.band);
  const auto inside = ddfcam::gui::toleranceColourAt(0.0, -0.1, 0.1, *style.band);
  // At the column's raster points the overcut red; half a raster step beside them, and far
  // away, the band's green.
  for (double y : {3.0, 15.0, 27.0}) {
    const QRgb pixel = pixelAt(image, {21.0, y, 0.25});
    QVERIFY2(colourDistance(pixel, overcut) <= 8, qPrintable(describe(pixel)));
    QCOMPARE(ddfcam::gui::toleranceClassOfColour(
                 {qRed(pixel) / 255.0, qGreen(pixel) / 255.0, qBlue(pixel) / 255.0}),
             ddfcam::planning::ToleranceClass::Overcut);
    for (double x : {20.5, 21.5, 30.0}) {
      const QRgb off = pixelAt(image, {x, y, 0.25});
      QVERIFY2(colourDistance(off, inside) <= 8, qPrintable(describe(off)));
    }
  }
}

void PartSceneRasterFieldTest::clearingRestoresThePlainSurface() {
  showCoarsePlane();
  const QImage plain = view_->renderImage();
  scene_->setSurfaceRasterField(column(1.0f), FieldStyle{ColourMap::Magma, 0.0, 1.0, "x"});
  QVERIFY(scene_->actor(Layer::Surface)->GetTexture() != nullptr);
  // A per-vertex field replaces the texture.
  scene_->setSurfaceField(std::vector<float>(scene_->surfaceVertexCount(), 0.5f),
                          FieldStyle{ColourMap::Magma, 0.0, 1.0, "x"});
  QVERIFY(scene_->actor(Layer::Surface)->GetTexture() == nullptr);
  scene_->setSurfaceRasterField(column(1.0f), FieldStyle{ColourMap::Magma, 0.0, 1.0, "x"});
  scene_->clearSurfaceField();
  QVERIFY(!scene_->isFieldShown());
  QVERIFY(scene_->actor(Layer::Surface)->GetTexture() == nullptr);
  QVERIFY(scene_->rasterFieldAtlas() == nullptr);
  const QImage cleared = view_->renderImage();
  QVERIFY(ddfcam::test::changedFraction(plain, cleared) < 0.001);
  // Picks keep working on the textured copy: same cell order, same "face" values.
  scene_->setSurfaceRasterField(column(1.0f), FieldStyle{ColourMap::Magma, 0.0, 1.0, "x"});
  view_->renderImage();
  const auto pick = scene_->pickSurface(*view_, view_->widgetPosition({21.0, 15.0, 0.25}));
  QVERIFY(pick.has_value());
  QVERIFY((pick->position - Eigen::Vector3d(21.0, 15.0, 0.25)).norm() < 0.2);
  QCOMPARE(pick->face, geometry_.surfaceTriangleFace[static_cast<std::size_t>(pick->cell)]);
}

void PartSceneRasterFieldTest::rejectsSurfacesWithoutRasterPositions() {
  showPlane(1'000'000);  // the raster mesh: exact per vertex, no texture needed
  QVERIFY(!geometry_.adaptiveSurface);
  QVERIFY(!scene_->showsRasterFields());
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           scene_->setSurfaceRasterField(column(1.0f), FieldStyle{}));
  showCoarsePlane();
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput,
                           scene_->setSurfaceRasterField(std::vector<float>(7), FieldStyle{}));
  QVERIFY(!scene_->isFieldShown());
}

void PartSceneRasterFieldTest::demoPartAtRasterResolutionScreenshot() {
  // The demo part (393,216 raster triangles, drawn adaptively) coloured by the distance to a
  // plane through it: a thin contour line shows at raster resolution.
  part_ = ddfcam::ddf::demoPart();
  geometry_ = ddfcam::gui::buildPartGeometry(part_.ddf, {});
  QVERIFY(geometry_.adaptiveSurface);
  scene_->setGeometry(geometry_.scene);
  QVERIFY(scene_->showsRasterFields());
  const auto values = rasterField(part_.ddf, [](const Eigen::Vector3d& q) {
    return std::abs(std::remainder(q.x() + 0.5 * q.y(), 10.0)) < 0.3 ? 1.0 : 0.0;
  });
  scene_->setSurfaceRasterField(values, FieldStyle{ColourMap::Viridis, 0.0, 1.0, "stripes [1]"});
  view_->fitCameraFrom(0.45, -1.0, 0.85, 0.0, 0.0, 1.0);
  const QImage image = view_->renderImage(QSize(800, 600));
  ddfcam::test::dumpFrame(image, "part_scene_demo_raster_stripes_800x600");
  // Stripes 0.6 mm wide every 10 mm: yellow (the map's top, lit) on a sizeable share of pixels.
  int yellow = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QRgb p = image.pixel(x, y);
      yellow += qRed(p) > 120 && qGreen(p) > 110 && qBlue(p) < 0.5 * qRed(p) ? 1 : 0;
    }
  QVERIFY2(yellow > image.width() * image.height() / 200, qPrintable(QString::number(yellow)));
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

DDFCAM_GUI_TEST_MAIN(PartSceneRasterFieldTest)
#include "part_scene_raster_field_test.moc"
