// SPDX-License-Identifier: MIT
// Simulation options under Xvfb: stock allowance, swept vs discrete, penetration correction in a
// bore, Preston removal, all through the Simulation panel against analytic expectations.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/panels/simulation_options.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/simulation_playback.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QRegularExpression>
#include <QScrollArea>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <cmath>

using ddfcam::gui::RemovalModel;
using ddfcam::gui::SimulationPanel;
using ddfcam::planning::SweepMode;

namespace {

constexpr double kPlaneZ = 0.25;

/// Plane z = 0.25 over 40 x 30 mm (z-map, vectors (0, 0, L)).
ddfcam::ddf::GeneratedSurface plane(double vectorLength = 1.0) {
  return ddfcam::ddf::planePatch(
      {.cellsX = 20, .cellsY = 15, .m = 9, .planeZMm = kPlaneZ, .vectorLengthMm = vectorLength});
}

/// The default roll (R 5, W 10) fed along +y at x = 20 from y = 5 to 25, sunk by @p depth.
ddfcam::planning::ToolPath rollAlongY(double step, double depth) {
  ddfcam::planning::ToolPath path;
  path.name = "line";
  for (double y = 5.0; y <= 25.0 + 1e-9; y += step) {
    const Eigen::Vector3d c(20.0, y, kPlaneZ);
    path.poses.push_back(
        {ddfcam::planning::rollPoseAtContact(c, {0, 0, 1}, {0, 1, 0}, 5.0, depth), c});
  }
  path.passStarts = {0};
  return path;
}

ddfcam::planning::Project projectOf(ddfcam::ddf::GeneratedSurface part,
                                    std::vector<ddfcam::planning::ToolPath> paths = {}) {
  ddfcam::planning::Project p;
  p.partName = "test part";
  p.tools = {ddfcam::planning::Tool{}};
  p.paths = std::move(paths);
  p.part = std::move(part.ddf);
  return p;
}

}  // namespace

class SimulationOptionsTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private:
  SimulationPanel& panel() { return *f_.window->findChild<SimulationPanel*>(); }
  QUndoStack& undo() { return *f_.window->document().undoStack(); }
  QString label(const char* name) { return f_.window->findChild<QLabel*>(name)->text(); }
  /// Heights after simulating path 0 in @p mode; the edit is undone again.
  std::vector<float> simulated(SweepMode mode) {
    panel().options().setSweepMode(mode);
    if (!panel().simulatePath(0)) return {};
    waitOk();
    std::vector<float> heights = project().part->allHeights();
    undo().undo();
    return heights;
  }

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void raiseByAllowanceOnAPlane();
  void stockFromAPartialMesh();
  void sweptCutsBetweenCoarsePoses();
  void correctPenetrationsInABore();
  void prestonRemovesTheConservedVolume();
  void prestonFeedIsThePathsFeed();
};

void SimulationOptionsTest::raiseByAllowanceOnAPlane() {
  const double length = 2.0;  // |v| = 2 mm: the height rises by 0.1 / 2
  load(projectOf(plane(length)));
  const std::vector<float> before = project().part->allHeights();
  const int count = undo().count();
  QVERIFY(panel().raiseByAllowance(0.1));
  waitOk();
  QCOMPARE(undo().count(), count + 1);
  const auto& after = project().part->allHeights();
  double worst = 0.0;
  for (std::size_t i = 0; i < after.size(); ++i)
    worst = std::max(worst, std::abs(double(after[i]) - (double(before[i]) + 0.1 / length)));
  QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
  QCOMPARE(project().states.size(), std::size_t{2});
  QCOMPARE(project().states[0].name, std::string("design"));
  QCOMPARE(project().states[0].heights, before);
  QCOMPARE(project().states[1].heights, after);
  QVERIFY(label("workpieceLabel").contains("design"));
  // A second raise keeps the one "design" state.
  QVERIFY(panel().raiseByAllowance(0.1));
  waitOk();
  QCOMPARE(project().states.size(), std::size_t{3});
  QCOMPARE(project().states[2].name, std::string("stock +0.1 mm"));
  undo().undo();
  undo().undo();
  QCOMPARE(project().part->allHeights(), before);
  QVERIFY(project().states.empty());
}

