// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPlayback: the view-dependent level of detail of the live surface (the
// camera handed to planning::LiveSimulation::setView whenever it moved).
#include <ddfcam/gui/panels/simulation_playback.h>

#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_view.h>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace ddfcam::gui {

void SimulationPlayback::updateLevelOfDetail(bool force) {
  if (!live_) return;
  VtkView& view = workbench_.partView.view();
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  double eye[3], focal[3];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  const double dpr = view.devicePixelRatioF();
  const int heightPx = std::max(1, static_cast<int>(view.height() * dpr));
  const int widthPx = std::max(1, static_cast<int>(view.width() * dpr));
  const std::array<double, 9> now = {eye[0],   eye[1],   eye[2],
                                     focal[0], focal[1], focal[2],
                                     camera->GetParallelProjection() ? camera->GetParallelScale()
                                                                     : camera->GetViewAngle(),
                                     static_cast<double>(widthPx), static_cast<double>(heightPx)};
  if (!force && now == lodView_) return;
  lodView_ = now;
  ddf::ViewBoundsParams bounds;
  bounds.eyeMm = ddf::Vec3(eye[0], eye[1], eye[2]);
  bounds.direction = ddf::Vec3(focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2]);
  if (!(bounds.direction.norm() > 0.0)) return;
  bounds.viewAngleDeg = camera->GetViewAngle();
  bounds.parallel = camera->GetParallelProjection() != 0;
  bounds.parallelScaleMm = camera->GetParallelScale();
  bounds.viewportHeightPx = heightPx;
  bounds.aspect = static_cast<double>(widthPx) / heightPx;
  bounds.pixelError = params_.lodPixelError;
  live_->setView(bounds);
  if (!live_->isPlaying()) showLatest();  // a paused playback shows the new detail at once
}

}  // namespace ddfcam::gui
