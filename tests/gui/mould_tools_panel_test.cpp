// SPDX-License-Identifier: MIT
// The Mould tools panel under Xvfb on analytic shapes: cube/sphere morph ends, engraved plate
// scaled and bent, one compensation step of the linear model (alpha law), the convergence
// plot, undo/redo, the radial blend at the picked point, and mesh export read back.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/gui/main_window.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/panels/mould_tools_panel.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/model/project.h>

#include <qcustomplot.h>
#include <QTabWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>

using ddfcam::gui::MouldToolsPanel;
using ddfcam::gui::ResponseSource;

namespace {

constexpr double kAlpha = 0.3;      // springback share of the linear model
constexpr double kRelaxedMm = 0.5;  // the relaxed shape P lies this far above the plane target
constexpr double kFormedMm = 0.3;   // the study's formed plane lies this far above the mould

// A 40 x 30 mm plane mould in z = 0 (the plane patch's support) and a formed plane above it.
ddfcam::planning::Project planeStudy() {
  ddfcam::ddf::PlanePatchParams plane;
  plane.cellsX = 8;
  plane.cellsY = 6;
  plane.m = 5;
  plane.planeZMm = 0.0;
  const ddfcam::ddf::TriangleMesh mould =
      ddfcam::ddf::extractSupportMesh(ddfcam::ddf::planePatch(plane).ddf);
  ddfcam::ddf::TriangleMesh formed = mould;
  for (auto& v : formed.vertices) v.z() += kFormedMm;
  ddfcam::planning::Project p;
  ddfcam::planning::MouldStudy study;
  study.mould = {"plane mould", "", mould, {}};
  study.formed = ddfcam::planning::LoadedSurface{"plane formed", "", formed, {}};
  study.comparison.resolution = plane.m;
  ddfcam::planning::ComparisonParams params = study.comparison;
  params.sequence.reachMm = 2.0;
  study.result = ddfcam::planning::compareSurfaces(mould, formed, params);
  p.mould = std::move(study);
  return p;
}

double maxAbsZ(const ddfcam::ddf::TriangleMesh& mesh) {
  double m = 0.0;
  for (const auto& v : mesh.vertices) m = std::max(m, std::abs(v.z()));
  return m;
}

}  // namespace

class MouldToolsPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void cubeSphereSliderEndsLieOnCubeAndSphere();
  void scaleVectorsMultipliesTheEngravingDepth();
  void bendPutsThePlateOnTheCylinder();
  void linearModelStepReducesDeviationByAlpha();
  void undoAndRedoOfAStep();
  void radialBlendHasFullWeightAtThePickedPoint();
  void exportWritesAReadableMesh();

 private:
  MouldToolsPanel* panel() { return f_.window->findChild<MouldToolsPanel*>(); }
  ddfcam::gui::MouldView& view() { return *f_.window->mouldView(); }
  void screenshot(const QString& name) {
    QApplication::processEvents();
    const QString dir = qEnvironmentVariable("DDFCAM_GUI_TEST_OUTPUT");
    if (!dir.isEmpty() && QDir(dir).exists())
      QVERIFY(view().saveScreenshot(QDir(dir).filePath(name + ".png")));
  }
  const ddfcam::planning::CompensationHistory& history() const {
    return *project().mould->compensation;
  }
  void startWithLinearModel();
};

void MouldToolsPanelTest::initTestCase() {
  QVERIFY(openWorkbench(false));
  QVERIFY(panel() != nullptr);
  QVERIFY(raisePanel("mouldTools"));
  f_.window->centralTabs()->setCurrentWidget(f_.window->mouldView());
}

void MouldToolsPanelTest::init() {
  f_.script.errors.clear();
  load(planeStudy());
}

// Independent of the morph code: the cube of edge a has max(|x|,|y|,|z|) = a/2 on its surface;
// the sphere heights come from an icosphere of radius R, whose points lie between its inradius
// (level 4: R cos of about 2.3 degrees) and R.
void MouldToolsPanelTest::cubeSphereSliderEndsLieOnCubeAndSphere() {
  ddfcam::ddf::CubeSphereParams params;
  params.subdivisions = 3;
  params.resolution = 3;
  params.sphereLevel = 4;
  panel()->setCubeSphereParams(params);
  QVERIFY(panel()->showCubeSphereDemo());
  waitOk();
  QVERIFY(panel()->cubeSphere().has_value());
  const double half = params.edgeMm / 2.0, radius = panel()->cubeSphere()->sphereRadiusMm;
  panel()->setMorphTime(0.0);
  QVERIFY(!panel()->shownSurface().vertices.empty());
  for (const auto& v : panel()->shownSurface().vertices)
    QVERIFY2(std::abs(v.cwiseAbs().maxCoeff() - half) < 1e-6 * half,
             qPrintable(QString::number(v.cwiseAbs().maxCoeff())));
  panel()->setMorphTime(1.0);
  for (const auto& v : panel()->shownSurface().vertices)
    QVERIFY2(v.norm() <= radius * (1 + 1e-6) && v.norm() >= radius * 0.995,
             qPrintable(QString::number(v.norm() / radius)));
  panel()->setMorphTime(0.5);
  screenshot("mould_tools_cube_sphere_t05");
}

