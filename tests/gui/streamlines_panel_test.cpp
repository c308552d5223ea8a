// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: field glyphs, singularity markers, automatic coverage of a
// region, the smoothing preview and its undo step, and the path list, on analytic parts.
#include "frame_checks.h"
#include "workbench_fixture.h"

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
#include <ddfcam/planning/project.h>
#include <ddfcam/planning/streamline.h>

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
using ddfcam::gui::StreamlinesPanel;
using ddfcam::planning::FlowFieldSource;

namespace {

constexpr double kRadius = 10.0;  // cylinder radius, mm

ddfcam::planning::Project projectOf(ddfcam::ddf::GeneratedSurface part, const char* name) {
  ddfcam::planning::Project project;
  project.partName = name;
  project.part = std::move(part.ddf);
  return project;
}

ddfcam::planning::Project cylinderProject() {
  return projectOf(
      ddfcam::ddf::cylinderPart(
          {.radiusMm = kRadius, .lengthMm = 30.0, .segments = 48, .rings = 12, .m = 9}),
      "cylinder");
}

// Points of every cell of a polydata, in cell order.
std::vector<std::vector<Vec3>> cellPoints(vtkPolyData* data) {
  std::vector<std::vector<Vec3>> out;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    auto* ids = data->GetCell(c)->GetPointIds();
    auto& cell = out.emplace_back();
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double p[3];
      data->GetPoint(ids->GetId(i), p);
      cell.emplace_back(p[0], p[1], p[2]);
    }
  }
  return out;
}

std::vector<std::vector<Vec3>> passContacts(const ddfcam::planning::ToolPath& path) {
  std::vector<std::vector<Vec3>> out;
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const std::size_t end =
        s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : path.poses.size();
    auto& line = out.emplace_back();
    for (std::size_t i = path.passStarts[s]; i < end; ++i) line.push_back(path.poses[i].contact);
  }
  return out;
}

}  // namespace

class StreamlinesPanelTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase();
  void init();
  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void glyphsShowFieldsAtSubsampledPoints();
  void singularityMarkersOnTheEllipsoid();
  void coverFillsTheRegion();
  void smoothingPreviewIsLiveAndApplyIsOneUndoStep();
  void fairingIsOneUndoStepWithinTheDeviation();
  void pathListShowsCountsAndLengths();
  void dragDrawsAStrokeTheFieldFollows();

 private:
  StreamlinesPanel& panel() { return *f_.window->findChild<StreamlinesPanel*>(); }
  const ddfcam::planning::Project& project() const { return f_.window->document().project(); }
  ddfcam::gui::PartScene& scene() { return f_.window->partView().scene(); }
  void load(ddfcam::planning::Project project) {
    f_.window->document().reset(std::move(project));
    QVERIFY(f_.window->waitForJobs());
  }
  void waitOk() {
    QVERIFY(f_.window->waitForJobs(60'000));
    QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  }

  ddfcam::test::WorkbenchFixture f_;
};

void StreamlinesPanelTest::initTestCase() {
  ddfcam::gui::VtkErrorMonitor::install();
  QVERIFY(f_.dir.isValid());
  QVERIFY(f_.open(false));
  QVERIFY(f_.window->findChild<StreamlinesPanel*>() != nullptr);
}

void StreamlinesPanelTest::init() {
  f_.script.errors.clear();
  panel().setRegion(-1);
  panel().setFieldSource(FlowFieldSource::MaxCurvatureDirection);
  panel().setFieldSmoothing(false);
  panel().setSmoothingWindow(0);
}

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

void StreamlinesPanelTest::smoothingPreviewIsLiveAndApplyIsOneUndoStep() {
  load(cylinderProject());
  // A circle (k_max line) through a point of face 0.
  ddfcam::ddf::SurfaceLocation seed;
  seed.face = 0;
  seed.bary = Vec3(1.0, 1.0, 1.0) / 3.0;
  QVERIFY(panel().seedAt(seed));
  waitOk();
  QCOMPARE(project().paths.size(), std::size_t{1});
  const auto raw = passContacts(project().paths.front());
  QCOMPARE(raw.size(), std::size_t{1});
  QVERIFY(raw.front().size() > 50);
  QUndoStack& undo = *f_.window->document().undoStack();
  const int undoBefore = undo.count();
  for (const int k : {3, 8}) {
    panel().setSmoothingWindow(k);
    QVERIFY(scene().hasOverlay(StreamlinesPanel::kPreviewOverlay));
    const auto drawn = cellPoints(scene().overlayData(StreamlinesPanel::kPreviewOverlay));
    const auto expected = ddfcam::planning::smoothMovingAverage(raw.front(), k);
    QCOMPARE(drawn.size(), std::size_t{1});
    QCOMPARE(drawn.front().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      QVERIFY((drawn.front()[i] - expected[i]).norm() < 1e-9);
    QCOMPARE(undo.count(), undoBefore);  // previews are not edits
  }
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_smoothing_preview");
  QVERIFY(panel().applySmoothing());
  QCOMPARE(undo.count(), undoBefore + 1);
  QCOMPARE(project().paths.size(), std::size_t{1});
  const auto smoothed = passContacts(project().paths.front());
  const auto expected = ddfcam::planning::smoothMovingAverage(raw.front(), 8);
  QCOMPARE(smoothed.front().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    // The filtered point lies slightly inside the circle; the cylinder's stubbles are radial,
    // so putting it back on the surface is the radial projection onto radius r.
    const Vec3& c = smoothed.front()[i];
    const Vec3 e = expected[i];
    const double re = std::hypot(e.x(), e.y());
    const Vec3 projected(e.x() * kRadius / re, e.y() * kRadius / re, e.z());
    QVERIFY2((c - projected).norm() < 2e-3, qPrintable(QString("point %1 of %2: %3 mm off")
                                                           .arg(i)
                                                           .arg(expected.size())
                                                           .arg((c - projected).norm())));
  }
  undo.undo();
  QCOMPARE(passContacts(project().paths.front()), raw);
  panel().setSmoothingWindow(0);
  QVERIFY(!scene().hasOverlay(StreamlinesPanel::kPreviewOverlay));
}

void StreamlinesPanelTest::fairingIsOneUndoStepWithinTheDeviation() {
  load(cylinderProject());
  ddfcam::ddf::SurfaceLocation seed;
  seed.face = 7;
  seed.bary = Vec3(0.5, 0.25, 0.25);
  QVERIFY(panel().seedAt(seed));
  waitOk();
  const auto raw = passContacts(project().paths.front());
  QUndoStack& undo = *f_.window->document().undoStack();
  const int undoBefore = undo.count();
  const double deviation = 0.05;
  QVERIFY(panel().fairSelected(deviation));
  waitOk();
  QCOMPARE(undo.count(), undoBefore + 1);
  QCOMPARE(project().paths.size(), std::size_t{1});
  const auto faired = passContacts(project().paths.front());
  QCOMPARE(faired.front().size(), raw.front().size());
  // Every faired contact is on the cylinder and within the deviation bound of the raw line
  // (brute force over the raw segments).
  for (const Vec3& c : faired.front()) {
    QVERIFY(std::abs(std::hypot(c.x(), c.y()) - kRadius) < 2e-3);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < raw.front().size(); ++i) {
      const Vec3 a = raw.front()[i - 1], ab = raw.front()[i] - a;
      const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * ab - c).norm());
    }
    QVERIFY2(nearest <= deviation + 1e-3, qPrintable(QString::number(nearest)));
  }
  undo.undo();
  QCOMPARE(passContacts(project().paths.front()), raw);
}

