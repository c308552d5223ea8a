// SPDX-License-Identifier: MIT
// The Mould comparison panel and the mould view under Xvfb: a flat mould and a ramp-shaped
// formed plate (deviation known in closed form), loaded from files through the panel, compared
// as a job; statistics against an independent compareSurfaces run and the analytic ramp,
// histogram, morph slider points, a section drawn by two clicks, undo/redo, both layouts and
// the shared springback pair once.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/adapters/section_plot.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/inspection/surface_comparison.h>

#include <qcustomplot.h>
#include <QDir>
#include <QFileInfo>
#include <QTabWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <cmath>

using ddfcam::gui::MouldPanel;
using ddfcam::gui::MouldView;

namespace {

constexpr double kSizeMm = 40.0;
constexpr int kCells = 10;

// Deviation of the formed plate over the flat mould z = 0 (normal +z): a ramp in x, exact at
// every raster point because both surfaces are planes along the stubbles.
double rampZ(double x) {
  return -0.2 + 0.8 * x / kSizeMm;
}

// A kCells x kCells grid of squares split into counter-clockwise triangles (normal +z), z(x).
ddfcam::ddf::TriangleMesh grid(double (*z)(double)) {
  ddfcam::ddf::TriangleMesh mesh;
  const double h = kSizeMm / kCells;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) mesh.vertices.emplace_back(i * h, j * h, z(i * h));
  auto at = [](int i, int j) { return j * (kCells + 1) + i; };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

double flatZ(double) {
  return 0.0;
}

QString formatMm(double value) {
  return QString::number(value, 'f', 3) + QStringLiteral(" mm");
}

}  // namespace

class MouldPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void statisticsMatchAnIndependentComparison();
  void bandAndFlipReevaluateTheComparison();
  void morphSliderMovesTheFormedSide();
  void sectionByTwoClicksPlotsBothCurves();
  void undoAndRedoTheComparison();
  void layoutsRender();
  void sharedSpringbackPair();

 private:
  MouldPanel* panel() { return f_.window->findChild<MouldPanel*>(); }
  MouldView* view() { return f_.window->mouldView(); }
  void loadAndCompare();
  QString mouldPath_, formedPath_;
};

void MouldPanelTest::initTestCase() {
  QVERIFY(openWorkbench(false));
  QVERIFY(panel() != nullptr);
  QVERIFY(view() != nullptr);
  QCOMPARE(f_.window->workbench().mouldView, view());
  mouldPath_ = f_.dir.filePath("mould.obj");
  formedPath_ = f_.dir.filePath("formed.obj");
  ddfcam::io::writeMesh(grid(flatZ), mouldPath_.toStdString());
  ddfcam::io::writeMesh(grid(rampZ), formedPath_.toStdString());
  // The Mould tab of the central area, raised as a user would.
  f_.window->centralTabs()->setCurrentWidget(view());
  QVERIFY(raisePanel("mouldComparison"));
}

void MouldPanelTest::init() {
  f_.script.errors.clear();
  load(ddfcam::planning::Project{});
  panel()->setResolution(4);
  panel()->setToleranceBand({-0.5, 0.5});
  panel()->setFlipNormal(false);
}

void MouldPanelTest::loadAndCompare() {
  QVERIFY(panel()->loadMould(mouldPath_));
  QVERIFY(panel()->loadFormed(formedPath_));
  QVERIFY(project().mould && project().mould->formed);
  QVERIFY(panel()->compare());
  waitOk();
  QVERIFY(project().mould->result.has_value());
}

void MouldPanelTest::statisticsMatchAnIndependentComparison() {
  loadAndCompare();
  ddfcam::planning::ComparisonParams params;
  params.resolution = 4;
  params.band = {-0.5, 0.5};
  const auto expected =
      ddfcam::planning::compareSurfaces(grid(flatZ), grid(rampZ), params).statistics;
  const QString text = panel()->statisticsText();
  for (double v : {expected.maxMm, expected.minMm, expected.meanMm, expected.sigmaMm})
    QVERIFY2(text.contains(formatMm(v)), qPrintable(text + " lacks " + formatMm(v)));
  QVERIFY(text.contains(QString::number(expected.inTolerancePercent, 'f', 1) + " %"));
  QVERIFY(text.contains(QString::number(expected.areaMm2, 'f', 1) + " mm²"));
  // The analytic ramp: from -0.2 at x = 0 to 0.6 at x = 40 mm, mean 0.2, area 40 x 40.
  QVERIFY(std::abs(expected.maxMm - 0.6) < 1e-3 && std::abs(expected.minMm + 0.2) < 1e-3);
  QVERIFY(std::abs(expected.meanMm - 0.2) < 1e-3);
  QVERIFY(std::abs(expected.areaMm2 - kSizeMm * kSizeMm) < 1e-3);
  QVERIFY(panel()->crossingText().contains("holds"));
  QVERIFY(view()->primaryColoured());
  QCustomPlot* plot = f_.window->plots().findPlot(MouldPanel::kHistogramTab);
  QVERIFY(plot != nullptr);
  QVERIFY(plot->plottableCount() >= 2);  // bars of at least two tolerance classes
  QCOMPARE(f_.window->plots().currentPlotName(), MouldPanel::kHistogramTab);
}

