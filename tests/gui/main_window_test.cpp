// SPDX-License-Identifier: MIT
// The workbench window under Xvfb, checked the way a person would look at it.
#include "frame_checks.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/main_window.h>
#include <ddfcam/gui/part_controller.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>

#include <QAction>
#include <QDir>
#include <QFile>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <memory>

using ddfcam::gui::Layer;
using ddfcam::gui::MainWindow;
using ddfcam::test::changedFraction;
using ddfcam::test::dumpFrame;
using ddfcam::test::frameStats;

class MainWindowTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase();
  void cleanupTestCase() { window_.reset(); }
  void init() { errors_.clear(); }
  void cleanup() { QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0); }
  void startsOnDemoPart();
  void viewShowsThePart();
  void dragMovesCamera();
  void overlaysChangeTheImage_data();
  void overlaysChangeTheImage();
  void openMeshThroughMenu();
  void corruptFileKeepsPreviousPart_data();
  void corruptFileKeepsPreviousPart();
  void saveScreenshotThroughMenu();

 private:
  QImage frame() { return window_->view()->renderImage(); }
  QAction* action(const char* name) { return window_->findChild<QAction*>(name); }
  QColor background() const { return window_->view()->backgroundColor(); }

  std::unique_ptr<MainWindow> window_;
  QTemporaryDir tmp_;
  QString nextOpenPath_;
  QString nextScreenshotPath_;
  QStringList errors_;
};

