// SPDX-License-Identifier: MIT
// Tests of surfaceNormal and toolPathFromStreamlines against analytic planes and spheres.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

ddf::SurfaceLocation locationAt(const ddf::DisplacementField& ddf, int face, const Vec3& bary) {
  const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), face, bary);
  return {face, bary, h, ddf.pointAt(face, bary, h)};
}

TEST(SurfaceNormal, PlaneIsUpEverywhere) {
  const auto plane = ddf::planePatch({.cellsX = 4, .cellsY = 3, .m = 9});
  for (int f = 0; f < plane.ddf.faceCount(); ++f)
    for (const Vec3& bary : {Vec3(1, 0, 0), Vec3(0.2, 0.5, 0.3), Vec3(0, 0.5, 0.5)})
      EXPECT_LT((surfaceNormal(plane.ddf, locationAt(plane.ddf, f, bary)) - Vec3::UnitZ()).norm(),
                1e-9);
}

TEST(SurfaceNormal, SphereIsRadialWithinTheRasterFacetAngle) {
  const auto sphere = ddf::spherePart({.radiusMm = 10.0, .subdivisions = 1, .m = 17});
  double worst = 0;
  for (int f = 0; f < sphere.ddf.faceCount(); ++f) {
    const auto at = locationAt(sphere.ddf, f, Vec3(0.31, 0.33, 0.36));
    const Vec3 n = surfaceNormal(sphere.ddf, at);
    worst = std::max(worst, std::acos(std::clamp(n.dot(at.point.normalized()), -1.0, 1.0)));
  }
  // The raster mesh's facets are a few degrees apart on this sphere; the normal of the facet
  // under the point must be well within one facet angle of the radial direction.
  const double spacing = 10.0 * 1.1 / 16.0;  // icosphere edge of R = 10 at level 1 over m - 1
  EXPECT_LT(worst, spacing / 10.0);
}

/// A straight streamline along +x across the plane patch through y = 15, z = 0.25.
Streamline straightLine(const ddf::DisplacementField& ddf) {
  const LineField field(ddf.allHeights().size(), Vec3::UnitX());
  std::optional<ddf::SurfaceLocation> seed;
  for (int f = 0; f < ddf.faceCount() && !seed; ++f)
    seed = ddf::locateOnFace(ddf, f, Vec3(20.0, 15.1, 0.25));
  EXPECT_TRUE(seed.has_value());
  return traceStreamline(ddf, field, *seed);
}

TEST(ToolPathFromStreamlines, RollTouchesThePlaneWithItsAxisAcrossTheFeed) {
  const auto plane = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9});
  const Streamline line = straightLine(plane.ddf);
  ASSERT_GT(line.points.size(), 10u);
  const Tool roll;
  const ToolPath path = toolPathFromStreamlines(plane.ddf, {line}, roll, 0, {.depthMm = 0.05});
  ASSERT_EQ(path.poses.size(), line.points.size());
  EXPECT_EQ(path.passStarts, std::vector<int>{0});
  for (const PathPose& p : path.poses) {
    EXPECT_NEAR(p.contact.z(), 0.25, 1e-9);
    const Vec3 centre = p.pose.translation();
    EXPECT_LT((centre - (p.contact + (roll.radiusMm - 0.05) * Vec3::UnitZ())).norm(), 1e-9);
    const Vec3 axis = p.pose.linear() * Vec3::UnitX();
    EXPECT_NEAR(std::abs(axis.y()), 1.0, 1e-9);  // across the feed (x), in the tangent plane
  }
}

TEST(ToolPathFromStreamlines, BallSitsOnTheNormalAndShortLinesAreSkipped) {
  const auto plane = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9});
  Streamline line = straightLine(plane.ddf);
  Streamline single;
  single.points = {line.points.front()};
  const Tool ball{.name = "ball R2", .kind = ToolKind::Sphere, .radiusMm = 2.0, .segments = 16};
  const ToolPath path = toolPathFromStreamlines(plane.ddf, {single, line, line}, ball, 1);
  EXPECT_EQ(path.tool, 1);
  EXPECT_EQ(path.passStarts, (std::vector<int>{0, static_cast<int>(line.points.size())}));
  for (const PathPose& p : path.poses) {
    EXPECT_LT((p.pose.translation() - (p.contact + 2.0 * Vec3::UnitZ())).norm(), 1e-9);
    EXPECT_TRUE(p.pose.linear().isIdentity(1e-12));
  }
  EXPECT_THROW(toolPathFromStreamlines(plane.ddf, {single}, ball, 0), InvalidInput);
}

/// Lowest z of @p tool's mesh placed at @p pose (part frame), mm.
double lowestZ(const Tool& tool, const Eigen::Isometry3d& pose) {
  const ddf::TriangleMesh mesh = toolMesh(tool);
  double lowest = 1e300;
  for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, (pose * v).z());
  return lowest;
}

