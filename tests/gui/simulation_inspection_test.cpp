// SPDX-License-Identifier: MIT
// Inspection while a simulation plays, under Xvfb: the largest overcut against the design, the
// tolerance band coloured per raster point in the view, and the level of detail that follows
// the camera.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "playback_test_base.h"

#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/vtk_view.h>

#include <QLabel>
#include <QPushButton>
#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

class SimulationInspectionTest : public ddfcam::test::PlaybackTestBase {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void overcutAgainstTheDesignIsInspectedLive();
  void toleranceBandIsColouredPerRasterPointLive();
  void levelOfDetailFollowsTheCamera();
};

void SimulationInspectionTest::overcutAgainstTheDesignIsInspectedLive() {
  auto* label = f_.window->findChild<QLabel*>("overcutLabel");
  auto* show = f_.window->findChild<QPushButton*>("showOvercutButton");
  // Without a design state nothing is inspected, and the panel says how to get one.
  loadDemo();
  QVERIFY(playback().step());
  QVERIFY2(label->text().startsWith("Overcut: not inspected"), qPrintable(label->text()));
  QVERIFY(!show->isEnabled());
  playback().cancel();
  const ddfcam::ddf::DisplacementField design = loadDemoWithDesign();
  for (int i = 0; i < 10; ++i) QVERIFY(playback().step());
  // Oracle: the deepest point of the whole simulated part below the design, brute force
  // ((h_design - h) (v . n) at every raster point, n the design's raster normal). The 10 mm
  // roll on the bumpy demo surface digs in with its edges well beyond the 0.02 mm it is sunk
  // at the contacts.
  const auto& work = playback().simulation()->workpiece();
  double deepest = 0.0;
  const int n = design.raster().steps();
  for (int f = 0; f < design.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const double below = design.height(f, i, k) - work.height(f, i, k);
        const auto v = design.vectorAt(f, design.rasterBary(i, k));
        deepest = std::max(deepest, below * v.dot(ddfcam::ddf::rasterNormal(design, f, i, k)));
      }
  const QString text = label->text();
  QVERIFY2(text.startsWith("Largest overcut so far: "), qPrintable(text));
  const double depth = text.section(' ', 4, 4).toDouble();
  QVERIFY2(std::abs(depth - deepest) < 1e-4, qPrintable(text + " " + QString::number(deepest)));
  const int pose = text.section("at pose ", 1).section(';', 0, 0).toInt();
  QVERIFY(pose >= 0 && pose < 10);
  QVERIFY(show->isEnabled());
  QTest::mouseClick(show, Qt::LeftButton);
  QCOMPARE(playback().simulation()->nextPose(), pose + 1);
  QVERIFY(toolOverlayAt(pose));
  QTest::qWait(50);  // the wrapped labels are laid out again first
  ddfcam::test::dumpFrame(playback().grab().toImage(), "playback_overcut");
  playback().cancel();
}


