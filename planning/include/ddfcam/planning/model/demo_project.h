// SPDX-License-Identifier: MIT
// ddfcam: the built-in demo session: demo part, default roll and a three-pass path.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/model/tool_path.h>

namespace ddfcam::planning {

/// @brief Parameters of demoPasses().
struct DemoPassesParams {
  double depthMm = 0.02;  ///< infeed below the design surface, mm (default 0.02)
  double stepMm = 0.25;   ///< distance between poses along the feed, mm (default 0.25)
  double startYMm = 4.0;  ///< first contact y, mm (default 4)
  double endYMm = 26.0;   ///< last contact y, mm (default 26)
  std::vector<double> passXMm = {14.0, 20.0, 26.0};  ///< contact line x of each pass, mm
};

/// @brief Three passes (by default) of the default roll along +y over the design surface of
/// ddf::demoPart(): the contacts lie on the design surface, the roll axis in its tangent plane
/// across the feed (rollPoseAtContact), sunk params.depthMm below it.
/// @param design the height-field design surface of the demo part (GeneratedSurface::design).
/// @param tool the roll (its radius places the poses; a ball placed this way touches the same
/// contact points). Poses are ordered pass by pass, y ascending; passStarts marks each pass.
/// @throws InvalidInput if @p design is not a HeightFieldSurface, @p tool fails validateTool(),
/// or params have stepMm <= 0, depthMm < 0, endYMm < startYMm or no pass.
ToolPath demoPasses(const ddf::AnalyticSurface& design, const Tool& tool,
                    const DemoPassesParams& params = {});

/// @brief The demo session: the demo part (name "demo part"), a "stock" simulation state
/// holding its initial heights, the default roll as tool 0, demoPasses() as path 0, and as
/// designMesh a regular triangulation of the design surface over the part's x-y extent (grid
/// step 0.25 mm, vertices on the surface) to compare the ground part with.
/// @throws ddfcam::Error from the generators.
Project demoProject();

}  // namespace ddfcam::planning
