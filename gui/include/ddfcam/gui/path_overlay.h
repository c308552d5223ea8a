// SPDX-License-Identifier: MIT
// ddfcam gui: what the part view draws of the tool paths: cuts, links between passes, and the
// selected path, each in a look of its own.
#pragma once

#include <ddfcam/gui/part_scene.h>
#include <ddfcam/planning/model/project.h>

#include <Eigen/Core>

#include <set>
#include <string>
#include <vector>

namespace ddfcam::gui {

/// Overlay of the cuts (every pass of every visible path, one polyline each).
inline constexpr const char* kPathCutsOverlay = "paths";
/// Overlay of the links: the move from each pass's last contact to the next pass's first.
inline constexpr const char* kPathLinksOverlay = "path links";
/// Overlay of the selected path's cuts, drawn over the others.
inline constexpr const char* kSelectedPathOverlay = "selected path";

/// @brief Polylines of the paths' contacts (mm, part frame) by kind.
struct PathOverlayLines {
  std::vector<std::vector<Eigen::Vector3d>> cuts;      ///< one per pass of a visible path
  std::vector<std::vector<Eigen::Vector3d>> links;     ///< one 2-point line per link
  std::vector<std::vector<Eigen::Vector3d>> selected;  ///< the selected path's passes
};

/// @brief The lines of @p project's paths, leaving out the paths named in @p hidden; the path
/// of index @p selected (-1: none) also goes to PathOverlayLines::selected if visible.
PathOverlayLines pathOverlayLines(const planning::Project& project,
                                  const std::set<std::string>& hidden, int selected);

/// @brief Looks that cannot be mistaken for one another nor for a region: region colours have
/// saturations from 0.35 to 0.75 (planning::distinctRegionColor, 0.6 from the segmentation),
/// so cuts are white (no saturation), links thin and near black, and the selected path a fully
/// saturated yellow, wider. All are drawn on top of the part (contacts lie on the design,
/// under the stock).
OverlayStyle pathCutStyle();
OverlayStyle pathLinkStyle();
OverlayStyle selectedPathStyle();

}  // namespace ddfcam::gui
