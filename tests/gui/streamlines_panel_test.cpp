// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: field glyphs, singularity markers and automatic coverage of a
// region, on analytic parts.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "streamlines_panel_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/flow_field_display.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_list.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/model/project.h>

#include <QLabel>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using ddfcam::ddf::Vec3;
using ddfcam::gui::FlowFieldDisplay;
using ddfcam::gui::GlyphField;
using ddfcam::planning::FlowFieldSource;
using ddfcam::test::cellPoints;
using ddfcam::test::cylinderProject;
using ddfcam::test::kRadius;
using ddfcam::test::projectOf;

class StreamlinesPanelTest : public ddfcam::test::StreamlinesPanelTestBase {
  Q_OBJECT

 private slots:
  void glyphsShowFieldsAtSubsampledPoints();
  void singularityMarkersOnTheEllipsoid();
  void coverFillsTheRegion();
};

void StreamlinesPanelTest::glyphsShowFieldsAtSubsampledPoints() {
  load(cylinderProject());
  QVERIFY(panel().showField());
  waitOk();
  FlowFieldDisplay& display = panel().fieldDisplay();
  display.setVisible(GlyphField::MaxDirection, true);
  display.setVisible(GlyphField::MinDirection, true);
  const auto& ddf = *project().part;
  const int n = ddf.raster().steps();
  for (const GlyphField which :
       {GlyphField::Flow, GlyphField::MaxDirection, GlyphField::MinDirection}) {
    const std::string name = FlowFieldDisplay::overlayName(which);
    QVERIFY2(scene().hasOverlay(name) && scene().isOverlayVisible(name), name.c_str());
    const auto& glyphs = display.glyphs(which);
    // Oracle for the count: distinct raster points (f, i, k) with i, k multiples of the stride.
    std::set<std::uint32_t> samples;
    for (int f = 0; f < ddf.faceCount(); ++f)
      for (int k = 0; k <= n; k += glyphs.stride)
        for (int i = 0; i + k <= n; i += glyphs.stride) samples.insert(ddf.topology().id(f, i, k));
    QVERIFY(glyphs.stride >= 1);
    // The cylinder is anisotropic everywhere: every sampled point has a glyph.
    QCOMPARE(scene().overlayCellCount(name), static_cast<long long>(samples.size()));
    const auto cells = cellPoints(scene().overlayData(name));
    for (const auto& cell : cells) {
      QCOMPARE(cell.size(), std::size_t{2});
      const Vec3 mid = 0.5 * (cell[0] + cell[1]), d = (cell[1] - cell[0]).normalized();
      QVERIFY(std::abs((cell[1] - cell[0]).norm() - glyphs.lengthMm) < 1e-9);
      // Centred on the point and lifted off the surface to the tool (outer) side.
      const double r = std::hypot(mid.x(), mid.y());
      QVERIFY2(r > kRadius && r < kRadius + 1.0, qPrintable(QString::number(r)));
      // Exact principal directions: k_max = 1/r along the circles, k_min = 0 along z.
      const Vec3 circle = Vec3(-mid.y(), mid.x(), 0.0).normalized();
      const double along =
          which == GlyphField::MinDirection ? std::abs(d.z()) : std::abs(d.dot(circle));
      QVERIFY2(along > 0.98, qPrintable(QString("%1: %2").arg(name.c_str()).arg(along)));
    }
  }
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusX);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_glyphs_cylinder");
  display.setVisible(GlyphField::MaxDirection, false);
  display.setVisible(GlyphField::MinDirection, false);
}

