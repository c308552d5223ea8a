// SPDX-License-Identifier: MIT
// ddfcam gui: VtkView, the QOpenGLWidget <-> vtkGenericOpenGLRenderWindow bridge.
#include <ddfcam/gui/vtk_view.h>

#include <ddfcam/error.h>

#include <QLineF>
#include <QMouseEvent>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLightKit.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace ddfcam::gui {

namespace {
constexpr double kBackground[3] = {0.20, 0.22, 0.27};
// GL_MAX_RENDERBUFFER_SIZE of Mesa llvmpipe and common desktop GPUs.
constexpr int kMaxImageSide = 16384;

struct ViewSetup {
  std::array<double, 3> towardsCamera;
  std::array<double, 3> up;
};

ViewSetup viewSetup(ViewDirection direction) {
  switch (direction) {
    case ViewDirection::PlusX:
      return {{1, 0, 0}, {0, 0, 1}};
    case ViewDirection::MinusX:
      return {{-1, 0, 0}, {0, 0, 1}};
    case ViewDirection::PlusY:
      return {{0, 1, 0}, {0, 0, 1}};
    case ViewDirection::MinusY:
      return {{0, -1, 0}, {0, 0, 1}};
    case ViewDirection::PlusZ:
      return {{0, 0, 1}, {0, 1, 0}};
    case ViewDirection::MinusZ:
      return {{0, 0, -1}, {0, 1, 0}};
    case ViewDirection::Isometric:
      return {{1, -1, 1}, {0, 0, 1}};
  }
  return {{1, -1, 1}, {0, 0, 1}};
}
}  // namespace

VtkView::VtkView(QWidget* parent) : QOpenGLWidget(parent) {
  renderWindow_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  interactor_ = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  renderer_ = vtkSmartPointer<vtkRenderer>::New();

  renderer_->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  renderer_->GradientBackgroundOff();
  // Key, fill and back lights that follow the camera read curvature better than one headlight.
  auto lights = vtkSmartPointer<vtkLightKit>::New();
  lights->AddLightsToRenderer(renderer_);
  renderWindow_->AddRenderer(renderer_);
  // 2D annotations in their own layer: drawn after the whole 3D scene, untouched by its
  // translucency passes, and never the target of camera interaction.
  annotationRenderer_ = vtkSmartPointer<vtkRenderer>::New();
  annotationRenderer_->SetLayer(1);
  annotationRenderer_->InteractiveOff();
  renderWindow_->SetNumberOfLayers(2);
  renderWindow_->AddRenderer(annotationRenderer_);
  // Qt owns the context and the final framebuffer: VTK renders offscreen and we blit.
  renderWindow_->SetOwnContext(false);
  renderWindow_->SetFrameBlitModeToNoBlit();
  renderWindow_->SetReadyForRendering(false);
  renderWindow_->SetMultiSamples(4);
  renderWindow_->SetForceMaximumHardwareLineWidth(1);

  for (auto event : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                     vtkCommand::WindowSupportsOpenGLEvent, vtkCommand::WindowIsDirectEvent})
    renderWindow_->AddObserver(event, this, &VtkView::onGlEvent);

  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor_->SetInteractorStyle(style);
  interactor_->SetRenderWindow(renderWindow_);
  // Rendering is driven by Qt: an interactor render request becomes a widget update.
  interactor_->EnableRenderOff();
  interactor_->AddObserver(vtkCommand::RenderEvent, this, &VtkView::onGlEvent);
  interactor_->Initialize();

  setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);
  setMinimumSize(160, 120);
}

VtkView::~VtkView() {
  // Trap 3: the context outlives us briefly; a late aboutToBeDestroyed would call into a
  // half-destroyed object, and VTK must release its GL objects while the context still exists.
  if (contextDestroyed_) QObject::disconnect(contextDestroyed_);
  releaseGraphics();
  renderWindow_->RemoveAllObservers();
  interactor_->RemoveAllObservers();
}

