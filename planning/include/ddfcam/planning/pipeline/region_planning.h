// SPDX-License-Identifier: MIT
// ddfcam: the planning of one region's lines from its RegionPlan (sec. 8.1-8.4): the flow
// field on the region, the spacing (fixed or from a scallop height), the seeding and tracing of
// the lines, their smoothing and fairing, and their order and direction for cutting. The
// workbench's Streamlines panel, `ddfcam-cli plan` and batch jobs all plan through these
// functions, so the three give the same lines for the same plan.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/flow_field.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/planning/model/region_plan.h>
#include <ddfcam/planning/placement/path_linking.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Smallest spacing a scallop height may ask for, mm: a finer spacing is below what a
/// grinding path can hold and would make the coverage take hours on a sharply curved spot.
inline constexpr double kMinScallopSpacingMm = 0.05;

/// @brief One entry per support face of @p part, 1 for the faces of @p region (indices out of
/// range are ignored), 0 elsewhere.
std::vector<std::uint8_t> regionFaceMask(const ddf::DisplacementField& part, const Region& region);

/// @brief The flow field of a region and what is derived from it.
struct RegionFields {
  LineField field;       ///< the plan's flow field, zero (undefined) outside the face mask
  LineField transverse;  ///< the field turned by 90 deg in the tangent plane
  std::vector<FieldSingularity> singularities;  ///< of field
};

/// @brief The flow field of @p plan (source, fixed direction, strokes, smoothing) on the faces
/// of @p faceMask (empty: every face), its transverse field and its singularities. Faces
/// outside the mask stay undefined, also where flowField() copies the region's boundary values
/// onto them, so that lines stop at the region's edge.
/// @param progress fraction in [0, 1]; false cancels.
/// @throws InvalidInput as flowField(); Cancelled.
RegionFields regionFields(const ddf::DisplacementField& part, const CurvatureField& curvature,
                          const RegionPlan& plan, const std::vector<std::uint8_t>& faceMask,
                          const ProgressCallback& progress = {});

/// @brief The distance between neighbouring lines of a region.
struct LineSpacing {
  double minMm = 0.0;  ///< smallest spacing used, mm (the fixed spacing when not varying)
  double maxMm = 0.0;  ///< largest spacing used, mm
  /// Share of the region's raster points that are too concave for the ball (the smallest
  /// spacing is used there), in [0, 1].
  double gougingFraction = 0.0;
  /// The spacing at a surface location, mm; empty: minMm everywhere.
  std::function<double(const ddf::SurfaceLocation&)> separationAt;
  bool fromScallop = false;  ///< the spacing follows from the plan's scallop height
  /// What the user should know about the choice (e.g. a scallop height that a roll cannot
  /// apply); empty when nothing is to be said.
  std::string note;
};

/// @brief The spacing of @p plan on @p fields: SpacingMode::FixedSpacing gives
/// plan.spacingMm; SpacingMode::ScallopTolerance gives, per raster point where the field is
/// defined, the spacing that leaves plan.scallopToleranceMm between lines of a tool with the
/// cross-feed radius of @p tool (scallopSpacingField()), at least kMinScallopSpacingMm. A tool
/// without a curved cross-feed profile (a straight roll) cannot apply a scallop height: then
/// plan.spacingMm is used and LineSpacing::note says so.
/// @throws InvalidInput when the ball gouges every point of the region (no scallop spacing
/// exists), naming the radius and what to change.
LineSpacing regionSpacing(const ddf::DisplacementField& part, const CurvatureField& curvature,
                          const RegionFields& fields, const RegionPlan& plan, const Tool& tool);

/// @brief How the lines of a region are placed.
enum class LineSeeding {
  Coverage,  ///< evenly spaced streamlines covering the region (evenlySpacedStreamlines())
  Family     ///< lines through seeds along the transverse line through one seed (fig. 8.13)
};

