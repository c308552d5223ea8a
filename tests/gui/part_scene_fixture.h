// SPDX-License-Identifier: MIT
// Test support: a VtkView with a PartScene per test function, and pixel and field helpers.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>

#include <QImage>
#include <QObject>
#include <QtTest/QtTest>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace ddfcam::test {

/// Per-raster-point values (layout of allHeights()) of f(surface point).
inline std::vector<float> rasterField(const ddf::DisplacementField& ddf,
                                      const std::function<double(const Eigen::Vector3d&)>& f) {
  std::vector<float> values(ddf.allHeights().size());
  const int n = ddf.resolution() - 1;
  for (int face = 0; face < ddf.faceCount(); ++face)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        values[face * ddf.pointsPerFace() + ddf.raster().index(i, k)] =
            static_cast<float>(f(ddf.surfacePoint(face, i, k)));
  return values;
}

/// Largest channel difference between pixel @p pixel and colour @p rgb (0..255 scale).
inline int colourDistance(QRgb pixel, const std::array<double, 3>& rgb) {
  return std::max({std::abs(qRed(pixel) - static_cast<int>(std::lround(255 * rgb[0]))),
                   std::abs(qGreen(pixel) - static_cast<int>(std::lround(255 * rgb[1]))),
                   std::abs(qBlue(pixel) - static_cast<int>(std::lround(255 * rgb[2])))});
}

/// A Qt Test class that gets a fresh 400 x 300 VtkView with an empty PartScene before every
/// test function. (Listed among the sources of each test that derives from it, for AUTOMOC.)
class PartSceneTestBase : public QObject {
  Q_OBJECT

 public:
  /// Called by QTEST_MAIN before QApplication exists.
  static void initMain() { gui::setDefaultSurfaceFormat(); }

 protected:
  /// The pixel of @p image (a render of view_) where @p world is drawn.
  QRgb pixelAt(const QImage& image, const Eigen::Vector3d& world) const {
    const QPointF p = view_->widgetPosition(world) * view_->devicePixelRatioF();
    return image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
  }

  /// Shows a 40 x 30 mm plane at z = 0.25 (600 support faces, 16 raster triangles each) seen
  /// from +z, with at most @p rasterTriangleBudget raster triangles drawn.
  void showPlane(std::size_t rasterTriangleBudget) {
    ddf::PlanePatchParams plane;
    plane.m = 5;
    part_ = ddf::planePatch(plane);
    gui::DisplayParams params;
    params.rasterTriangleBudget = rasterTriangleBudget;
    geometry_ = gui::buildPartGeometry(part_.ddf, params);
    scene_->setGeometry(geometry_.scene);
    view_->viewFrom(gui::ViewDirection::PlusZ);
  }

  std::unique_ptr<gui::VtkView> view_;
  std::unique_ptr<gui::PartScene> scene_;
  ddf::GeneratedSurface part_;
  gui::PartGeometry geometry_;

 private slots:
  void initTestCase() { gui::VtkErrorMonitor::install(); }
  void init() {
    gui::VtkErrorMonitor::reset();
    view_ = std::make_unique<gui::VtkView>();
    view_->resize(400, 300);
    scene_ = std::make_unique<gui::PartScene>(view_->renderer());
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
  }
  void cleanup() {
    scene_.reset();
    view_.reset();
  }
};

}  // namespace ddfcam::test