vtkRenderer* VtkView::renderer() const {
  return renderer_;
}
vtkRenderer* VtkView::annotationRenderer() const {
  return annotationRenderer_;
}

vtkGenericOpenGLRenderWindow* VtkView::renderWindow() const {
  return renderWindow_;
}

QColor VtkView::backgroundColor() const {
  return QColor::fromRgbF(static_cast<float>(kBackground[0]), static_cast<float>(kBackground[1]),
                          static_cast<float>(kBackground[2]));
}

void VtkView::fitCamera() {
  renderer_->ResetCamera();
  requestRender();
}

void VtkView::fitCameraFrom(double dx, double dy, double dz, double upX, double upY, double upZ) {
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(dx, dy, dz);
  camera->SetViewUp(upX, upY, upZ);
  camera->OrthogonalizeViewUp();
  fitCamera();
}

void VtkView::viewFrom(ViewDirection direction) {
  const ViewSetup v = viewSetup(direction);
  fitCameraFrom(v.towardsCamera[0], v.towardsCamera[1], v.towardsCamera[2], v.up[0], v.up[1],
                v.up[2]);
}

void VtkView::requestRender() {
  update();
}

QImage VtkView::renderImage() {
  return grabFramebuffer();
}

bool VtkView::saveScreenshot(const QString& path) {
  const QImage image = renderImage();
  return !image.isNull() && image.save(path);
}

QImage VtkView::renderImage(QSize devicePixels) {
  const int w = devicePixels.width(), h = devicePixels.height();
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
    throw InvalidInput("renderImage: image size " + std::to_string(w) + " x " + std::to_string(h) +
                       " pixels, each side must be 1 to " + std::to_string(kMaxImageSide));
  // grabFramebuffer() creates the context and runs initializeGL() for a widget never shown.
  if (!glReady_) grabFramebuffer();
  if (!glReady_) return {};
  makeCurrent();
  const int oldW = renderWindow_->GetSize()[0], oldH = renderWindow_->GetSize()[1];
  setRenderSize(w, h);
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->Render();
  renderWindow_->SetReadyForRendering(false);
  QImage image = readDisplayFramebuffer(w, h);
  setRenderSize(oldW, oldH);
  doneCurrent();
  // The widget's framebuffer still holds its last frame; repaint it at its own size anyway so
  // nothing of the offscreen frame can show.
  update();
  return image;
}

bool VtkView::saveScreenshot(const QString& path, QSize devicePixels) {
  const QImage image = renderImage(devicePixels);
  return !image.isNull() && image.save(path);
}

QImage VtkView::readDisplayFramebuffer(int width, int height) {
  vtkOpenGLFramebufferObject* display = renderWindow_->GetDisplayFramebuffer();
  if (!display) return {};
  std::vector<unsigned char> rgba(static_cast<std::size_t>(width) * height * 4);
  vtkOpenGLState* state = renderWindow_->GetState();
  state->PushFramebufferBindings();
  display->Bind(GL_READ_FRAMEBUFFER);
  display->ActivateReadBuffer(0);
  // RGBA rows are 4-byte aligned, the default GL_PACK_ALIGNMENT: no pixel-store change that
  // VTK's state cache would not know about.
  context()->functions()->glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  state->PopFramebufferBindings();
  QImage image(width, height, QImage::Format_RGB32);
  // GL rows run bottom-up; alpha is dropped (trap 2: VTK leaves it below 1 on the background).
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = rgba.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
    auto* out = reinterpret_cast<QRgb*>(image.scanLine(y));
    for (int x = 0; x < width; ++x) out[x] = qRgb(row[4 * x], row[4 * x + 1], row[4 * x + 2]);
  }
  return image;
}

