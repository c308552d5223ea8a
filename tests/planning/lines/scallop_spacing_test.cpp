// SPDX-License-Identifier: MIT
// Tests of the scallop-height path spacing: oracle table, limits, fields, even coverage.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>
#include <ddfcam/planning/lines/scallop_spacing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// Independent oracle: the law of cosines in the cross-feed plane, written per side. Convex:
// tool centres at rho + R from the centre of curvature, cusp at rho + h; concave: rho - R and
// rho - h. theta is the angle between a tool centre and the cusp seen from the centre; the
// passes are 2 theta rho apart on the surface.
double lawOfCosinesSpacing(double r, double rho, double h, bool convex) {
  const double a = convex ? rho + r : rho - r;
  const double b = convex ? rho + h : rho - h;
  const double cosTheta = (a * a + b * b - r * r) / (2.0 * a * b);
  return 2.0 * std::acos(cosTheta) * rho;
}

TEST(ScallopSpacing, MatchesOracleTable) {
  // oracles.md "Path spacing (scallop height)": R = 5, h = 0.01.
  EXPECT_NEAR(*scallopSpacingMm(5.0, 0.0, 0.01), 0.632139, 1e-6);
  const struct {
    double rho, convex, concave;
  } rows[] = {{20.0, 0.565266, 0.730124}, {50.0, 0.602662, 0.666401}, {200.0, 0.624367, 0.640208}};
  for (const auto& row : rows) {
    EXPECT_NEAR(*scallopSpacingMm(5.0, 1.0 / row.rho, 0.01), row.convex, 1e-6) << row.rho;
    EXPECT_NEAR(*scallopSpacingMm(5.0, -1.0 / row.rho, 0.01), row.concave, 1e-6) << row.rho;
  }
}

TEST(ScallopSpacing, MatchesLawOfCosinesAndPlaneLimit) {
  for (const double rho : {7.0, 13.0, 40.0, 1000.0})
    for (const double h : {0.001, 0.05, 0.5}) {
      const double convex = lawOfCosinesSpacing(5.0, rho, h, true);
      const double concave = lawOfCosinesSpacing(5.0, rho, h, false);
      EXPECT_NEAR(*scallopSpacingMm(5.0, 1.0 / rho, h), convex, 1e-7 * rho);
      EXPECT_NEAR(*scallopSpacingMm(5.0, -1.0 / rho, h), concave, 1e-7 * rho);
    }
  // Plane: w = 2 sqrt(R^2 - (R - h)^2), also reached continuously from both sides.
  const double plane = 2.0 * std::sqrt(25.0 - 4.99 * 4.99);
  EXPECT_NEAR(*scallopSpacingMm(5.0, 0.0, 0.01), plane, 1e-12);
  EXPECT_NEAR(*scallopSpacingMm(5.0, 1e-9, 0.01), plane, 1e-8);  // dL/dkappa ~ -1.6 mm^2
  EXPECT_NEAR(*scallopSpacingMm(5.0, -1e-9, 0.01), plane, 1e-8);
  // Small-scallop approximation L ~ sqrt(8 h R rho / (rho +- R)).
  EXPECT_NEAR(*scallopSpacingMm(5.0, 0.01, 1e-4), std::sqrt(8e-4 * 5.0 * 100.0 / 105.0), 1e-5);
}

TEST(ScallopSpacing, GougeAndUnreachableGiveNullopt) {
  EXPECT_FALSE(scallopSpacingMm(5.0, -0.25, 0.01));  // concave radius 4 < R
  EXPECT_FALSE(scallopSpacingMm(5.0, -0.2, 0.01));   // concave radius = R
  EXPECT_FALSE(scallopSpacingMm(5.0, -0.19, 1.0));   // radius 5.26: cusp never 1 mm high
  EXPECT_TRUE(scallopSpacingMm(5.0, -0.19, 0.001));
  EXPECT_TRUE(scallopSpacingMm(5.0, 100.0, 4.0));  // convex: always a spacing
}

TEST(ScallopSpacing, RejectsInvalidInput) {
  EXPECT_THROW(scallopSpacingMm(0.0, 0.0, 0.01), InvalidInput);
  EXPECT_THROW(scallopSpacingMm(5.0, 0.0, 0.0), InvalidInput);
  EXPECT_THROW(scallopSpacingMm(5.0, 0.0, 5.0), InvalidInput);
  EXPECT_THROW(scallopSpacingMm(5.0, std::nan(""), 0.01), InvalidInput);
  EXPECT_THROW(scallopSpacingMm(std::numeric_limits<double>::infinity(), 0.0, 0.01), InvalidInput);
}