/// @brief Parameters of planRegionLines().
struct RegionLinesParams {
  LineSeeding seeding = LineSeeding::Coverage;       ///< default coverage
  StreamlineMethod tracing = StreamlineMethod::Rk4;  ///< tracer of a family (default RK4)
  /// Seed of a family; empty: the raster point with a defined field nearest to the centroid
  /// of the region's raster points (default empty).
  std::optional<ddf::SurfaceLocation> seed;
  /// Longest line, mm; 0: four times the part's bounding-box diagonal, beyond which a line
  /// only winds round a closed part again (default 0).
  double maxLineLengthMm = 0.0;
  int smoothHalfWindow = 0;   ///< moving-average smoothing on the surface, points (default 0: off)
  bool fair = false;          ///< fair every line (fairStreamline()) (default false)
  ProgressCallback progress;  ///< fraction in [0, 1]; false cancels (default none)
};

/// @brief The lines of a region with the spacing @p spacing on @p fields, seeded and traced
/// as @p params says, smoothed and faired if asked, without repeated points and fold-backs
/// (dropRepeatedPoints()) and without lines of fewer than two points.
/// @param faceMask the region's faces (empty: every face); lines stop at its edge.
/// @throws InvalidInput when the field is undefined everywhere in the region, when a varying
/// spacing meets family seeding, or when no line with two points can be traced; Cancelled.
std::vector<Streamline> planRegionLines(const ddf::DisplacementField& part,
                                        const RegionFields& fields,
                                        const std::vector<std::uint8_t>& faceMask,
                                        const LineSpacing& spacing,
                                        const RegionLinesParams& params = {});

/// @brief One line through each of @p seeds, traced by @p method with @p trace (one crust hash
/// shared by the continuous tracer), in the order of the seeds; nothing is dropped.
/// @param progress fraction of the seeds traced; false cancels.
/// @throws InvalidInput as traceStreamlineWith(); Cancelled.
std::vector<Streamline> traceLinesThrough(const ddf::DisplacementField& part,
                                          const LineField& field,
                                          const std::vector<ddf::SurfaceLocation>& seeds,
                                          StreamlineMethod method,
                                          const StreamlineParams& trace = {},
                                          const ProgressCallback& progress = {});

/// @brief The raster point of the faces of @p faceMask (empty: every face) where @p field is
/// defined that is nearest to the centroid of those faces' raster points.
/// @throws InvalidInput when the field is undefined on every point of the mask.
ddf::SurfaceLocation centralSeed(const ddf::DisplacementField& part, const LineField& field,
                                 const std::vector<std::uint8_t>& faceMask);

/// @brief The linking parameters of @p plan: its order and feed sign, the rest from @p base.
LinkingParams linkingParamsOf(const RegionPlan& plan, LinkingParams base = {});

/// @brief A region's lines made a tool path.
struct RegionPath {
  /// The lines in cutting order, each oriented as it is cut (as traced when not linked).
  std::vector<Streamline> lines;
  std::optional<LinkedPaths> linked;  ///< the linking report; empty when not linked
  PlacedPath placed;                  ///< the tool path and how each pass was sampled
  double cuttingLengthMm = 0.0;       ///< summed length of the lines, mm
};

/// @brief Orders and orients @p lines for cutting by @p plan's linking order and feed sign
/// (orderLinesForCutting(), when @p link and more than one line) and places @p tool along them
/// (toolPathFromStreamlinesDetailed()). The placed path keeps the ordered lines as its
/// ToolPath::rawLines and the linking's idle length as ToolPath::linkedIdleMm.
/// @param toolIndex index of @p tool in Project::tools, stored in the path.
/// @throws InvalidInput as orderLinesForCutting() and toolPathFromStreamlinesDetailed().
RegionPath regionToolPath(const ddf::DisplacementField& part, std::vector<Streamline> lines,
                          const RegionPlan& plan, const Tool& tool, int toolIndex, bool link,
                          const StreamlinePathParams& placement);

}  // namespace ddfcam::planning
