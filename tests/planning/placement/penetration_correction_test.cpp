// SPDX-License-Identifier: MIT
// Tests of the tangential-DDF penetration correction against analytic lifts and brute force.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/penetration_correction.h>
#include <ddfcam/planning/placement/tangential_grid.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace ddfcam::planning {
namespace {

/// z = s (rho - sqrt(rho^2 - y^2)): a trough (s = +1, concave across y) or a ridge (s = -1)
/// of radius rho with its axis along x, lowest (highest) line z = 0.
class TroughSurface : public ddf::HeightFieldSurface {
 public:
  TroughSurface(double rho, double sign) : rho_(rho), sign_(sign) {}
  ddf::HeightDerivatives evaluate(double, double y) const override {
    const double r = std::sqrt(rho_ * rho_ - y * y);
    return {sign_ * (rho_ - r), 0.0, sign_ * y / r, 0.0, 0.0, sign_ * rho_ * rho_ / (r * r * r)};
  }
  std::string name() const override { return "trough"; }

 private:
  double rho_, sign_;
};

constexpr double kRho = 20.0;

ddf::GeneratedSurface trough(double sign) {
  ddf::GraphPatchParams grid{
      .origin = {-12.0, -12.0}, .size = {24.0, 24.0}, .cellsX = 24, .cellsY = 24, .m = 9};
  return ddf::graphPatch(std::make_shared<TroughSurface>(kRho, sign), grid);
}

ddf::TriangleMesh roll(double radius = 5.0, double width = 10.0) {
  return makeCylinderTool({.radiusMm = radius, .widthMm = width, .segments = 64});
}

/// Roll at the trough bottom (origin, normal +z) with its axis along @p axisAngle from x.
Eigen::Isometry3d rollAt(const ddf::Vec3& contact, const ddf::Vec3& normal, double axisAngle) {
  // rollPoseAtContact puts the axis at normal x feed, so the feed is the axis turned by -90 deg.
  const ddf::Vec3 feed(std::sin(axisAngle), -std::cos(axisAngle), 0.0);
  return rollPoseAtContact(contact, normal, feed, 5.0, 0.0);
}

TEST(PenetrationCorrection, RollAcrossAConcaveTroughLiftsByTheSagitta) {
  const auto part = trough(+1.0);
  const double halfWidth = 5.0;
  const double exact = kRho - std::sqrt(kRho * kRho - halfWidth * halfWidth);  // 0.635 mm
  double previous = 0.0;
  for (int grid : {50, 200}) {
    PenetrationCorrectionParams p;
    p.gridSize = grid;
    const double lift =
        penetrationDepth(part.ddf, roll(), rollAt({0, 0, 0}, {0, 0, 1}, std::numbers::pi / 2),
                         {0, 0, 0}, {0, 0, 1}, p);
    // Cell centres reach to half a cell from the rim, where the surface slope is 5 / 19.4,
    // and half a cell off the roll's lowest line, where its 64-gon rises by tan(pi / 64).
    const double cell = 2.0 * halfWidth / grid;
    const double slope = halfWidth / std::sqrt(kRho * kRho - halfWidth * halfWidth);
    EXPECT_LE(lift, exact + 1e-4) << grid;
    EXPECT_GE(lift, exact - (slope + std::tan(std::numbers::pi / 64)) * cell / 2.0 - 1e-3) << grid;
    if (grid == 200) EXPECT_GT(lift, previous);
    previous = lift;
  }
}

TEST(PenetrationCorrection, RollAlongTheTroughAxisAndOnConvexSurfacesNeedsNoLift) {
  const auto concave = trough(+1.0);
  EXPECT_NEAR(penetrationDepth(concave.ddf, roll(), rollAt({0, 0, 0}, {0, 0, 1}, 0.0), {0, 0, 0},
                               {0, 0, 1}),
              0.0, 1e-4);
  const auto ridge = trough(-1.0);
  for (double angle : {0.0, 0.7, std::numbers::pi / 2})
    EXPECT_NEAR(penetrationDepth(ridge.ddf, roll(), rollAt({0, 0, 0}, {0, 0, 1}, angle), {0, 0, 0},
                                 {0, 0, 1}),
                0.0, 1e-4);
  const auto sphere = ddf::spherePart({.radiusMm = 10.0, .subdivisions = 3, .m = 9});
  const ddf::Vec3 c(0, 0, 10);
  // The sphere's raster is a polyhedron: the contact lies up to the raster sag below its facets.
  EXPECT_LT(penetrationDepth(sphere.ddf, roll(3.0, 6.0),
                             rollPoseAtContact(c, c.normalized(), {1, 0, 0}, 3.0, 0.0), c,
                             c.normalized()),
            2e-3);
}

/// Naive reference: per cell centre, a ray along the normal against every triangle.
double bruteForceLift(const ddf::TriangleMesh& surface, const ddf::TriangleMesh& tool,
                      const Eigen::Isometry3d& pose, const TangentFrame& frame, int grid) {
  const ddf::TriangleMesh placed = tool.transformed(pose);
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300, top = -1e300;
  for (const auto& p : placed.vertices) {
    const ddf::Vec3 l = frame.toLocal(p);
    u0 = std::min(u0, l.x()), u1 = std::max(u1, l.x()), v0 = std::min(v0, l.y());
    v1 = std::max(v1, l.y()), top = std::max(top, l.z());
  }
  // Crossing parameter w of the ray (u, v) with triangle (a, b, c), or NaN.
  const auto hit = [&](const ddf::TriangleMesh& m, const std::array<int, 3>& t, double u,
                       double v) {
    const ddf::Vec3 a = frame.toLocal(m.vertices[t[0]]), b = frame.toLocal(m.vertices[t[1]]),
                    c = frame.toLocal(m.vertices[t[2]]);
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-14) return std::numeric_limits<double>::quiet_NaN();
    const double s = ((u - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (v - a.y())) / det;
    const double t2 = ((b.x() - a.x()) * (v - a.y()) - (u - a.x()) * (b.y() - a.y())) / det;
    if (s < -1e-9 || t2 < -1e-9 || s + t2 > 1 + 1e-9)
      return std::numeric_limits<double>::quiet_NaN();
    return a.z() + s * (b.z() - a.z()) + t2 * (c.z() - a.z());
  };
  double lift = 0.0;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const double u = u0 + (i + 0.5) * (u1 - u0) / grid, v = v0 + (j + 0.5) * (v1 - v0) / grid;
      double ht = 1e300, hw = -1e300;
      for (const auto& t : placed.triangles)
        if (const double w = hit(placed, t, u, v); w == w) ht = std::min(ht, w);
      for (const auto& t : surface.triangles)
        if (const double w = hit(surface, t, u, v); w == w && w <= top) hw = std::max(hw, w);
      if (ht < 1e299 && hw > -1e299) lift = std::max(lift, hw - ht);
    }
  return lift;
}

