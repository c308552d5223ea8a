// SPDX-License-Identifier: MIT
// Tests of path spacing from error maps against the analytic iso-scallop path count.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/scallop_spacing.h>
#include <ddfcam/planning/lines/spacing_refinement.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

/// A grid patch on an analytic surface: (a, b) in [0, 1]^2 maps to point(a, b) with the unit
/// normal on the tool side normal(point); triangles face the tool side.
ddf::GeneratedSurface gridPatch(std::shared_ptr<const ddf::AnalyticSurface> surface,
                                const std::function<Vec3(double, double)>& point,
                                const std::function<Vec3(const Vec3&)>& normal, int cellsA,
                                int cellsB, int m, double vectorLengthMm) {
  std::vector<Vec3> points, vectors;
  for (int b = 0; b <= cellsB; ++b)
    for (int a = 0; a <= cellsA; ++a) {
      points.push_back(point(static_cast<double>(a) / cellsA, static_cast<double>(b) / cellsB));
      vectors.push_back(vectorLengthMm * normal(points.back()));
    }
  std::vector<std::array<int, 3>> triangles;
  const auto at = [&](int a, int b) { return b * (cellsA + 1) + a; };
  for (int b = 0; b < cellsB; ++b)
    for (int a = 0; a < cellsA; ++a)
      for (std::array<int, 3> t : {std::array{at(a, b), at(a + 1, b), at(a + 1, b + 1)},
                                   std::array{at(a, b), at(a + 1, b + 1), at(a, b + 1)}}) {
        const Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
        if (n.dot(vectors[t[0]]) < 0.0) std::swap(t[1], t[2]);
        triangles.push_back(t);
      }
  return ddf::fromAnalytic(ddf::makeSupportMesh(points, triangles), std::move(vectors), m,
                           std::move(surface));
}

/// One test case: a part, its feed direction field, the tool, the tolerance and the
/// independent oracle (transverse width W, analytic spacing w, sign of the surface's implicit
/// value on the material-left side).
struct Case {
  ddf::GeneratedSurface part;
  std::function<Vec3(const Vec3&)> feed;
  Tool tool;
  double toleranceMm = 0.0;
  double widthMm = 0.0;
  double spacingMm = 0.0;
  double leftSign = 1.0;
};

LineField feedField(const Case& c) {
  LineField field;
  const ddf::DisplacementField& ddf = c.part.ddf;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < ddf.resolution(); ++k)
      for (int i = 0; i + k < ddf.resolution(); ++i)
        field.push_back(c.feed(ddf.surfacePoint(f, i, k)));
  // Raster order inside a face is index(i, k) = rowOffset(k) + i, the loop order above.
  return field;
}

/// Largest material left over the raster points of the simulated part, measured as the
/// distance of each point from the exact surface (independent of the error map).
double exactMaxMaterialLeft(const Case& c, const ddf::DisplacementField& produced) {
  double worst = -1e9;
  for (int f = 0; f < produced.faceCount(); ++f)
    for (int k = 0; k < produced.resolution(); ++k)
      for (int i = 0; i + k < produced.resolution(); ++i)
        worst = std::max(worst, c.leftSign * c.part.surface->value(produced.surfacePoint(f, i, k)));
  return worst;
}

/// Runs the refinement and checks tolerance and path count against ceil(W / w): the front puts
/// its first path half a spacing inside the region and stops when the far end lies within half
/// a spacing, so the ideal count has no "+1" for paths on both boundaries. w comes from
/// scallopSpacingMm() (ball) or the closed-form flat-wheel step, never from the code under test.
void expectIsoScallopCount(const char* name, const Case& c) {
  const auto start = std::chrono::steady_clock::now();
  SpacingRefinementParams params;
  params.toleranceMm = c.toleranceMm;
  params.tracing.stepMm = 0.25;
  const SpacingRefinementResult r = refineSpacing(c.part.ddf, feedField(c), {}, c.tool, params);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int analytic = static_cast<int>(std::ceil(c.widthMm / c.spacingMm));
  const int count = static_cast<int>(r.paths.size());
  const double exact = exactMaxMaterialLeft(c, r.produced);
  std::printf(
      "[%s] paths %d (front %d, %zu fix-up iterations), analytic ceil(%.3f / %.4f) = %d, "
      "max error %.5f (exact %.5f) mm, tolerance %.3f mm, length %.1f mm, %.2f s\n",
      name, count, r.iterations.front().pathCount, r.iterations.size() - 1, c.widthMm, c.spacingMm,
      analytic, r.maxErrorMm, exact, c.toleranceMm, r.totalLengthMm, seconds);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.maxErrorMm, c.toleranceMm);
  EXPECT_LE(exact, c.toleranceMm + 1e-4) << "exact distance of the produced raster points";
  EXPECT_LE(std::abs(count - analytic), 0.1 * analytic) << count << " paths, analytic " << analytic;
  EXPECT_EQ(r.toolPath.passStarts.size(), r.paths.size());
  ASSERT_FALSE(r.iterations.empty());
  EXPECT_EQ(r.iterations.back().pathCount, count);
  EXPECT_NEAR(r.totalLengthMm, r.iterations.back().totalLengthMm, 1e-9);
}