// Oracle: the ramp -0.2 + 0.8 x / 40 lies within +-0.1 for x in [5, 15], a quarter of the plate;
// reversed, it runs from 0.2 down to -0.6. Each of the two band edges may misplace up to one
// raster spacing (4 mm / 3 at m = 4) of the 40 mm: 6.7 % of the area.
void MouldPanelTest::bandAndFlipReevaluateTheComparison() {
  loadAndCompare();
  QCustomPlot* plot = f_.window->plots().findPlot(MouldPanel::kHistogramTab);
  QStringList names;
  for (int i = 0; i < plot->plottableCount(); ++i) names << plot->plottable(i)->name();
  QVERIFY2(names.contains("short of the mould") && names.contains("beyond the mould"),
           qPrintable(names.join(", ")));
  panel()->setToleranceBand({-0.1, 0.1});
  const auto& stats = [this]() -> const ddfcam::planning::ErrorStatistics& {
    return project().mould->result->statistics;
  };
  const double bound = 2.0 * (kSizeMm / kCells / 3.0) / kSizeMm * 100.0;
  QVERIFY2(std::abs(stats().inTolerancePercent - 25.0) <= bound,
           qPrintable(QString::number(stats().inTolerancePercent)));
  QVERIFY(panel()->statisticsText().contains(QString::number(stats().inTolerancePercent, 'f', 1)));
  panel()->setFlipNormal(true);
  QVERIFY(std::abs(stats().maxMm - 0.2) < 1e-3 && std::abs(stats().minMm + 0.6) < 1e-3);
  QVERIFY(std::abs(stats().inTolerancePercent - 25.0) <= bound);
  f_.window->document().undoStack()->undo();
  QVERIFY(std::abs(stats().maxMm - 0.6) < 1e-3);
  f_.window->document().undoStack()->undo();
  QCOMPARE(project().mould->result->band.upperMm, 0.5);
  waitOk();
}

void MouldPanelTest::morphSliderMovesTheFormedSide() {
  loadAndCompare();
  const auto& r = *project().mould->result;
  const ddfcam::ddf::DisplacementField& ddf = r.sequence.stages.front().ddf;
  const ddfcam::ddf::RasterMesh raster = ddfcam::ddf::extractRasterMesh(ddf);
  for (double lambda : {0.0, 1.0, 0.5}) {
    QVERIFY(panel()->setMorphLambda(lambda));
    QCOMPARE(view()->secondaryPointCount(), static_cast<int>(raster.mesh.vertices.size()));
    for (std::size_t v = 0; v < raster.vertexPoint.size(); ++v) {
      ddfcam::ddf::PointCopy copy;
      bool first = true;
      ddf.topology().forEachCopy(raster.vertexPoint[v], [&](ddfcam::ddf::PointCopy c) {
        if (first) copy = c;
        first = false;
      });
      const ddfcam::ddf::RasterCoord rc = ddf.topology().coord(copy);
      const Eigen::Vector3d mould = ddf.basePoint(copy.face, ddf.rasterBary(rc.i, rc.k));
      // The formed plate above the mould point: the stubbles of a flat mould are vertical.
      const Eigen::Vector3d formed(mould.x(), mould.y(), rampZ(mould.x()));
      const Eigen::Vector3d expected = mould + lambda * (formed - mould);
      const Eigen::Vector3d shown = view()->secondaryPoint(static_cast<int>(v));
      QVERIFY2((shown - expected).norm() < 1e-5, qPrintable(QString("lambda %1 vertex %2 off by %3")
                                                                .arg(lambda)
                                                                .arg(v)
                                                                .arg((shown - expected).norm())));
    }
  }
  QVERIFY(panel()->exportMorphSurface(f_.dir.filePath("morph.obj")));
  QCOMPARE(ddfcam::io::readMesh(f_.dir.filePath("morph.obj").toStdString()).triangles.size(),
           raster.mesh.triangles.size());
  QVERIFY(panel()->exportDeviation(f_.dir.filePath("deviation.vtp")));
  QVERIFY(QFileInfo(f_.dir.filePath("deviation.vtp")).size() > 0);
  waitOk();
}

