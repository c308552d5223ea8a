// SPDX-License-Identifier: MIT
// Acceptance of the batch pipeline under Xvfb: `ddfcam-cli run job.json` and the same steps
// through the workbench panels (segmentation, streamlines with placement, stock allowance,
// simulation, error map) give the same paths, states and error map.
#include "gui_test_registry.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/panels/error_map_panel.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/spacing_refinement_panel.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/project/project_loader.h>

#include <QImage>
#include <QtTest/QtTest>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

namespace {

/// The job the workbench repeats: region 0 of the curvature-type segmentation, lines along y
/// 3 mm apart, the default roll (no tool given: both sides use planning::Tool{}), poses from a
/// 0.01 mm tolerance at a 2 mm step, raised by 0.02 mm, ground (discrete), error map.
constexpr const char* kJob = R"({
  "part": "part.ddf",
  "segmentation": {"method": "curvatureType", "flatCurvaturePerMm": 0.001, "minFaces": 4},
  "regions": [{"region": 0, "field": "fixed", "direction": [0, 1, 0], "smooth": false,
               "lines": "even", "spacingMm": 3, "link": true}],
  "placement": {"samplingToleranceMm": 0.01, "samplingStepMm": 2},
  "simulation": {"allowanceMm": 0.02, "mode": "discrete"},
  "errorMap": {"lowerMm": -0.01, "upperMm": 0.01},
  "project": "job.ddfproj",
  "report": "report.json"
})";

/// Spacing refinement as the Spacing refinement panel runs it: the whole part, a field along x
/// computed without smoothing (the panel never smooths), the default roll, tolerance 0.05 mm;
/// then the same stock allowance and simulation as above.
constexpr const char* kRefinedJob = R"({
  "part": "part.ddf",
  "regions": [{"region": "all", "field": "fixed", "direction": [1, 0, 0], "smooth": false,
               "lines": "refined", "toleranceMm": 0.05, "maxIterations": 20}],
  "simulation": {"allowanceMm": 0.02, "mode": "discrete"},
  "project": "job.ddfproj",
  "report": "report.json"
})";

/// A coarse job with an error map and a screenshot rendered by the workbench.
constexpr const char* kScreenshotJob = R"({
  "part": "part.ddf",
  "tools": [{"name": "ball end", "kind": "ball_end", "radiusMm": 5, "widthMm": 10}],
  "regions": [{"field": "fixed", "direction": [0, 1, 0], "smooth": false, "spacingMm": 3}],
  "placement": {"samplingToleranceMm": 0.01, "samplingStepMm": 2},
  "simulation": {"allowanceMm": 0.02, "mode": "swept"},
  "errorMap": {"lowerMm": -0.01, "upperMm": 0.01},
  "project": "job.ddfproj",
  "report": "report.json",
  "screenshots": ["view.png"]
})";

/// Largest difference of two height lists (infinity on a size mismatch or NaN in only one).
double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]) != std::isnan(b[i])) return std::numeric_limits<double>::infinity();
    if (!std::isnan(a[i])) worst = std::max(worst, std::abs(static_cast<double>(a[i]) - b[i]));
  }
  return worst;
}

}  // namespace

class BatchJobGuiTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void jobReproducesTheWorkbench();
  void refinedJobReproducesTheSpacingRefinementPanel();
  void screenshotShowsTheErrorMap();

 private:
  template <typename T>
  T* panel() {
    return f_.window->findChild<T*>();
  }
  /// Runs ddfcam-cli on the job in @p dir and reads the project it saved.
  ddfcam::planning::Project runBatch(const std::filesystem::path& dir, const char* job = kJob);
  /// The job's steps through the panels, on the document.
  void runPanels(const std::filesystem::path& part);
  void compareResults(const ddfcam::planning::Project& gui, const ddfcam::planning::Project& batch,
                      const char* field);
};

ddfcam::planning::Project BatchJobGuiTest::runBatch(const std::filesystem::path& dir,
                                                    const char* job) {
  std::ofstream(dir / "job.json") << job;
  const std::string command = std::string("'") + DDFCAM_CLI_PATH + "' run '" +
                              (dir / "job.json").string() + "' > '" + (dir / "log.txt").string() +
                              "' 2>&1";
  const int status = std::system(command.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream log(dir / "log.txt");
    const std::string text((std::istreambuf_iterator<char>(log)), {});
    qWarning("ddfcam-cli failed: %s", text.c_str());
    return {};
  }
  return ddfcam::io::readProject(dir / "job.ddfproj");
}

