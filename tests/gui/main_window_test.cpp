// SPDX-License-Identifier: MIT
// The workbench window under Xvfb, checked the way a person would look at it: the start-up
// part, the view, opening files through the menu (a job), bad files, screenshots, drops.
#include "gui_test_registry.h"
#include "../support/conversion_meshes.h"
#include "frame_checks.h"
#include "workbench_fixture.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/project_actions.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/model/project.h>

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QMimeData>
#include <QtTest/QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>

using ddfcam::gui::Layer;
using ddfcam::test::changedFraction;
using ddfcam::test::dumpFrame;
using ddfcam::test::frameStats;

namespace {

/// A 16 x 12 mm hill z = 2 exp(-((x-8)^2 + (y-6)^2) / 20) on a grid of nx x ny quads, as OFF.
QByteArray hillOff(int nx, int ny) {
  QByteArray text = "OFF\n";
  text += QByteArray::number((nx + 1) * (ny + 1)) + " " + QByteArray::number(2 * nx * ny) + " 0\n";
  for (int y = 0; y <= ny; ++y)
    for (int x = 0; x <= nx; ++x) {
      const double z = 2.0 * std::exp(-((x - 8.0) * (x - 8.0) + (y - 6.0) * (y - 6.0)) / 20.0);
      text += QByteArray::number(x) + " " + QByteArray::number(y) + " " +
              QByteArray::number(z, 'g', 17) + "\n";
    }
  auto at = [nx](int x, int y) { return QByteArray::number(y * (nx + 1) + x); };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      text += "3 " + at(x, y) + " " + at(x + 1, y) + " " + at(x + 1, y + 1) + "\n";
      text += "3 " + at(x, y) + " " + at(x + 1, y + 1) + " " + at(x, y + 1) + "\n";
    }
  return text;
}

bool writeFile(const QString& path, const QByteArray& bytes) {
  QFile file(path);
  return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

}  // namespace

class MainWindowTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase();
  void cleanupTestCase() { f_.window.reset(); }
  void init() { f_.script.errors.clear(); }
  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void startsOnDemoSession();
  void viewShowsThePart();
  void dragMovesCamera();
  void overlaysChangeTheImage_data();
  void overlaysChangeTheImage();
  void openMeshThroughMenu();
  void openInvalidMeshIsFlagged();
  void corruptFileKeepsDocument_data();
  void corruptFileKeepsDocument();
  void saveScreenshotAtChosenSize();
  void dropOpensFile();
  void dockLayoutSurvivesRestart();

 private:
  QImage frame() { return f_.window->view()->renderImage(); }
  QAction* action(const char* name) { return f_.window->findChild<QAction*>(name); }
  QColor background() const { return f_.window->view()->backgroundColor(); }
  const ddfcam::planning::Project& project() const { return f_.window->document().project(); }

  ddfcam::test::WorkbenchFixture f_;
};

void MainWindowTest::initTestCase() {
  ddfcam::gui::VtkErrorMonitor::install();
  QVERIFY(f_.dir.isValid());
  QVERIFY(f_.open());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
}

void MainWindowTest::startsOnDemoSession() {
  QVERIFY(project().part.has_value());
  QCOMPARE(QString::fromStdString(project().partName), QString("demo part"));
  // The demo part's grid is documented: cellsX x cellsY quads, two triangles each, at m.
  const ddfcam::ddf::DemoPartParams demo;
  QCOMPARE(project().part->faceCount(), 2 * demo.cellsX * demo.cellsY);
  QCOMPARE(project().part->resolution(), demo.m);
  QVERIFY2(f_.window->statusText().contains("support 1,536 faces, m = "),
           qPrintable(f_.window->statusText()));
  QVERIFY(f_.window->partView().scene().cellCount(Layer::Surface) > 1000);
  // The demo session brings a tool and a path to simulate, and the path is drawn.
  QCOMPARE(project().tools.size(), std::size_t{1});
  QCOMPARE(project().paths.size(), std::size_t{1});
  QVERIFY(f_.window->partView().scene().overlayCellCount("paths") >= 3);
  QVERIFY(!f_.window->document().isModified());
  QVERIFY(f_.window->windowTitle().startsWith("demo part"));
}

