// SPDX-License-Identifier: MIT
// Tests: the planning of one region's lines (the pipeline the workbench, `plan` and batch jobs
// share): the feed sign reaches the cut, the scallop spacing ignores points without a field,
// keeps its floor and falls back for a straight roll, and a family follows its seed.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/pipeline/region_planning.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace ddfcam::planning {
namespace {

// z = 0 for x <= 0, then a circular arc of radius kRho bending down (convex from the +z tool
// side, axis along y); C1 at x = 0.
class FlatThenConvex : public ddf::HeightFieldSurface {
 public:
  static constexpr double kRho = 12.0;
  ddf::HeightDerivatives evaluate(double x, double) const override {
    if (x <= 0.0) return {};
    const double r = std::sqrt(kRho * kRho - x * x);
    return {.f = r - kRho, .fx = -x / r, .fxx = -kRho * kRho / (r * r * r)};
  }
  std::string name() const override { return "flat then convex"; }
};

ddf::DisplacementField flatThenConvex() {
  return ddf::graphPatch(
             std::make_shared<FlatThenConvex>(),
             {.origin = {-10.0, -8.0}, .size = {18.0, 16.0}, .cellsX = 18, .cellsY = 16, .m = 9})
      .ddf;
}

// Scallop spacing by the law of cosines in the cross-feed plane (tool centres at rho + R from
// the centre of curvature, the cusp at rho + h); the plane: 2 sqrt(2 R h - h^2).
double scallopArcMm(double rho, double toolR, double h) {
  if (std::isinf(rho)) return 2.0 * std::sqrt(2.0 * toolR * h - h * h);
  const double a = rho + toolR, b = rho + h;
  return 2.0 * rho * std::acos((a * a + b * b - toolR * toolR) / (2.0 * a * b));
}

RegionPlan alongY() {
  RegionPlan plan;
  plan.flowSource = FlowFieldSource::FixedDirection;
  plan.fixedDirection = ddf::Vec3::UnitY();
  plan.smoothField = false;
  return plan;
}

// The faces whose centroid lies at x < limit (the flat part of flatThenConvex for limit 0).
std::vector<std::uint8_t> facesLeftOf(const ddf::DisplacementField& part, double limit) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(part.faceCount()), 0);
  for (int f = 0; f < part.faceCount(); ++f) {
    const int n = part.raster().steps();
    const double x =
        (part.surfacePoint(f, 0, 0) + part.surfacePoint(f, n, 0) + part.surfacePoint(f, 0, n)).x() /
        3.0;
    mask[static_cast<std::size_t>(f)] = x < limit ? 1 : 0;
  }
  return mask;
}

const Tool kBall{.kind = ToolKind::Sphere, .radiusMm = 5.0};

TEST(RegionPlanning, FeedSignOrientsTheCut) {
  const ddf::GeneratedSurface plane = ddf::planePatch({});
  const CurvatureField curvature = computeCurvature(plane.ddf);
  for (const LinkingOrder order : {LinkingOrder::ZigZag, LinkingOrder::OneDirection})
    for (const int sign : {1, -1}) {
      RegionPlan plan = alongY();
      plan.fixedDirection = ddf::Vec3::UnitX();
      plan.spacingMm = 5.0;
      plan.feedSign = sign;
      plan.linking = order;
      const RegionFields fields = regionFields(plane.ddf, curvature, plan, {});
      const LineSpacing spacing = regionSpacing(plane.ddf, curvature, fields, plan, kBall);
      const RegionPath path = regionToolPath(
          plane.ddf, planRegionLines(plane.ddf, fields, {}, spacing), plan, kBall, 0, true, {});
      ASSERT_GE(path.lines.size(), 3u);
      ASSERT_TRUE(path.linked.has_value());
      // The field runs along x: the first cut (and with one direction every cut) goes along
      // sign * x, as the plan says.
      for (std::size_t l = 0; l < path.lines.size(); ++l) {
        const double dx =
            path.lines[l].points.back().point.x() - path.lines[l].points.front().point.x();
        const int expected = order == LinkingOrder::ZigZag && l % 2 == 1 ? -sign : sign;
        EXPECT_GT(dx * expected, 10.0) << "line " << l << ", feed sign " << sign;
        if (order == LinkingOrder::ZigZag && l > 0) break;
      }
      // The placed poses follow the oriented lines.
      const ToolPath& poses = path.placed.path;
      ASSERT_GE(poses.poses.size(), 2u);
      EXPECT_GT((poses.poses[1].contact - poses.poses[0].contact).x() * sign, 0.0);
      // The path keeps the lines it was placed along, one per pass, and the linking's idle
      // length, so every front end's project can smooth or fair it again.
      ASSERT_EQ(poses.rawLines.size(), path.lines.size());
      EXPECT_EQ(poses.rawLines.size(), poses.passStarts.size());
      for (std::size_t l = 0; l < path.lines.size(); ++l) {
        ASSERT_EQ(poses.rawLines[l].points.size(), path.lines[l].points.size());
        EXPECT_EQ(poses.rawLines[l].points.front().point, path.lines[l].points.front().point);
        EXPECT_EQ(poses.rawLines[l].points.back().point, path.lines[l].points.back().point);
        // pass l starts where its line starts (the placement follows the oriented line)
        EXPECT_LT((poses.poses[static_cast<std::size_t>(poses.passStarts[l])].contact -
                   path.lines[l].points.front().point)
                      .norm(),
                  1.0);
      }
      ASSERT_TRUE(poses.linkedIdleMm.has_value());
      EXPECT_EQ(*poses.linkedIdleMm, path.linked->idleLengthMm);
    }
}