TEST(ScallopSpacing, MonotonicInHeightAndScaleInvariant) {
  for (const double k : {-0.1, -0.02, 0.0, 0.03, 0.3}) {
    double previous = 0.0;
    for (double h = 0.001; h < 2.0; h *= 1.5) {
      const double l = *scallopSpacingMm(5.0, k, h);
      EXPECT_GT(l, previous) << k << " " << h;
      previous = l;
    }
    for (const double c : {0.1, 3.0, 17.0})
      EXPECT_NEAR(*scallopSpacingMm(5.0 * c, k / c, 0.02 * c), c * *scallopSpacingMm(5.0, k, 0.02),
                  1e-12 * c);
  }
}

const ddf::GeneratedSurface& cylinder() {
  static const ddf::GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 20.0, .segments = 48, .rings = 8, .m = 9});
  return part;
}

template <typename Fn>
LineField fieldOf(const ddf::DisplacementField& ddf, Fn&& dir) {
  LineField out;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) out.push_back(dir(ddf.surfacePoint(f, i, k)));
  return out;
}

TEST(ScallopSpacing, CrossFeedCurvatureOnCylinder) {
  const auto& ddf = cylinder().ddf;
  const CurvatureField curvature = computeCurvature(ddf);
  const LineField around = fieldOf(ddf, [](const Vec3& p) { return Vec3(-p.y(), p.x(), 0.0); });
  for (std::size_t i = 0; i < curvature.size(); i += 7) {
    // Feed along the axis: the cross section is the circle (convex, 1/r); around: the line.
    EXPECT_NEAR(crossFeedCurvature(curvature, i, Vec3::UnitZ()), 0.1, 2e-4) << i;
    EXPECT_NEAR(crossFeedCurvature(curvature, i, -3.0 * Vec3::UnitZ()), 0.1, 2e-4) << i;
    EXPECT_NEAR(crossFeedCurvature(curvature, i, around[i]), 0.0, 2e-4) << i;
    // Euler: at 45 degrees half of each.
    const Vec3 diagonal = around[i].normalized() + Vec3::UnitZ();
    EXPECT_NEAR(crossFeedCurvature(curvature, i, diagonal), 0.05, 2e-4) << i;
  }
  EXPECT_THROW(crossFeedCurvature(curvature, curvature.size(), Vec3::UnitZ()), InvalidInput);
}

TEST(ScallopSpacing, FieldOnCylinderMatchesOracle) {
  const auto& ddf = cylinder().ddf;
  const CurvatureField curvature = computeCurvature(ddf);
  LineField axial(ddf.allHeights().size(), Vec3::UnitZ());
  axial[3] = Vec3::Zero();  // undefined flow: plane value
  const std::vector<float> spacing = scallopSpacingField(ddf, curvature, axial, 5.0, 0.05);
  const double expected = lawOfCosinesSpacing(5.0, 10.0, 0.05, true);
  for (std::size_t i = 0; i < spacing.size(); ++i) {
    if (i == 3) continue;
    ASSERT_NEAR(spacing[i], expected, 1e-3 * expected) << i;
  }
  EXPECT_NEAR(spacing[3], 2.0 * std::sqrt(25.0 - 4.95 * 4.95), 1e-5);
  // A concave point narrower than the ball: NaN, and spacingFunction falls back to the minimum.
  CurvatureField gouging = curvature;
  gouging.kMax.assign(gouging.size(), -0.5f);
  gouging.kMin.assign(gouging.size(), -0.5f);
  const std::vector<float> none = scallopSpacingField(ddf, gouging, axial, 5.0, 0.05);
  EXPECT_TRUE(std::isnan(none[0]));
  EXPECT_FALSE(smallestFiniteSpacing({std::nanf(""), std::nanf("")}));
  EXPECT_NEAR(*smallestFiniteSpacing(spacing), expected, 1e-3 * expected);
  const auto fallback = spacingFunction(ddf, none, 0.4);
  EXPECT_DOUBLE_EQ(fallback({.face = 0, .bary = Vec3(0.2, 0.3, 0.5)}), 0.4);
  const auto interpolated = spacingFunction(ddf, spacing, 0.4);
  EXPECT_NEAR(interpolated({.face = 5, .bary = Vec3(0.2, 0.3, 0.5)}), expected, 1e-3 * expected);
  EXPECT_DOUBLE_EQ(spacingFunction(ddf, spacing, 5.0)({.face = 5, .bary = Vec3(1, 0, 0)}), 5.0);
  EXPECT_THROW(scallopSpacingField(ddf, curvature, LineField(3), 5.0, 0.05), InvalidInput);
  EXPECT_THROW(spacingFunction(ddf, spacing, 0.0), InvalidInput);
}