Eigen::Vector2d VtkView::displayPosition(QPointF widgetPos) const {
  const double dpr = devicePixelRatioF();
  const int height = renderWindow_->GetSize()[1];
  return {widgetPos.x() * dpr, height - widgetPos.y() * dpr};
}

QPointF VtkView::widgetPosition(const Eigen::Vector3d& world) const {
  renderer_->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  renderer_->WorldToDisplay();
  const double* display = renderer_->GetDisplayPoint();
  const double dpr = devicePixelRatioF();
  const int height = renderWindow_->GetSize()[1];
  return {display[0] / dpr, (height - display[1]) / dpr};
}

void VtkView::setMotionRendering(bool moving) {
  if (!softwareRendering_) return;
  renderer_->SetUseFXAA(!moving);
  requestRender();
}

void VtkView::initializeGL() {
  if (contextDestroyed_) QObject::disconnect(contextDestroyed_);
  // A reparented widget gets a new context; VTK's objects of the old one must go first.
  contextDestroyed_ =
      connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] { releaseGraphics(); });
  // A software rasterizer (Mesa llvmpipe under Xvfb or a remote desktop) pays for 4x MSAA in
  // fill rate, which halved the frame rate of a live simulation; FXAA smooths the edges at a
  // fraction of that cost. Decided before VTK creates its framebuffers.
  const auto* name = reinterpret_cast<const char*>(context()->functions()->glGetString(GL_RENDERER));
  const QString renderer = name ? QString::fromLatin1(name) : QString();
  softwareRendering_ = renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                       renderer.contains("swrast") || renderer.contains("Software");
  if (softwareRendering_) {
    renderWindow_->SetMultiSamples(0);
    renderer_->UseFXAAOn();
  }
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->InitializeFromCurrentContext();
  renderWindow_->SetReadyForRendering(false);
  renderWindow_->SetMapped(true);
  glReady_ = true;
  resizeGL(width(), height());
}

void VtkView::resizeGL(int w, int h) {
  const double dpr = devicePixelRatioF();
  setRenderSize(std::max(1, static_cast<int>(std::lround(w * dpr))),
                std::max(1, static_cast<int>(std::lround(h * dpr))));
}

void VtkView::setRenderSize(int devicePixelsX, int devicePixelsY) {
  renderWindow_->SetSize(devicePixelsX, devicePixelsY);
  interactor_->UpdateSize(devicePixelsX, devicePixelsY);
}

void VtkView::paintGL() {
  if (!glReady_) return;
  QElapsedTimer clock;
  clock.start();
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->Render();
  renderWindow_->SetReadyForRendering(false);
  blitToWidget();
  ++renderedFrames_;
  renderSeconds_ += clock.nsecsElapsed() * 1e-9;
}

void VtkView::blitToWidget() {
  vtkOpenGLFramebufferObject* display = renderWindow_->GetDisplayFramebuffer();
  if (!display) return;
  const int* size = renderWindow_->GetSize();
  vtkOpenGLState* state = renderWindow_->GetState();
  state->PushFramebufferBindings();
  // The widget's FBO, never 0: QOpenGLWidget composites from its own framebuffer.
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  state->vtkglDrawBuffer(GL_COLOR_ATTACHMENT0);
  display->Bind(GL_READ_FRAMEBUFFER);
  display->ActivateReadBuffer(0);
  state->vtkglViewport(0, 0, size[0], size[1]);
  state->vtkglScissor(0, 0, size[0], size[1]);
  state->vtkglBlitFramebuffer(0, 0, size[0], size[1], 0, 0, size[0], size[1], GL_COLOR_BUFFER_BIT,
                              GL_NEAREST);
  // Trap 2: VTK leaves alpha < 1 where nothing was drawn; grabFramebuffer() and the
  // compositor would show those pixels as black or translucent.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(true, true, true, true);
  state->PopFramebufferBindings();
}

void VtkView::releaseGraphics() {
  if (!glReady_ || !context()) return;
  makeCurrent();
  renderWindow_->Finalize();
  doneCurrent();
  glReady_ = false;
}