TEST(PenetrationCorrection, MatchesABruteForceRayCastOnASaddle) {
  const auto saddle =
      ddf::saddlePatch({.a = 0.04, .b = 0.04, .grid = {.cellsX = 16, .cellsY = 16, .m = 5}});
  const ddf::TriangleMesh surface = ddf::extractRasterMesh(saddle.ddf).mesh;
  const auto tool = roll(3.0, 6.0);
  for (const ddf::Vec3 c : {ddf::Vec3(0, 0, 0), ddf::Vec3(2.0, -1.5, 0.04 * 4 - 0.04 * 2.25)}) {
    const ddf::Vec3 n = ddf::Vec3(-0.08 * c.x(), 0.08 * c.y(), 1.0).normalized();
    for (double angle : {0.0, 0.6, 1.9}) {
      const Eigen::Isometry3d pose =
          rollPoseAtContact(c, n, {std::cos(angle), std::sin(angle), 0}, 3.0, 0.0);
      PenetrationCorrectionParams p;
      p.gridSize = 24;
      const double fast = penetrationDepth(saddle.ddf, tool, pose, c, n, p);
      const double naive =
          bruteForceLift(surface, tool, pose, tangentFrame(c, n, pose.linear().col(0)), 24);
      EXPECT_NEAR(fast, naive, 2e-5) << angle;
    }
  }
}

