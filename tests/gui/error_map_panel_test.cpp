// SPDX-License-Identifier: MIT
// The Error map panel under Xvfb: the demo part ground by its roll passes against its stock
// state: the groove is overcut by the infeed, the colours the view draws agree with the
// area statistics, band edits recolour, the deviation along a pass follows the groove, undo,
// and the scallop table against the ball-on-plane formula.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/adapters/error_plots.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/panels/error_map_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <qcustomplot.h>
#include <QDockWidget>
#include <QLabel>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkScalarsToColors.h>
#include <vtkTexture.h>

#include <algorithm>
#include <array>
#include <cmath>

using ddfcam::gui::ErrorMapPanel;
using ddfcam::planning::ToleranceBand;
using ddfcam::planning::ToleranceClass;

namespace {

// The demo passes sink the roll this far below the design surface (DemoPassesParams); the
// demo stock lies this far above it along z (DemoPartParams).
const double kInfeedMm = ddfcam::planning::DemoPassesParams{}.depthMm;
const double kStockMm = ddfcam::ddf::DemoPartParams{}.allowanceMm;

struct ClassAreas {
  std::array<double, 3> area{};  // indexed by ToleranceClass
  double noValue = 0.0;          // drawn in the grey of "no value"
  double percent(ToleranceClass c) const {
    return 100.0 * area[static_cast<int>(c)] / (area[0] + area[1] + area[2]);
  }
};

// Reads the colours back from what the surface actor draws, classified by colour:
// - per vertex: every display vertex's scalar through the actor's own lookup table, each
//   triangle's area split equally among its corners;
// - textured (a coarse adaptive display coloured at raster resolution): the texel each
//   fragment samples (nearest, from the interpolated texture coordinates) at 21 points of a
//   barycentric grid per triangle, each carrying a 21st of the triangle's area.
// Independent of planning::errorStatistics' raster quadrature.
using Corners = std::array<vtkIdType, 3>;

// Adds @p area to the class of colour @p rgb; the grey of "no value" (a raster point where the
// desired surface has none) belongs to no class, as in the statistics.
void addColour(const std::array<double, 3>& rgb, double area, ClassAreas& result) {
  if (std::abs(rgb[0] - rgb[1]) < 0.02 && std::abs(rgb[1] - rgb[2]) < 0.02) {
    result.noValue += area;
    return;
  }
  result.area[static_cast<int>(ddfcam::gui::toleranceClassOfColour(rgb))] += area;
}

void addPerVertex(vtkPolyData* data, vtkScalarsToColors* table, const Corners& ids, double area,
                  ClassAreas& result) {
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  for (vtkIdType id : ids) {
    std::array<double, 3> rgb{};
    table->GetColor(scalars->GetTuple1(id), rgb.data());
    addColour(rgb, area / 3.0, result);
  }
}

void addTextured(vtkPolyData* data, vtkImageData* image, const Corners& ids, double area,
                 ClassAreas& result) {
  const int* size = image->GetDimensions();
  std::array<Eigen::Vector2d, 3> st;
  for (int c = 0; c < 3; ++c) {
    const double* t = data->GetPointData()->GetTCoords()->GetTuple2(ids[c]);
    st[c] = {t[0], t[1]};
  }
  constexpr int kSteps = 5;  // 21 points: (a, b, c) / 5 with a + b + c = 5
  for (int a = 0; a <= kSteps; ++a)
    for (int b = 0; a + b <= kSteps; ++b) {
      const Eigen::Vector2d at =
          (a * st[0] + b * st[1] + (kSteps - a - b) * st[2]) / static_cast<double>(kSteps);
      const int x = std::clamp(static_cast<int>(std::floor(at.x() * size[0])), 0, size[0] - 1);
      const int y = std::clamp(static_cast<int>(std::floor(at.y() * size[1])), 0, size[1] - 1);
      const auto* texel = static_cast<const unsigned char*>(image->GetScalarPointer(x, y, 0));
      const std::array<double, 3> rgb = {texel[0] / 255.0, texel[1] / 255.0, texel[2] / 255.0};
      addColour(rgb, area / 21.0, result);
    }
}

ClassAreas drawnClassAreas(vtkActor* actor) {
  vtkMapper* mapper = actor->GetMapper();
  auto* data = vtkPolyData::SafeDownCast(mapper->GetInput());
  vtkDataArray* tcoords = data->GetPointData()->GetTCoords();
  vtkImageData* image = actor->GetTexture() ? actor->GetTexture()->GetInput() : nullptr;
  const bool textured = image && tcoords && tcoords->GetNumberOfTuples() > 0;
  ClassAreas result;
  vtkCellArray* polys = data->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (polys->InitTraversal(); polys->GetNextCell(ids);) {
    if (ids->GetNumberOfIds() != 3) continue;
    const Corners corners = {ids->GetId(0), ids->GetId(1), ids->GetId(2)};
    std::array<Eigen::Vector3d, 3> p;
    for (int c = 0; c < 3; ++c) data->GetPoint(corners[c], p[c].data());
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (textured)
      addTextured(data, image, corners, area, result);
    else
      addPerVertex(data, mapper->GetLookupTable(), corners, area, result);
  }
  return result;
}

}  // namespace

class ErrorMapPanelTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase();
  void init();
  void stockIsLeftAndGroovesAreOvercut();
  void drawnColoursMatchTheStatistics();
  void bandEditsRecolourAndUpdateStatistics();
  void deviationAlongAPassFollowsTheGroove();
  void undoRemovesTheErrorMap();
  void aRegionsMapShowsTheRegionOnly();
  void scallopTableMatchesTheBallFormula();
  void coverageAndClampingShowBesideTheStatistics();

 private:
  ErrorMapPanel* panel() { return f_.window->findChild<ErrorMapPanel*>(); }
  QUndoStack& undo() const { return *f_.window->document().undoStack(); }
  const ddfcam::planning::ScalarField* deviation() const {
    for (const auto& field : project().fields)
      if (field.name == ErrorMapPanel::kDeviationField) return &field;
    return nullptr;
  }
  /// The demo project ground by its passes, simulated once for all tests (each loads a copy).
  ddfcam::planning::Project ground_;
};

void ErrorMapPanelTest::initTestCase() {
  QVERIFY(openWorkbench(false));
  QVERIFY(panel() != nullptr);
  ground_ = ddfcam::planning::demoProject();
  ddfcam::planning::simulatePath(*ground_.part, ground_.tools.front(), ground_.paths.front());
}

// The demo project ground by its three passes (simulated once, outside the code under test),
// then the error map against the design mesh with the band [-0.01, 0.01] mm.
void ErrorMapPanelTest::init() {
  f_.script.errors.clear();
  load(ground_);
  if (auto* dock = f_.window->findChild<QDockWidget*>("panel_errorMap")) dock->raise();
  QVERIFY(panel()->setDesiredSurface(-1));
  panel()->setToleranceBand({-0.01, 0.01});
  QVERIFY(panel()->computeErrorMap());
  waitOk();
  QVERIFY(deviation() != nullptr);
}

void ErrorMapPanelTest::stockIsLeftAndGroovesAreOvercut() {
  const auto& stats = panel()->statistics();
  QVERIFY(stats.has_value());
  // Untouched stock stands the allowance (along z) above the design: at most that along the
  // normal, all of it where the design is level. The grooves reach at least the infeed below
  // it (more where the straight roll's rims dip into concave places).
  QVERIFY2(stats->maxMm <= kStockMm + 1e-3 && stats->maxMm > 0.95 * kStockMm,
           qPrintable(QString::number(stats->maxMm)));
  QVERIFY2(stats->minMm < -0.9 * kInfeedMm, qPrintable(QString::number(stats->minMm)));
  QVERIFY(stats->overcutPercent > 1.0);
  QVERIFY(stats->materialLeftPercent > 1.0);
  QVERIFY(std::abs(stats->inTolerancePercent + stats->overcutPercent + stats->materialLeftPercent -
                   100.0) < 1e-6);
  const auto& display = f_.window->partView().fieldDisplay();
  QCOMPARE(display.field, std::string(ErrorMapPanel::kDeviationField));
  QVERIFY(display.band.has_value());
  QCOMPARE(display.band->lowerMm, -0.01);
}