TEST(ScallopSpacing, EffectiveRadiusOfTools) {
  EXPECT_DOUBLE_EQ(*effectiveCrossFeedRadiusMm({.kind = ToolKind::Sphere, .radiusMm = 3.0}), 3.0);
  EXPECT_FALSE(effectiveCrossFeedRadiusMm({.kind = ToolKind::CylinderRoll}));
  EXPECT_THROW(effectiveCrossFeedRadiusMm({.kind = ToolKind::Sphere, .radiusMm = -1.0}),
               InvalidInput);
}

// Corrugated sheet z = A sin(x / s): cross sections across y are convex on the crest
// (x = pi s / 2) and concave in the trough (x = 3 pi s / 2); straight lines along y.
class CorrugatedSheet : public ddf::HeightFieldSurface {
 public:
  static constexpr double kAmplitude = 2.0, kScale = 5.0;  // curvature +-0.08 1/mm
  ddf::HeightDerivatives evaluate(double x, double) const override {
    const double c = std::cos(x / kScale), s = std::sin(x / kScale);
    return {.f = kAmplitude * s,
            .fx = kAmplitude * c / kScale,
            .fxx = -kAmplitude * s / (kScale * kScale)};
  }
  std::string name() const override { return "corrugated sheet"; }
  // Tool-side cross-feed curvature (upward normal): -f'' / (1 + f'^2)^1.5.
  static double curvature(double x) {
    const double fx = kAmplitude * std::cos(x / kScale) / kScale;
    return kAmplitude * std::sin(x / kScale) / (kScale * kScale) / std::pow(1.0 + fx * fx, 1.5);
  }
  static double arcLength(double x0, double x1) {
    double sum = 0.0;
    const int steps = 200;
    for (int i = 0; i < steps; ++i) {
      const double x = x0 + (i + 0.5) * (x1 - x0) / steps;
      const double fx = kAmplitude * std::cos(x / kScale) / kScale;
      sum += std::sqrt(1.0 + fx * fx) * (x1 - x0) / steps;
    }
    return sum;
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? std::nan("") : v[v.size() / 2];
}

TEST(ScallopSpacing, EvenCoverageFollowsLocalScallopSpacing) {
  constexpr double kR = 5.0, kH = 0.03;
  const double period = 2.0 * std::numbers::pi * CorrugatedSheet::kScale;
  const ddf::GeneratedSurface part = ddf::graphPatch(
      std::make_shared<CorrugatedSheet>(),
      {.origin = {0.0, 0.0}, .size = {period, 8.0}, .cellsX = 40, .cellsY = 6, .m = 9});
  const auto& ddf = part.ddf;
  const CurvatureField curvature = computeCurvature(ddf);
  const LineField feed(ddf.allHeights().size(), Vec3::UnitY());
  const std::vector<float> spacing = scallopSpacingField(ddf, curvature, feed, kR, kH);
  const double minimum = *smallestFiniteSpacing(spacing);
  EvenSpacingParams params;
  params.separationMm = minimum;
  params.separationAt = spacingFunction(ddf, spacing, minimum);
  const std::vector<Streamline> lines = evenlySpacedStreamlines(ddf, feed, params);
  // Lines run along y at constant x: their positions across the feed, sorted.
  std::vector<double> xs;
  for (const auto& line : lines) {
    if (line.points.size() < 10) continue;
    std::vector<double> x;
    for (const auto& p : line.points) x.push_back(p.point.x());
    xs.push_back(median(x));
  }
  std::sort(xs.begin(), xs.end());
  ASSERT_GT(xs.size(), 10u);
  std::vector<double> convexGap, concaveGap, convexRatio, concaveRatio;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double mid = 0.5 * (xs[i] + xs[i + 1]);
    const double gap = CorrugatedSheet::arcLength(xs[i], xs[i + 1]);
    const double k = CorrugatedSheet::curvature(mid);
    const double expected = lawOfCosinesSpacing(kR, 1.0 / std::abs(k), kH, k > 0.0);
    if (k > 0.05) convexGap.push_back(gap), convexRatio.push_back(gap / expected);
    if (k < -0.05) concaveGap.push_back(gap), concaveRatio.push_back(gap / expected);
  }
  std::printf(
      "scallop coverage: %zu lines, convex gap %.3f (ratio %.3f, n %zu), concave gap "
      "%.3f (ratio %.3f, n %zu)\n",
      xs.size(), median(convexGap), median(convexRatio), convexGap.size(), median(concaveGap),
      median(concaveRatio), concaveGap.size());
  ASSERT_GE(convexGap.size(), 3u);
  ASSERT_GE(concaveGap.size(), 3u);
  EXPECT_LT(median(convexGap), 0.9 * median(concaveGap));
  EXPECT_NEAR(median(convexRatio), 1.0, 0.15);
  EXPECT_NEAR(median(concaveRatio), 1.0, 0.15);
}

}  // namespace
}  // namespace ddfcam::planning
