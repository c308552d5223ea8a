// SPDX-License-Identifier: MIT
// ddfcam: scallop height predicted from theory and measured on a simulated surface.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/progress.h>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Exact scallop (cusp) height between two passes of a ball of radius @p radiusMm at
/// distance @p spacingMm on a plane: h = R - sqrt(R^2 - w^2/4), mm.
/// @throws InvalidInput if R <= 0, w < 0 or w > 2R.
double ballScallopOnPlaneMm(double radiusMm, double spacingMm);

/// @brief Exact scallop height of a ball (cross-feed circle of radius R) on a surface whose
/// cross-feed section is a circle of curvature kappa (tool-side sign: > 0 convex, < 0 concave, 0
/// plane), passes @p spacingMm apart as arc length on the surface: the tool circles' centres lie
/// at rho + R (convex) from the centre of curvature, theta = w kappa apart; the cusp is their
/// intersection on the bisector, h its distance from the surface circle. The inverse of
/// scallopSpacingMm() (scallop_spacing.h).
/// @return nullopt if the ball gouges the concave section (1 + kappa R <= 0) or the circles do
/// not meet (passes too far apart).
/// @throws InvalidInput for non-finite arguments, R <= 0 or w < 0.
std::optional<double> ballScallopMm(double radiusMm, double spacingMm,
                                    double crossFeedCurvaturePerMm);

/// @brief The approximation h = (w^2/8)(1/R_eff + kappa_s) for any tool with effective
/// cross-feed radius R_eff (oracles note "Path spacing"); R_eff = infinity (a flat profile) gives
/// w^2 kappa_s / 8. Negative where the tool gouges (1/R_eff + kappa_s < 0).
/// @throws InvalidInput if R_eff <= 0 or w < 0.
double approximateScallopMm(double effectiveRadiusMm, double spacingMm,
                            double crossFeedCurvaturePerMm);

/// @brief Exact scallop of a flat (uncrowned) wheel of width B whose axis lies across the feed,
/// passes w apart (arc length) on a convex cross-feed circle of curvature kappa: the produced
/// section is the polygon of the passes' tangent lines, whose corner lies rho (sec(theta/2) - 1)
/// above the circle (theta = w kappa; ~ kappa w^2/8); 0 on a plane.
/// @return nullopt when the tangent segments of half width B/2 do not meet (rho tan(theta/2) >
/// B/2 on a convex section, w > B on a plane: stock is left between the passes) or the section
/// is concave (the wheel edges gouge: see flatWheelEdgeErrorMm()).
/// @throws InvalidInput if B <= 0, w < 0 or an argument is not finite.
std::optional<double> flatWheelScallopMm(double widthMm, double spacingMm,
                                         double crossFeedCurvaturePerMm);

/// @brief Signed form error of one pass of a flat wheel of width B at its edges on a cross-feed
/// circle of curvature kappa, mm along the surface normal: convex sqrt(rho^2 + B^2/4) - rho
/// (material left), concave -(rho - sqrt(rho^2 - B^2/4)) (overcut); both ~ kappa B^2/8; 0 on
/// a plane.
/// @throws InvalidInput if B <= 0, if the concave radius is below B/2, or an argument is not
/// finite.
double flatWheelEdgeErrorMm(double widthMm, double crossFeedCurvaturePerMm);

/// @brief Effective cross-feed radius of a flat-end cutter of radius R_t inclined by the lead
/// angle l in the feed direction: R_eff = R_t / sin l (the rim's section across the feed is an
/// ellipse with semi-axes R_t and R_t sin l).
/// @throws InvalidInput if R_t <= 0 or l is not in (0, pi/2].
double tiltedFlatEffectiveRadiusMm(double radiusMm, double leadAngleRad);

/// @brief Exact scallop of a flat-end cutter of radius R_t at lead angle l on a plane, passes w
/// apart: the rim ellipse gives h = R_t sin l (1 - sqrt(1 - w^2/(4 R_t^2))).
/// @throws InvalidInput as tiltedFlatEffectiveRadiusMm(), or if w < 0 or w > 2 R_t.
double tiltedFlatScallopOnPlaneMm(double radiusMm, double leadAngleRad, double spacingMm);

/// @brief Options of measuredScallopMm().
struct ScallopMeasureParams {
  /// Area quantile of the deviation taken as the scallop height; 1 = the maximum (default 1).
  /// The maximum is exact when the region lies between the passes (no stock or pass ends in
  /// it); a quantile such as 0.995 damps single outliers (e.g. a poorly resolved pose end).
  double quantile = 1.0;
};

/// @brief Scallop height measured on a simulated surface: the material-left deviation of the
/// region @p faces at the area quantile params.quantile (weights rasterPointAreas(@p ddf)),
/// clamped below at 0 (an overcut region has no scallop). The caller chooses a region strictly
/// between the first and last pass and away from the pass ends, where only cusps remain.
/// @param deviation error map laid out like ddf.allHeights() (deviationMap()), mm.
/// @param faces region faces; empty = all faces.
/// @throws InvalidInput for a wrong field size, a face out of range, a quantile outside (0, 1],
/// or a region without finite values.
double measuredScallopMm(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                         std::span<const int> faces = {}, const ScallopMeasureParams& params = {});

