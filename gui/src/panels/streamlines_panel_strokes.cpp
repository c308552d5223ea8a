// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel direction strokes drawn by dragging on the part.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/region_commands.h>
#include <ddfcam/gui/user_action.h>
#include <ddfcam/gui/vtk_view.h>

#include <QComboBox>
#include <QEvent>
#include <QMouseEvent>
#include <QToolButton>

namespace ddfcam::gui {

void StreamlinesPanel::setDrawDirection(bool on) {
  draw_->setChecked(on);
}

const std::vector<std::vector<ddf::Vec3>>& StreamlinesPanel::strokes() const {
  const planning::RegionPlan* plan = selectedPlan();
  return plan ? plan->strokes : strokes_;
}

void StreamlinesPanel::setPlanStrokes(std::vector<std::vector<ddf::Vec3>> strokes,
                                      const QString& text) {
  runUserAction(workbench().reportError, text, [&] {
    Document& document = workbench().document;
    const int region = region_->currentData().toInt();
    std::vector<planning::Region> after = document.project().regions;
    planning::RegionPlan& plan = after.at(region).plan;
    plan.strokes = std::move(strokes);
    // A region with strokes is planned along them, as the panel's field now is.
    if (!plan.strokes.empty()) plan.flowSource = planning::FlowFieldSource::UserStrokes;
    const QString undoText =
        QString("%1 (%2)").arg(text, QString::fromStdString(after[region].name));
    document.push(std::make_unique<SetRegionsCommand>(document, undoText, std::move(after)));
  });
}

void StreamlinesPanel::addStroke(std::vector<ddf::Vec3> stroke) {
  if (stroke.size() < 2) return;
  setFieldSource(planning::FlowFieldSource::UserStrokes);
  if (const planning::RegionPlan* plan = selectedPlan()) {
    std::vector<std::vector<ddf::Vec3>> strokes = plan->strokes;
    strokes.push_back(std::move(stroke));
    setPlanStrokes(std::move(strokes), tr("Draw direction stroke"));
  } else {
    strokes_.push_back(std::move(stroke));
  }
  showStrokes();
}

void StreamlinesPanel::clearStrokes() {
  stroke_.reset();
  const planning::RegionPlan* plan = selectedPlan();
  if (plan && !plan->strokes.empty())
    setPlanStrokes({}, tr("Clear direction strokes"));
  else if (!plan)
    strokes_.clear();
  showStrokes();
}

void StreamlinesPanel::showStrokes() {
  PartScene& scene = workbench().partView.scene();
  std::vector<std::vector<Eigen::Vector3d>> lines = strokes();
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
