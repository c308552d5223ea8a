// SPDX-License-Identifier: MIT
// ddfcam: path spacing from a scallop height that follows the cross-feed curvature.
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/scallop_spacing.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace ddfcam::planning {
namespace {

void checkScallopInput(double toolRadiusMm, double scallopHeightMm, const char* where) {
  if (!std::isfinite(toolRadiusMm) || toolRadiusMm <= 0.0)
    throw InvalidInput(std::string(where) + ": tool radius " + std::to_string(toolRadiusMm) +
                       " mm must be finite and > 0");
  if (!std::isfinite(scallopHeightMm) || scallopHeightMm <= 0.0 || scallopHeightMm >= toolRadiusMm)
    throw InvalidInput(std::string(where) + ": scallop height " + std::to_string(scallopHeightMm) +
                       " mm must be > 0 and below the tool " + "radius " +
                       std::to_string(toolRadiusMm) + " mm");
}

void checkSize(std::size_t size, const ddf::DisplacementField& ddf, const char* what) {
  if (size != ddf.allHeights().size())
    throw InvalidInput(std::string(what) + " has " + std::to_string(size) + " entries, expected " +
                       std::to_string(ddf.allHeights().size()) + " (one per raster point)");
}

}  // namespace

std::optional<double> scallopSpacingMm(double toolRadiusMm, double crossFeedCurvaturePerMm,
                                       double scallopHeightMm) {
  checkScallopInput(toolRadiusMm, scallopHeightMm, "scallopSpacingMm");
  const double k = crossFeedCurvaturePerMm;
  if (!std::isfinite(k))
    throw InvalidInput("scallopSpacingMm: cross-feed curvature " + std::to_string(k) +
                       " 1/mm is not finite");
  const double r = toolRadiusMm;
  const double h = scallopHeightMm;
  const double toolFactor = 1.0 + k * r;
  if (toolFactor <= 0.0) return std::nullopt;  // concave radius <= R: the ball gouges
  // D = R^2 - (R - h)^2 without the cancellation of the difference of squares.
  const double d = h * (2.0 * r - h);
  const double sRho = std::sqrt(d) / (2.0 * std::sqrt(toolFactor * (1.0 + k * h)));
  const double s = sRho * std::abs(k);  // sin of half the angle between the passes
  if (s > 1.0) return std::nullopt;
  // asin(s)/s = 1 + s^2/6 + ...: the series avoids 0/0 on (nearly) flat surfaces.
  const double ratio = s < 1e-4 ? 1.0 + s * s / 6.0 : std::asin(s) / s;
  return 4.0 * sRho * ratio;
}

double crossFeedCurvature(const CurvatureField& curvature, std::size_t index,
                          const ddf::Vec3& feedDirection) {
  if (index >= curvature.size())
    throw InvalidInput("crossFeedCurvature: index " + std::to_string(index) +
                       " out of range (curvature field has " + std::to_string(curvature.size()) +
                       " points)");
  const double kMax = curvature.kMax[index];
  const double kMin = curvature.kMin[index];
  // The transverse direction is the feed turned by 90 degrees in the tangent plane, so
  // cos^2(transverse, dirMax) = sin^2(feed, dirMax) = b^2 / (a^2 + b^2).
  const double a = feedDirection.dot(curvature.dirMax[index]);
  const double b = feedDirection.dot(curvature.dirMin[index]);
  const double tangential = a * a + b * b;
  if (!(tangential > 1e-12 * feedDirection.squaredNorm())) return 0.5 * (kMax + kMin);
  return (kMax * b * b + kMin * a * a) / tangential;
}

std::vector<float> scallopSpacingField(const ddf::DisplacementField& ddf,
                                       const CurvatureField& curvature, const LineField& flowField,
                                       double toolRadiusMm, double scallopHeightMm) {
  checkScallopInput(toolRadiusMm, scallopHeightMm, "scallopSpacingField");
  checkSize(curvature.size(), ddf, "scallopSpacingField: curvature field");
  checkSize(flowField.size(), ddf, "scallopSpacingField: flow field");
  const double flat = *scallopSpacingMm(toolRadiusMm, 0.0, scallopHeightMm);
  std::vector<float> out(flowField.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < flowField.size(); ++i) {
    if (!(flowField[i].squaredNorm() > 0.0)) {
      out[i] = static_cast<float>(flat);
      continue;
    }
    const double k = crossFeedCurvature(curvature, i, flowField[i]);
    if (!std::isfinite(k)) continue;
    if (const auto spacing = scallopSpacingMm(toolRadiusMm, k, scallopHeightMm))
      out[i] = static_cast<float>(*spacing);
  }
  return out;
}

std::function<double(const ddf::SurfaceLocation&)> spacingFunction(
    const ddf::DisplacementField& ddf, std::vector<float> spacing, double minimumMm) {
  checkSize(spacing.size(), ddf, "spacingFunction: spacing field");
  if (!std::isfinite(minimumMm) || minimumMm <= 0.0)
    throw InvalidInput("spacingFunction: minimum spacing " + std::to_string(minimumMm) +
                       " mm must be finite and > 0");
  return [&ddf, values = std::move(spacing), minimumMm](const ddf::SurfaceLocation& at) {
    const double v = ddf::interpolateOnFace(ddf, values, at.face, at.bary);
    if (!std::isfinite(v)) return minimumMm;
    return v < minimumMm ? minimumMm : v;
  };
}

std::optional<double> smallestFiniteSpacing(const std::vector<float>& spacing) {
  std::optional<double> smallest;
  for (const float v : spacing)
    if (std::isfinite(v) && (!smallest || v < *smallest)) smallest = v;
  return smallest;
}

std::optional<double> effectiveCrossFeedRadiusMm(const Tool& tool) {
  validateTool(tool);
  if (tool.kind == ToolKind::Sphere) return tool.radiusMm;
  return std::nullopt;  // straight roll across the feed: flat cross-feed profile
}

}  // namespace ddfcam::planning
