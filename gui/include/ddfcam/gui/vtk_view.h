// SPDX-License-Identifier: MIT
// ddfcam gui: a QOpenGLWidget hosting a VTK renderer (vtkGenericOpenGLRenderWindow, no QVTK).
#pragma once

#include <QColor>
#include <QImage>
#include <QMetaObject>
#include <QOpenGLWidget>
#include <QString>

#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;
class vtkObject;

namespace ddfcam::gui {

/// @brief 3D view: VTK renders into its own framebuffers inside the widget's GL context and the
/// result is blitted into the widget framebuffer. Mouse input drives a trackball camera
/// (left: rotate, middle or shift+left: pan, right or wheel: zoom).
///
/// Requires a default QSurfaceFormat of OpenGL >= 3.2 core (see setDefaultSurfaceFormat())
/// set before the QApplication is created.
class VtkView : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit VtkView(QWidget* parent = nullptr);
  ~VtkView() override;

  /// @brief The single renderer of the view; add actors to it and call requestRender().
  vtkRenderer* renderer() const;
  /// @brief The VTK render window bound to this widget's GL context.
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  /// @brief Uniform background colour of the view (no gradient, so tests can compare pixels).
  QColor backgroundColor() const;

  /// @brief Resets the camera so that all visible props fit the view, keeping the viewing
  /// direction; schedules a repaint.
  void fitCamera();
  /// @brief Looks at the visible props from direction (@p dx, @p dy, @p dz) (from the focal
  /// point towards the camera, part frame) with the given view-up, then fits them.
  void fitCameraFrom(double dx, double dy, double dz, double upX, double upY, double upZ);
  /// @brief Schedules a repaint (VTK renders inside paintGL).
  void requestRender();
  /// @brief Renders a frame now and returns it (device pixels, opaque).
  QImage renderImage();
  /// @brief Renders a frame and writes it to @p path (format from the suffix, e.g. .png).
  /// @return false if the image could not be written.
  bool saveScreenshot(const QString& path);

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void onMakeCurrent();
  void onGlEvent(vtkObject* caller, unsigned long eventId, void* callData);
  void blitToWidget();
  void releaseGraphics();
  void setEventPosition(const QPointF& pos, Qt::KeyboardModifiers modifiers);

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkRenderer> renderer_;
  QMetaObject::Connection contextDestroyed_;
  bool glReady_ = false;
};

}  // namespace ddfcam::gui
