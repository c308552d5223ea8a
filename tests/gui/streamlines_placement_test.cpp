// SPDX-License-Identifier: MIT
// Streamlines panel under Xvfb: the "Tool placement" group (lead angle, sampling from a
// tolerance) shapes the paths the panel creates, checked against the geometry of a plane.
#include "gui_test_registry.h"
#include "streamlines_panel_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/planning/model/project.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QRegularExpression>
#include <QtTest/QtTest>

#include <cmath>
#include <numbers>

using ddfcam::ddf::Vec3;
using ddfcam::planning::FlowFieldSource;
using ddfcam::test::passContacts;
using ddfcam::test::projectOf;

class StreamlinesPlacementTest : public ddfcam::test::StreamlinesPanelTestBase {
  Q_OBJECT

 private slots:
  void leadAndToleranceShapeTheCreatedPath();
  void withoutSamplingPosesSitAtTheLinePoints();

 private:
  /// A 40 x 30 mm plane at z = 0.25 (5 mm cells, m = 9) with a ball-end cutter of radius 3.
  void loadPlane() {
    auto project = projectOf(ddfcam::ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9}), "plane");
    project.tools.push_back({.name = "ball end R3",
                             .kind = ddfcam::planning::ToolKind::BallEnd,
                             .radiusMm = 3.0,
                             .widthMm = 8.0});
    load(std::move(project));
    panel().setFieldSource(FlowFieldSource::FixedDirection, Vec3::UnitX());
  }
  /// Seeds one streamline along x through the middle of the plane; @p path is the new path.
  void seedMiddle(ddfcam::planning::ToolPath& path) {
    const auto& ddf = *project().part;
    std::optional<ddfcam::ddf::SurfaceLocation> seed;
    for (int f = 0; f < ddf.faceCount() && !seed; ++f)
      seed = ddfcam::ddf::locateOnFace(ddf, f, Vec3(20.0, 15.1, 0.25));
    QVERIFY(seed.has_value());
    const std::size_t before = project().paths.size();
    QVERIFY(panel().seedAt(*seed));
    waitOk();
    QCOMPARE(project().paths.size(), before + 1);
    path = project().paths.back();
  }
};

void StreamlinesPlacementTest::leadAndToleranceShapeTheCreatedPath() {
  loadPlane();
  const double radius = 3.0, tolerance = 0.001;
  panel().setPlacementAngles(10.0, 0.0);
  panel().setSampling(true, tolerance);
  QVERIFY(panel().findChild<QCheckBox*>("sampleFromTolerance")->isChecked());
  QCOMPARE(panel().findChild<QDoubleSpinBox*>("placementLead")->value(), 10.0);
  ddfcam::planning::ToolPath path;
  seedMiddle(path);
  if (QTest::currentTestFailed()) return;
  QCOMPARE(path.passStarts.size(), std::size_t{1});
  // Tool axis (tool +z of a cutter) against the plane's normal +z: 10 deg everywhere.
  for (const auto& pose : path.poses) {
    const Vec3 axis = pose.pose.linear().col(2);
    const double angle = std::acos(std::clamp(axis.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    QVERIFY2(std::abs(angle - 10.0) < 1e-6, qPrintable(QString::number(angle)));
  }
  // The label shows the step; on a plane the ball's cusp rule binds at 2 sqrt(2 R T - T^2)
  // (0.1549 mm, below the raster spacing of 0.71 mm).
  const QString text = panel().findChild<QLabel*>("samplingLabel")->text();
  const auto match = QRegularExpression("step ([0-9.eE+-]+) mm \\(([a-z ]+)\\)").match(text);
  QVERIFY2(match.hasMatch(), qPrintable(text));
  const double step = match.captured(1).toDouble();
  QCOMPARE(match.captured(2), QString("tool profile"));
  const double sagitta = 2.0 * std::sqrt(2.0 * radius * tolerance - tolerance * tolerance);
  QVERIFY2(std::abs(step - sagitta) < 1e-4 * sagitta, qPrintable(text));
  // Poses evenly spaced at length / ceil(length / step) along the straight line.
  const auto line = passContacts(path).front();
  const double length = (line.back() - line.front()).norm();
  const int k = static_cast<int>(std::ceil(length / step - 1e-9));
  QCOMPARE(static_cast<int>(line.size()), k + 1);
  for (std::size_t i = 1; i < line.size(); ++i)
    QVERIFY(std::abs((line[i] - line[i - 1]).norm() - length / k) < 1e-6);
  QCOMPARE(panel().lastSampling().size(), std::size_t{1});
}

void StreamlinesPlacementTest::withoutSamplingPosesSitAtTheLinePoints() {
  loadPlane();
  panel().setPlacementAngles(0.0, 0.0);
  panel().setSampling(false, 0.01);
  ddfcam::planning::ToolPath path;
  seedMiddle(path);
  if (QTest::currentTestFailed()) return;
  QVERIFY(panel().lastSampling().empty());
  QCOMPARE(panel().findChild<QLabel*>("samplingLabel")->text(),
           QString("poses at the streamline points"));
  // Lead 0: the ball-end's tip is the contact, its axis the normal.
  for (const auto& pose : path.poses) {
    QVERIFY((pose.pose.translation() - pose.contact).norm() < 1e-9);
    QVERIFY((pose.pose.linear().col(2) - Vec3::UnitZ()).norm() < 1e-9);
  }
}

DDFCAM_GUI_TEST_MAIN(StreamlinesPlacementTest)
#include "streamlines_placement_test.moc"