void ErrorMapPanelTest::drawnColoursMatchTheStatistics() {
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  const QImage frame = view.renderImage();
  ddfcam::test::dumpFrame(frame, "error_map_band");
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "error_map_window");
  const ClassAreas drawn =
      drawnClassAreas(f_.window->partView().scene().actor(ddfcam::gui::Layer::Surface));
  const auto& stats = *panel()->statistics();
  qInfo(
      "drawn: in tolerance %.2f %%, overcut %.2f %%, left %.2f %%; statistics: %.2f %%, "
      "%.2f %%, %.2f %%",
      drawn.percent(ToleranceClass::InTolerance), drawn.percent(ToleranceClass::Overcut),
      drawn.percent(ToleranceClass::MaterialLeft), stats.inTolerancePercent, stats.overcutPercent,
      stats.materialLeftPercent);
  QVERIFY(std::abs(drawn.percent(ToleranceClass::Overcut) - stats.overcutPercent) < 2.0);
  QVERIFY(std::abs(drawn.percent(ToleranceClass::InTolerance) - stats.inTolerancePercent) < 2.0);
  QVERIFY(std::abs(drawn.percent(ToleranceClass::MaterialLeft) - stats.materialLeftPercent) < 2.0);
}

void ErrorMapPanelTest::bandEditsRecolourAndUpdateStatistics() {
  // A band wider than the extremes holds the whole part; a narrower lower bound marks more
  // of the grooves overcut.
  const auto extremes = *panel()->statistics();
  panel()->setToleranceBand({extremes.minMm - 0.01, extremes.maxMm + 0.01});
  QVERIFY(std::abs(panel()->statistics()->inTolerancePercent - 100.0) < 1e-9);
  const ClassAreas wide =
      drawnClassAreas(f_.window->partView().scene().actor(ddfcam::gui::Layer::Surface));
  QVERIFY2(wide.percent(ToleranceClass::InTolerance) > 99.5,
           qPrintable(QString("%1 %2 %3").arg(wide.percent(ToleranceClass::InTolerance)).arg(wide.percent(ToleranceClass::Overcut)).arg(wide.percent(ToleranceClass::MaterialLeft))));
  panel()->setToleranceBand({-0.005, 0.01});
  const double narrow = panel()->statistics()->overcutPercent;
  panel()->setToleranceBand({-0.01, 0.01});
  QVERIFY(narrow > panel()->statistics()->overcutPercent);
  auto* plot = f_.window->plots().findPlot(ErrorMapPanel::kHistogramTab);
  QVERIFY(plot != nullptr);
  QCOMPARE(plot->plottableCount(), 3);
}

void ErrorMapPanelTest::aRegionsMapShowsTheRegionOnly() {
  // A region of the faces left of x = 20 mm (support centroids), the grooves partly inside.
  ddfcam::planning::Project p = project();
  ddfcam::planning::Region left{"left half", {}, {0.3f, 0.3f, 0.9f}, {}};
  double regionArea = 0.0, partArea = 0.0;
  for (int f = 0; f < p.part->faceCount(); ++f) {
    const auto& v = p.part->faceVertices(f);
    const Eigen::Vector3d a = p.part->position(v[0]), b = p.part->position(v[1]),
                          c = p.part->position(v[2]);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    partArea += area;
    if ((a + b + c).x() / 3.0 < 20.0) {
      left.faces.push_back(f);
      regionArea += area;
    }
  }
  p.regions = {left};
  load(p);
  panel()->setRegion(0);
  const auto& stats = *panel()->statistics();
  QCOMPARE(f_.window->partView().fieldDisplay().faces, left.faces);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  ddfcam::test::dumpFrame(view.renderImage(), "error_map_region");
  const ClassAreas drawn =
      drawnClassAreas(f_.window->partView().scene().actor(ddfcam::gui::Layer::Surface));
  // Outside the region the grey of "no value", about the share of the support outside it
  // (the surface lies close over the support); inside, the classes of the region's statistics.
  const double total = drawn.noValue + drawn.area[0] + drawn.area[1] + drawn.area[2];
  QVERIFY2(std::abs(drawn.noValue / total - (1.0 - regionArea / partArea)) < 0.03,
           qPrintable(QString("%1 %2").arg(drawn.noValue / total).arg(regionArea / partArea)));
  QVERIFY(std::abs(drawn.percent(ToleranceClass::Overcut) - stats.overcutPercent) < 2.0);
  QVERIFY(std::abs(drawn.percent(ToleranceClass::MaterialLeft) - stats.materialLeftPercent) < 2.0);
  // The whole part again: no grey.
  panel()->setRegion(-1);
  QVERIFY(f_.window->partView().fieldDisplay().faces.empty());
  const ClassAreas all =
      drawnClassAreas(f_.window->partView().scene().actor(ddfcam::gui::Layer::Surface));
  QVERIFY(all.noValue < 0.01 * (all.area[0] + all.area[1] + all.area[2]));
}