constexpr double kBallRadius = 5.0;

Tool ball() {
  return Tool{.name = "ball R5", .kind = ToolKind::Sphere, .radiusMm = kBallRadius, .segments = 96};
}

Tool flatRoll(double widthMm) {
  return Tool{.name = "roll",
              .kind = ToolKind::CylinderRoll,
              .radiusMm = 5.0,
              .widthMm = widthMm,
              .segments = 720};
}

/// Plane z = 0.25 over x in [0, 2] (feed), y in [0, 20] (transverse); 2 mm cells at raster
/// resolution m.
Case planeCase(Tool tool, double toleranceMm, double spacingMm, int m) {
  Case c{ddf::planePatch({.size = {2.0, 20.0}, .cellsX = 1, .cellsY = 10, .m = m}),
         [](const Vec3&) { return Vec3::UnitX(); },
         std::move(tool),
         toleranceMm,
         20.0,
         spacingMm};
  return c;
}

/// Cylinder of radius rho about z, arc of 20 mm, z in [0, 2] (feed along the axis); the tool
/// outside (convex) or inside (concave, vectors towards the axis).
Case cylinderCase(bool convex, Tool tool, double toleranceMm, double spacingMm, int m) {
  constexpr double rho = 20.0, arc = 20.0;
  auto surface = std::make_shared<ddf::CylinderSurface>(rho);
  const double side = convex ? 1.0 : -1.0;
  Case c{gridPatch(
             surface,
             [&](double a, double b) {
               const double phi = b * arc / rho;
               return Vec3(rho * std::cos(phi), rho * std::sin(phi), 2.0 * a);
             },
             [side](const Vec3& p) -> Vec3 { return side * Vec3(p.x(), p.y(), 0.0).normalized(); },
             1, 8, m, 2.0),
         [](const Vec3&) { return Vec3::UnitZ(); },
         std::move(tool),
         toleranceMm,
         arc,
         spacingMm,
         side};
  return c;
}

/// Torus R = 30, r = 10: u in [0, 0.05] rad (feed along the parallels), v in [-0.8, 0.8] rad
/// around the outer equator (a 16 mm meridian arc with cross-feed curvature 1/r).
Case torusCase(Tool tool, double toleranceMm, double spacingMm, int m) {
  auto surface = std::make_shared<ddf::TorusSurface>(30.0, 10.0);
  Case c{
      gridPatch(
          surface, [&](double a, double b) { return surface->point(0.05 * a, -0.8 + 1.6 * b); },
          [&](const Vec3& p) -> Vec3 { return surface->gradient(p).normalized(); }, 1, 8, m, 2.0),
      [](const Vec3& p) { return Vec3(-p.y(), p.x(), 0.0).normalized(); },
      std::move(tool),
      toleranceMm,
      16.0,
      spacingMm};
  return c;
}

/// Cross-feed step of a flat (straight) wheel of width B on a convex cross-section of radius
/// rho: the form error rho (1 / cos(phi) - 1) reaches h at phi = acos(rho / (rho + h)).
double flatWheelSpacing(double widthMm, double rho, double h) {
  return std::min(widthMm, 2.0 * rho * std::acos(rho / (rho + h)));
}

TEST(SpacingRefinement, BallOnPlaneMatchesIsoScallopCount) {
  expectIsoScallopCount("ball/plane",
                        planeCase(ball(), 0.05, *scallopSpacingMm(kBallRadius, 0.0, 0.05), 13));
}

TEST(SpacingRefinement, BallOnConvexCylinderMatchesIsoScallopCount) {
  expectIsoScallopCount(
      "ball/convex cylinder",
      cylinderCase(true, ball(), 0.05, *scallopSpacingMm(kBallRadius, 0.05, 0.05), 17));
}

TEST(SpacingRefinement, BallInConcaveCylinderMatchesIsoScallopCount) {
  expectIsoScallopCount(
      "ball/concave cylinder",
      cylinderCase(false, ball(), 0.05, *scallopSpacingMm(kBallRadius, -0.05, 0.05), 17));
}

TEST(SpacingRefinement, BallOnTorusMatchesIsoScallopCount) {
  expectIsoScallopCount("ball/torus",
                        torusCase(ball(), 0.05, *scallopSpacingMm(kBallRadius, 0.1, 0.05), 15));
}