void StreamlinesPanelTest::singularityMarkersOnTheEllipsoid() {
  load(projectOf(ddfcam::ddf::ellipsoidPart({.axesMm = {3.0, 2.0, 1.0}, .subdivisions = 2, .m = 9}),
                 "ellipsoid"));
  // Smoothing fills the umbilic points, so the field is defined everywhere and the indices
  // of its singularities sum to the Euler characteristic of the sphere.
  panel().setFieldSmoothing(true, 0.02);
  QVERIFY(panel().showField());
  waitOk();
  FlowFieldDisplay& display = panel().fieldDisplay();
  display.setSingularitiesVisible(true);
  const auto& singularities = display.singularities();
  double sum = 0.0;
  long long positive = 0, negative = 0;
  for (const auto& s : singularities) {
    sum += s.index;
    (s.index > 0 ? positive : negative) += 1;
  }
  QVERIFY2(std::abs(sum - 2.0) < 1e-9, qPrintable(QString::number(sum)));
  QVERIFY(positive >= 4);  // the four umbilics of a triaxial ellipsoid, +1/2 each
  QCOMPARE(scene().overlayCellCount(FlowFieldDisplay::kPositiveSingularities), positive);
  QCOMPARE(scene().overlayCellCount(FlowFieldDisplay::kNegativeSingularities), negative);
  QVERIFY(scene().isOverlayVisible(FlowFieldDisplay::kPositiveSingularities));
  // Markers sit on the ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1.
  for (const auto& cell :
       cellPoints(scene().overlayData(FlowFieldDisplay::kPositiveSingularities))) {
    const Vec3& p = cell.front();
    const double level = std::pow(p.x() / 3, 2) + std::pow(p.y() / 2, 2) + p.z() * p.z();
    QVERIFY2(std::abs(level - 1.0) < 0.02, qPrintable(QString::number(level)));
  }
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_singularities_ellipsoid");
  display.setSingularitiesVisible(false);
}

void StreamlinesPanelTest::coverFillsTheRegion() {
  auto cylinder = cylinderProject();
  const auto& ddf = *cylinder.part;
  ddfcam::planning::Region half;
  half.name = "front half";
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (ddf.surfacePoint(f, n / 3, n / 3).x() > 0) half.faces.push_back(f);
  half.plan.spacingMm = 2.0;
  half.plan.flowSource = FlowFieldSource::MinCurvatureDirection;
  cylinder.regions.push_back(half);
  load(std::move(cylinder));
  panel().setRegion(0);
  const int undoBefore = f_.window->document().undoStack()->count();
  const double dSep = 2.0;
  QVERIFY(panel().coverRegion(dSep));
  waitOk();
  QCOMPARE(project().paths.size(), std::size_t{1});
  QCOMPARE(f_.window->document().undoStack()->count(), undoBefore + 1);
  // The project had no tool: the default roll came with the path, and the panel says so.
  QCOMPARE(project().tools.size(), std::size_t{1});
  const QString status = f_.window->findChild<QLabel*>("streamlineStatus")->text();
  QVERIFY2(status.contains("added the default roll R5 W10") && status.contains("Tools panel"),
           qPrintable(status));
  const auto& path = project().paths.front();
  QVERIFY(path.passStarts.size() >= 5);
  // Brute force: every raster point of the region lies within d_sep (+ half a trace step and
  // the chord error) of a contact; no contact leaves the region (x >= 0 half).
  const auto& part = *project().part;
  double worst = 0.0;
  for (const int f : project().regions[0].faces)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 q = part.surfacePoint(f, i, k);
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& pose : path.poses) nearest = std::min(nearest, (pose.contact - q).norm());
        worst = std::max(worst, nearest);
      }
  QVERIFY2(worst <= dSep + 0.25, qPrintable(QString("farthest point %1 mm").arg(worst)));
  double leftmost = std::numeric_limits<double>::infinity();
  for (const auto& pose : path.poses) leftmost = std::min(leftmost, pose.contact.x());
  QVERIFY2(leftmost > -0.5, qPrintable(QString::number(leftmost)));
  // From +y the region (x > 0) is the left half of the picture.
  panel().fieldDisplay().setVisible(GlyphField::Flow, false);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusY);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_cover_region");
  f_.window->document().undoStack()->undo();
  QVERIFY(project().paths.empty());
}

DDFCAM_GUI_TEST_MAIN(StreamlinesPanelTest)
#include "streamlines_panel_test.moc"
