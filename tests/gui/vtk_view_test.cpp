// SPDX-License-Identifier: MIT
// VtkView under Xvfb: a real frame, an opaque background, camera interaction, no VTK errors.
#include "gui_test_registry.h"
#include "frame_checks.h"

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/app_setup.h>
#include <ddfcam/gui/camera_tool_bar.h>
#include <ddfcam/gui/vtk_error_monitor.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <QAction>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSetGet.h>

#include <array>
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
  void clickEmitsClickedButDragDoesNot();
  void viewFromPutsCameraOnThatSide();
  void cameraToolBarActionsMoveTheCamera();
  void widgetPositionFindsTheRollCentre();
  void renderImageAtChosenSize();
  void renderImageOfHiddenView();

 private:
  Eigen::Vector3d directionOfProjection() const;
  void dragFrom(QPoint start, QPoint offset);

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

Eigen::Vector3d VtkViewTest::directionOfProjection() const {
  double d[3];
  view_->renderer()->GetActiveCamera()->GetDirectionOfProjection(d);
  return {d[0], d[1], d[2]};
}

void VtkViewTest::dragFrom(QPoint start, QPoint offset) {
  QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, start);
  for (int i = 1; i <= 4; ++i) {
    const QPointF p = QPointF(start) + QPointF(offset) * (i / 4.0);
    QMouseEvent move(QEvent::MouseMove, p, view_->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(view_.get(), &move);
  }
  QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, start + offset);
}

void VtkViewTest::clickEmitsClickedButDragDoesNot() {
  QSignalSpy spy(view_.get(), &VtkView::clicked);
  const QPoint c = view_->rect().center();
  QTest::mouseClick(view_.get(), Qt::LeftButton, Qt::ShiftModifier, c + QPoint(5, -7));
  QCOMPARE(spy.count(), 1);
  QCOMPARE(spy.at(0).at(0).toPointF(), QPointF(c + QPoint(5, -7)));
  QCOMPARE(spy.at(0).at(1).value<Qt::KeyboardModifiers>(),
           Qt::KeyboardModifiers(Qt::ShiftModifier));
  // A hand that trembles by 2 px still clicks.
  dragFrom(c, QPoint(2, 1));
  QCOMPARE(spy.count(), 2);
  // A drag rotates instead, also when it ends near where it started.
  dragFrom(c, QPoint(60, 20));
  QCOMPARE(spy.count(), 2);
  QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, c);
  QMouseEvent away(QEvent::MouseMove, QPointF(c + QPoint(30, 0)),
                   view_->mapToGlobal(QPointF(c + QPoint(30, 0))), Qt::NoButton, Qt::LeftButton,
                   Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &away);
  QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, c + QPoint(1, 0));
  QCOMPARE(spy.count(), 2);
  // Other buttons never click.
  QTest::mouseClick(view_.get(), Qt::RightButton, Qt::NoModifier, c);
  QCOMPARE(spy.count(), 2);
}

void VtkViewTest::viewFromPutsCameraOnThatSide() {
  using ddfcam::gui::ViewDirection;
  struct Case {
    ViewDirection direction;
    Eigen::Vector3d towardsCamera, up;
  };
  const Case cases[] = {
      {ViewDirection::PlusX, {1, 0, 0}, {0, 0, 1}},
      {ViewDirection::MinusX, {-1, 0, 0}, {0, 0, 1}},
      {ViewDirection::PlusY, {0, 1, 0}, {0, 0, 1}},
      {ViewDirection::MinusY, {0, -1, 0}, {0, 0, 1}},
      {ViewDirection::PlusZ, {0, 0, 1}, {0, 1, 0}},
      {ViewDirection::MinusZ, {0, 0, -1}, {0, 1, 0}},
      {ViewDirection::Isometric, Eigen::Vector3d(1, -1, 1).normalized(), {0, 0, 1}},
  };
  vtkCamera* camera = view_->renderer()->GetActiveCamera();
  for (const Case& c : cases) {
    view_->viewFrom(c.direction);
    QVERIFY((directionOfProjection() + c.towardsCamera).norm() < 1e-9);
    double up[3], position[3], focal[3];
    camera->GetViewUp(up);
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    // The view-up is the requested axis made orthogonal to the viewing direction.
    const Eigen::Vector3d upOrtho =
        (c.up - c.up.dot(c.towardsCamera) * c.towardsCamera).normalized();
    QVERIFY((Eigen::Vector3d(up[0], up[1], up[2]) - upOrtho).norm() < 1e-9);
    // Fitted: the roll (radius 10-ish at the origin) is looked at, from outside.
    QVERIFY(Eigen::Vector3d(focal[0], focal[1], focal[2]).norm() < 30.0);
    const Eigen::Vector3d offset(position[0] - focal[0], position[1] - focal[1],
                                 position[2] - focal[2]);
    QVERIFY(offset.dot(c.towardsCamera) > 0.0);
    const QImage image = view_->renderImage();
    const auto stats = frameStats(image, view_->backgroundColor());
    QVERIFY(stats.cornersBackground);
    QVERIFY2(stats.centreForeground > 0.3, qPrintable(QString::number(stats.centreForeground)));
  }
  // PlusZ looks down: the camera is above the focal point.
  view_->viewFrom(ViewDirection::PlusZ);
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  QVERIFY(position[2] > focal[2]);
}