// Fig. 9.2 b/c: vectors x3 triple the engraving depth, x-3 turns the grooves into ridges; the
// depth at every vertex is checked against the plate's own groove formula.
void MouldToolsPanelTest::scaleVectorsMultipliesTheEngravingDepth() {
  ddfcam::ddf::EngravedPlateParams plate;
  plate.subdivisions = 6;
  plate.resolution = 9;
  panel()->setEngravedPlateParams(plate);
  QVERIFY(panel()->showEngravedPlate());
  screenshot("mould_tools_plate");
  for (const double factor : {3.0, -1.0}) {  // x3, then x(-1): overall -3
    QVERIFY(panel()->scalePlateVectors(factor));
    const double total = factor == 3.0 ? 3.0 : -3.0;
    for (const auto& v : panel()->shownSurface().vertices) {
      const double expected = -total * ddfcam::ddf::engravingDepthMm(plate, v.x(), v.y());
      QVERIFY2(std::abs(v.z() - expected) < 1e-4,
               qPrintable(QString("%1 vs %2").arg(v.z()).arg(expected)));
    }
    screenshot(QString("mould_tools_plate_x%1").arg(total));
  }
  QVERIFY(f_.script.errors.isEmpty());
}

// Fig. 9.2 d: with the default bend frame the plate's ungrooved points land on the cylinder of
// radius R about the axis through (0, *, -R).
void MouldToolsPanelTest::bendPutsThePlateOnTheCylinder() {
  ddfcam::ddf::EngravedPlateParams plate;
  plate.subdivisions = 6;
  plate.resolution = 5;
  panel()->setEngravedPlateParams(plate);
  QVERIFY(panel()->showEngravedPlate());
  const double radius = 80.0;
  QVERIFY(panel()->bendPlateOntoCylinder(radius));
  int checked = 0;
  const auto& flat = ddfcam::ddf::extractRasterMesh(ddfcam::ddf::engravedPlate(plate)).mesh;
  const auto& bent = panel()->shownSurface();
  QCOMPARE(bent.vertices.size(), flat.vertices.size());
  for (std::size_t i = 0; i < bent.vertices.size(); ++i) {
    if (std::abs(flat.vertices[i].z()) > 1e-12) continue;
    // Support vertices lie on the cylinder exactly; raster points between them on chords.
    const double r = std::hypot(bent.vertices[i].x(), bent.vertices[i].z() + radius);
    QVERIFY2(r <= radius + 1e-6 && r > radius - 100.0 * 100.0 / (8 * radius * 36),
             qPrintable(QString::number(r)));
    ++checked;
  }
  QVERIFY(checked > 10);
  screenshot("mould_tools_plate_bent");
}

void MouldToolsPanelTest::startWithLinearModel() {
  QVERIFY(panel()->startCompensation());
  QVERIFY(project().mould->compensation.has_value());
  const ddfcam::ddf::DisplacementField& target = history().target;
  ddfcam::planning::LinearSpringbackModel model;
  model.alpha = kAlpha;
  model.relaxedHeights.resize(target.allHeights().size());
  // Plane support, parallel equal vectors: P is kRelaxedMm above the target everywhere.
  const double length = target.vector(0).norm();
  std::fill(model.relaxedHeights.begin(), model.relaxedHeights.end(),
            static_cast<float>(kRelaxedMm / length));
  panel()->setLinearModel(model);
  panel()->setResponseSource(ResponseSource::LinearModel);
  panel()->setLambda(1.0);
}

// s = P + (1 - alpha)(c - P): the first mould (the target) forms alpha P; one step with lambda 1
// leaves alpha^2 P. Max and RMS are uniform on the plane, so both drop by alpha.
void MouldToolsPanelTest::linearModelStepReducesDeviationByAlpha() {
  startWithLinearModel();
  QVERIFY(panel()->step());
  waitOk();
  QVERIFY(panel()->evaluateLastMould());
  waitOk();
  QCOMPARE(history().iterations.size(), std::size_t{2});
  QCOMPARE(panel()->historyRows(), 2);
  const auto& it0 = history().iterations[0];
  const auto& it1 = history().iterations[1];
  QVERIFY2(std::abs(it0.maxDeviationMm - kAlpha * kRelaxedMm) < 1e-4,
           qPrintable(QString::number(it0.maxDeviationMm)));
  QVERIFY(std::abs(it0.rmsDeviationMm - kAlpha * kRelaxedMm) < 1e-4);
  QVERIFY(std::abs(it1.maxDeviationMm - kAlpha * kAlpha * kRelaxedMm) < 1e-4);
  QVERIFY(std::abs(it1.rmsDeviationMm / it0.rmsDeviationMm - kAlpha) < 1e-3);
  // The convergence plot: one point per iteration in each series.
  QCustomPlot* plot = f_.window->plots().findPlot(MouldToolsPanel::kConvergenceTab);
  QVERIFY(plot != nullptr);
  QCOMPARE(plot->graphCount(), 2);
  for (int g = 0; g < 2; ++g) QCOMPARE(plot->graph(g)->data()->size(), 2);
  QVERIFY(std::abs(plot->graph(0)->data()->at(1)->value - it1.maxDeviationMm) < 1e-9);
  // The shown mould moved lambda alpha P below the target everywhere.
  QVERIFY(view().primaryColoured());
  for (float offset : panel()->shownMouldOffsets())
    QVERIFY2(std::abs(offset + kAlpha * kRelaxedMm) < 1e-4, qPrintable(QString::number(offset)));
  ddfcam::test::dumpFrame(panel()->grab().toImage(), "mould_tools_panel_widgets");
  f_.window->plots().showPlot(MouldToolsPanel::kConvergenceTab);
  screenshot("mould_tools_compensated_mould");
  ddfcam::test::dumpFrame(plot->toPixmap(600, 400).toImage(), "mould_tools_convergence");
}

