// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: "Cover region" for a ScallopTolerance region plan spaces the
// lines by the scallop-height formula with a ball, and falls back to the fixed spacing with a
// straight roll.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/project.h>

#include <QDockWidget>
#include <QLabel>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

using ddfcam::ddf::Vec3;
using ddfcam::gui::StreamlinesPanel;
using ddfcam::planning::FlowFieldSource;

namespace {

// z = 0 for x <= 0, then a circular arc of radius rho bending down (convex from the +z tool
// side, cross-section radius rho, axis along y); C1 at x = 0.
class FlatThenConvex : public ddfcam::ddf::HeightFieldSurface {
 public:
  static constexpr double kRho = 12.0;
  ddfcam::ddf::HeightDerivatives evaluate(double x, double) const override {
    if (x <= 0.0) return {};
    const double r = std::sqrt(kRho * kRho - x * x);
    return {.f = r - kRho, .fx = -x / r, .fxx = -kRho * kRho / (r * r * r)};
  }
  std::string name() const override { return "flat then convex"; }
  // Arc length across the rulings from x = 0, mm.
  static double arc(double x) { return x <= 0.0 ? x : kRho * std::asin(x / kRho); }
};

// Oracle of the scallop spacing, by the law of cosines in the cross-feed plane: tool centres
// at rho + R from the centre of curvature, the cusp at rho + h and at R from each centre; the
// contacts lie under the centres, rho theta apart. The plane: 2 sqrt(2 R h - h^2).
double scallopArcMm(double rho, double toolR, double h) {
  if (std::isinf(rho)) return 2.0 * std::sqrt(2.0 * toolR * h - h * h);
  const double a = rho + toolR, b = rho + h;
  return 2.0 * rho * std::acos((a * a + b * b - toolR * toolR) / (2.0 * a * b));
}

// The gaps (arc length across the rulings) between neighbouring coverage lines whose mean x
// are both below -1 mm (flat) or both above 1 mm (convex).
struct Gaps {
  std::vector<double> flat, convex;
};
Gaps rulingGaps(const ddfcam::planning::ToolPath& path) {
  std::vector<double> xs;
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const std::size_t end =
        s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : path.poses.size();
    double sum = 0.0;
    for (std::size_t i = path.passStarts[s]; i < end; ++i) sum += path.poses[i].contact.x();
    xs.push_back(sum / static_cast<double>(end - path.passStarts[s]));
  }
  std::sort(xs.begin(), xs.end());
  Gaps gaps;
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const double gap = FlatThenConvex::arc(xs[i]) - FlatThenConvex::arc(xs[i - 1]);
    if (xs[i] < -1.0) gaps.flat.push_back(gap);
    if (xs[i - 1] > 1.0) gaps.convex.push_back(gap);
  }
  return gaps;
}

}  // namespace

class StreamlinesPanelScallopTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void scallopToleranceSpacingFollowsTheCurvature();

 private:
  StreamlinesPanel& panel() { return *f_.window->findChild<StreamlinesPanel*>(); }
};

// Cover a flat-then-convex part with a ScallopTolerance plan along y: with a ball the gaps
// follow the scallop formula (wider on the flat, narrower on the convex arc); with a straight
// roll the plan's fixed spacing is used and the status says so.
void StreamlinesPanelScallopTest::scallopToleranceSpacingFollowsTheCurvature() {
  const double toolR = 5.0, h = 0.05, fixedMm = 3.0;
  const auto make = [&](int tool) {
    ddfcam::planning::Project p;
    p.partName = "flat then convex";
    p.part =
        ddfcam::ddf::graphPatch(
            std::make_shared<FlatThenConvex>(),
            {.origin = {-10.0, -8.0}, .size = {18.0, 16.0}, .cellsX = 18, .cellsY = 16, .m = 9})
            .ddf;
    p.tools.push_back({.kind = ddfcam::planning::ToolKind::Sphere, .radiusMm = toolR});
    p.tools.push_back({.kind = ddfcam::planning::ToolKind::CylinderRoll, .radiusMm = toolR});
    ddfcam::planning::Region all;
    all.name = "all";
    for (int f = 0; f < p.part->faceCount(); ++f) all.faces.push_back(f);
    all.plan.tool = tool;
    all.plan.flowSource = FlowFieldSource::FixedDirection;
    all.plan.fixedDirection = Vec3::UnitY();
    all.plan.smoothField = false;
    all.plan.spacingMode = ddfcam::planning::SpacingMode::ScallopTolerance;
    all.plan.scallopToleranceMm = h;
    all.plan.spacingMm = fixedMm;
    p.regions.push_back(all);
    return p;
  };
  const double flatMm = scallopArcMm(std::numeric_limits<double>::infinity(), toolR, h);
  const double convexMm = scallopArcMm(FlatThenConvex::kRho, toolR, h);
  auto* status = panel().findChild<QLabel*>("streamlineStatus");
  QVERIFY(status);
  // Ball.
  load(make(0));
  panel().setRegion(0);
  QVERIFY(panel().coverRegion(1.0));
  waitOk();
  Gaps gaps = rulingGaps(project().paths.back());
  QVERIFY(gaps.flat.size() >= 3 && gaps.convex.size() >= 3);
  QString report = QString("ball: flat %1 mm, convex %2 mm; gaps flat").arg(flatMm).arg(convexMm);
  for (double g : gaps.flat) report += QString(" %1").arg(g, 0, 'f', 3);
  report += ", convex";
  for (double g : gaps.convex) report += QString(" %1").arg(g, 0, 'f', 3);
  qInfo("%s", qPrintable(report));
  for (double g : gaps.flat) QVERIFY2(std::abs(g - flatMm) < 0.05 * flatMm, qPrintable(report));
  for (double g : gaps.convex)
    QVERIFY2(std::abs(g - convexMm) < 0.05 * convexMm, qPrintable(report));
  QVERIFY(status->text().contains("ball"));
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_scallop_ball");
  // Straight roll.
  load(make(1));
  panel().setRegion(0);
  QVERIFY(panel().coverRegion(1.0));
  waitOk();
  QVERIFY2(status->text().contains("straight roll"), qPrintable(status->text()));
  gaps = rulingGaps(project().paths.back());
  QVERIFY(gaps.flat.size() >= 2);
  for (double g : gaps.flat)
    QVERIFY2(std::abs(g - fixedMm) < 0.05 * fixedMm, qPrintable(QString::number(g)));
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "streamlines_scallop_roll");
  QVERIFY(raisePanel("streamlines"));
  ddfcam::test::dumpFrame(panel().grab().toImage(), "streamlines_scallop_panel");
}

DDFCAM_GUI_TEST_MAIN(StreamlinesPanelScallopTest)
#include "streamlines_panel_scallop_test.moc"