TEST(ToolPathFromStreamlines, EveryKindTouchesThePlaneAtTheContactWithLeadAndTilt) {
  const auto plane = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9});
  const Streamline line = straightLine(plane.ddf);
  const std::vector<Tool> tools = {
      {.name = "ball end", .kind = ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 8.0},
      {.name = "flat end", .kind = ToolKind::FlatEnd, .radiusMm = 3.0, .widthMm = 8.0},
      {.name = "torus",
       .kind = ToolKind::TorusCutter,
       .radiusMm = 4.0,
       .widthMm = 8.0,
       .edgeRadiusMm = 1.0},
      {.name = "belt",
       .kind = ToolKind::BeltContactWheel,
       .radiusMm = 20.0,
       .widthMm = 10.0,
       .segments = 0},
      {.name = "roll",
       .kind = ToolKind::CylinderRoll,
       .radiusMm = 5.0,
       .widthMm = 10.0,
       .edgeRadiusMm = 1.0,
       .segments = 0}};
  const PlacementParams placements[] = {{}, {.leadDeg = 10.0}, {.leadDeg = 5.0, .tiltDeg = -8.0}};
  for (const Tool& tool : tools)
    for (const PlacementParams& placement : placements) {
      SCOPED_TRACE(tool.name + " lead " + std::to_string(placement.leadDeg) + " tilt " +
                   std::to_string(placement.tiltDeg));
      const ToolPath path =
          toolPathFromStreamlines(plane.ddf, {line}, tool, 0, {.placement = placement});
      ASSERT_EQ(path.poses.size(), line.points.size());
      for (std::size_t i = 0; i < path.poses.size(); i += 7) {
        const PathPose& p = path.poses[i];
        // The mesh is inscribed in the true tool, so its lowest vertex may sit up to the
        // chord tolerance (0.005 mm) above the plane, never below it (wheels: segments 0, as a
        // lead spins the wheel's facets away from the lowest line).
        EXPECT_NEAR(lowestZ(tool, p.pose), 0.25, 0.006);
        EXPECT_GE(lowestZ(tool, p.pose), 0.25 - 1e-9);
        EXPECT_LT((placedNormal(tool, p.pose, placement) - Vec3::UnitZ()).norm(), 1e-9);
        // Cutters: the axis leans by the lead towards the feed (+x) and by the tilt across it.
        if (tool.kind == ToolKind::BallEnd || tool.kind == ToolKind::FlatEnd) {
          const Vec3 axis = p.pose.linear() * Vec3::UnitZ();
          const double lead = placement.leadDeg * std::numbers::pi / 180.0;
          const double tilt = placement.tiltDeg * std::numbers::pi / 180.0;
          EXPECT_NEAR(std::abs(axis.x()), std::sin(lead), 1e-9);
          EXPECT_NEAR(axis.z(), std::cos(lead) * std::cos(tilt), 1e-9);
        }
      }
    }
}

TEST(ToolPathFromStreamlines, SamplingFromToleranceGivesTheBallSagittaStep) {
  const auto plane = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9});
  const Streamline line = straightLine(plane.ddf);
  double length = 0;
  for (std::size_t i = 1; i < line.points.size(); ++i)
    length += (line.points[i].point - line.points[i - 1].point).norm();
  const Tool ball{.name = "ball end", .kind = ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 8.0};
  const double r = 3.0, t = 0.001;
  // Cusp between two balls on a plane: sagitta step 2 sqrt(2 R T - T^2) = 0.155 mm, well below
  // the raster spacing (5 mm cells, m = 9: 0.71 mm) and the straight feed's infinite chord step.
  const double step = 2.0 * std::sqrt(2.0 * r * t - t * t);
  StreamlinePathParams params{.placement = {.leadDeg = 10.0}};
  params.sampling = PathSamplingParams{.toleranceMm = t};
  const PlacedPath placed =
      toolPathFromStreamlinesDetailed(plane.ddf, {line, line}, ball, 0, params);
  const int expected = static_cast<int>(std::ceil(length / step)) + 1;
  ASSERT_EQ(placed.path.passStarts, (std::vector<int>{0, expected}));
  ASSERT_EQ(placed.path.poses.size(), 2u * expected);
  ASSERT_EQ(placed.passes.size(), 2u);
  EXPECT_EQ(placed.passes[0].bindingRule, StepRule::ToolProfile);
  EXPECT_NEAR(placed.passes[0].step.stepMm, step, 1e-4);
  const double uniform = length / (expected - 1);
  for (int i = 1; i < expected; ++i)
    EXPECT_NEAR((placed.path.poses[i].contact - placed.path.poses[i - 1].contact).norm(), uniform,
                1e-6);
  EXPECT_LT((placed.path.poses.front().contact - line.points.front().point).norm(), 1e-9);
  EXPECT_LT((placed.path.poses[expected - 1].contact - line.points.back().point).norm(), 1e-9);
}

TEST(ToolPathFromStreamlines, StepOverrideIsUsedAsIs) {
  const auto plane = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 9});
  const Streamline line = straightLine(plane.ddf);
  const double length = (line.points.back().point - line.points.front().point).norm();
  const Tool flat{.name = "flat", .kind = ToolKind::FlatEnd, .radiusMm = 2.0, .widthMm = 6.0};
  StreamlinePathParams params;
  params.sampling = PathSamplingParams{.stepOverrideMm = 1.5};
  const PlacedPath placed = toolPathFromStreamlinesDetailed(plane.ddf, {line}, flat, 2, params);
  EXPECT_EQ(placed.path.tool, 2);
  EXPECT_EQ(placed.path.name, "streamlines");
  EXPECT_EQ(static_cast<int>(placed.path.poses.size()),
            static_cast<int>(std::ceil(length / 1.5)) + 1);
  EXPECT_EQ(placed.passes.at(0).bindingRule, StepRule::Override);
}

}  // namespace
}  // namespace ddfcam::planning