void VtkViewTest::cameraToolBarActionsMoveTheCamera() {
  ddfcam::gui::CameraToolBar bar(view_.get());
  const std::array<std::pair<const char*, const char*>, 8> expected = {{
      {"actionViewFit", "Fit"},
      {"actionViewPlusX", "+X"},
      {"actionViewMinusX", "-X"},
      {"actionViewPlusY", "+Y"},
      {"actionViewMinusY", "-Y"},
      {"actionViewPlusZ", "+Z"},
      {"actionViewMinusZ", "-Z"},
      {"actionViewIsometric", "Iso"},
  }};
  for (const auto& [name, text] : expected) {
    auto* action = bar.findChild<QAction*>(name);
    QVERIFY2(action != nullptr, name);
    QCOMPARE(action->text(), QString(text));
    QVERIFY(action->isEnabled());
  }
  bar.findChild<QAction*>("actionViewMinusY")->trigger();
  QVERIFY((directionOfProjection() - Eigen::Vector3d(0, 1, 0)).norm() < 1e-9);
  bar.directionAction(ddfcam::gui::ViewDirection::PlusZ)->trigger();
  QVERIFY((directionOfProjection() - Eigen::Vector3d(0, 0, -1)).norm() < 1e-9);
  // Fit after a zoom brings the camera back to the fitted distance, direction kept.
  vtkCamera* camera = view_->renderer()->GetActiveCamera();
  const double fitted = camera->GetDistance();
  camera->Dolly(3.0);
  QVERIFY(camera->GetDistance() < 0.5 * fitted);
  bar.fitAction()->trigger();
  QVERIFY(std::abs(camera->GetDistance() - fitted) < 1e-6 * fitted);
  QVERIFY((directionOfProjection() - Eigen::Vector3d(0, 0, -1)).norm() < 1e-9);
  bar.setView(nullptr);
  QVERIFY(!bar.fitAction()->isEnabled());
  QVERIFY(!bar.directionAction(ddfcam::gui::ViewDirection::PlusX)->isEnabled());
}

void VtkViewTest::widgetPositionFindsTheRollCentre() {
  // The roll is centred at the origin and the camera was fitted onto it.
  view_->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  double focal[3];
  view_->renderer()->GetActiveCamera()->GetFocalPoint(focal);
  const QPointF centre = view_->widgetPosition({focal[0], focal[1], focal[2]});
  QVERIFY(std::abs(centre.x() - view_->width() / 2.0) < 1.0);
  QVERIFY(std::abs(centre.y() - view_->height() / 2.0) < 1.0);
  // Round trip through VTK display coordinates.
  const QPointF p(37.25, 81.5);
  const Eigen::Vector2d display = view_->displayPosition(p);
  const double dpr = view_->devicePixelRatioF();
  QVERIFY(std::abs(display.x() - p.x() * dpr) < 1e-9);
  QVERIFY(std::abs(display.y() - (qRound(view_->height() * dpr) - p.y() * dpr)) < 1e-9);
  // Up in the world (+z, the view-up) is up on the screen.
  const QPointF above = view_->widgetPosition({focal[0], focal[1], focal[2] + 5.0});
  QVERIFY(above.y() < centre.y() - 5.0);
}

void VtkViewTest::renderImageAtChosenSize() {
  const QImage before = view_->renderImage();
  const int* sizeBefore = view_->renderWindow()->GetSize();
  const int w0 = sizeBefore[0], h0 = sizeBefore[1];
  const QImage big = view_->renderImage(QSize(640, 480));
  ddfcam::test::dumpFrame(big, "vtk_view_roll_640x480");
  QCOMPARE(big.size(), QSize(640, 480));
  const auto stats = frameStats(big, view_->backgroundColor());
  QVERIFY2(stats.centreForeground > 0.4, qPrintable(QString::number(stats.centreForeground)));
  QVERIFY(stats.borderBackground > 0.9);
  QVERIFY(stats.cornersBackground);
  // The widget is left as it was: same render size, same frame.
  QCOMPARE(view_->renderWindow()->GetSize()[0], w0);
  QCOMPARE(view_->renderWindow()->GetSize()[1], h0);
  const QImage after = view_->renderImage();
  QCOMPARE(after.size(), before.size());
  QVERIFY2(changedFraction(before, after) < 0.002,
           qPrintable(QString::number(changedFraction(before, after))));
  // A non-default aspect ratio and a file.
  QTemporaryDir dir;
  const QString path = dir.filePath("shot.png");
  QVERIFY(view_->saveScreenshot(path, QSize(300, 500)));
  const QImage saved(path);
  QCOMPARE(saved.size(), QSize(300, 500));
  QVERIFY(frameStats(saved, view_->backgroundColor()).cornersBackground);
  QVERIFY_THROWS_EXCEPTION(ddfcam::InvalidInput, view_->renderImage(QSize(0, 10)));
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

void VtkViewTest::renderImageOfHiddenView() {
  // A view that was never shown (batch screenshots) still renders at the requested size.
  VtkView hidden;
  hidden.resize(200, 150);
  ddfcam::planning::CylinderToolParams params;
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(ddfcam::gui::toSurfacePolyData(ddfcam::planning::makeCylinderTool(params)));
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  hidden.renderer()->AddActor(actor);
  hidden.viewFrom(ddfcam::gui::ViewDirection::Isometric);
  const QImage image = hidden.renderImage(QSize(320, 240));
  QCOMPARE(image.size(), QSize(320, 240));
  const auto stats = frameStats(image, hidden.backgroundColor());
  QVERIFY(stats.cornersBackground);
  QVERIFY2(stats.centreForeground > 0.3, qPrintable(QString::number(stats.centreForeground)));
  QCOMPARE(ddfcam::gui::VtkErrorMonitor::errorCount(), 0);
}

DDFCAM_GUI_TEST_MAIN(VtkViewTest)
#include "vtk_view_test.moc"