void BatchJobGuiTest::runPanels(const std::filesystem::path& part) {
  load(ddfcam::io::openProject(part));
  auto* segmentation = panel<ddfcam::gui::SegmentationPanel>();
  QVERIFY(segmentation != nullptr);
  segmentation->setSegmentationOptions(ddfcam::gui::SegmentationMethod::CurvatureType, 1e-3, {}, 4);
  QVERIFY(segmentation->segment());
  waitOk();
  auto* streamlines = panel<ddfcam::gui::StreamlinesPanel>();
  QVERIFY(streamlines != nullptr);
  streamlines->setRegion(0);  // sets the field from the region's plan: override it after
  streamlines->setFieldSource(ddfcam::planning::FlowFieldSource::FixedDirection,
                              Eigen::Vector3d::UnitY());
  streamlines->setFieldSmoothing(false);
  streamlines->setPlacementAngles(0.0, 0.0);
  streamlines->setSampling(true, 0.01, 2.0);
  QVERIFY(streamlines->coverRegion(3.0));
  waitOk();
  auto* simulation = panel<ddfcam::gui::SimulationPanel>();
  QVERIFY(simulation != nullptr);
  QVERIFY(simulation->raiseByAllowance(0.02));
  waitOk();
  QVERIFY(simulation->simulatePath(0));
  waitOk();
  auto* errors = panel<ddfcam::gui::ErrorMapPanel>();
  QVERIFY(errors != nullptr);
  int design = -1;
  for (std::size_t s = 0; s < project().states.size(); ++s)
    if (project().states[s].name == "design") design = static_cast<int>(s);
  QVERIFY(errors->setDesiredSurface(design));
  QVERIFY(errors->computeErrorMap());
  waitOk();
}

/// The one path, its poses and contacts, every state, the final heights and field @p field of
/// the workbench's project @p gui equal those of the job's project @p batch.
void BatchJobGuiTest::compareResults(const ddfcam::planning::Project& gui,
                                     const ddfcam::planning::Project& batch, const char* field) {
  QCOMPARE(gui.paths.size(), std::size_t{1});
  QCOMPARE(batch.paths.size(), std::size_t{1});
  const auto& a = gui.paths[0];
  const auto& b = batch.paths[0];
  QCOMPARE(QString::fromStdString(a.name), QString::fromStdString(b.name));
  QVERIFY(a.passStarts == b.passStarts);
  QCOMPARE(a.poses.size(), b.poses.size());
  double poseDiff = 0.0;
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    poseDiff = std::max(poseDiff, (a.poses[i].pose.matrix() - b.poses[i].pose.matrix()).norm());
    poseDiff = std::max(poseDiff, (a.poses[i].contact - b.poses[i].contact).norm());
  }
  qInfo("%s: %zu passes, %zu poses; largest pose difference %.3g", field, a.passStarts.size(),
        a.poses.size(), poseDiff);
  QVERIFY(poseDiff <= 1e-9);
  QCOMPARE(gui.states.size(), batch.states.size());
  for (std::size_t s = 0; s < gui.states.size(); ++s) {
    QCOMPARE(QString::fromStdString(gui.states[s].name),
             QString::fromStdString(batch.states[s].name));
    QVERIFY2(maxDifference(gui.states[s].heights, batch.states[s].heights) <= 1e-9,
             gui.states[s].name.c_str());
  }
  QVERIFY(maxDifference(gui.part->allHeights(), batch.part->allHeights()) <= 1e-9);
  const auto values = [field](const ddfcam::planning::Project& p) {
    for (const auto& f : p.fields)
      if (f.name == field) return f.values;
    return std::vector<float>{};
  };
  QVERIFY(!values(batch).empty());
  QVERIFY(maxDifference(values(gui), values(batch)) <= 1e-9);
}

