// SPDX-License-Identifier: MIT
// ddfcam gui: tool and collision overlays.
#include <ddfcam/gui/tool_overlay.h>

#include <ddfcam/gui/adapters/line_glyphs.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/part_scene.h>

namespace ddfcam::gui {

void showToolOverlay(PartScene& scene, const planning::Tool& tool, const Eigen::Isometry3d& pose,
                     bool colliding) {
  const planning::ToolMeshes meshes = planning::toolMeshes(tool);
  OverlayStyle cutting;
  cutting.rgb = {0.95, 0.62, 0.22};
  cutting.opacity = 0.6;
  cutting.surface = true;
  scene.setOverlay(kToolCuttingOverlay, toSurfacePolyData(meshes.cutting.transformed(pose)),
                   cutting);
  if (meshes.nonCutting.triangles.empty()) {
    scene.removeOverlay(kToolNonCuttingOverlay);
    return;
  }
  OverlayStyle rest = cutting;
  rest.rgb =
      colliding ? std::array<double, 3>{0.9, 0.1, 0.1} : std::array<double, 3>{0.55, 0.62, 0.75};
  scene.setOverlay(kToolNonCuttingOverlay, toSurfacePolyData(meshes.nonCutting.transformed(pose)),
                   rest);
}

void hideToolOverlay(PartScene& scene) {
  scene.removeOverlay(kToolCuttingOverlay);
  scene.removeOverlay(kToolNonCuttingOverlay);
}

void showCollisionMarkers(PartScene& scene, const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) {
    scene.removeOverlay(kCollisionOverlay);
    return;
  }
  OverlayStyle style;
  style.rgb = {0.9, 0.1, 0.1};
  style.pointSize = 9.0;
  style.onTop = true;
  scene.setOverlay(kCollisionOverlay, toPointPolyData(points), style);
}

Eigen::Isometry3d toolShowcasePose(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                   const planning::Tool& tool, double clearanceMm) {
  const bool wheel = tool.kind == planning::ToolKind::CylinderRoll ||
                     tool.kind == planning::ToolKind::BeltContactWheel ||
                     tool.kind == planning::ToolKind::Sphere;
  // Wheels and the bare ball are centred at the origin; cutters stand on their tip.
  const double lift = wheel ? tool.radiusMm : 0.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()),
                                       hi.z() + clearanceMm + lift);
  return pose;
}

}  // namespace ddfcam::gui
