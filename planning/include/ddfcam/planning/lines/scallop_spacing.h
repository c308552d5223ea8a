// SPDX-License-Identifier: MIT
// ddfcam: path spacing from a scallop height that follows the cross-feed curvature.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/tools/tool.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief Exact distance between neighbouring paths, as arc length on the surface, that leaves
/// a scallop (cusp) of height @p scallopHeightMm between two passes of a tool whose cross-feed
/// profile is a circle of radius R = @p toolRadiusMm, on a surface whose normal curvature across
/// the feed is kappa = @p crossFeedCurvaturePerMm (tool-side sign as CurvatureField: positive
/// convex, negative concave, 0 plane).
/// In the cross-feed plane the two tool centres lie at distance rho + R from the surface's
/// centre of curvature (rho = 1/kappa), the cusp at rho + h, and each centre at R from the cusp;
/// the law of cosines gives the half angle theta/2 between the passes, and in a form that stays
/// stable for kappa -> 0: D = R^2 - (R - h)^2, s_rho = sqrt(D) / (2 sqrt((1 + kappa R)(1 +
/// kappa h))), s = s_rho |kappa| = sin(theta/2), L = 4 s_rho asin(s) / s (asin(s)/s = 1 at
/// s = 0). On a plane L = 2 sqrt(D) = 2 sqrt(2 R h - h^2) (R = 5, h = 0.01: 0.632139 mm).
/// Effective radius R: a ball's radius; for other tools see effectiveCrossFeedRadiusMm().
/// @return nullopt when no spacing exists: the tool gouges the concave surface (1 + kappa R
/// <= 0, i.e. a concave radius <= R), or s > 1: on a concave surface barely wider than the tool
/// even passes on opposite sides leave a lower cusp than h (never on convex ones, where s^2 <
/// 1/2); callers treat both as "use the smallest spacing" (scallopSpacingField gives NaN).
/// @throws InvalidInput if an argument is not finite, R <= 0, h <= 0 or h >= R.
std::optional<double> scallopSpacingMm(double toolRadiusMm, double crossFeedCurvaturePerMm,
                                       double scallopHeightMm);

/// @brief Normal curvature across the feed at raster point @p index of @p curvature (Euler's
/// formula): with the transverse direction t = n x feed, kappa = kMax cos^2(a) + kMin sin^2(a),
/// a the angle between t and dirMax; computed from the components of @p feedDirection along
/// dirMax and dirMin, so the feed's normal component, its length and its sign do not matter.
/// Where the directions are undefined (zero) or the feed is (nearly) normal to the surface, the
/// mean curvature (exact at umbilic points).
/// @param feedDirection the path direction at the point, part frame, any length.
/// @return 1/mm, tool-side sign.
/// @throws InvalidInput if @p index is out of range.
double crossFeedCurvature(const CurvatureField& curvature, std::size_t index,
                          const ddf::Vec3& feedDirection);

/// @brief scallopSpacingMm() at every raster point of @p ddf for paths that follow
/// @p flowField: kappa = crossFeedCurvature(curvature, i, flowField[i]). Where the flow field
/// is undefined (zero) the plane value; where the tool gouges or the spacing does not exist,
/// NaN.
/// @param flowField line field (feed direction) laid out like ddf.allHeights().
/// @return mm, one entry per raster point copy, laid out like ddf.allHeights().
/// @throws InvalidInput if the curvature or flow field is not sized like ddf.allHeights(), or
/// as scallopSpacingMm() for the tool radius and height.
std::vector<float> scallopSpacingField(const ddf::DisplacementField& ddf,
                                       const CurvatureField& curvature, const LineField& flowField,
                                       double toolRadiusMm, double scallopHeightMm);

/// @brief A spacing function for EvenSpacingParams::separationAt: the value of @p spacing
/// (laid out like ddf.allHeights(), mm; e.g. scallopSpacingField()) interpolated at the
/// location (interpolateOnFace), clamped to at least @p minimumMm; NaN, infinite or
/// interpolated-from-NaN values give @p minimumMm (the safe side: closer paths leave lower
/// scallops). Keeps @p ddf by reference: it must outlive the function.
/// @throws InvalidInput if @p spacing is not sized like ddf.allHeights() or @p minimumMm is not
/// finite and > 0.
std::function<double(const ddf::SurfaceLocation&)> spacingFunction(
    const ddf::DisplacementField& ddf, std::vector<float> spacing, double minimumMm);

/// @brief The smallest finite entry of @p spacing, mm; nullopt if there is none.
std::optional<double> smallestFiniteSpacing(const std::vector<float>& spacing);

/// @brief Radius R of @p tool's cross-feed profile for scallopSpacingMm():
/// - a ball (ToolKind::Sphere): its radiusMm;
/// - a cylindrical roll that grinds with its axis across the feed (ToolKind::CylinderRoll, as
///   rollPoseAtContact places it): its cross-feed profile is a straight line of width widthMm
///   (R = infinity), so the scallop model does not apply: the result is nullopt. Callers then
///   use the plan's fixed spacing (RegionPlan::spacingMm, at most the roll width for full
///   coverage); a crowned or edge-grinding roll is not modelled by Tool, and a caller that
///   knows its crown radius passes that radius to scallopSpacingMm() directly.
/// @throws InvalidInput as validateTool().
std::optional<double> effectiveCrossFeedRadiusMm(const Tool& tool);

}  // namespace ddfcam::planning