void VtkView::onGlEvent(vtkObject* caller, unsigned long eventId, void* callData) {
  Q_UNUSED(caller);
  switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
      onMakeCurrent();
      break;
    case vtkCommand::WindowIsCurrentEvent:
      *static_cast<bool*>(callData) =
          context() != nullptr && QOpenGLContext::currentContext() == context();
      break;
    case vtkCommand::WindowSupportsOpenGLEvent:
      *static_cast<int*>(callData) = 1;
      break;
    case vtkCommand::WindowIsDirectEvent:
      *static_cast<int*>(callData) = 1;
      break;
    case vtkCommand::RenderEvent:
      update();
      break;
    default:
      break;
  }
}

void VtkView::onMakeCurrent() {
  // Trap 1: inside paintGL the context is already current with the widget FBO bound, and VTK's
  // state cache knows about its own bindings; QOpenGLWidget::makeCurrent() would rebind the
  // widget FBO behind VTK's back. Only switch when another context (or none) is current.
  QOpenGLContext* ctx = context();
  if (ctx && QOpenGLContext::currentContext() != ctx) makeCurrent();
}

void VtkView::setEventPosition(const QPointF& pos, Qt::KeyboardModifiers modifiers) {
  const double dpr = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(
      static_cast<int>(std::lround(pos.x() * dpr)), static_cast<int>(std::lround(pos.y() * dpr)),
      (modifiers & Qt::ControlModifier) ? 1 : 0, (modifiers & Qt::ShiftModifier) ? 1 : 0);
  interactor_->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
}

void VtkView::mousePressEvent(QMouseEvent* event) {
  setEventPosition(event->position(), event->modifiers());
  interactor_->SetRepeatCount(event->type() == QEvent::MouseButtonDblClick ? 1 : 0);
  switch (event->button()) {
    case Qt::LeftButton:
      leftDown_ = true;
      dragged_ = false;
      pressPosition_ = event->position();
      interactor_->LeftButtonPressEvent();
      break;
    case Qt::MiddleButton:
      interactor_->MiddleButtonPressEvent();
      break;
    case Qt::RightButton:
      interactor_->RightButtonPressEvent();
      break;
    default:
      return QOpenGLWidget::mousePressEvent(event);
  }
  event->accept();
}

void VtkView::mouseReleaseEvent(QMouseEvent* event) {
  setEventPosition(event->position(), event->modifiers());
  switch (event->button()) {
    case Qt::LeftButton: {
      interactor_->LeftButtonReleaseEvent();
      const bool click = leftDown_ && !dragged_ &&
                         QLineF(pressPosition_, event->position()).length() < kClickSlopPx;
      leftDown_ = false;
      if (click) emit clicked(event->position(), event->modifiers());
      break;
    }
    case Qt::MiddleButton:
      interactor_->MiddleButtonReleaseEvent();
      break;
    case Qt::RightButton:
      interactor_->RightButtonReleaseEvent();
      break;
    default:
      return QOpenGLWidget::mouseReleaseEvent(event);
  }
  event->accept();
}

void VtkView::mouseMoveEvent(QMouseEvent* event) {
  // Once a press has wandered off it is a drag, even if it comes back.
  if (leftDown_ && QLineF(pressPosition_, event->position()).length() >= kClickSlopPx)
    dragged_ = true;
  setEventPosition(event->position(), event->modifiers());
  interactor_->MouseMoveEvent();
  event->accept();
}

void VtkView::wheelEvent(QWheelEvent* event) {
  setEventPosition(event->position(), event->modifiers());
  const int delta = event->angleDelta().y();
  if (delta > 0) interactor_->MouseWheelForwardEvent();
  if (delta < 0) interactor_->MouseWheelBackwardEvent();
  event->accept();
}

}  // namespace ddfcam::gui
