// SPDX-License-Identifier: MIT
// ddfcam: path spacing from error maps (sec. 8.4.1): an advancing front of paths, then fix-ups.
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief Options of refineSpacing().
struct SpacingRefinementParams {
  /// Largest material left (deviation above the goal along its normal) allowed anywhere in the
  /// region, mm, > 0 (default 0.01).
  double toleranceMm = 0.01;
  /// Largest number of fix-up iterations after the advancing front, >= 0 (default 20).
  int maxIterations = 20;
  /// Tracing of the feed paths (streamlines of the flow field) and of the transverse line;
  /// its faceMask is replaced by the region's, its progress is ignored (default:
  /// StreamlineParams{}). The poses along a path are resampled by placeAlongPath().
  StreamlineParams tracing;
  /// Stock above the goal along its normal that the simulated workpiece starts with, mm;
  /// 0 picks 2.5 x toleranceMm (default 0). Must exceed 2 x toleranceMm: the edge of a
  /// step-shaped groove (flat wheel) lies somewhere between the last cut and the first uncut
  /// raster point, and the walk puts the tolerance crossing at toleranceMm / allowance of that
  /// interval, so the next path 2 d further never leaves an uncut raster row; it must also fit
  /// into the crust (h <= 1).
  double stockAllowanceMm = 0.0;
  /// Start of the transverse line (a location in the region); the line through it is traced
  /// in both directions to the region boundary. Default: the region raster point nearest to the
  /// centroid of the region's raster points.
  std::optional<ddf::SurfaceLocation> transverseSeed;
  /// Arc-length step at which the deviation is sampled along the transverse line, mm; 0 picks
  /// a quarter of the mean raster spacing (default 0).
  double sampleStepMm = 0.0;
  /// Smallest distance between two front paths, mm; 0 picks the mean raster spacing
  /// (default 0). Guards against a tool that cannot meet the tolerance at all.
  double minSpacingMm = 0.0;
  /// Keep the deviation field of every iteration in RefinementIteration::errorField (default
  /// true; false keeps only the final one).
  bool keepErrorFields = true;
  /// Tool path settings (name, infeed depth, feed rate) for placeAlongPath(); default name
  /// "refined spacing".
  StreamlinePathParams pathParams{.name = "refined spacing"};
  /// Depth-buffer settings of the simulation (default: DepthBufferParams{}).
  ddf::DepthBufferParams depthBuffer;
  /// Index of the tool in the project's tool list (ToolPath::tool) (default 0).
  int toolIndex = 0;
  /// Progress in [0, 1] (front: fraction of the transverse line done, scaled to [0, 0.5];
  /// fix-ups: iterations of maxIterations); returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief State after one iteration of refineSpacing(). Iteration 0 is the advancing front
/// (all its paths), each later iteration one fix-up pass.
struct RefinementIteration {
  int pathsAdded = 0;          ///< paths added in this iteration
  int pathCount = 0;           ///< paths after this iteration
  double maxErrorMm = 0.0;     ///< largest deviation (material left) over the region, mm
  double minErrorMm = 0.0;     ///< smallest deviation over the region (negative: overcut), mm
  double totalLengthMm = 0.0;  ///< sum of the path lengths after this iteration, mm
  /// Where maxErrorMm occurs (raster point), mm, part frame.
  ddf::Vec3 worstPoint = ddf::Vec3::Zero();
  /// All paths after this iteration, the #pathsAdded new ones last.
  std::vector<Streamline> paths;
  /// Deviation of the simulated from the goal surface after this iteration, mm, laid out like
  /// goal.allHeights() (NaN outside the region); empty unless keepErrorFields (and always
  /// empty for the last iteration, whose field is SpacingRefinementResult::errorField).
  std::vector<float> errorField;
};

/// @brief Result of refineSpacing().
struct SpacingRefinementResult {
  std::vector<RefinementIteration> iterations;  ///< front first, then each fix-up
  std::vector<Streamline> paths;  ///< final paths: front in transverse order, fix-ups after
  ToolPath toolPath;              ///< one pass per path, in the order of paths
  /// Simulated workpiece after all paths (the goal raised by the allowance, then cut).
  ddf::DisplacementField produced;
  /// Final deviation, mm, laid out like goal.allHeights() (NaN outside the region).
  std::vector<float> errorField;
  /// Distances between consecutive front paths along the transverse line (arc length), mm.
  std::vector<double> frontSpacingsMm;
  double maxErrorMm = 0.0;     ///< final largest deviation over the region, mm
  double minErrorMm = 0.0;     ///< final smallest deviation over the region, mm
  double totalLengthMm = 0.0;  ///< final sum of path lengths, mm
  double allowanceMm = 0.0;    ///< stock allowance used, mm
  bool converged = false;      ///< maxErrorMm <= toleranceMm
};

/// @brief Paths of @p field over a region whose spacing follows from simulated error maps
/// (sec. 8.4.1). The workpiece is @p goal raised by the stock allowance along the goal normal;
/// each path is a streamline of @p field, the tool touches the goal along it (placeAlongPath(),
/// poses every step that keeps the feed chord and the cusp between poses below
/// toleranceMm / 20) and is cut into the workpiece by a discrete simulateGrinding(); the error
/// is deviationMap() of the workpiece against the goal over the raster points of the region
/// faces. Material left is thus measured wherever the tool did not reach the goal.
/// 1. Advancing front along a transverse streamline (transverseField of @p field) through the
///    region, sampled every sampleStepMm and closed by its two end points. The front aims at
///    the target T' = toleranceMm - toleranceMm / 20 (the poses meet the line at any phase).
///    A trial groove measures the distance d at which a single groove's deviation first
///    exceeds T'; the first path goes at d from the start of the line. From each placed path
///    the walk along the line to the first sample above T' gives d again, and the next path
///    goes g 2 d further (for a symmetric groove the scallop between two paths 2 d apart peaks
///    at T'), until no sample beyond the last path exceeds T'. Every front path is checked:
///    while the largest deviation between it and its predecessor (or the line start) exceeds
///    T', it is undone and placed closer (up to 4 times). The gain g (1 at first, in
///    [0.8, 1.25]) is updated from the scallop each accepted path actually left (aiming at
///    0.95 T'), which absorbs tool facets and asymmetric grooves on curved surfaces.
/// 2. Fix-ups: while the region's maximum deviation exceeds the tolerance, paths are seeded at
///    the worst raster point and at each further violating point (of the 4096 worst) farther
///    than half the smallest front spacing from every path added in this iteration and than a
///    quarter of it from every earlier path (one iteration each). Iterations stop when no
///    such seed exists (e.g. material left only at path ends): converged is then false.
/// @param goal the desired surface (not modified).
/// @param field feed direction line field laid out like goal.allHeights().
/// @param faceMask region faces, one entry per support face (non-zero: in the region); empty
/// = every face.
/// @param tool the tool (any kind placeAlongPath() places: Sphere, CylinderRoll, BallEnd, ...).
/// @throws InvalidInput for a wrong field or mask size, an empty region, a tolerance <= 0, an
/// allowance <= 2 x tolerance or one that leaves the crust, an invalid tool, or when no path
/// or transverse line can be traced in the region. @throws Cancelled through params.progress.
SpacingRefinementResult refineSpacing(const ddf::DisplacementField& goal, const LineField& field,
                                      const std::vector<std::uint8_t>& faceMask, const Tool& tool,
                                      const SpacingRefinementParams& params = {});

}  // namespace ddfcam::planning
