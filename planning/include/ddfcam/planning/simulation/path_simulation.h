// SPDX-License-Identifier: MIT
// ddfcam: grinding a tool path into a DDF with the depth buffer (dissertation sec. 8.3).
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <cstddef>

namespace ddfcam::planning {

/// @brief Parameters of simulatePath().
struct PathSimulationParams {
  /// Depth-buffer settings (threads, interval restriction). Default: DepthBufferParams{}.
  ddf::DepthBufferParams depthBuffer;
  /// Progress in [0, 1] (fraction of poses cut) and cancellation; called at least every
  /// 64 poses and at least every ~0.1 s of work, so a cancel takes effect quickly. Default none.
  ProgressCallback progress;
};

/// @brief What simulatePath() did.
struct PathSimulationReport {
  int poses = 0;                  ///< poses cut
  std::size_t pointsLowered = 0;  ///< raster point heights lowered (copies counted per face)
  /// Of the lowerings, those clamped to the crust bottom h = -1 because the tool reached below
  /// it (copies counted per face and pose): the true cut is deeper there.
  std::size_t pointsClamped = 0;
  double seconds = 0.0;  ///< wall time of the cut
};

/// @brief Cuts every pose of @p path with the mesh of @p tool into @p ddf (h = min(h, h_tool)),
/// in machining order, through one CrustHash built for the call; shared raster points are
/// synchronised with the minimum policy as by cutByMesh.
/// @param ddf the part, modified in place; on Cancelled or any exception it is left partly cut,
/// so callers that must stay unchanged cut a copy.
/// @throws InvalidInput for an unusable tool (toolMesh); Cancelled through params.progress.
PathSimulationReport simulatePath(ddf::DisplacementField& ddf, const Tool& tool,
                                  const ToolPath& path, const PathSimulationParams& params = {});

}  // namespace ddfcam::planning