void MouldToolsPanelTest::undoAndRedoOfAStep() {
  startWithLinearModel();
  QVERIFY(panel()->step());
  waitOk();
  QUndoStack& undo = *f_.window->document().undoStack();
  QCOMPARE(history().iterations.size(), std::size_t{2});
  undo.undo();
  QCOMPARE(history().iterations.size(), std::size_t{1});
  QVERIFY(history().iterations[0].formedHeights.empty());
  QCOMPARE(panel()->historyRows(), 1);
  undo.redo();
  QCOMPARE(history().iterations.size(), std::size_t{2});
  QCOMPARE(panel()->historyRows(), 2);
  undo.undo();
  undo.undo();  // the start
  QVERIFY(!project().mould->compensation.has_value());
  QCOMPARE(panel()->historyRows(), 0);
}

// Radial d = value (1 - S(dist / radius)): full strength at the picked centre, so the blended
// point there lies value x the formed offset above the mould; beyond the radius it stays put.
void MouldToolsPanelTest::radialBlendHasFullWeightAtThePickedPoint() {
  ddfcam::planning::BlendParams params;
  params.kind = ddfcam::planning::BlendKind::Radial;
  params.value = 0.5;
  params.radiusMm = 10.0;
  panel()->setBlendParams(params);
  panel()->setBlendPickMode(ddfcam::gui::BlendPickMode::PickCentre);
  const Eigen::Vector3d centre(20.0, 15.0, 0.0);  // a support vertex of the plane grid
  panel()->applyPick(centre);
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QVERIFY(!panel()->blendWeightsShown().empty());
  QVERIFY(std::abs(*std::max_element(panel()->blendWeightsShown().begin(),
                                     panel()->blendWeightsShown().end()) -
                   0.5) < 1e-6);
  const auto& mesh = panel()->shownSurface();
  int atCentre = 0, far = 0;
  for (const auto& v : mesh.vertices) {
    const double d = std::hypot(v.x() - centre.x(), v.y() - centre.y());
    if (d < 1e-6) {
      QVERIFY(std::abs(v.z() - 0.5 * kFormedMm) < 1e-4);
      ++atCentre;
    } else if (d > 10.0 + 1e-6) {
      QVERIFY(std::abs(v.z()) < 1e-4);
      ++far;
    }
  }
  QCOMPARE(atCentre, 1);
  QVERIFY(far > 10);
  screenshot("mould_tools_radial_blend");
}

void MouldToolsPanelTest::exportWritesAReadableMesh() {
  startWithLinearModel();
  QVERIFY(panel()->step());
  waitOk();
  const QString dir = f_.dir.path();
  QVERIFY(panel()->exportMould(1, dir + "/mould1.stl"));
  const ddfcam::ddf::TriangleMesh mould = ddfcam::io::readMesh((dir + "/mould1.stl").toStdString());
  QVERIFY(!mould.triangles.empty());
  // c_1 = -lambda alpha P: the exported mould lies alpha P below the plane target.
  for (const auto& v : mould.vertices) QVERIFY(std::abs(v.z() + kAlpha * kRelaxedMm) < 1e-4);
  ddfcam::ddf::EngravedPlateParams plate;
  plate.subdivisions = 4;
  plate.resolution = 5;
  panel()->setEngravedPlateParams(plate);
  QVERIFY(panel()->showEngravedPlate());
  QVERIFY(panel()->exportShownSurface(dir + "/plate.ply"));
  const ddfcam::ddf::TriangleMesh back = ddfcam::io::readMesh((dir + "/plate.ply").toStdString());
  QCOMPARE(back.triangles.size(), panel()->shownSurface().triangles.size());
  QVERIFY(std::abs(maxAbsZ(back) - maxAbsZ(panel()->shownSurface())) < 1e-4);
  QVERIFY(f_.script.errors.isEmpty());
}

DDFCAM_GUI_TEST_MAIN(MouldToolsPanelTest)
#include "mould_tools_panel_test.moc"
