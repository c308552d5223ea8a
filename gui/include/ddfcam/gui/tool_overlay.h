// SPDX-License-Identifier: MIT
// ddfcam gui: a tool drawn in the part view at a pose, cutting and non-cutting parts in two
// colours, and markers of colliding poses.
#pragma once

#include <ddfcam/planning/tools/tool.h>

#include <Eigen/Geometry>

#include <vector>

namespace ddfcam::gui {

class PartScene;

/// Overlay name of the tool's cutting part.
inline constexpr const char* kToolCuttingOverlay = "tool cutting";
/// Overlay name of the tool's non-cutting part (shank, holder, arbor, flanges).
inline constexpr const char* kToolNonCuttingOverlay = "tool non-cutting";
/// Overlay name of the markers of colliding poses.
inline constexpr const char* kCollisionOverlay = "collisions";

/// @brief Shows @p tool at @p pose (tool frame -> part frame, mm) as two shaded overlays: the
/// cutting part amber, the non-cutting part blue-grey (red when @p colliding).
/// @throws InvalidInput if the tool fails planning::validateTool().
void showToolOverlay(PartScene& scene, const planning::Tool& tool, const Eigen::Isometry3d& pose,
                     bool colliding = false);
/// @brief Removes both tool overlays.
void hideToolOverlay(PartScene& scene);
/// @brief Shows @p points (mm, part frame) as red point markers drawn on top; empty removes
/// the overlay.
void showCollisionMarkers(PartScene& scene, const std::vector<Eigen::Vector3d>& points);

/// @brief Where the tools panel shows a tool that no path uses yet: the pose putting the
/// tool's reference point @p clearanceMm above the centre of the box [lo, hi] (mm, part
/// frame), axis as in the tool frame (wheels along x, cutters along z).
Eigen::Isometry3d toolShowcasePose(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                   const planning::Tool& tool, double clearanceMm = 1.0);

}  // namespace ddfcam::gui