/// Poses along the trough with the roll axis turning from along x (no lift) to across.
ToolPath turningRollPath(int count) {
  ToolPath path;
  for (int i = 0; i < count; ++i) {
    const double s = double(i) / (count - 1);
    const ddf::Vec3 c(-3.0 + 6.0 * s, 0.0, 0.0);
    path.poses.push_back({rollAt(c, {0, 0, 1}, 0.5 * std::numbers::pi * s), c});
  }
  path.passStarts = {0};
  return path;
}

TEST(PenetrationCorrection, CorrectedPosesClearTheAnalyticSurface) {
  const auto part = trough(+1.0);
  ToolPath path = turningRollPath(60);
  const auto tool = roll();
  const auto report = correctPenetrations(part.ddf, tool, path);
  EXPECT_EQ(report.exactPoses, 60);
  EXPECT_GT(report.maxLiftMm, 0.5);
  const TroughSurface exact(kRho, 1.0);
  double worstBefore = 0.0, worstAfter = 0.0;
  const ToolPath original = turningRollPath(60);
  for (std::size_t i = 0; i < path.poses.size(); ++i)
    for (const auto& v : tool.vertices) {
      const ddf::Vec3 before = original.poses[i].pose * v, after = path.poses[i].pose * v;
      worstBefore = std::max(worstBefore, exact.height(before.x(), before.y()) - before.z());
      worstAfter = std::max(worstAfter, exact.height(after.x(), after.y()) - after.z());
    }
  EXPECT_GT(worstBefore, 0.5);
  // Rim vertices lie half a grid cell beyond the outermost sampled ray (slope <= 0.26).
  EXPECT_LT(worstAfter, 0.26 * 0.1 + 1e-3);
}

TEST(PenetrationCorrection, EveryKthPoseWithCheckAgreesWithEveryPose) {
  const auto part = trough(+1.0);
  const auto tool = roll();
  ToolPath all = turningRollPath(101), sparse = turningRollPath(101);
  const auto exact = correctPenetrations(part.ddf, tool, all);
  PenetrationCorrectionParams p;
  p.every = 25;
  const auto fast = correctPenetrations(part.ddf, tool, sparse, p);
  EXPECT_EQ(fast.exactPoses, 5);
  EXPECT_EQ(fast.checkedPoses, 96);
  EXPECT_LE(fast.maxResidualMm, p.toleranceMm);
  for (int i = 0; i <= 100; ++i) {
    // Never below the exact lift by more than the tolerance; above it only by the chord of a
    // smooth lift curve between exact poses.
    EXPECT_GE(fast.liftMm[i], exact.liftMm[i] - p.toleranceMm - 1e-9) << i;
    EXPECT_LE(fast.liftMm[i], exact.liftMm[i] + 0.05) << i;
  }
}

TEST(PenetrationCorrection, RejectsBadParameters) {
  const auto part = trough(+1.0);
  ToolPath path = turningRollPath(3);
  PenetrationCorrectionParams p;
  p.every = 0;
  EXPECT_THROW(correctPenetrations(part.ddf, roll(), path, p), InvalidInput);
  p = {};
  p.normals.resize(2);
  EXPECT_THROW(correctPenetrations(part.ddf, roll(), path, p), InvalidInput);
  EXPECT_THROW(correctPenetrations(part.ddf, ddf::TriangleMesh{}, path), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
