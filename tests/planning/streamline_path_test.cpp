// SPDX-License-Identifier: MIT
// Tests of surfaceNormal and toolPathFromStreamlines against analytic planes and spheres.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/streamline_path.h>

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace ddfcam::planning