void ErrorMapPanelTest::deviationAlongAPassFollowsTheGroove() {
  QVERIFY(panel()->plotAlongPath(0));
  QCustomPlot* plot = f_.window->plots().findPlot(ErrorMapPanel::kAlongPathTab);
  QVERIFY(plot != nullptr);
  QCPGraph* graph = nullptr;
  for (int i = 0; i < plot->graphCount(); ++i)
    if (plot->graph(i)->name() == "deviation") graph = plot->graph(i);
  QVERIFY(graph != nullptr && graph->data()->size() > 10);
  // Every contact is the bottom of its groove: the infeed below the desired surface.
  int near = 0;
  for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
    near += std::abs(it->value + kInfeedMm) < 0.15 * kInfeedMm ? 1 : 0;
  QVERIFY2(near > 0.9 * graph->data()->size(), qPrintable(QString::number(near)));
}

void ErrorMapPanelTest::undoRemovesTheErrorMap() {
  const int before = undo().count();
  undo().undo();
  QVERIFY(deviation() == nullptr);
  QVERIFY(!panel()->statistics().has_value());
  undo().redo();
  QVERIFY(deviation() != nullptr);
  QVERIFY(panel()->statistics().has_value());
  QCOMPARE(undo().count(), before);
}

void ErrorMapPanelTest::scallopTableMatchesTheBallFormula() {
  // Fewer, shorter passes and a coarser tool mesh than the panel's default (whose precision
  // ScallopPrediction.DefaultPrecisionBallOnPlaneMatchesExactScallop checks): the inscribed
  // mesh leaves at most its chord tolerance, 4 % of the exact scallop here.
  ddfcam::planning::ScallopSimulationParams simulation;
  simulation.passes = 3;
  simulation.passLengthMm = 1.0;
  simulation.chordToleranceMm = 0.001;
  panel()->setScallopSimulation(simulation);
  QVERIFY(panel()->computeScallopTable());
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& rows = panel()->scallopRows();
  QCOMPARE(rows.size(), ErrorMapPanel::defaultScallopCases().size());
  // Ball R5, passes 1 mm apart on a plane: h = R - sqrt(R^2 - w^2/4).
  const double exact = 5.0 - std::sqrt(25.0 - 0.25);
  QVERIFY(std::abs(rows[0].predictedMm - exact) < 1e-12);
  QVERIFY2(std::abs(rows[0].simulatedMm - exact) < 0.1 * exact,
           qPrintable(QString::number(rows[0].simulatedMm)));
  auto* table = f_.window->findChild<QTableWidget*>("scallopTable");
  QVERIFY(table != nullptr);
  QCOMPARE(table->rowCount(), static_cast<int>(rows.size()));
}

// The statistics come with their coverage; heights a cut left at the crust bottom are counted
// and flagged, since the true overcut is deeper there.
void ErrorMapPanelTest::coverageAndClampingShowBesideTheStatistics() {
  QVERIFY(panel()->coverage().has_value());
  QVERIFY2(panel()->coverage()->percent() > 95.0,
           qPrintable(QString::number(panel()->coverage()->percent())));
  QCOMPARE(panel()->clamping()->points, std::size_t{0});
  auto* label = f_.window->findChild<QLabel*>("errorStatisticsLabel");
  QVERIFY(label != nullptr);
  QVERIFY2(label->text().contains("coverage"), qPrintable(label->text()));
  QVERIFY(!label->text().contains("clamped"));
  // Face 0 cut down to the crust bottom.
  ddfcam::planning::Project p = ddfcam::planning::demoProject();
  auto heights = p.part->heights(0);
  std::fill(heights.begin(), heights.end(), -1.0f);
  load(std::move(p));
  QVERIFY(panel()->setDesiredSurface(-1));
  QVERIFY(panel()->computeErrorMap());
  waitOk();
  QVERIFY(panel()->clamping().has_value());
  // Face 0's raster points (a shared edge point's sign may follow a neighbour's normal).
  const std::size_t perFace = project().part->pointsPerFace();
  QVERIFY2(panel()->clamping()->points > perFace / 2 && panel()->clamping()->points <= perFace,
           qPrintable(QString::number(panel()->clamping()->points)));
  QVERIFY2(label->text().contains("min is only a bound"), qPrintable(label->text()));
}

DDFCAM_GUI_TEST_MAIN(ErrorMapPanelTest)
#include "error_map_panel_test.moc"