void MainWindowTest::viewShowsThePart() {
  const QImage image = frame();
  dumpFrame(image, "main_window_demo");
  const auto stats = frameStats(image, background());
  QVERIFY2(stats.centreForeground > 0.5, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY2(stats.borderBackground > 0.8, qPrintable(QString::number(stats.borderBackground)));
  QVERIFY(stats.cornersBackground);
}

void MainWindowTest::dragMovesCamera() {
  auto* view = f_.window->view();
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  double p0[3], p1[3];
  camera->GetPosition(p0);
  const QImage before = frame();
  const QPoint c = view->rect().center();
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, c);
  for (int i = 1; i <= 6; ++i) {
    const QPointF p = c + QPoint(-12 * i, 5 * i);
    QMouseEvent move(QEvent::MouseMove, p, view->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(view, &move);
  }
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, c + QPoint(-72, 30));
  camera->GetPosition(p1);
  QVERIFY(std::hypot(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]) > 1.0);
  QVERIFY(changedFraction(before, frame()) > 0.05);
  // Back to the standard view for the following checks.
  action("actionViewIsometric")->trigger();
}

void MainWindowTest::overlaysChangeTheImage_data() {
  QTest::addColumn<QString>("actionName");
  QTest::newRow("support") << "actionShowSupport";
  QTest::newRow("stubbles") << "actionShowStubbles";
  QTest::newRow("vectors") << "actionShowVectors";
  QTest::newRow("paths") << "actionShowPaths";
  QTest::newRow("crust above") << "actionShowCrustAbove";
  QTest::newRow("crust below") << "actionShowCrustBelow";
}

void MainWindowTest::overlaysChangeTheImage() {
  QFETCH(QString, actionName);
  QAction* toggle = action(qPrintable(actionName));
  QVERIFY(toggle && toggle->isCheckable());
  const QImage before = frame();
  toggle->trigger();
  const QImage after = frame();
  dumpFrame(after, "main_window_" + actionName);
  QVERIFY2(changedFraction(before, after) > 0.002,
           qPrintable(QString::number(changedFraction(before, after))));
  toggle->trigger();
  QVERIFY(changedFraction(before, frame()) < 0.001);
}