void MainWindowTest::initTestCase() {
  ddfcam::gui::VtkErrorMonitor::install();
  QVERIFY(tmp_.isValid());
  ddfcam::gui::WorkbenchDialogs dialogs;
  dialogs.openPath = [this] { return nextOpenPath_; };
  dialogs.screenshotPath = [this] { return nextScreenshotPath_; };
  dialogs.error = [this](const QString& title, const QString& message) {
    errors_ << title + ": " + message;
  };
  window_ = std::make_unique<MainWindow>(dialogs);
  window_->resize(900, 640);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void MainWindowTest::startsOnDemoPart() {
  const ddfcam::gui::PartDocument* doc = window_->controller().document();
  QVERIFY(doc != nullptr);
  QCOMPARE(QString::fromStdString(doc->name), QString("demo part"));
  // The demo part's grid is documented: cellsX x cellsY quads, two triangles each, at m.
  const ddfcam::ddf::DemoPartParams demo;
  QCOMPARE(doc->ddf.faceCount(), 2 * demo.cellsX * demo.cellsY);
  QCOMPARE(doc->ddf.resolution(), demo.m);
  QVERIFY2(window_->statusText().contains("faces: 1,536"), qPrintable(window_->statusText()));
  QVERIFY(window_->statusText().contains("m: 17"));
  QVERIFY(window_->scene().cellCount(Layer::Surface) > 1000);
}

void MainWindowTest::viewShowsThePart() {
  const QImage image = frame();
  dumpFrame(image, "main_window_demo");
  const auto stats = frameStats(image, background());
  QVERIFY2(stats.centreForeground > 0.6, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY2(stats.borderBackground > 0.8, qPrintable(QString::number(stats.borderBackground)));
  QVERIFY(stats.cornersBackground);
}

void MainWindowTest::dragMovesCamera() {
  auto* view = window_->view();
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
  QVERIFY(changedFraction(before, frame()) > 0.02);
  window_->findChild<QAction*>("actionFitView")->trigger();
  QVERIFY(frameStats(frame(), background()).cornersBackground);
}

void MainWindowTest::overlaysChangeTheImage_data() {
  QTest::addColumn<QString>("actionName");
  QTest::addColumn<int>("layer");
  QTest::newRow("support mesh") << "actionShowSupport" << static_cast<int>(Layer::Support);
  QTest::newRow("stubbles") << "actionShowStubbles" << static_cast<int>(Layer::Stubbles);
}

void MainWindowTest::overlaysChangeTheImage() {
  QFETCH(QString, actionName);
  QFETCH(int, layer);
  QAction* toggle = action(qPrintable(actionName));
  QVERIFY(toggle && toggle->isCheckable() && !toggle->isChecked());
  QVERIFY(window_->scene().cellCount(static_cast<Layer>(layer)) > 100);
  const QImage off = frame();
  toggle->trigger();
  auto restore = qScopeGuard([toggle] { toggle->setChecked(false); });
  QVERIFY(window_->scene().isVisible(static_cast<Layer>(layer)));
  const QImage on = frame();
  dumpFrame(on, "main_window_" + actionName);
  QVERIFY2(changedFraction(off, on) > 0.01, qPrintable(QString::number(changedFraction(off, on))));
  QVERIFY(frameStats(on, background()).cornersBackground);
  toggle->trigger();
  QVERIFY(!window_->scene().isVisible(static_cast<Layer>(layer)));
  QVERIFY(changedFraction(off, frame()) < 0.001);
}

namespace {

/// A 16 x 12 mm hill z = 2 exp(-((x-8)^2 + (y-6)^2) / 20) sampled on a 16 x 12 grid, as OFF text.
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

void MainWindowTest::openMeshThroughMenu() {
  const QString path = tmp_.filePath("hill.off");
  QVERIFY(writeFile(path, hillOff(16, 12)));
  const QImage demoImage = frame();
  nextOpenPath_ = path;
  action("actionOpen")->trigger();
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
  const ddfcam::gui::PartDocument* doc = window_->controller().document();
  QCOMPARE(QString::fromStdString(doc->name), QString("hill.off"));
  QVERIFY(window_->statusText().startsWith("hill.off"));
  // A converted mesh is the support itself: the hill's triangles and its 16 x 12 mm extent.
  QCOMPARE(doc->ddf.faceCount(), 2 * 16 * 12);
  QVERIFY(doc->load.converted);
  const auto box = ddfcam::ddf::extractSupportMesh(doc->ddf).bounds();
  QVERIFY(box[0].isApprox(Eigen::Vector3d(0, 0, 2.0 * std::exp(-(64.0 + 36.0) / 20.0)), 1e-9));
  QCOMPARE(box[1].x(), 16.0);
  QCOMPARE(box[1].y(), 12.0);
  QCOMPARE(box[1].z(), 2.0);
  const QImage image = frame();
  dumpFrame(image, "main_window_hill");
  const auto stats = frameStats(image, background());
  QVERIFY2(stats.centreForeground > 0.5, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY(stats.cornersBackground);
  QVERIFY(changedFraction(demoImage, image) > 0.05);
}

void MainWindowTest::corruptFileKeepsPreviousPart_data() {
  QTest::addColumn<QString>("fileName");
  QTest::addColumn<QByteArray>("content");
  QTest::newRow("ddf garbage") << "broken.ddf" << QByteArray("DDFCAM\x1a\n garbage, not a field");
  QTest::newRow("off bad index") << "broken.off"
                                 << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  QTest::newRow("stl truncated") << "broken.stl"
                                 << QByteArray("solid s\n facet normal 0 0 1\n  outer loop\n");
}

void MainWindowTest::corruptFileKeepsPreviousPart() {
  QFETCH(QString, fileName);
  QFETCH(QByteArray, content);
  const QString path = tmp_.filePath(fileName);
  QVERIFY(writeFile(path, content));
  const ddfcam::gui::PartDocument* before = window_->controller().document();
  QVERIFY(before != nullptr);
  const std::string nameBefore = before->name;
  const QString statusBefore = window_->statusText();
  const QImage imageBefore = frame();

  nextOpenPath_ = path;
  action("actionOpen")->trigger();
  QCOMPARE(errors_.size(), 1);
  QVERIFY2(errors_.front().contains(fileName), qPrintable(errors_.front()));
  QCOMPARE(window_->controller().document(), before);
  QCOMPARE(window_->controller().document()->name, nameBefore);
  QCOMPARE(window_->statusText(), statusBefore);
  QVERIFY(changedFraction(imageBefore, frame()) < 0.001);
}

void MainWindowTest::saveScreenshotThroughMenu() {
  nextScreenshotPath_ = tmp_.filePath("shot.png");
  action("actionSaveScreenshot")->trigger();
  QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
  const QImage saved(nextScreenshotPath_);
  QVERIFY(!saved.isNull());
  const double dpr = window_->view()->devicePixelRatioF();
  QCOMPARE(saved.width(), qRound(window_->view()->width() * dpr));
  QVERIFY(frameStats(saved, background()).cornersBackground);
  // A path that cannot be written is reported, not silently ignored.
  nextScreenshotPath_ = tmp_.filePath("no/such/folder/shot.png");
  action("actionSaveScreenshot")->trigger();
  QCOMPARE(errors_.size(), 1);
}

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
