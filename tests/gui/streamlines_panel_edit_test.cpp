// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: the smoothing preview and its undo step, fairing, the path list,
// drawn strokes and the raw lines kept with a path, on the cylinder.
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
#include <ddfcam/gui/path_commands.h>
#include <ddfcam/gui/path_list.h>
#include <ddfcam/gui/project_actions.h>
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
using ddfcam::gui::GlyphField;
using ddfcam::gui::StreamlinesPanel;
using ddfcam::planning::FlowFieldSource;
using ddfcam::test::cellPoints;
using ddfcam::test::cylinderProject;
using ddfcam::test::kRadius;
using ddfcam::test::passContacts;

class StreamlinesPanelEditTest : public ddfcam::test::StreamlinesPanelTestBase {
  Q_OBJECT

 private slots:
  void smoothingPreviewIsLiveAndApplyIsOneUndoStep();
  void fairingIsOneUndoStepWithinTheDeviation();
  void pathListShowsCountsAndLengths();
  void dragDrawsAStrokeTheFieldFollows();
  void planningResultsLiveWithThePath();
};

namespace {

/// Pushes the undoable replacement of path @p index by a copy named @p name, as a rename does.
void renamePath(ddfcam::gui::Document& document, int index, const std::string& name) {
  ddfcam::planning::ToolPath renamed = document.project().paths.at(index);
  renamed.name = name;
  document.push(std::make_unique<ddfcam::gui::ReplacePathCommand>(
      document, index, std::move(renamed), QString("Rename path to '%1'").arg(name.c_str())));
}

}  // namespace

void StreamlinesPanelEditTest::smoothingPreviewIsLiveAndApplyIsOneUndoStep() {
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

void StreamlinesPanelEditTest::fairingIsOneUndoStepWithinTheDeviation() {
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

void StreamlinesPanelEditTest::pathListShowsCountsAndLengths() {
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

void StreamlinesPanelEditTest::dragDrawsAStrokeTheFieldFollows() {
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

void StreamlinesPanelEditTest::planningResultsLiveWithThePath() {
  load(cylinderProject());
  ddfcam::gui::Document& document = f_.window->document();
  QUndoStack& undo = *document.undoStack();
  ddfcam::ddf::SurfaceLocation seed;
  seed.face = 0;
  seed.bary = Vec3(1.0, 1.0, 1.0) / 3.0;
  QVERIFY(panel().seedAt(seed));
  waitOk();
  QCOMPARE(project().paths.size(), std::size_t{1});
  const ddfcam::planning::ToolPath planned = project().paths.front();
  // The path holds its line as traced: a circle of the cylinder (analytic), one per pass.
  QCOMPARE(planned.rawLines.size(), std::size_t{1});
  QCOMPARE(planned.rawLines.size(), planned.passStarts.size());
  QVERIFY(!planned.linkedIdleMm);  // a single line is not linked
  const auto raw = planned.rawLines.front().polyline();
  QVERIFY(raw.size() > 50);
  for (const Vec3& p : raw)  // on the DDF of the cylinder, as the placed contacts are
    QVERIFY2(std::abs(std::hypot(p.x(), p.y()) - kRadius) < 2e-3,
             qPrintable(QString::number(std::hypot(p.x(), p.y()) - kRadius)));

  // Renamed, the path is still smoothed from its raw line (by name it no longer was).
  renamePath(document, 0, "renamed circle");
  QCOMPARE(project().paths.front().rawLines, planned.rawLines);
  for (const int k : {8, 3}) {
    panel().setSmoothingWindow(k);
    QVERIFY(panel().applySmoothing());
    const ddfcam::planning::ToolPath& smoothed = project().paths.front();
    QCOMPARE(smoothed.name, std::string("renamed circle"));
    QCOMPARE(smoothed.rawLines, planned.rawLines);  // carried over: smoothing again starts here
    // Each smoothing is of the raw line, not of the previous result: the moving average of
    // the raw points put back radially on the cylinder.
    const auto contacts = passContacts(smoothed).front();
    const auto expected = ddfcam::planning::smoothMovingAverage(raw, k);
    QCOMPARE(contacts.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const Vec3 e = expected[i];
      const double re = std::hypot(e.x(), e.y());
      QVERIFY((contacts[i] - Vec3(e.x() * kRadius / re, e.y() * kRadius / re, e.z())).norm() <
              2e-3);
    }
  }
  panel().setSmoothingWindow(0);

  // A linked family keeps its linking's idle length through a rename.
  panel().setFieldSource(FlowFieldSource::MinCurvatureDirection);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusX);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, view.rect().center());
  QVERIFY(panel().seedFamily());
  waitOk();
  QCOMPARE(project().paths.size(), std::size_t{2});
  const ddfcam::planning::ToolPath family = project().paths[1];
  QVERIFY(family.linkedIdleMm.has_value());
  QCOMPARE(family.rawLines.size(), family.passStarts.size());
  QTableWidget& table = *panel().pathList().table();
  const QString idle = table.item(1, 3)->text();
  QCOMPARE(idle, QString::number(*family.linkedIdleMm, 'f', 1) + " (linked)");
  renamePath(document, 1, "renamed family");
  QCOMPARE(table.item(1, 0)->text(), QString("renamed family"));
  QCOMPARE(table.item(1, 3)->text(), idle);
  QCOMPARE(project().paths[1].rawLines, family.rawLines);

  // Saved and opened again, both paths have them.
  const QString file = f_.dir.filePath("planned.ddfproj");
  QVERIFY(f_.window->projectActions().saveAs(file));
  const ddfcam::planning::Project saved = project();
  QVERIFY(f_.window->openPath(file));
  waitOk();
  QVERIFY(ddfcam::planning::projectsEqual(project(), saved));
  QCOMPARE(project().paths[0].rawLines, planned.rawLines);
  QCOMPARE(project().paths[1].linkedIdleMm, family.linkedIdleMm);
  QCOMPARE(panel().pathList().table()->item(1, 3)->text(), idle);
  panel().pathList().selectPath(0);
  panel().setSmoothingWindow(3);
  QVERIFY(panel().applySmoothing());
  QCOMPARE(project().paths[0].rawLines, planned.rawLines);
  panel().setSmoothingWindow(0);

  // Undo back to before the planning removes the paths and their lines; redo restores them.
  load(cylinderProject());
  panel().setFieldSource(FlowFieldSource::MaxCurvatureDirection);  // the circle again
  QVERIFY(panel().seedAt(seed));
  waitOk();
  QCOMPARE(project().paths.front().rawLines, planned.rawLines);
  QVERIFY(undo.canUndo());
  undo.undo();
  QVERIFY(project().paths.empty());
  undo.redo();
  QCOMPARE(project().paths.size(), std::size_t{1});
  QCOMPARE(project().paths.front().rawLines, planned.rawLines);
}

DDFCAM_GUI_TEST_MAIN(StreamlinesPanelEditTest)
#include "streamlines_panel_edit_test.moc"