void MainWindowTest::openMeshThroughMenu() {
  const QString path = f_.dir.filePath("hill.off");
  QVERIFY(writeFile(path, hillOff(16, 12)));
  const QImage demoImage = frame();
  f_.script.openPath = path;
  action("actionOpen")->trigger();
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(QString::fromStdString(project().partName), QString("hill.off"));
  QVERIFY(f_.window->statusText().startsWith("hill.off"));
  // A converted mesh is the support itself: the hill's triangles and its 16 x 12 mm extent.
  QCOMPARE(project().part->faceCount(), 2 * 16 * 12);
  QVERIFY(project().designMesh.has_value());
  QCOMPARE(project().designMesh->triangles.size(), std::size_t{2 * 16 * 12});
  QCOMPARE(project().states.size(), std::size_t{1});
  const auto box = ddfcam::ddf::extractSupportMesh(*project().part).bounds();
  QVERIFY(box[0].isApprox(Eigen::Vector3d(0, 0, 2.0 * std::exp(-(64.0 + 36.0) / 20.0)), 1e-9));
  QCOMPARE(box[1].x(), 16.0);
  QCOMPARE(box[1].y(), 12.0);
  QCOMPARE(box[1].z(), 2.0);
  const QImage image = frame();
  dumpFrame(image, "main_window_hill");
  const auto stats = frameStats(image, background());
  QVERIFY2(stats.centreForeground > 0.4, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY(stats.cornersBackground);
  QVERIFY(changedFraction(demoImage, image) > 0.05);
}

void MainWindowTest::openInvalidMeshIsFlagged() {
  // A fan whose face normals surround the origin: no vector at its centre faces all faces.
  const QString path = f_.dir.filePath("fan.off");
  ddfcam::io::writeMesh(ddfcam::test::foldedFanMesh(), path.toStdString());
  QSignalSpy reported(&f_.window->projectActions(),
                      &ddfcam::gui::ProjectActions::conversionReported);
  f_.script.openPath = path;
  action("actionOpen")->trigger();
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(QString::fromStdString(project().partName), QString("fan.off"));
  QCOMPARE(reported.count(), 1);
  QCOMPARE(reported.front().at(1).toBool(), false);
  // The same words as `ddfcam-cli convert`, in the status and, with the details, the console.
  QVERIFY2(f_.window->statusText().contains("fan.off: INVALID DDF: violates constraint 1"),
           qPrintable(f_.window->statusText()));
  QTRY_VERIFY_WITH_TIMEOUT(
      f_.window->console().text().contains("constraint 1 (front-facing vectors) fails at 1 vertex"),
      2000);
  // A valid mesh opened next clears the flag.
  const QString hill = f_.dir.filePath("hill.off");
  QVERIFY(writeFile(hill, hillOff(16, 12)));
  f_.script.openPath = hill;
  action("actionOpen")->trigger();
  QVERIFY(f_.window->waitForJobs());
  QCOMPARE(reported.count(), 2);
  QCOMPARE(reported.back().at(1).toBool(), true);
  QVERIFY2(!f_.window->statusText().contains("INVALID"), qPrintable(f_.window->statusText()));
}

void MainWindowTest::corruptFileKeepsDocument_data() {
  QTest::addColumn<QString>("fileName");
  QTest::addColumn<QByteArray>("content");
  QTest::newRow("ddf garbage") << "broken.ddf" << QByteArray("DDFCAM\x1a\n garbage, not a field");
  QTest::newRow("off bad index") << "broken.off"
                                 << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  QTest::newRow("stl truncated") << "broken.stl"
                                 << QByteArray("solid s\n facet normal 0 0 1\n  outer loop\n");
  QTest::newRow("project garbage") << "broken.ddfproj" << QByteArray("not a project at all");
}

void MainWindowTest::corruptFileKeepsDocument() {
  QFETCH(QString, fileName);
  QFETCH(QByteArray, content);
  const QString path = f_.dir.filePath(fileName);
  QVERIFY(writeFile(path, content));
  const ddfcam::planning::Project before = project();
  const QString statusBefore = f_.window->statusText();
  const QImage imageBefore = frame();

  f_.script.openPath = path;
  action("actionOpen")->trigger();
  QVERIFY(f_.window->waitForJobs());
  QCOMPARE(f_.script.errors.size(), 1);
  QVERIFY2(f_.script.errors.front().contains(fileName), qPrintable(f_.script.errors.front()));
  // The console keeps the same unrolled message (log lines arrive through the event loop).
  QTRY_VERIFY_WITH_TIMEOUT(f_.window->console().text().contains(fileName), 2000);
  QVERIFY(ddfcam::planning::projectsEqual(project(), before));
  QCOMPARE(f_.window->statusText(), statusBefore);
  QVERIFY(changedFraction(imageBefore, frame()) < 0.001);
}

void MainWindowTest::saveScreenshotAtChosenSize() {
  f_.script.screenshot =
      ddfcam::gui::ScreenshotRequest{f_.dir.filePath("shot.png"), QSize(640, 400)};
  action("actionSaveScreenshot")->trigger();
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  const QImage saved(f_.script.screenshot->path);
  QVERIFY(!saved.isNull());
  QCOMPARE(saved.size(), QSize(640, 400));
  const auto stats = frameStats(saved, background());
  QVERIFY(stats.cornersBackground);
  QVERIFY(stats.centreForeground > 0.3);
  // No size: the view's own size (device pixels), as documented.
  const QString viewSized = f_.dir.filePath("view.png");
  QVERIFY(f_.window->saveScreenshot(viewSized));
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(QImage(viewSized).size(), frame().size());
  // A path that cannot be written is reported, not silently ignored.
  f_.script.screenshot->path = f_.dir.filePath("no/such/folder/shot.png");
  action("actionSaveScreenshot")->trigger();
  QCOMPARE(f_.script.errors.size(), 1);
}

void MainWindowTest::dropOpensFile() {
  const QString path = f_.dir.filePath("dropped.off");
  QVERIFY(writeFile(path, hillOff(6, 4)));
  QMimeData mime;
  mime.setUrls({QUrl::fromLocalFile(path)});
  const QPoint at = f_.window->rect().center();
  QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  enter.ignore();
  QApplication::sendEvent(f_.window.get(), &enter);
  QVERIFY(enter.isAccepted());
  QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(f_.window.get(), &drop);
  QVERIFY(f_.window->waitForJobs());
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(QString::fromStdString(project().partName), QString("dropped.off"));
  QCOMPARE(project().part->faceCount(), 2 * 6 * 4);
  // Files the workbench cannot open are refused at the door.
  QMimeData text;
  text.setUrls({QUrl::fromLocalFile(f_.dir.filePath("notes.txt"))});
  QDragEnterEvent refused(at, Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
  refused.ignore();
  QApplication::sendEvent(f_.window.get(), &refused);
  QVERIFY(!refused.isAccepted());
}

void MainWindowTest::dockLayoutSurvivesRestart() {
  auto* console = f_.window->findChild<QDockWidget*>("consoleDock");
  auto* part = f_.window->findChild<QDockWidget*>("panel_part");
  QVERIFY(console && part);
  QVERIFY(!part->isHidden());
  part->hide();
  f_.script.unsaved = ddfcam::gui::UnsavedChoice::Discard;
  QVERIFY(f_.window->close());
  QVERIFY(f_.open());
  QVERIFY(f_.window->findChild<QDockWidget*>("panel_part")->isHidden());
  QVERIFY(!f_.window->findChild<QDockWidget*>("panel_fields")->isHidden());
}

DDFCAM_GUI_TEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