TEST(RegionPlanning, ScallopSpacingOfARegionIgnoresTheFacesOutsideIt) {
  const ddf::DisplacementField part = flatThenConvex();
  const CurvatureField curvature = computeCurvature(part);
  RegionPlan plan = alongY();
  plan.spacingMode = SpacingMode::ScallopTolerance;
  plan.scallopToleranceMm = 0.05;
  const double flat = scallopArcMm(std::numeric_limits<double>::infinity(), 5.0, 0.05);
  const double convex = scallopArcMm(FlatThenConvex::kRho, 5.0, 0.05);
  ASSERT_LT(convex, 0.9 * flat);
  // The flat region only: the convex faces (narrower spacing) are outside it and must not set
  // the smallest spacing.
  const std::vector<std::uint8_t> mask = facesLeftOf(part, -1.0);
  const RegionFields fields = regionFields(part, curvature, plan, mask);
  const LineSpacing spacing = regionSpacing(part, curvature, fields, plan, kBall);
  EXPECT_TRUE(spacing.fromScallop);
  EXPECT_NEAR(spacing.minMm, flat, 0.02 * flat);
  EXPECT_NEAR(spacing.maxMm, flat, 0.02 * flat);
  EXPECT_EQ(spacing.gougingFraction, 0.0);
  // The whole part: from the convex arc's spacing to the flat one.
  const RegionFields all = regionFields(part, curvature, plan, {});
  const LineSpacing both = regionSpacing(part, curvature, all, plan, kBall);
  EXPECT_NEAR(both.minMm, convex, 0.03 * convex);
  EXPECT_NEAR(both.maxMm, flat, 0.02 * flat);
  ASSERT_TRUE(both.separationAt);
  const std::vector<Streamline> lines = planRegionLines(part, all, {}, both);
  EXPECT_GE(lines.size(), 5u);
}

TEST(RegionPlanning, ScallopSpacingKeepsItsFloorAndARollUsesTheFixedSpacing) {
  const ddf::GeneratedSurface plane = ddf::planePatch({});
  const CurvatureField curvature = computeCurvature(plane.ddf);
  RegionPlan plan = alongY();
  plan.spacingMode = SpacingMode::ScallopTolerance;
  plan.scallopToleranceMm = 1e-5;  // 2 sqrt(2 R h) = 0.02 mm, below the floor
  plan.spacingMm = 3.0;
  const RegionFields fields = regionFields(plane.ddf, curvature, plan, {});
  ASSERT_LT(scallopArcMm(std::numeric_limits<double>::infinity(), 5.0, 1e-5), kMinScallopSpacingMm);
  const LineSpacing floored = regionSpacing(plane.ddf, curvature, fields, plan, kBall);
  EXPECT_DOUBLE_EQ(floored.minMm, kMinScallopSpacingMm);
  const Tool roll{.kind = ToolKind::CylinderRoll, .radiusMm = 5.0};
  const LineSpacing fixed = regionSpacing(plane.ddf, curvature, fields, plan, roll);
  EXPECT_FALSE(fixed.fromScallop);
  EXPECT_DOUBLE_EQ(fixed.minMm, 3.0);
  EXPECT_FALSE(fixed.separationAt);
  EXPECT_NE(fixed.note.find("straight roll"), std::string::npos) << fixed.note;
}

TEST(RegionPlanning, AFamilyIsSpacedAlongTheTransverseLineThroughItsSeed) {
  const ddf::GeneratedSurface plane = ddf::planePatch({});
  const CurvatureField curvature = computeCurvature(plane.ddf);
  RegionPlan plan = alongY();
  const RegionFields fields = regionFields(plane.ddf, curvature, plan, {});
  LineSpacing spacing;
  spacing.minMm = spacing.maxMm = 4.0;
  RegionLinesParams params;
  params.seeding = LineSeeding::Family;
  // The central seed of the plane is its raster point nearest to the centroid; the lines run
  // along y at x = seed + 4 k.
  const ddf::SurfaceLocation seed = centralSeed(plane.ddf, fields.field, {});
  const std::vector<Streamline> lines = planRegionLines(plane.ddf, fields, {}, spacing, params);
  ASSERT_GE(lines.size(), 5u);
  for (const Streamline& line : lines) {
    const double x = line.points.front().point.x();
    const double k = (x - seed.point.x()) / 4.0;
    EXPECT_NEAR(k, std::round(k), 1e-3);
    EXPECT_NEAR(line.points.back().point.x(), x, 1e-6);
  }
  // A varying spacing cannot seed a family.
  spacing.separationAt = [](const ddf::SurfaceLocation&) { return 4.0; };
  EXPECT_THROW(planRegionLines(plane.ddf, fields, {}, spacing, params), InvalidInput);
}

TEST(RegionPlanning, ARegionWithoutAFieldIsRefusedByName) {
  const ddf::GeneratedSurface plane = ddf::planePatch({});
  const CurvatureField curvature = computeCurvature(plane.ddf);
  const RegionFields fields = regionFields(plane.ddf, curvature, alongY(), {});
  const std::vector<std::uint8_t> none(static_cast<std::size_t>(plane.ddf.faceCount()), 0);
  try {
    centralSeed(plane.ddf, fields.field, none);
    FAIL() << "no seed expected";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("undefined everywhere"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ddfcam::planning
