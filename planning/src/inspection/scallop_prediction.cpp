// SPDX-License-Identifier: MIT
// ddfcam: scallop heights from theory (ball, flat wheel, tilted flat end) and from error maps.
#include "error_region.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/scallop_prediction.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

// Below this |kappa| (1/mm; radius > 1e9 mm) a section counts as a straight line.
constexpr double kFlatCurvature = 1e-9;

void requireFinite(const char* what, std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) throw InvalidInput(std::string(what) + ": non-finite argument");
}

void requirePositive(const char* what, const char* name, double value) {
  if (!(value > 0.0)) {
    throw InvalidInput(std::string(what) + ": " + name + " = " + std::to_string(value) +
                       " must be > 0");
  }
}

void requireSpacing(const char* what, double spacingMm) {
  if (spacingMm < 0.0) {
    throw InvalidInput(std::string(what) + ": spacing " + std::to_string(spacingMm) +
                       " mm must be >= 0");
  }
}

}  // namespace

double ballScallopOnPlaneMm(double radiusMm, double spacingMm) {
  requireFinite("ballScallopOnPlaneMm", {radiusMm, spacingMm});
  requirePositive("ballScallopOnPlaneMm", "radius", radiusMm);
  requireSpacing("ballScallopOnPlaneMm", spacingMm);
  if (spacingMm > 2.0 * radiusMm) {
    throw InvalidInput("ballScallopOnPlaneMm: spacing " + std::to_string(spacingMm) +
                       " mm exceeds the ball diameter");
  }
  const double q = spacingMm * spacingMm / 4.0;
  // R - sqrt(R^2 - q) without cancellation.
  return q / (radiusMm + std::sqrt(radiusMm * radiusMm - q));
}

std::optional<double> ballScallopMm(double radiusMm, double spacingMm,
                                    double crossFeedCurvaturePerMm) {
  requireFinite("ballScallopMm", {radiusMm, spacingMm, crossFeedCurvaturePerMm});
  requirePositive("ballScallopMm", "radius", radiusMm);
  requireSpacing("ballScallopMm", spacingMm);
  const double kappa = crossFeedCurvaturePerMm;
  if (std::abs(kappa) < kFlatCurvature) {
    if (spacingMm > 2.0 * radiusMm) return std::nullopt;
    return ballScallopOnPlaneMm(radiusMm, spacingMm);
  }
  const double rho = 1.0 / std::abs(kappa);
  if (kappa < 0.0 && rho <= radiusMm) return std::nullopt;  // the ball gouges
  const double half = 0.5 * spacingMm * std::abs(kappa);
  if (half >= std::numbers::pi) return std::nullopt;
  // Tool centres at distance a from the centre of curvature; cusp on the bisector at d.
  const double a = kappa > 0.0 ? rho + radiusMm : rho - radiusMm;
  const double disc = radiusMm * radiusMm - a * a * std::sin(half) * std::sin(half);
  if (disc < 0.0) return std::nullopt;
  if (kappa > 0.0) return a * std::cos(half) - std::sqrt(disc) - rho;
  return rho - (a * std::cos(half) + std::sqrt(disc));
}

double approximateScallopMm(double effectiveRadiusMm, double spacingMm,
                            double crossFeedCurvaturePerMm) {
  requireFinite("approximateScallopMm", {spacingMm, crossFeedCurvaturePerMm});
  requirePositive("approximateScallopMm", "R_eff", effectiveRadiusMm);
  requireSpacing("approximateScallopMm", spacingMm);
  return spacingMm * spacingMm / 8.0 * (1.0 / effectiveRadiusMm + crossFeedCurvaturePerMm);
}

std::optional<double> flatWheelScallopMm(double widthMm, double spacingMm,
                                         double crossFeedCurvaturePerMm) {
  requireFinite("flatWheelScallopMm", {widthMm, spacingMm, crossFeedCurvaturePerMm});
  requirePositive("flatWheelScallopMm", "width", widthMm);
  requireSpacing("flatWheelScallopMm", spacingMm);
  const double kappa = crossFeedCurvaturePerMm;
  if (std::abs(kappa) < kFlatCurvature)
    return spacingMm <= widthMm ? std::optional<double>(0.0) : std::nullopt;
  if (kappa < 0.0) return std::nullopt;
  const double half = 0.5 * spacingMm * kappa;
  if (half >= 0.5 * std::numbers::pi || std::tan(half) / kappa > 0.5 * widthMm) return std::nullopt;
  // rho (sec(half) - 1) = rho (1 - cos) / cos, with 1 - cos = 2 sin^2(half / 2).
  const double s = std::sin(0.5 * half);
  return 2.0 * s * s / (kappa * std::cos(half));
}