void StreamlinesPanelTest::pathListShowsCountsAndLengths() {
  load(cylinderProject());
  ddfcam::ddf::SurfaceLocation seed;
  seed.face = 5;
  seed.bary = Vec3(0.2, 0.3, 0.5);
  panel().setFieldSource(FlowFieldSource::MinCurvatureDirection);  // rulings along z
  QVERIFY(panel().seedAt(seed));
  waitOk();
  // A family needs a pick: click the middle of the view.
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusX);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, view.rect().center());
  QVERIFY(panel().seedFamily());
  waitOk();
  QCOMPARE(project().paths.size(), std::size_t{2});
  QTableWidget& table = *panel().pathList().table();
  QCOMPARE(table.rowCount(), 2);
  double totalCut = 0.0;
  int totalLines = 0;
  for (int r = 0; r < 2; ++r) {
    const auto lines = passContacts(project().paths[r]);
    double cut = 0.0;
    for (const auto& line : lines)
      for (std::size_t i = 1; i < line.size(); ++i) cut += (line[i] - line[i - 1]).norm();
    totalCut += cut;
    totalLines += static_cast<int>(lines.size());
    QCOMPARE(table.item(r, 0)->text(), QString::fromStdString(project().paths[r].name));
    QCOMPARE(table.item(r, 1)->text().toInt(), static_cast<int>(lines.size()));
    QVERIFY(std::abs(table.item(r, 2)->text().toDouble() - cut) <= 0.051);
  }
  // The family is linked: its idle length (lifted links) is at least the straight gaps
  // between its passes.
  const auto family = passContacts(project().paths[1]);
  double gaps = 0.0;
  for (std::size_t l = 1; l < family.size(); ++l)
    gaps += (family[l].front() - family[l - 1].back()).norm();
  QVERIFY(table.item(1, 3)->text().endsWith("(linked)"));
  QVERIFY2(table.item(1, 3)->text().split(' ').front().toDouble() >= gaps - 0.05,
           qPrintable(table.item(1, 3)->text() + " vs " + QString::number(gaps)));
  // A ruling of the 30 mm cylinder is 30 mm long.
  QVERIFY(std::abs(table.item(0, 2)->text().toDouble() - 30.0) < 0.2);
  QVERIFY(project().paths[1].passStarts.size() >= 5);
  const QString total = panel().pathList().totalText();
  QVERIFY2(total.startsWith(QString("2 paths, %1 lines").arg(totalLines)), qPrintable(total));
  QVERIFY2(total.contains(QString("cutting %1 mm").arg(totalCut, 0, 'f', 1)), qPrintable(total));
  ddfcam::test::dumpFrame(view.renderImage(), "streamlines_path_list");
  ddfcam::test::dumpFrame(panel().grab().toImage(), "streamlines_panel_widget");
}

void StreamlinesPanelTest::dragDrawsAStrokeTheFieldFollows() {
  load(cylinderProject());
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusX);
  panel().setDrawDirection(true);
  // A vertical drag over the middle of the cylinder: a stroke along a ruling (z).
  const QPoint centre = view.rect().center();
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(0, -60));
  for (int dy = -50; dy <= 60; dy += 10) QTest::mouseMove(&view, centre + QPoint(0, dy));
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(0, 60));
  panel().setDrawDirection(false);
  QCOMPARE(panel().strokes().size(), std::size_t{1});
  const auto& stroke = panel().strokes().front();
  QVERIFY(stroke.size() >= 5);
  for (const Vec3& p : stroke) QVERIFY(std::abs(std::hypot(p.x(), p.y()) - kRadius) < 1e-2);
  QVERIFY(std::abs(stroke.back().z() - stroke.front().z()) > 3.0);  // it runs along z
  QCOMPARE(scene().overlayCellCount(StreamlinesPanel::kStrokeOverlay), 1LL);
  QVERIFY(project().paths.empty());  // drawing never seeds
  // The field from the stroke follows it: glyphs within 1 mm of the stroke point along z.
  QVERIFY(panel().showField());
  waitOk();
  const auto& glyphs = panel().fieldDisplay().glyphs(GlyphField::Flow);
  int near = 0;
  for (std::size_t g = 0; g < glyphs.centres.size(); ++g) {
    double distance = std::numeric_limits<double>::infinity();
    for (const Vec3& p : stroke) distance = std::min(distance, (glyphs.centres[g] - p).norm());
    if (distance > 1.0) continue;
    ++near;
    QVERIFY2(std::abs(glyphs.directions[g].z()) > 0.95,
             qPrintable(QString::number(glyphs.directions[g].z())));
  }
  QVERIFY(near >= 3);
  ddfcam::test::dumpFrame(view.renderImage(), "streamlines_drawn_stroke");
  panel().clearStrokes();
  QVERIFY(!scene().hasOverlay(StreamlinesPanel::kStrokeOverlay));
}

QTEST_MAIN(StreamlinesPanelTest)
#include "streamlines_panel_test.moc"
