// SPDX-License-Identifier: MIT
// ddfcam: the sampling step along a path chosen from a tolerance, and tool placement along
// surface paths at that step (004 sec. 5.4.2 adapted to the DDF raster).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/tools/tool.h>

#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Unit surface normal at @p location, continuous inside a support face (tool side, as
/// surfaceNormal()): the raster point normals (sum of the cross products of the raster triangles
/// around each point within the face, i.e. their area-weighted normals) interpolated with the
/// location's weights in its raster triangle. Unlike the piecewise constant surfaceNormal() it
/// does not jump at raster edges, so a long tool's axis does not jump from pose to pose (it
/// still jumps slightly across support edges, where the fans are one-sided).
/// @throws InvalidInput if the location's face is out of range or its bary is not finite.
ddf::Vec3 smoothSurfaceNormal(const ddf::DisplacementField& ddf,
                              const ddf::SurfaceLocation& location);

/// @brief Options of the sampling step along a path.
struct PathSamplingParams {
  /// Tolerance T, mm, > 0 (default 0.01): bound of the feed chord error and of the feed cusp
  /// between two tool instances.
  double toleranceMm = 0.01;
  /// Fixed step along the path, mm (> 0); set: used as is (rule Override, no eq. 5.8 insertion)
  /// (default none).
  std::optional<double> stepOverrideMm{};
  /// The step is at most this factor times the raster spacing, and eq. 5.8 uses this times the
  /// raster spacing as its pixel size w; 0 disables both raster rules (default 1).
  double rasterSpacingFactor = 1.0;
  std::string name = "placed path";  ///< name of the ToolPath (default "placed path")
  double feedMmPerMin = 1000.0;      ///< feed rate of the ToolPath, mm/min (default 1000)
};

/// @brief Which rule set the sampling step.
enum class StepRule {
  Override,          ///< PathSamplingParams::stepOverrideMm
  FeedChord,         ///< chord error kappa_f L^2 / 8 <= T along the feed
  RasterSpacing,     ///< step <= raster spacing (every stubble under the path is met)
  ToolProfile,       ///< cusp between two tool instances <= T (004 eq. 5.7, sagitta form)
  OrientationSweep,  ///< 004 eq. 5.8: poses inserted because the axis ends swept more than w
  Unconstrained      ///< no rule limits the step (straight path, flat tool): whole pass
};

/// @brief Short lower-case name of @p rule ("override", "feed chord", "raster spacing",
/// "tool profile", "orientation sweep", "unconstrained").
const char* stepRuleName(StepRule rule);

/// @brief What the step rules see of one pass.
struct StepInputs {
  double feedCurvaturePerMm = 0.0;  ///< largest curvature of the path polyline, 1/mm (>= 0)
  /// Largest normal curvature of the surface along the feed, tool-side sign (> 0 convex), 1/mm
  /// (default 0).
  double feedNormalCurvaturePerMm = 0.0;
  double rasterSpacingMm = 0.0;  ///< raster spacing under the pass, mm; 0 = unknown (default 0)
};

/// @brief A chosen step and the rule that bound it.
struct SamplingStep {
  double stepMm = 0.0;  ///< largest allowed step along the path, mm (may be inf)
  StepRule rule = StepRule::Unconstrained;  ///< the binding rule
  double feedChordStepMm = 0.0;             ///< sqrt(8 T / kappa_f) (inf for a straight path), mm
  double rasterStepMm = 0.0;       ///< rasterSpacingFactor x raster spacing (inf if off), mm
  double toolProfileStepMm = 0.0;  ///< toolFeedStepMm() (inf if unbounded), mm
};

/// @brief Largest step along the feed for which two instances of @p tool placed with
/// @p placement leave a cusp of at most @p toleranceMm between them on a surface of normal
/// curvature @p feedNormalCurvaturePerMm along the feed: the width, along the feed, of the
/// tool's section by the feed plane (t, n) at height T - kappa x^2 / 2 above the tangent plane
/// (004 eq. 5.7 generalised: for a feed section that is a circle of radius R on a plane it is
/// 2 sqrt(2 R T - T^2); the printed eq. 5.7 transposes T and w/2 against its figure 5.13).
/// Flat end with lead l on a plane: T (tan l + cot l). Computed by bisection on the profile
/// sampled at 1e-6 of its size.
/// @throws InvalidInput as validateTool(), for T <= 0 or non-finite inputs, or bad angles.
double toolFeedStepMm(const Tool& tool, const PlacementParams& placement,
                      double feedNormalCurvaturePerMm, double toleranceMm);

