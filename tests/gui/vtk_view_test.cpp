// SPDX-License-Identifier: MIT
// VtkView under Xvfb: a real frame, an opaque background, camera interaction, no VTK errors.
#include "frame_checks.h"

#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/tool_shapes.h>

#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSetGet.h>

#include <memory>

using ddfcam::gui::VtkView;
using ddfcam::test::changedFraction;
using ddfcam::test::frameStats;

class VtkViewTest : public QObject {
  Q_OBJECT

 public:
  static void initMain() { ddfcam::gui::setDefaultSurfaceFormat(); }

 private slots:
  void initTestCase() { ddfcam::gui::VtkErrorMonitor::install(); }
  void init();
  void cleanup() { view_.reset(); }
  void rendersPartWithOpaqueBackground();
  void dragRotatesCamera();
  void wheelZooms();
  void imageHasDevicePixelSize();
  void errorMonitorCountsVtkErrors();

 private:
  std::unique_ptr<VtkView> view_;
};

void VtkViewTest::init() {
  ddfcam::gui::VtkErrorMonitor::reset();
  view_ = std::make_unique<VtkView>();
  view_->resize(400, 300);
  // A closed roll seen from an oblique angle: a compact blob in the middle of the frame.
  ddfcam::planning::CylinderToolParams params;
  params.segments = 48;
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(ddfcam::gui::toSurfacePolyData(ddfcam::planning::makeCylinderTool(params)));
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  view_->renderer()->AddActor(actor);
  view_->renderer()->GetActiveCamera()->SetPosition(30, 20, 40);
  view_->renderer()->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  view_->fitCamera();
  view_->show();
  QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
}

void VtkViewTest::rendersPartWithOpaqueBackground() {
  const QImage image = view_->renderImage();
  ddfcam::test::dumpFrame(image, "vtk_view_roll");
  QVERIFY(!image.isNull());
  const auto stats = frameStats(image, view_->backgroundColor());
  QVERIFY2(stats.centreForeground > 0.5, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY2(stats.borderBackground > 0.9, qPrintable(QString::number(stats.borderBackground)));
  QVERIFY(stats.cornersBackground);
  // Trap 2: the grabbed background must be opaque, not black/transparent.
  QCOMPARE(qAlpha(image.pixel(0, 0)), 255);
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void VtkViewTest::dragRotatesCamera() {
  vtkCamera* camera = view_->renderer()->GetActiveCamera();
  const QImage before = view_->renderImage();
  double p0[3];
  camera->GetPosition(p0);
  const QPoint c = view_->rect().center();
  QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, c);
  for (int i = 1; i <= 8; ++i) {
    QMouseEvent move(QEvent::MouseMove, QPointF(c + QPoint(10 * i, 3 * i)),
                     view_->mapToGlobal(QPointF(c + QPoint(10 * i, 3 * i))), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view_.get(), &move);
  }
  QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, c + QPoint(80, 24));
  double p1[3];
  camera->GetPosition(p1);
  const double moved = std::hypot(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
  QVERIFY2(moved > 1.0, qPrintable(QString::number(moved)));
  const QImage after = view_->renderImage();
  ddfcam::test::dumpFrame(after, "vtk_view_roll_rotated");
  QVERIFY(changedFraction(before, after) > 0.01);
  QVERIFY(frameStats(after, view_->backgroundColor()).cornersBackground);
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void VtkViewTest::wheelZooms() {
  vtkCamera* camera = view_->renderer()->GetActiveCamera();
  const double d0 = camera->GetDistance();
  const QPointF c = view_->rect().center();
  QWheelEvent wheel(c, view_->mapToGlobal(c), QPoint(), QPoint(0, 120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(view_.get(), &wheel);
  QVERIFY2(camera->GetDistance() < 0.99 * d0,
           qPrintable(QString("%1 -> %2").arg(d0).arg(camera->GetDistance())));
}

void VtkViewTest::imageHasDevicePixelSize() {
  // Run by CTest a second time with QT_SCALE_FACTOR=2: the frame must cover the whole widget.
  const QImage image = view_->renderImage();
  const double dpr = view_->devicePixelRatioF();
  QCOMPARE(image.width(), qRound(view_->width() * dpr));
  QCOMPARE(image.height(), qRound(view_->height() * dpr));
  const auto stats = frameStats(image, view_->backgroundColor());
  QVERIFY(stats.cornersBackground);
  QVERIFY(stats.centreForeground > 0.5);
}

void VtkViewTest::errorMonitorCountsVtkErrors() {
  // The "no VTK error" checks above are only meaningful if errors do reach the monitor.
  ddfcam::gui::VtkErrorMonitor::reset();
  auto object = vtkSmartPointer<vtkObject>::New();
  vtkErrorWithObjectMacro(object, "deliberate test error");
  vtkWarningWithObjectMacro(object, "deliberate test warning");
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 1);
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::warningCount(), 1);
  ddfcam::gui::VtkErrorMonitor::reset();
}

QTEST_MAIN(VtkViewTest)
#include "vtk_view_test.moc"
