// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel direction strokes drawn by dragging on the part.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_view.h>

#include <QEvent>
#include <QMouseEvent>
#include <QToolButton>

namespace ddfcam::gui {

void StreamlinesPanel::setDrawDirection(bool on) {
  draw_->setChecked(on);
}

void StreamlinesPanel::addStroke(std::vector<ddf::Vec3> stroke) {
  if (stroke.size() < 2) return;
  strokes_.push_back(std::move(stroke));
  setFieldSource(planning::FlowFieldSource::UserStrokes);
  showStrokes();
}

void StreamlinesPanel::clearStrokes() {
  strokes_.clear();
  stroke_.reset();
  showStrokes();
}

void StreamlinesPanel::showStrokes() {
  PartScene& scene = workbench().partView.scene();
  std::vector<std::vector<Eigen::Vector3d>> lines = strokes_;
  if (stroke_) lines.push_back(*stroke_);
  if (lines.empty()) {
    scene.removeOverlay(kStrokeOverlay);
  } else {
    OverlayStyle style;
    style.rgb = {1.0, 1.0, 1.0};
    style.lineWidth = 4.0;
    style.onTop = true;
    scene.setOverlay(kStrokeOverlay, toPolylinePolyData(lines), style);
  }
  workbench().partView.view().requestRender();
}

void StreamlinesPanel::appendStrokePoint(QPointF widgetPos) {
  drawing_ = true;
  const std::optional<PickResult> hit = workbench().partView.pick(widgetPos);
  drawing_ = false;
  if (!hit || !stroke_) return;
  if (stroke_->empty() || (stroke_->back() - hit->location.point).norm() > 0)
    stroke_->push_back(hit->location.point);
  showStrokes();
}

bool StreamlinesPanel::eventFilter(QObject* watched, QEvent* event) {
  // Compare before anything else: at shutdown the filter still sees the view's hide events
  // after the workbench is gone.
  if (watched != viewWidget_ || !draw_ || !draw_->isChecked())
    return Panel::eventFilter(watched, event);
  const auto* mouse = dynamic_cast<QMouseEvent*>(event);
  switch (event->type()) {
    case QEvent::MouseButtonPress:
      if (mouse->button() != Qt::LeftButton) break;
      stroke_.emplace();
      appendStrokePoint(mouse->position());
      return true;  // the drag draws; it does not turn the camera
    case QEvent::MouseMove:
      if (!stroke_) break;
      appendStrokePoint(mouse->position());
      return true;
    case QEvent::MouseButtonRelease: {
      if (mouse->button() != Qt::LeftButton || !stroke_) break;
      appendStrokePoint(mouse->position());
      std::vector<ddf::Vec3> stroke = std::move(*stroke_);
      stroke_.reset();
      if (stroke.size() >= 2)
        addStroke(std::move(stroke));
      else
        showStrokes();
      return true;
    }
    default:
      break;
  }
  return Panel::eventFilter(watched, event);
}

}  // namespace ddfcam::gui