/// @brief The step for one pass: the override if set, else the smallest of the feed chord step
/// sqrt(8 T / kappa_f), rasterSpacingFactor x raster spacing (if both > 0) and
/// toolFeedStepMm(tool, placement, inputs.feedNormalCurvaturePerMm, T); ties go to the rule
/// listed first in StepRule.
/// @throws InvalidInput naming the field for T <= 0, an override <= 0, a negative factor,
/// curvature or spacing, non-finite values, or as toolFeedStepMm().
SamplingStep chooseStep(const Tool& tool, const PlacementParams& placement,
                        const StepInputs& inputs, const PathSamplingParams& params);

/// @brief Sampling of one pass of placeAlongPath.
struct PassSampling {
  StepInputs inputs;           ///< what the rules saw
  SamplingStep step;           ///< the uniform step and its rule
  double lengthMm = 0.0;       ///< pass length (input polyline), mm
  int uniformPoses = 0;        ///< ceil(length / step) + 1 (2 when unconstrained)
  int sweepInsertedPoses = 0;  ///< poses added by eq. 5.8 (orientation sweep)
  /// step.rule, or OrientationSweep when eq. 5.8 inserted poses (shown in the GUI).
  StepRule bindingRule = StepRule::Unconstrained;
  int firstPose = 0;  ///< index of the pass's first pose in the ToolPath
};

/// @brief A placed path and how each pass was sampled (for display).
struct PlacedPath {
  ToolPath path;                     ///< poses and passes
  std::vector<PassSampling> passes;  ///< one per pass kept in the path
};

/// @brief Places @p tool along @p passes (each a polyline of surface locations on @p ddf, e.g.
/// Streamline::points): every pass is resampled at a uniform arc-length step (chooseStep();
/// inputs: the polyline's largest curvature from circles through points one raster spacing
/// apart (at least two input segments), the largest normal curvature of that circle along n,
/// the smallest mean raster
/// spacing of the faces visited), sample points are put back on the surface (barycentric
/// interpolation within a face, ddf::locateOnFace across faces), and the tool is placed at
/// each sample (placeToolDetailed) with the normal smoothSurfaceNormal() and the feed along
/// the chord through the path points half a step before and after. Then 004 eq. 5.8/5.9: for
/// every interval, N = ceil(max(|v_b|, |v_t|) / w), with v_b, v_t the moves of the two axis
/// ends (toolAxisEnds; Euclidean length, the DDF has no pixel frame) and w = factor x raster
/// spacing, and N - 1 poses are inserted evenly in arc length. Passes with fewer than two
/// points or zero length are left out.
/// @param toolIndex index of @p tool in the project's tool list (ToolPath::tool).
/// @throws InvalidInput as chooseStep() / placeToolDetailed(), for a location whose face is
/// out of range, if a pass would need more than 10^7 poses, or if no pass has two distinct
/// points.
PlacedPath placeAlongPathDetailed(const ddf::DisplacementField& ddf,
                                  const std::vector<std::vector<ddf::SurfaceLocation>>& passes,
                                  const Tool& tool, int toolIndex, const PlacementParams& placement,
                                  const PathSamplingParams& sampling = {});

/// @brief placeAlongPathDetailed(...).path.
ToolPath placeAlongPath(const ddf::DisplacementField& ddf,
                        const std::vector<std::vector<ddf::SurfaceLocation>>& passes,
                        const Tool& tool, int toolIndex, const PlacementParams& placement,
                        const PathSamplingParams& sampling = {});

/// @brief placeAlongPath() with one pass per streamline (its points).
ToolPath placeAlongPath(const ddf::DisplacementField& ddf,
                        const std::vector<Streamline>& streamlines, const Tool& tool, int toolIndex,
                        const PlacementParams& placement, const PathSamplingParams& sampling = {});

}  // namespace ddfcam::planning