/// @brief Tool models of the scallop table.
enum class ScallopToolModel {
  Ball,          ///< ball of radius radiusMm (ToolKind::Sphere), centre R above the contact
  FlatWheel,     ///< cylindrical roll radius radiusMm, width widthMm, axis across the feed
  TiltedFlatEnd  ///< flat-end cutter radius radiusMm inclined by leadAngleRad along the feed
};

/// @brief One case of the scallop table: tool, spacing and surface (plane or convex cylinder).
struct ScallopCase {
  std::string label = "ball R5";                    ///< tool label in the table
  ScallopToolModel model = ScallopToolModel::Ball;  ///< tool model (default ball)
  double radiusMm = 5.0;      ///< ball, wheel or cutter radius, mm (default 5)
  double widthMm = 10.0;      ///< wheel width B, mm (FlatWheel only; default 10)
  double leadAngleRad = 0.2;  ///< lead angle l (TiltedFlatEnd only), rad (default 0.2)
  double spacingMm = 1.0;     ///< path spacing w (arc length on the surface), mm (default 1)
  /// Cross-feed curvature kappa_s, 1/mm: 0 = plane, > 0 = convex cylinder of radius 1/kappa with
  /// the feed along its axis (default 0).
  double crossFeedCurvaturePerMm = 0.0;
};

/// @brief Exact theoretical scallop of @p c: ballScallopMm(), flatWheelScallopMm() (or the
/// edge error for a single pass) or tiltedFlatScallopOnPlaneMm() (on a cylinder the
/// approximation with R_eff); NaN where the theory gives no value.
/// @throws InvalidInput as the formulas.
double predictedScallopMm(const ScallopCase& c);

/// @brief A row of the scallop table, mm.
struct ScallopRow {
  std::string tool;              ///< ScallopCase::label
  double spacingMm = 0.0;        ///< path spacing w, mm
  double curvaturePerMm = 0.0;   ///< cross-feed curvature kappa_s, 1/mm
  double predictedMm = 0.0;      ///< predictedScallopMm()
  double approximateMm = 0.0;    ///< (w^2/8)(1/R_eff + kappa_s)
  double simulatedMm = 0.0;      ///< measuredScallopMm() on the simulated surface
  double relativeError = 0.0;    ///< (simulated - predicted) / predicted; 0 if both are 0
  double rasterSpacingMm = 0.0;  ///< raster spacing of the simulation, mm
};

/// @brief Options of simulateScallopCase().
struct ScallopSimulationParams {
  int passes = 4;                       ///< parallel passes, >= 2 (default 4)
  double rasterStepsPerSpacing = 10.0;  ///< raster points per path spacing, >= 2 (default 10)
  double passLengthMm = 6.0;            ///< length of every pass along the feed, mm (default 6)
  double chordToleranceMm = 0.0005;     ///< tool mesh chord tolerance, mm (default 0.0005)
  double stockMm = 0.3;                 ///< stock allowance above the desired surface, mm (0.3)
  ProgressCallback progress;            ///< progress and cancel (default none)
};

/// @brief Simulates @p c: a plane patch or a convex cylinder part (analytic_generators.h) raised
/// by the stock, params.passes parallel straight passes w apart along the feed, cut by
/// simulatePath(); then the error map against the desired heights (deviationMap()) and
/// measuredScallopMm() (the maximum) over the faces between the first and last pass (the
/// passes cover the whole patch along the feed, so no pass end lies inside). Passes and cusps
/// lie on raster lines: on a cylinder the spacing is rounded to two support segments
/// (ScallopRow::spacingMm is the spacing used; the prediction is made for it). Poses lie on
/// every raster line across the feed, so a ball's or wheel's feed cusps do not show at raster
/// points; a tilted flat end, whose feed cusps grow linearly with the step (~ step tan l),
/// gets steps of at most 2 % of the predicted scallop / tan l (at most 64 per raster step) and
/// runs on beyond the patch by its trailing rim offset. relativeError is +inf if only the
/// prediction is 0. Cost grows with the tool mesh (chord tolerance): a ball of R = 5 at the
/// default 0.0005 mm has ~200k triangles, several seconds per case.
/// @throws InvalidInput for invalid case values or params; Cancelled through params.progress.
ScallopRow simulateScallopCase(const ScallopCase& c, const ScallopSimulationParams& params = {});

/// @brief simulateScallopCase() for every case, in order (the predicted-against-simulated table).
/// @throws as simulateScallopCase().
std::vector<ScallopRow> scallopTable(std::span<const ScallopCase> cases,
                                     const ScallopSimulationParams& params = {});

}  // namespace ddfcam::planning