void SimulationOptionsTest::stockFromAPartialMesh() {
  // A flat stock z = 0.6 over x <= 20.1 only (between raster columns): the z-map heights there
  // become 0.6 / L; the stubbles with x > 20.1 miss it and keep the part's height 0.25 / L.
  load(projectOf(plane()));
  const std::vector<float> before = project().part->allHeights();
  ddfcam::ddf::TriangleMesh stock;
  stock.vertices = {{-5, -5, 0.6}, {20.1, -5, 0.6}, {20.1, 35, 0.6}, {-5, 35, 0.6}};
  stock.triangles = {{0, 1, 2}, {0, 2, 3}};
  const QString file = f_.dir.filePath("stock.stl");
  ddfcam::io::writeMesh(stock, file.toStdString());
  f_.window->console().clear();
  QVERIFY(panel().stockFromMesh(file));
  waitOk();
  const auto& part = *project().part;
  const auto& after = part.allHeights();
  const int n = part.raster().steps();
  std::size_t missing = 0, wrong = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t at = f * part.pointsPerFace() + part.raster().index(i, k);
        const double x = part.surfacePoint(f, i, k).x();
        missing += x > 20.1;
        wrong += std::abs(after[at] - (x > 20.1 ? kPlaneZ : 0.6)) > 1e-5;
      }
  QCOMPARE(wrong, std::size_t{0});
  QVERIFY(missing > 100);
  QVERIFY2(
      label("workpieceLabel")
          .startsWith(QString("Stock from 'stock.stl': %1 of %2").arg(missing).arg(after.size())),
      qPrintable(label("workpieceLabel")));
  QVERIFY(f_.window->console().text().contains("[warning]"));
  undo().undo();
  QCOMPARE(project().part->allHeights(), before);
  // A missing file is a clear error, not a crash.
  QVERIFY(panel().stockFromMesh(f_.dir.filePath("none.stl")));
  QVERIFY(f_.window->waitForJobs());
  QCOMPARE(f_.script.errors.size(), qsizetype{1});
  QVERIFY2(f_.script.errors.front().contains("none.stl"), qPrintable(f_.script.errors.front()));
  f_.script.errors.clear();
}

void SimulationOptionsTest::sweptCutsBetweenCoarsePoses() {
  // Poses 4 mm apart, roll sunk 0.2 mm: midway the discrete roll's rim is 5 - sqrt(25 - 4) =
  // 0.417 mm above its lowest line, above the plane, so the plane stays; the swept hull of two
  // poses has a straight bottom line at the full depth, z = 0.25 - 0.2.
  load(projectOf(plane(), {rollAlongY(4.0, 0.2)}));
  const std::vector<float> discrete = simulated(SweepMode::Discrete);
  QVERIFY(label("simulationReport").contains("discrete"));
  const std::vector<float> swept = simulated(SweepMode::Swept);
  QVERIFY(label("simulationReport").contains("swept volume"));
  QVERIFY(!discrete.empty() && !swept.empty());
  const auto& part = *project().part;
  const int n = part.raster().steps();
  std::size_t midway = 0;
  double sweptLo = 1e9, sweptHi = -1e9, discreteLo = 1e9;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const auto g = part.surfacePoint(f, i, k);  // heights of the stock: z = h L with L = 1
        const double yMid = 7.0 + 4.0 * std::round((g.y() - 7.0) / 4.0);
        if (std::abs(g.x() - 20.0) > 3.0 || std::abs(g.y() - yMid) > 0.1 || yMid < 6.0 ||
            yMid > 24.0)
          continue;
        const std::size_t at = f * part.pointsPerFace() + part.raster().index(i, k);
        ++midway;
        sweptLo = std::min(sweptLo, double(swept[at]));
        sweptHi = std::max(sweptHi, double(swept[at]));
        discreteLo = std::min(discreteLo, double(discrete[at]));
      }
  QVERIFY(midway > 20);
  QVERIFY2(sweptLo > kPlaneZ - 0.2 - 1e-3 && sweptHi < kPlaneZ - 0.2 + 0.005,
           qPrintable(QString("swept midway %1 .. %2").arg(sweptLo).arg(sweptHi)));
  QVERIFY2(discreteLo > kPlaneZ - 1e-6, qPrintable(QString::number(discreteLo)));
  // The playback cuts with the same options: stepping through in swept mode gives the same.
  auto& playback = panel().playback();
  playback.setPathIndex(0);
  for (std::size_t i = 0; i < project().paths[0].poses.size(); ++i) QVERIFY(playback.step());
  QVERIFY(!playback.isActive());  // finished and applied
  QCOMPARE(project().part->allHeights(), swept);
  undo().undo();
}

void SimulationOptionsTest::correctPenetrationsInABore() {
  // A bore of radius 20 machined from inside by a roll fed along the axis, its axis tangent to
  // the circle: the 10 mm wide roll touching at the middle penetrates by the sagitta
  // 20 - sqrt(400 - 25) at both rims, so each pose must rise by that along the inward normal.
  const double radius = 20.0, sagitta = radius - std::sqrt(radius * radius - 25.0);
  auto bore = ddfcam::ddf::cylinderPart(
      {.radiusMm = radius, .lengthMm = 30.0, .segments = 48, .rings = 10, .m = 9});
  ddfcam::planning::ToolPath path;
  path.name = "bore";
  const Eigen::Vector3d inward(-1.0, 0.0, 0.0);
  for (double z = 8.0; z <= 22.0 + 1e-9; z += 2.0) {
    const Eigen::Vector3d c(radius, 0.0, z);
    path.poses.push_back({ddfcam::planning::rollPoseAtContact(c, inward, {0, 0, 1}, 5.0, 0.0), c});
  }
  path.passStarts = {0};
  load(projectOf(std::move(bore), {path}));
  const int count = undo().count();
  QVERIFY(panel().correctPenetrations(0, 50, 3));
  waitOk();
  QCOMPARE(undo().count(), count + 1);
  const auto& corrected = project().paths[0];
  QCOMPARE(corrected.poses.size(), path.poses.size());
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const Eigen::Vector3d d =
        corrected.poses[i].pose.translation() - path.poses[i].pose.translation();
    // Cell centres reach to half a 0.2 mm cell from the rims (slope 0.26, 48-gon 0.066).
    QVERIFY2(
        d.dot(inward) > sagitta - 0.04 && d.dot(inward) < sagitta + 1e-3,
        qPrintable(
            QString("pose %1 lifted by %2, sagitta %3").arg(i).arg(d.dot(inward)).arg(sagitta)));
    // Along the normal of the raster triangle at the contact: radial up to its facet tilt.
    const double sideways = (d - d.dot(inward) * inward).norm();
    QVERIFY2(sideways < 0.03 * d.norm(), qPrintable(QString::number(sideways)));
  }
  const QString text = label("correctionLabel");
  QVERIFY2(text.startsWith(QString("%1 poses lifted, max lift 0.").arg(path.poses.size())),
           qPrintable(text));
  undo().undo();
  QVERIFY(project().paths[0] == path);
}