double flatWheelEdgeErrorMm(double widthMm, double crossFeedCurvaturePerMm) {
  requireFinite("flatWheelEdgeErrorMm", {widthMm, crossFeedCurvaturePerMm});
  requirePositive("flatWheelEdgeErrorMm", "width", widthMm);
  const double kappa = crossFeedCurvaturePerMm;
  const double q = widthMm * widthMm / 4.0;  // (B/2)^2
  if (kappa >= 0.0) return kappa * q / (std::sqrt(1.0 + kappa * kappa * q) + 1.0);
  if (kappa * kappa * q > 1.0) {
    throw InvalidInput("flatWheelEdgeErrorMm: concave radius " + std::to_string(-1.0 / kappa) +
                       " mm is below half the wheel width " + std::to_string(widthMm / 2.0));
  }
  return kappa * q / (1.0 + std::sqrt(1.0 - kappa * kappa * q));
}

double tiltedFlatEffectiveRadiusMm(double radiusMm, double leadAngleRad) {
  requireFinite("tiltedFlatEffectiveRadiusMm", {radiusMm, leadAngleRad});
  requirePositive("tiltedFlatEffectiveRadiusMm", "radius", radiusMm);
  if (!(leadAngleRad > 0.0) || leadAngleRad > 0.5 * std::numbers::pi) {
    throw InvalidInput("tiltedFlatEffectiveRadiusMm: lead angle " + std::to_string(leadAngleRad) +
                       " rad outside (0, pi/2]");
  }
  return radiusMm / std::sin(leadAngleRad);
}

double tiltedFlatScallopOnPlaneMm(double radiusMm, double leadAngleRad, double spacingMm) {
  tiltedFlatEffectiveRadiusMm(radiusMm, leadAngleRad);
  requireSpacing("tiltedFlatScallopOnPlaneMm", spacingMm);
  if (spacingMm > 2.0 * radiusMm) {
    throw InvalidInput("tiltedFlatScallopOnPlaneMm: spacing " + std::to_string(spacingMm) +
                       " mm exceeds the cutter diameter");
  }
  return std::sin(leadAngleRad) * ballScallopOnPlaneMm(radiusMm, spacingMm);
}

double measuredScallopMm(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                         std::span<const int> faces, const ScallopMeasureParams& params) {
  if (!(params.quantile > 0.0) || params.quantile > 1.0) {
    throw InvalidInput("measuredScallopMm: quantile " + std::to_string(params.quantile) +
                       " outside (0, 1]");
  }
  auto samples = detail::weightedRegionValues(ddf, deviation.values, faces, "measuredScallopMm");
  if (samples.empty())
    throw InvalidInput("measuredScallopMm: no finite deviation with positive area in the region");
  return std::max(0.0, detail::weightedQuantile(std::move(samples), params.quantile));
}

double predictedScallopMm(const ScallopCase& c) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const double kappa = c.crossFeedCurvaturePerMm;
  switch (c.model) {
    case ScallopToolModel::Ball:
      return ballScallopMm(c.radiusMm, c.spacingMm, kappa).value_or(kNaN);
    case ScallopToolModel::FlatWheel:
      return flatWheelScallopMm(c.widthMm, c.spacingMm, kappa).value_or(kNaN);
    case ScallopToolModel::TiltedFlatEnd:
      if (std::abs(kappa) < kFlatCurvature)
        return tiltedFlatScallopOnPlaneMm(c.radiusMm, c.leadAngleRad, c.spacingMm);
      return approximateScallopMm(tiltedFlatEffectiveRadiusMm(c.radiusMm, c.leadAngleRad),
                                  c.spacingMm, kappa);
  }
  throw InvalidInput("predictedScallopMm: unknown tool model of case '" + c.label + "'");
}

}  // namespace ddfcam::planning
