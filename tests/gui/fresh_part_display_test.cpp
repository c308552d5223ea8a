// SPDX-License-Identifier: MIT
// What a newly opened part shows under Xvfb: the first part opened in a fresh window is in view
// without Fit, and a part opened after another drops the plots of the previous one.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include <QAction>
#include <QtTest/QtTest>

class FreshPartDisplayTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void firstPartOpenedIsInViewWithoutFit();
  void anotherPartDropsThePlotsOfThePreviousOne();

 private:
  /// Writes a sphere of radius @p radiusMm centred at (500, 200, 100) mm (its DDF's raster
  /// mesh) as STL; opens it.
  void openSphere(double radiusMm, const QString& name) {
    ddfcam::ddf::SphereParams sphere;
    sphere.radiusMm = radiusMm;
    sphere.subdivisions = 2;
    sphere.m = 3;
    ddfcam::ddf::TriangleMesh mesh =
        ddfcam::ddf::extractRasterMesh(ddfcam::ddf::spherePart(sphere).ddf).mesh;
    for (auto& v : mesh.vertices) v += Eigen::Vector3d(500.0, 200.0, 100.0);
    const QString path = f_.dir.filePath(name);
    ddfcam::io::writeMesh(mesh, path.toStdString());
    f_.script.openPath = path;
    f_.window->findChild<QAction*>("actionOpen")->trigger();
    waitOk();
  }
};

void FreshPartDisplayTest::firstPartOpenedIsInViewWithoutFit() {
  // Far from the origin and small: only a camera fitted to it shows it.
  openSphere(3.0, "first.stl");
  QVERIFY(project().part.has_value());
  auto& view = *f_.window->view();
  const QImage image = view.renderImage();
  ddfcam::test::dumpFrame(image, "fresh_part_first_open");
  const auto stats = ddfcam::test::frameStats(image, view.backgroundColor());
  QVERIFY2(stats.centreForeground > 0.3, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY(stats.cornersBackground);
}

void FreshPartDisplayTest::anotherPartDropsThePlotsOfThePreviousOne() {
  openSphere(3.0, "a.stl");
  QVERIFY(f_.window->findChild<ddfcam::gui::FieldsPanel*>()->compute(
      ddfcam::gui::FieldKind::KMax));
  waitOk();
  auto& plots = f_.window->plots();
  QVERIFY(!plots.plotNames().isEmpty());
  openSphere(20.0, "b.stl");
  QVERIFY2(plots.plotNames().isEmpty(), qPrintable(plots.plotNames().join(", ")));
  QVERIFY(!plots.exportAction()->isEnabled());
  // The new part's own field plots again.
  QVERIFY(f_.window->findChild<ddfcam::gui::FieldsPanel*>()->compute(
      ddfcam::gui::FieldKind::KMax));
  waitOk();
  QVERIFY(!plots.plotNames().isEmpty());
}

DDFCAM_GUI_TEST_MAIN(FreshPartDisplayTest)
#include "fresh_part_display_test.moc"
