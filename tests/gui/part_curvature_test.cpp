// SPDX-License-Identifier: MIT
// The curvature the workbench shows for an imported mesh part with the default (reduced)
// support: k_max and k_min from the Fields panel against the analytic curvature of a torus.
#include "gui_test_registry.h"
#include "../support/test_meshes.h"
#include "frame_checks.h"
#include "workbench_fixture.h"

#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/model/project.h>

#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>

using ddfcam::gui::FieldKind;

namespace {

constexpr double kR = 20.0, kTube = 6.0;  // torus radii, mm

}  // namespace

class PartCurvatureTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase() { QVERIFY(f_.open(false)); }
  void cleanupTestCase() { f_.window.reset(); }
  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void reducedPartShowsTheCurvatureOfItsMesh();

 private:
  const ddfcam::planning::Project& project() { return f_.window->document().project(); }
  /// The largest |field - exact| over all raster points, 1/mm.
  double largestError(const ddfcam::planning::ScalarField& field, bool kMax) {
    const auto& part = *project().part;
    double worst = 0.0;
    for (int f = 0; f < part.faceCount(); ++f)
      for (int k = 0; k <= part.raster().steps(); ++k)
        for (int i = 0; i < part.raster().rowLength(k); ++i) {
          const auto [k1, k2] = ddfcam::test::torusCurvature(kR, kTube, part.surfacePoint(f, i, k));
          const float value = field.values[f * part.pointsPerFace() + part.raster().index(i, k)];
          worst = std::max(worst, std::abs(value - (kMax ? k1 : k2)));
        }
    return worst;
  }

  ddfcam::test::WorkbenchFixture f_;
};

void PartCurvatureTest::reducedPartShowsTheCurvatureOfItsMesh() {
  // A torus tessellated with 11,520 triangles, imported as a new user would: the dialog's
  // default choices reduce the support, and the heights then follow the mesh's flat triangles.
  const QString path = f_.dir.filePath("torus.off");
  ddfcam::io::writeMesh(ddfcam::test::torusMesh(kR, kTube, 120, 48), path.toStdString());
  f_.script.importChoices = ddfcam::gui::PartImportChoices{};
  QVERIFY(f_.window->openPath(path));
  QVERIFY(f_.window->waitForJobs(300'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QVERIFY(project().part->faceCount() < 11520 / 4);
  auto* fields = f_.window->findChild<ddfcam::gui::FieldsPanel*>();
  QVERIFY(fields->compute(FieldKind::KMax));
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY(fields->compute(FieldKind::KMin));
  QVERIFY(f_.window->waitForJobs(120'000));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const auto& all = project().fields;
  const auto kMax = std::find_if(all.begin(), all.end(), [](auto& x) { return x.name == "k_max"; });
  const auto kMin = std::find_if(all.begin(), all.end(), [](auto& x) { return x.name == "k_min"; });
  QVERIFY(kMax != all.end() && kMin != all.end());
  // Oracle: the torus' own curvature, 1/r = 0.167 around the tube and -0.071..0.038 around the
  // axis; the fits of a 0.8 mm tessellation are within 2 % of 1/r (the raster differences of
  // the same part are off by up to 19 1/mm at the mesh's edges).
  const double maxError = largestError(*kMax, true), minError = largestError(*kMin, false);
  qInfo("torus, %d support faces: |k_max - exact| <= %.3g, |k_min - exact| <= %.3g 1/mm",
        project().part->faceCount(), maxError, minError);
  QVERIFY(maxError < 0.02 / kTube);
  QVERIFY(minError < 0.02 / kTube);
  f_.window->partView().showField("k_min");
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "part_curvature_torus_kmin");
}

DDFCAM_GUI_TEST_MAIN(PartCurvatureTest)
#include "part_curvature_test.moc"
