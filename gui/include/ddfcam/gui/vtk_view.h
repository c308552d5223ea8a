// SPDX-License-Identifier: MIT
// ddfcam gui: a QOpenGLWidget hosting a VTK renderer (vtkGenericOpenGLRenderWindow, no QVTK).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include <QColor>
#include <QImage>
#include <QMetaObject>
#include <QOpenGLWidget>
#include <QPointF>
#include <QSize>
#include <QString>

#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;
class vtkObject;

namespace ddfcam::gui {

/// @brief Standard viewing directions: the camera sits on the named side of the part (PlusZ:
/// above it, looking down -z). Side views keep +z up; the top and bottom views keep +y up.
enum class ViewDirection {
  PlusX = 0,  ///< camera on +x, looking towards -x
  MinusX,     ///< camera on -x
  PlusY,      ///< camera on +y
  MinusY,     ///< camera on -y
  PlusZ,      ///< camera on +z (top view), +y up
  MinusZ,     ///< camera on -z (bottom view), +y up
  Isometric,  ///< camera on (1, -1, 1) (front right, above), +z up
};

/// @brief 3D view: VTK renders into its own framebuffers inside the widget's GL context and the
/// result is blitted into the widget framebuffer. Mouse input drives a trackball camera
/// (left: rotate, middle or shift+left: pan, right or wheel: zoom). A left press and release
/// without dragging emits clicked().
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
  /// @brief Renderer of 2D annotations (scalar bars, legends), a layer drawn over the 3D scene
  /// after it is complete (translucent props included) and ignored by camera interaction.
  vtkRenderer* annotationRenderer() const;
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
  /// @brief Looks at the visible props from @p direction (see ViewDirection), then fits them.
  void viewFrom(ViewDirection direction);
  /// @brief Schedules a repaint (VTK renders inside paintGL).
  void requestRender();
  /// @brief Frames rendered into the widget so far (paintGL calls that rendered): a display
  /// rate is the difference over a time span.
  std::uint64_t renderedFrames() const { return renderedFrames_; }
  /// @brief Wall time spent rendering those frames, s (the cost of a frame is its share).
  double renderSeconds() const { return renderSeconds_; }
  /// @brief True when the GL context is a software rasterizer (then FXAA replaces 4x MSAA).
  bool softwareRendering() const { return softwareRendering_; }
  /// @brief While @p moving (a live simulation playing), a software rasterizer skips FXAA: at
  /// 30 or more frames per second the edges alias unnoticed and the pass costs a third of a
  /// frame; back to smooth edges when it stops. No effect with hardware rendering (MSAA).
  void setMotionRendering(bool moving);
  /// @brief Renders a frame now and returns it (device pixels, opaque).
  QImage renderImage();
  /// @brief Renders one frame offscreen at exactly @p devicePixels (e.g. 1920 x 1080 for a
  /// report, independent of the widget size) and returns it, opaque RGB. The camera's view
  /// angle is kept, so a different aspect ratio shows more or less at the sides. The widget
  /// and its next frames are unaffected. Initialises the GL context if the widget was never
  /// shown.
  /// @return a null image if no GL context could be made.
  /// @throws InvalidInput if a side is below 1 or above 16384 pixels.
  QImage renderImage(QSize devicePixels);
  /// @brief Renders a frame and writes it to @p path (format from the suffix, e.g. .png).
  /// @return false if the image could not be written.
  bool saveScreenshot(const QString& path);
  /// @brief renderImage(devicePixels) written to @p path (format from the suffix).
  /// @return false if the image could not be made or written.
  /// @throws InvalidInput as renderImage(QSize).
  bool saveScreenshot(const QString& path, QSize devicePixels);

  /// @brief VTK display coordinates (device pixels, origin bottom left, as vtkRenderer and
  /// vtkPicker take them) of widget position @p widgetPos (logical pixels, origin top left).
  Eigen::Vector2d displayPosition(QPointF widgetPos) const;
  /// @brief Where world point @p world (mm, part frame) appears in the widget (logical pixels,
  /// origin top left) with the current camera; the inverse of a pick.
  QPointF widgetPosition(const Eigen::Vector3d& world) const;

  /// A press and release closer than this (logical pixels) count as a click, not a drag.
  static constexpr double kClickSlopPx = 4.0;

 signals:
  /// @brief Left button pressed and released with less than kClickSlopPx of movement at
  /// @p widgetPos (logical pixels, origin top left); drags (camera rotation) do not emit it.
  void clicked(QPointF widgetPos, Qt::KeyboardModifiers modifiers);

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
  void setRenderSize(int devicePixelsX, int devicePixelsY);
  QImage readDisplayFramebuffer(int width, int height);

  std::uint64_t renderedFrames_ = 0;
  double renderSeconds_ = 0.0;
  bool softwareRendering_ = false;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkRenderer> annotationRenderer_;
  QMetaObject::Connection contextDestroyed_;
  bool glReady_ = false;
  bool leftDown_ = false;  ///< a left press is in progress
  bool dragged_ = false;   ///< ... and has moved kClickSlopPx or more
  QPointF pressPosition_;  ///< where it started, logical pixels
};

}  // namespace ddfcam::gui
