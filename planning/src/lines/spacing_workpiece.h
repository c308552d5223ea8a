// SPDX-License-Identifier: MIT
// ddfcam: the simulated workpiece of refineSpacing(): stock, incremental cuts, region error.
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ddfcam::planning::spacing {

/// @brief @p goal with every height raised by @p allowanceMm along the goal normal: the stock
/// h + a / (v . n), (v . n) taken from deviationMap() of a unit height step so that the stock's
/// deviation is exactly a.
/// @throws InvalidInput if a raised height leaves the crust (h > 1) or v . n is not positive.
ddf::DisplacementField raisedStock(const ddf::DisplacementField& goal, double allowanceMm);

/// @brief Largest and smallest finite value of an error field and where the largest is.
struct FieldExtremes {
  double maxMm = 0.0;     ///< largest value, mm (-inf if none)
  double minMm = 0.0;     ///< smallest value, mm (+inf if none)
  std::size_t worst = 0;  ///< stored index of the largest value
  bool any = false;       ///< a finite value exists
};

/// @brief Extremes of @p values (NaN skipped).
FieldExtremes fieldExtremes(const std::vector<float>& values);

/// @brief deviationMap(@p work, goal heights) with NaN on every face outside @p faceMask
/// (empty mask: every face).
std::vector<float> regionDeviation(const ddf::DisplacementField& work,
                                   const ddf::DisplacementField& goal,
                                   const std::vector<std::uint8_t>& faceMask);

/// @brief The surface location of the goal raster point with stored index @p index.
ddf::SurfaceLocation rasterLocation(const ddf::DisplacementField& goal, std::size_t index);

/// @brief Mean length of the support edges of the region faces divided by m - 1, mm.
double meanRasterSpacing(const ddf::DisplacementField& goal,
                         const std::vector<std::uint8_t>& faceMask);

/// @brief The region raster point nearest to the centroid of the region's raster points.
ddf::SurfaceLocation regionCentreLocation(const ddf::DisplacementField& goal,
                                          const std::vector<std::uint8_t>& faceMask);

/// @brief Distance from @p p to the polyline of @p line, mm (infinity for no points).
double distanceToLine(const ddf::Vec3& p, const Streamline& line);

/// @brief The tool path of @p lines: placeAlongPath() with the infeed, name and feed of
/// @p pathParams, the sampling step bounded by @p feedToleranceMm (feed chord and cusp between
/// consecutive poses) and by the raster spacing.
ToolPath placeLines(const ddf::DisplacementField& goal, const std::vector<Streamline>& lines,
                    const Tool& tool, int toolIndex, const StreamlinePathParams& pathParams,
                    double feedToleranceMm);

/// @brief placeLines() and a discrete simulateGrinding() of its poses into @p work (no
/// V-convexity or collision checks); lines with fewer than two points are skipped.
void cutLines(ddf::DisplacementField& work, const ddf::DisplacementField& goal,
              const std::vector<Streamline>& lines, const Tool& tool, int toolIndex,
              const StreamlinePathParams& pathParams, const ddf::DepthBufferParams& depthBuffer,
              double feedToleranceMm);

}  // namespace ddfcam::planning::spacing