void BatchJobGuiTest::jobReproducesTheWorkbench() {
  QTemporaryDir tmp;
  QVERIFY(tmp.isValid());
  const std::filesystem::path dir = tmp.path().toStdString();
  ddfcam::io::writeDdf(ddfcam::ddf::demoPart({.cellsX = 8, .cellsY = 6, .m = 9}).ddf,
                       dir / "part.ddf");
  const ddfcam::planning::Project batch = runBatch(dir);
  QVERIFY(batch.part.has_value());
  runPanels(dir / "part.ddf");
  const ddfcam::planning::Project& gui = project();

  QCOMPARE(gui.regions.size(), batch.regions.size());
  for (std::size_t r = 0; r < gui.regions.size(); ++r)
    QVERIFY(gui.regions[r].faces == batch.regions[r].faces);
  QCOMPARE(gui.tools.size(), std::size_t{1});
  QVERIFY(gui.tools[0] == batch.tools[0]);
  compareResults(gui, batch, "deviation");
}

void BatchJobGuiTest::refinedJobReproducesTheSpacingRefinementPanel() {
  QTemporaryDir tmp;
  QVERIFY(tmp.isValid());
  const std::filesystem::path dir = tmp.path().toStdString();
  ddfcam::io::writeDdf(
      ddfcam::ddf::planePatch({.size = {2.0, 20.0}, .cellsX = 1, .cellsY = 10, .m = 9}).ddf,
      dir / "part.ddf");
  const ddfcam::planning::Project batch = runBatch(dir, kRefinedJob);
  QVERIFY(batch.part.has_value());

  ddfcam::planning::Project loaded = ddfcam::io::openProject(dir / "part.ddf");
  loaded.tools = {ddfcam::planning::Tool{}};  // the job's default tool
  load(std::move(loaded));
  auto* refinement = panel<ddfcam::gui::SpacingRefinementPanel>();
  QVERIFY(refinement != nullptr);
  refinement->setRegion(-1);
  refinement->setTool(0);
  refinement->setFieldSource(ddfcam::planning::FlowFieldSource::FixedDirection);
  refinement->setTolerance(0.05);
  refinement->setMaxIterations(20);
  QVERIFY(refinement->refine());
  waitOk();
  QVERIFY(refinement->result() != nullptr);
  QVERIFY(refinement->apply());
  auto* simulation = panel<ddfcam::gui::SimulationPanel>();
  QVERIFY(simulation != nullptr);
  QVERIFY(simulation->raiseByAllowance(0.02));
  waitOk();
  QVERIFY(simulation->simulatePath(0));
  waitOk();
  const ddfcam::planning::Project& gui = project();

  compareResults(gui, batch, "refinement error");
}

void BatchJobGuiTest::screenshotShowsTheErrorMap() {
  QTemporaryDir tmp;
  QVERIFY(tmp.isValid());
  const std::filesystem::path dir = tmp.path().toStdString();
  ddfcam::io::writeDdf(ddfcam::ddf::demoPart({.cellsX = 8, .cellsY = 6, .m = 9}).ddf,
                       dir / "part.ddf");
  QVERIFY(qEnvironmentVariableIsSet("DISPLAY"));  // ddfcam-cli renders only with a display
  const ddfcam::planning::Project batch = runBatch(dir, kScreenshotJob);
  QVERIFY(batch.part.has_value());
  const QImage image(QString::fromStdString((dir / "view.png").string()));
  QVERIFY2(!image.isNull(), "the job wrote no readable view.png");
  // The tolerance-band colours (material left: blues, in tolerance: green) cover the part;
  // the plain brass surface (the picture before the field was shown) has neither. The
  // scalar bar alone is below 1 % of the window.
  std::size_t band = 0, green = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      const bool blue = c.blue() > c.red() + 50 && c.blue() > c.green() + 20;
      const bool isGreen = c.green() > c.red() + 50 && c.green() > c.blue() + 40;
      band += blue || isGreen ? 1 : 0;
      green += isGreen ? 1 : 0;
    }
  const double percent = 100.0 * band / (image.width() * image.height());
  qInfo("screenshot %dx%d: %.1f %% band colours (%zu green pixels)", image.width(), image.height(),
        percent, green);
  QVERIFY2(percent > 5.0, qPrintable(QString::number(percent)));
}

DDFCAM_GUI_TEST_MAIN(BatchJobGuiTest)
#include "batch_job_gui_test.moc"