// The live tolerance band at raster resolution: every raster point's texel has the class of
// its deviation from the design (brute force), and the rendered view shows that class where
// the point appears, also inside display triangles much larger than a raster cell.
void SimulationInspectionTest::toleranceBandIsColouredPerRasterPointLive() {
  using ddfcam::planning::ToleranceClass;
  const ddfcam::ddf::DisplacementField design = loadDemoWithDesign();
  for (int i = 0; i < 12; ++i) QVERIFY(playback().step());
  const auto* surface = playback().liveSurface();
  QVERIFY(surface != nullptr && surface->atlas() != nullptr);
  QVERIFY(scene().actor(ddfcam::gui::Layer::Surface)->GetTexture() == surface->texture());
  QVERIFY(f_.window->findChild<QLabel*>("overcutLabel")->text().contains("per raster point"));
  const auto& work = playback().simulation()->workpiece();
  const double tol = ddfcam::gui::PlaybackParams{}.overcutToleranceMm;
  const int n = design.raster().steps();
  const int columns = surface->atlas()->width() / (n + 1);
  std::map<ToleranceClass, std::vector<Eigen::Vector3d>> samples;
  int checked = 0;
  for (int f = 0; f < design.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const auto v = design.vectorAt(f, design.rasterBary(i, k));
        const double d = (work.height(f, i, k) - design.height(f, i, k)) *
                         v.dot(ddfcam::ddf::rasterNormal(design, f, i, k));
        // Near a bound the two normal estimates may disagree on the class: not a test point.
        if (std::abs(std::abs(d) - tol) < 2e-3) continue;
        const ToleranceClass expected = d > tol    ? ToleranceClass::MaterialLeft
                                        : d < -tol ? ToleranceClass::Overcut
                                                   : ToleranceClass::InTolerance;
        const auto rgb = surface->atlas()->texel((f % columns) * (n + 1) + i,
                                                 (f / columns) * (n + 1) + k);
        const std::array<double, 3> colour = {rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0};
        QVERIFY2(ddfcam::gui::toleranceClassOfColour(colour) == expected,
                 qPrintable(QString("face %1 point (%2, %3), deviation %4 mm")
                                .arg(f).arg(i).arg(k).arg(d)));
        ++checked;
        if (i > 0 && k > 0 && i + k < n && f % 3 == 0)
          samples[expected].push_back(work.surfacePoint(f, i, k));
      }
  QVERIFY(checked > 10000);
  for (auto c :
       {ToleranceClass::MaterialLeft, ToleranceClass::InTolerance, ToleranceClass::Overcut})
    QVERIFY2(samples[c].size() >= 3, qPrintable(QString("class %1").arg(static_cast<int>(c))));
  // The view from above, the tool hidden: the pixel at each sample shows its class.
  for (const char* overlay :
       {ddfcam::gui::kToolCuttingOverlay, ddfcam::gui::kToolNonCuttingOverlay})
    if (scene().hasOverlay(overlay)) scene().setOverlayVisible(overlay, false);
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  const QImage image = view.renderImage();
  ddfcam::test::dumpFrame(image, "playback_tolerance_band");
  const double dpr = image.width() / static_cast<double>(view.width());
  for (const auto& [expected, points] : samples) {
    int agree = 0, inView = 0;
    for (const Eigen::Vector3d& q : points) {
      const QPointF at = view.widgetPosition(q) * dpr;
      if (!image.rect().contains(at.toPoint())) continue;
      ++inView;
      const QColor c = image.pixelColor(at.toPoint());
      if (ddfcam::gui::toleranceClassOfColour({c.redF(), c.greenF(), c.blueF()}) == expected)
        ++agree;
    }
    QVERIFY(inView >= 3);
    // A sample can sit on the edge of a one-cell band; nearly all must show their class.
    QVERIFY2(agree >= 0.8 * inView, qPrintable(QString("class %1: %2 of %3 pixels")
                                                   .arg(static_cast<int>(expected))
                                                   .arg(agree)
                                                   .arg(inView)));
  }
  playback().cancel();
}

// The live surface is triangulated for the view: zoomed far out it is coarser, back in finer,
// and the panel says which pixel error it keeps.
void SimulationInspectionTest::levelOfDetailFollowsTheCamera() {
  loadDemo();
  for (int i = 0; i < 5; ++i) QVERIFY(playback().step());
  auto& view = *f_.window->view();
  view.viewFrom(ddfcam::gui::ViewDirection::Isometric);
  QTest::qWait(400);  // the level-of-detail check runs every 200 ms
  const vtkIdType near = playback().liveSurface()->polyData()->GetNumberOfCells();
  auto* rates = f_.window->findChild<QLabel*>("playbackRates");
  QVERIFY2(rates->text().contains("within 0.5 px"), qPrintable(rates->text()));
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  camera->Dolly(0.05);  // twenty times as far
  view.requestRender();
  QTest::qWait(400);
  const vtkIdType far = playback().liveSurface()->polyData()->GetNumberOfCells();
  QVERIFY2(2 * far < near, qPrintable(QString("%1 -> %2 triangles").arg(near).arg(far)));
  camera->Dolly(20.0);
  view.requestRender();
  QTest::qWait(400);
  QCOMPARE(playback().liveSurface()->polyData()->GetNumberOfCells(), near);
  std::printf("playback level of detail: %lld triangles near, %lld twenty times as far\n",
              static_cast<long long>(near), static_cast<long long>(far));
  playback().cancel();
}

DDFCAM_GUI_TEST_MAIN(SimulationInspectionTest)
#include "simulation_inspection_test.moc"