void MouldPanelTest::sectionByTwoClicksPlotsBothCurves() {
  loadAndCompare();
  view()->primaryView().viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  QApplication::processEvents();
  panel()->setPickMode(MouldPanel::PickMode::SectionStart);
  const Eigen::Vector3d a(4.0, 21.0, 0.0), b(36.0, 21.0, 0.0);
  QVERIFY(view()->pickAt(MouldView::kPrimary, view()->primaryView().widgetPosition(a)));
  QCOMPARE(panel()->pickMode(), MouldPanel::PickMode::SectionEnd);
  QVERIFY(view()->pickAt(MouldView::kPrimary, view()->primaryView().widgetPosition(b)));
  QCOMPARE(panel()->pickMode(), MouldPanel::PickMode::None);
  waitOk();
  QCustomPlot* plot = f_.window->plots().findPlot(MouldPanel::kSectionTab);
  QVERIFY(plot != nullptr);
  QCOMPARE(ddfcam::gui::sectionCurveCount(plot), 2);
  // The formed curve rises by the ramp's slope over the drawn span.
  auto* formed = qobject_cast<QCPCurve*>(plot->plottable(1));
  QVERIFY(formed != nullptr && formed->data()->size() >= 2);
  const double t0 = formed->data()->constBegin()->value;
  const double t1 = (formed->data()->constEnd() - 1)->value;
  QVERIFY2(std::abs((t1 - t0) - 0.8 * 32.0 / kSizeMm) < 0.05,
           qPrintable(QString("rise %1").arg(t1 - t0)));
}

void MouldPanelTest::undoAndRedoTheComparison() {
  loadAndCompare();
  const QString shown = panel()->statisticsText();
  QUndoStack& undo = *f_.window->document().undoStack();
  undo.undo();
  QVERIFY(!project().mould->result);
  QVERIFY(panel()->statisticsText().contains("No comparison"));
  QVERIFY(!view()->primaryColoured());
  undo.redo();
  QVERIFY(project().mould->result);
  QCOMPARE(panel()->statisticsText(), shown);
  undo.undo();
  undo.undo();
  undo.undo();
  QVERIFY(!project().mould);
  QCOMPARE(view()->secondaryPointCount(), 0);
}

void MouldPanelTest::layoutsRender() {
  loadAndCompare();
  QVERIFY(panel()->setMorphLambda(2.0));
  view()->fitCameras();
  const QString out = qEnvironmentVariable("DDFCAM_GUI_TEST_OUTPUT");
  for (auto layout : {MouldView::Layout::SideBySide, MouldView::Layout::Overlay}) {
    view()->setLayout(layout);
    QApplication::processEvents();
    QCOMPARE(view()->secondaryView().isVisible(), layout == MouldView::Layout::SideBySide);
    const QImage frame = view()->primaryView().renderImage();
    const auto stats = ddfcam::test::frameStats(frame, view()->primaryView().backgroundColor());
    QVERIFY2(stats.centreForeground > 0.3, qPrintable(QString::number(stats.centreForeground)));
    QVERIFY(stats.cornersBackground);
    const QString name = layout == MouldView::Layout::Overlay ? "mould_overlay" : "mould_side";
    if (!out.isEmpty()) QVERIFY(view()->saveScreenshot(QDir(out).filePath(name + ".png")));
  }
  view()->setLayout(MouldView::Layout::SideBySide);
}

void MouldPanelTest::sharedSpringbackPair() {
  const QString dir = QStringLiteral(DDFCAM_SHARED_DATA_DIR) + "/meshes/springback-deepdrawn";
  if (!QFileInfo::exists(dir + "/target_AF_bs.stl")) QSKIP("shared springback pair absent");
  QVERIFY(panel()->loadMould(dir + "/target_AF_bs.stl"));
  QVERIFY(panel()->loadFormed(dir + "/mesh_ausgerichtet1.stl"));
  panel()->setResolution(2);
  QElapsedTimer timer;
  timer.start();
  QVERIFY(panel()->compare());
  waitOk();
  qInfo("shared pair compared at m = 2 in %lld ms: %s | %s", timer.elapsed(),
        qPrintable(panel()->statisticsText()), qPrintable(panel()->crossingText()));
  const auto& s = project().mould->result->statistics;
  // The lead's distances of formed vertices to the target: min -7.77, 1 % -6.78, 99 % 1.15,
  // max 6.42 mm; the mould's raster points see the deep side, the positive outliers (formed
  // vertices off the target's rim) have no mould point above them.
  QVERIFY2(s.minMm < -5.0 && s.minMm > -9.0, qPrintable(QString::number(s.minMm)));
  QVERIFY2(s.maxMm > 0.5 && s.maxMm < 8.0, qPrintable(QString::number(s.maxMm)));
  QVERIFY(panel()->setMorphLambda(0.5));
  view()->setLayout(MouldView::Layout::SideBySide);
  view()->fitCameras();
  QApplication::processEvents();
  const QString out = qEnvironmentVariable("DDFCAM_GUI_TEST_OUTPUT");
  if (!out.isEmpty()) {
    QVERIFY(view()->saveScreenshot(QDir(out).filePath("mould_springback.png")));
    f_.window->plots().exportPlot(MouldPanel::kHistogramTab,
                                  QDir(out).filePath("mould_springback_histogram.png"));
  }
  waitOk();
}

DDFCAM_GUI_TEST_MAIN(MouldPanelTest)
#include "mould_panel_test.moc"