TEST(SpacingRefinement, FlatWheelInConcaveCylinderAroundTheBoreStepsByItsWidth) {
  // An uncrowned wheel fed along the bore's axis would gouge the concave cross-section (oracles
  // note); fed around the bore, with its axis along the straight generators, its R = 5 mm rim
  // fits the rho = 20 mm circle along the feed and the cross-feed section is straight: the step
  // is the width. Arc of 2 mm around the bore (feed), 20 mm along the axis (transverse); a
  // raster of 1/16 mm resolves the edges of the step-shaped grooves.
  constexpr double rho = 20.0;
  auto surface = std::make_shared<ddf::CylinderSurface>(rho);
  Case c{gridPatch(
             surface,
             [&](double a, double b) {
               const double phi = a * 2.0 / rho;
               return Vec3(rho * std::cos(phi), rho * std::sin(phi), 20.0 * b);
             },
             [](const Vec3& p) -> Vec3 { return -Vec3(p.x(), p.y(), 0.0).normalized(); }, 1, 10, 33,
             2.0),
         [](const Vec3& p) { return Vec3(-p.y(), p.x(), 0.0).normalized(); },
         flatRoll(1.2),
         0.02,
         20.0,
         1.2,
         -1.0};
  expectIsoScallopCount("flat wheel/concave cylinder", c);
}

TEST(SpacingRefinement, FlatWheelOnPlaneStepsByItsWidth) {
  // A straight generator on a plane: no form error across the wheel, the step is the width.
  expectIsoScallopCount("flat wheel/plane", planeCase(flatRoll(1.2), 0.02, 1.2, 17));
}

TEST(SpacingRefinement, FlatWheelOnConvexCylinderIsLimitedByItsFormError) {
  // Feed along the axis, 3 mm wide wheel: the form error kappa B^2 / 8 = 0.056 mm exceeds
  // h = 0.01, so the step is sqrt(8 h / kappa) ~ 1.26 mm rather than B.
  expectIsoScallopCount(
      "flat wheel/convex cylinder",
      cylinderCase(true, flatRoll(3.0), 0.01, flatWheelSpacing(3.0, 20.0, 0.01), 17));
}

TEST(SpacingRefinement, FlatWheelOnTorusIsLimitedByItsFormError) {
  // Feed along the parallels, the wheel axis along the meridian (cross-feed radius r = 10).
  expectIsoScallopCount("flat wheel/torus",
                        torusCase(flatRoll(3.0), 0.02, flatWheelSpacing(3.0, 10.0, 0.02), 15));
}

TEST(SpacingRefinement, RecordsIterationsAndReportsProgress) {
  const Case c = planeCase(flatRoll(1.2), 0.02, 1.2, 9);
  SpacingRefinementParams params;
  params.toleranceMm = c.toleranceMm;
  std::vector<double> seen;
  params.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const SpacingRefinementResult r = refineSpacing(c.part.ddf, feedField(c), {}, c.tool, params);
  ASSERT_FALSE(r.iterations.empty());
  const RefinementIteration& front = r.iterations.front();
  EXPECT_EQ(front.pathsAdded, front.pathCount);
  EXPECT_EQ(front.paths.size(), static_cast<std::size_t>(front.pathCount));
  EXPECT_EQ(r.frontSpacingsMm.size() + 1, static_cast<std::size_t>(front.pathCount));
  EXPECT_NEAR(r.allowanceMm, 2.5 * c.toleranceMm, 1e-12);
  EXPECT_EQ(r.errorField.size(), c.part.ddf.allHeights().size());
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
}

TEST(SpacingRefinement, CancelThrows) {
  const Case c = planeCase(flatRoll(1.2), 0.02, 1.2, 9);
  SpacingRefinementParams params;
  params.toleranceMm = c.toleranceMm;
  params.progress = [](double f) { return f < 0.2; };
  EXPECT_THROW(refineSpacing(c.part.ddf, feedField(c), {}, c.tool, params), Cancelled);
}

TEST(SpacingRefinement, RejectsInvalidInput) {
  const Case c = planeCase(flatRoll(1.2), 0.02, 1.2, 5);
  const LineField field = feedField(c);
  SpacingRefinementParams params;
  params.toleranceMm = 0.0;
  EXPECT_THROW(refineSpacing(c.part.ddf, field, {}, c.tool, params), InvalidInput);
  params.toleranceMm = 0.02;
  params.stockAllowanceMm = 0.03;  // not above 2 x tolerance
  EXPECT_THROW(refineSpacing(c.part.ddf, field, {}, c.tool, params), InvalidInput);
  params.stockAllowanceMm = 0.9;  // the plane sits at h = 0.25 in a 1 mm crust
  EXPECT_THROW(refineSpacing(c.part.ddf, field, {}, c.tool, params), InvalidInput);
  params.stockAllowanceMm = 0.0;
  EXPECT_THROW(refineSpacing(c.part.ddf, LineField(3), {}, c.tool, params), InvalidInput);
  const std::vector<std::uint8_t> none(c.part.ddf.faceCount(), 0);
  EXPECT_THROW(refineSpacing(c.part.ddf, field, none, c.tool, params), InvalidInput);
  EXPECT_THROW(refineSpacing(c.part.ddf, field, {1, 1}, c.tool, params), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
