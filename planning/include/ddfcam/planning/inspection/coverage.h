// SPDX-License-Identifier: MIT
// ddfcam: how much of a part a result covers (a simulated tool path, a surface comparison), so
// that statistics over an empty or tiny share of the part are not read as the part's.
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief Area share of a part (or of a region of it) that a result covers.
struct Coverage {
  double coveredAreaMm2 = 0.0;  ///< area covered, mm^2
  double totalAreaMm2 = 0.0;    ///< area of the part or region, mm^2
  /// @brief 100 x covered / total, %; 0 for a part without area.
  double percent() const {
    return totalAreaMm2 > 0.0 ? 100.0 * coveredAreaMm2 / totalAreaMm2 : 0.0;
  }
};

/// Default warning threshold of a simulated path's coverage, %. A finishing path covers at least
/// a region of the part; below 5 % it most likely misses the part (wrong frame, unit or
/// translation) and the deviation statistics describe the untouched surface.
inline constexpr double kLowPathCoveragePercent = 5.0;

/// Default warning threshold of a comparison's coverage, %. A formed part and its mould overlap
/// almost entirely; below half of the mould the comparison describes another surface or a patch
/// of it, and its statistics say nothing about the rest.
inline constexpr double kLowComparisonCoveragePercent = 50.0;

/// @brief Area of the raster point copies of @p ddf flagged in @p covered over the area of the
/// region, both weighted by rasterPointAreas(@p ddf).
/// @param covered one flag per raster point copy (layout of allHeights()), != 0 = covered.
/// @param faces support faces of the region; empty = all faces.
/// @throws InvalidInput for a wrong size of @p covered or a face out of range.
Coverage maskCoverage(const ddf::DisplacementField& ddf, std::span<const std::uint8_t> covered,
                      std::span<const int> faces = {});

/// @brief Parameters of pathCoverage().
struct PathCoverageParams {
  /// A raster point counts as touched when the tool, at some pose, comes within this distance of
  /// the desired surface there (along the surface normal), mm. Default 0.1 mm: ten times the
  /// default tolerance band, so that the scallops between well-spaced passes count as touched
  /// while a tool passing a millimetre above the part does not.
  double reachMm = 0.1;
  /// Depth-buffer settings of the cuts. Default DepthBufferParams{}.
  ddf::DepthBufferParams depthBuffer;
  /// Progress in [0, 1] and cancellation (throws Cancelled). Default none.
  ProgressCallback progress;
};

/// @brief Which raster points a tool path touches.
struct PathCoverage {
  Coverage coverage;                  ///< touched area over the part's area
  std::vector<std::uint8_t> touched;  ///< per raster point copy (layout of allHeights()): 1 touched
};

/// @brief The raster points of @p goal (the desired surface) that @p tool touches along @p path:
/// a copy of @p goal raised by params.reachMm along its unit normal (rasterPointNormals(); heights
/// capped at the crust top) is cut by every pose (simulatePath()), and a point is touched where
/// its height dropped. Independent of the workpiece and of the removal model: it measures where
/// the tool went, not what it removed. A path placed away from the part touches nothing
/// (coverage 0); an empty path too.
/// @throws InvalidInput for an unusable tool or reachMm <= 0 or not finite; Cancelled through
/// params.progress.
PathCoverage pathCoverage(const ddf::DisplacementField& goal, const Tool& tool,
                          const ToolPath& path, const PathCoverageParams& params = {});

}  // namespace ddfcam::planning
