// SPDX-License-Identifier: MIT
// ddfcam gui: RegionViewTool's brush circle under the mouse and Escape cancelling a stroke.
#include <ddfcam/gui/panels/region_view_tool.h>

#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_view.h>

#include <QKeyEvent>

#include <vtkActor2D.h>

#include <cmath>
#include <numbers>

namespace ddfcam::gui {
namespace {

// A closed polyline of @p radius around @p centre in the plane normal to @p normal.
std::vector<Eigen::Vector3d> circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                                    double radius) {
  const Eigen::Vector3d n = normal.norm() > 0 ? normal.normalized() : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  constexpr int kSegments = 48;
  std::vector<Eigen::Vector3d> ring;
  for (int s = 0; s <= kSegments; ++s) {
    const double a = 2.0 * std::numbers::pi * s / kSegments;
    ring.push_back(centre + radius * (std::cos(a) * u + std::sin(a) * v));
  }
  return ring;
}

}  // namespace

void RegionViewTool::setBrushRadiusMm(double radiusMm) {
  radiusMm_ = radiusMm;
  if (cursorCentre_) updateBrushCursor(cursorPos_);
}

void RegionViewTool::updateBrushCursor(QPointF pos) {
  PartView& partView = workbench_.partView;
  const std::optional<SurfacePick> hit = workbench_.document.project().part
                                             ? partView.scene().pickSurface(partView.view(), pos)
                                             : std::nullopt;
  if (!hit || hit->face < 0 || hit->face >= static_cast<int>(faceFrameCache().size())) {
    hideBrushCursor();
    return;
  }
  const planning::FaceFrame& frame = faceFrameCache()[hit->face];
  cursorCentre_ = hit->position;
  cursorPos_ = pos;
  OverlayStyle style;
  style.rgb =
      mode_ == RegionEditMode::Erase ? std::array{1.0, 0.35, 0.3} : std::array{1.0, 1.0, 1.0};
  style.lineWidth = 2.0;
  style.onTop = true;
  partView.scene().setOverlay(kBrushCursorOverlay,
                              toPolylinePolyData({circle(hit->position, frame.normal, radiusMm_)}),
                              style);
  partView.view().requestRender();
}

void RegionViewTool::hideBrushCursor() {
  cursorCentre_.reset();
  if (workbench_.partView.scene().removeOverlay(kBrushCursorOverlay))
    workbench_.partView.view().requestRender();
}

bool RegionViewTool::cancelStroke() {
  if (!dragging_) return false;
  dragging_ = false;
  painted_.clear();
  lasso_.clear();
  outline_->VisibilityOff();
  rebuildColours(workbench_.document.project().regions);  // drop the preview
  return true;
}

bool RegionViewTool::handleKey(QEvent* event) {
  if (static_cast<QKeyEvent*>(event)->key() != Qt::Key_Escape || !dragging_) return false;
  // The window's Escape shortcut (cancel job) must not take the key while a stroke is drawn.
  if (event->type() == QEvent::ShortcutOverride) {
    event->accept();
    return true;
  }
  cancelStroke();
  return true;
}

}  // namespace ddfcam::gui