void SimulationOptionsTest::prestonRemovesTheConservedVolume() {
  // Oracle (oracles note, material removal): a long pass removes the cross-section
  // K_p F v_s / v_f whatever the contact shape, so the volume is that times the path length.
  load(projectOf(plane(), {rollAlongY(0.5, 0.0)}));
  panel().options().setRemovalModel(RemovalModel::Preston);
  QVERIFY(!panel().playback().isEnabled());
  panel().options().setPreston(1e-7, 10.0, 30.0, 600.0);
  const std::vector<float> before = project().part->allHeights();
  f_.window->console().clear();
  QVERIFY(panel().simulatePath(0));
  waitOk();
  const auto& after = project().part->allHeights();
  std::size_t lowered = 0, raised = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    lowered += after[i] < before[i];
    raised += after[i] > before[i];
  }
  QVERIFY(lowered > 100);
  QCOMPARE(raised, std::size_t{0});
  const double expected = 1e-7 * 10.0 * 30000.0 / 10.0 * 20.0;
  const double measured = ddfcam::planning::volumeBetween(*project().part, before, after);
  QVERIFY2(std::abs(measured - expected) < 0.05 * expected,
           qPrintable(QString("%1 vs %2 mm³").arg(measured).arg(expected)));
  const QRegularExpression removed("removed ([0-9.]+) mm³");
  const auto match = removed.match(label("simulationReport"));
  QVERIFY2(match.hasMatch(), qPrintable(label("simulationReport")));
  QVERIFY(match.captured(1).toDouble() > 0.0);
  QVERIFY(f_.window->console().text().contains("Preston removal along 'line': removed"));
  panel().options().setRemovalModel(RemovalModel::Rigid);
  QVERIFY(panel().playback().isEnabled());
  QVERIFY(raisePanel("simulation"));
  auto* scroll = panel().findChild<QScrollArea*>("simulationScroll");
  ddfcam::test::dumpFrame(scroll->widget()->grab().toImage(), "simulation_options_panel");
}

void SimulationOptionsTest::prestonFeedIsThePathsFeed() {
  // One feed: the one exported programs are written with (ToolPath::feedMmPerMin) is the one
  // the panel shows and Preston removal uses (it showed 600 mm/min whatever the path's feed).
  ddfcam::planning::ToolPath path = rollAlongY(0.5, 0.0);
  path.feedMmPerMin = 1500.0;
  load(projectOf(plane(), {path}));
  auto* feed = f_.window->findChild<QDoubleSpinBox*>("prestonFeedSpin");
  QCOMPARE(feed->value(), 1500.0);
  panel().options().setRemovalModel(RemovalModel::Preston);
  const ddfcam::planning::PrestonParams shown = panel().options().prestonParams();
  const std::vector<float> before = project().part->allHeights();
  QVERIFY(panel().simulatePath(0));
  waitOk();
  // Oracle as above: cross-section K_p F v_s / v_f times the 20 mm path.
  const double expected = shown.prestonCoefficientMm2PerN * shown.forceN *
                          shown.surfaceSpeedMmPerS / (1500.0 / 60.0) * 20.0;
  const double measured =
      ddfcam::planning::volumeBetween(*project().part, before, project().part->allHeights());
  QVERIFY2(std::abs(measured - expected) < 0.05 * expected,
           qPrintable(QString("%1 vs %2 mm³").arg(measured).arg(expected)));
  undo().undo();
  // Editing the feed edits the selected path: one undo step, saved with the path.
  const int step = undo().index();
  feed->setValue(750.0);
  QCOMPARE(project().paths[0].feedMmPerMin, 750.0);
  QCOMPARE(undo().index(), step + 1);
  undo().undo();
  QCOMPARE(project().paths[0].feedMmPerMin, 1500.0);
  QCOMPARE(feed->value(), 1500.0);
  panel().options().setRemovalModel(RemovalModel::Rigid);
}

DDFCAM_GUI_TEST_MAIN(SimulationOptionsTest)
#include "simulation_options_test.moc"
