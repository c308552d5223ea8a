// SPDX-License-Identifier: MIT
// Tests of the grinding simulation against analytic grooves, brute-force z-maps and the
// V-convexity and collision situations of sec. 8.4-8.5.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
constexpr double kPi = std::numbers::pi;

/// Simulation parameters without designated initializers (which warn about the rest).
GrindingSimulationParams simParams(SweepMode mode, bool checkVConvexity = true) {
  GrindingSimulationParams p;
  p.mode = mode;
  p.checkVConvexity = checkVConvexity;
  return p;
}

/// An empty path named @p name with one pass starting at pose 0.
ToolPath namedPath(const char* name) {
  ToolPath p;
  p.name = name;
  p.passStarts = {0};
  return p;
}

using test::zmap;

/// Calls fn(x, y, z) for every stored raster point of a z-map with vector length L.
template <class Fn>
void forEachPoint(const ddf::DisplacementField& f, double lengthMm, Fn&& fn) {
  for (int face = 0; face < f.faceCount(); ++face)
    for (int k = 0; k < f.resolution(); ++k)
      for (int i = 0; i + k < f.resolution(); ++i) {
        const Vec3 g = f.basePoint(face, f.rasterBary(i, k));
        fn(g.x(), g.y(), f.height(face, i, k) * lengthMm);
      }
}

ToolPath linePath(const Vec3& from, const Vec3& to, int poses) {
  ToolPath path = namedPath("line");
  for (int s = 0; s < poses; ++s) {
    PathPose p;
    p.pose.translation() = from + (to - from) * (poses == 1 ? 0.0 : double(s) / (poses - 1));
    path.poses.push_back(p);
  }
  return path;
}

/// Ball slot oracle (oracles.md "Material removal").
double slotArea(double r, double d) {
  return r * r * std::acos((r - d) / r) - (r - d) * std::sqrt(2.0 * r * d - d * d);
}

struct BallGroove {
  static constexpr double R = 2.0, d = 0.8, L = 12.0, y0 = 6.0;
  ToolMeshes ball{planning::makeSphereTool(R, 16, 32), {}};
  ddf::DisplacementField run(SweepMode mode, int poses, GrindingReport* report = nullptr) const {
    ddf::DisplacementField part = zmap(20.0, 12.0, 20, 12, 9, 2.0);  // 0.125 mm raster
    const GrindingSimulationParams params = simParams(mode, false);
    const ToolPath path = linePath({4.0, y0, R - d}, {4.0 + L, y0, R - d}, poses);
    const GrindingReport r = simulateGrinding(part, ball, path, params);
    if (report) *report = r;
    return part;
  }
};

TEST(GrindingSimulation, SweptBallSlotDoesNotDependOnTheSamplingStep) {
  const BallGroove groove;
  const ddf::DisplacementField coarse = groove.run(SweepMode::Swept, 3);
  const ddf::DisplacementField fine = groove.run(SweepMode::Swept, 300);
  const ddf::DisplacementField discrete = groove.run(SweepMode::Discrete, 3);
  double sweptDiff = 0.0, discreteDiff = 0.0;
  for (std::size_t i = 0; i < fine.allHeights().size(); ++i) {
    sweptDiff =
        std::max(sweptDiff, double(std::abs(coarse.allHeights()[i] - fine.allHeights()[i])));
    discreteDiff =
        std::max(discreteDiff, double(std::abs(discrete.allHeights()[i] - fine.allHeights()[i])));
  }
  // Heights are in units of L = 2 mm.
  EXPECT_LT(2.0 * sweptDiff, 1e-4) << "swept groove changed with the sampling step";
  EXPECT_GT(2.0 * discreteDiff, 0.5) << "3 discrete balls 6 mm apart must leave ridges";
}

TEST(GrindingSimulation, SweptBallSlotMatchesTheAnalyticCrossSectionAndVolume) {
  const BallGroove groove;
  GrindingReport report;
  const ddf::DisplacementField part = groove.run(SweepMode::Swept, 3, &report);
  const double R = BallGroove::R, d = BallGroove::d;
  // Faceted ball (32 segments, 16 rings): within ~R (1 - cos(pi / 16)) of the true sphere.
  const double facet = R * (1.0 - std::cos(kPi / 16.0)) + 1e-5;
  int inside = 0;
  forEachPoint(part, 2.0, [&](double x, double y, double z) {
    if (x < 6.0 || x > 14.0) return;  // the straight part, away from the end caps
    const double r = std::abs(y - BallGroove::y0);
    const double expected = r < R ? std::min(0.0, -d + R - std::sqrt(R * R - r * r)) : 0.0;
    EXPECT_NEAR(z, expected, facet) << "at (" << x << ", " << y << ")";
    inside += expected < -facet;
  });
  EXPECT_GT(inside, 500);
  const double volume = slotArea(R, d) * BallGroove::L + kPi * d * d * (3.0 * R - d) / 3.0;
  // Quadrature and faceting: the rim (length ~2 L + 2 pi c) smeared over one raster step.
  const double c = std::sqrt(2.0 * R * d - d * d);
  const double tolerance =
      (2.0 * BallGroove::L + 2.0 * kPi * c) * 0.125 * 0.125 + facet * 2 * c * 16;
  EXPECT_NEAR(report.removedVolumeMm3, volume, tolerance);
  ASSERT_EQ(report.passes.size(), 1u);
  EXPECT_EQ(report.passes[0].poseCount, 3);
  EXPECT_DOUBLE_EQ(report.passes[0].removedVolumeMm3, report.removedVolumeMm3);
  EXPECT_EQ(report.posesCut, 3);
}

/// Roll of radius 5, width 10, axis x, 48 segments (a vertex line at the bottom).
ToolMeshes roll() {
  return {planning::makeCylinderTool({.radiusMm = 5.0, .widthMm = 10.0, .segments = 48}), {}};
}

TEST(GrindingSimulation, StraightRollPassCutsAFlatBottomedGrooveOfTheAnalyticVolume) {
  // Roll axis x, fed along y over 6 mm at depth d; two passes at different x and depths.
  const double R = 5.0, W = 10.0, feed = 6.0;
  const double depth[2] = {0.5, 0.3};
  const double xc[2] = {8.0, 22.0};
  ddf::DisplacementField part = zmap(30.0, 20.0, 15, 10, 17, 1.0);  // 0.125 mm raster
  ToolPath path = namedPath("two passes");
  path.passStarts.clear();
  for (int p = 0; p < 2; ++p) {
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    const ToolPath pass =
        linePath({xc[p], 7.0, R - depth[p]}, {xc[p], 7.0 + feed, R - depth[p]}, 4);
    path.poses.insert(path.poses.end(), pass.poses.begin(), pass.poses.end());
  }
  const GrindingReport report =
      simulateGrinding(part, roll(), path, simParams(SweepMode::Swept, false));
  forEachPoint(part, 1.0, [&](double x, double y, double z) {
    for (int p = 0; p < 2; ++p) {
      const double c = std::sqrt(2.0 * R * depth[p] - depth[p] * depth[p]);
      if (std::abs(x - xc[p]) < W / 2 - 0.01 && y > 7.0 && y < 7.0 + feed) {
        EXPECT_NEAR(z, -depth[p], 1e-5) << "flat bottom at (" << x << ", " << y << ")";
      }
      if (std::abs(x - xc[p]) > W / 2 + 0.01 && std::abs(x - xc[p]) < W / 2 + 1.5) {
        EXPECT_EQ(z, 0.0) << "beside the roll at (" << x << ", " << y << ")";
      }
      // Groove length along the feed: feed + 2 sqrt(2 R d - d^2).
      const bool underRoll = std::abs(x - xc[p]) < W / 2 - 0.01;
      if (underRoll && (y < 7.0 - c - 0.05 || y > 7.0 + feed + c + 0.05)) {
        EXPECT_EQ(z, 0.0) << "beyond the groove end at (" << x << ", " << y << ")";
      }
      if (underRoll && std::abs(y - (7.0 - c / 2)) < 0.0625) {
        EXPECT_LT(z, 0.0) << "inside the entry arc at (" << x << ", " << y << ")";
      }
    }
  });
  ASSERT_EQ(report.passes.size(), 2u);
  for (int p = 0; p < 2; ++p) {
    const double d = depth[p], c = std::sqrt(2.0 * R * d - d * d);
    // Cross-section of the swept region below z = 0: d x feed plus the circular segment.
    const double volume = W * (d * feed + slotArea(R, d));
    // Rim smeared over one raster step, plus the 48-gon's deficit of the segment area.
    const double tolerance =
        2.0 * (W + feed + 2 * c) * 0.125 * d + W * 2 * c * R * (1 - std::cos(kPi / 48));
    EXPECT_NEAR(report.passes[p].removedVolumeMm3, volume, tolerance) << "pass " << p;
    EXPECT_EQ(report.passes[p].poseCount, 4);
  }
  EXPECT_NEAR(report.removedVolumeMm3,
              report.passes[0].removedVolumeMm3 + report.passes[1].removedVolumeMm3, 1e-9);
}

TEST(GrindingSimulation, ZMapCutEqualsABruteForceZMap) {
  // A tilted roll at a few poses: the DDF on a planar support with constant vectors is a z-map,
  // so each height must be min(stock, lowest hit of the vertical line with the posed mesh).
  const double L = 2.0;
  ddf::DisplacementField part = zmap(16.0, 12.0, 8, 6, 9, L);
  const ToolMeshes tool = roll();
  ToolPath path = namedPath("tilted");
  for (int s = 0; s < 4; ++s) {
    PathPose p;
    p.pose = Eigen::Translation3d(5.0 + 2.0 * s, 6.0 + 0.3 * s, 4.4 + 0.1 * s) *
             Eigen::AngleAxisd(0.2 + 0.1 * s, Vec3::UnitZ()) *
             Eigen::AngleAxisd(0.15, Vec3::UnitY());
    path.poses.push_back(p);
  }
  const ddf::DisplacementField stock = part;
  simulateGrinding(part, tool, path, simParams(SweepMode::Discrete, false));
  int lowered = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k < part.resolution(); ++k)
      for (int i = 0; i + k < part.resolution(); ++i) {
        const Vec3 g = part.basePoint(f, part.rasterBary(i, k));
        double z = stock.height(f, i, k) * L;
        for (const PathPose& p : path.poses)
          for (const auto& t : tool.cutting.triangles) {
            const Vec3 a = p.pose * tool.cutting.vertices[t[0]],
                       b = p.pose * tool.cutting.vertices[t[1]],
                       c = p.pose * tool.cutting.vertices[t[2]];
            const Vec3 n = (b - a).cross(c - a);
            if (n.z() >= 0.0) continue;  // entry faces only: their outward normal points down
            // Barycentric test in the xy projection.
            const double det =
                (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
            const double u =
                ((g.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (g.y() - a.y())) / det;
            const double w =
                ((b.x() - a.x()) * (g.y() - a.y()) - (g.x() - a.x()) * (b.y() - a.y())) / det;
            if (u < 0.0 || w < 0.0 || u + w > 1.0) continue;
            z = std::min(z, std::max(-L, a.z() + u * (b.z() - a.z()) + w * (c.z() - a.z())));
          }
        EXPECT_NEAR(part.height(f, i, k) * L, z, 1e-5)
            << "face " << f << " (" << i << ", " << k << ")";
        lowered += z < 0.0;
      }
  EXPECT_GT(lowered, 300);
}

/// A mesh from @p mesh placed by @p pose.
ddf::TriangleMesh placed(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  return mesh.transformed(pose);
}

TEST(GrindingSimulation, BallTouchingFromAboveIsVConvex) {
  ddf::DisplacementField part = zmap(20.0, 12.0, 20, 12, 9, 2.0);
  const ToolMeshes ball{planning::makeSphereTool(2.0, 16, 32), {}};
  const GrindingReport report =
      simulateGrinding(part, ball, linePath({4.0, 6.0, 1.2}, {16.0, 6.0, 1.2}, 7));
  EXPECT_TRUE(report.vConvexity.empty()) << report.vConvexity.size() << " poses reported";
  EXPECT_EQ(report.vConvexityStubbles, 0u);
  EXPECT_GT(report.pointsLowered, 0u);
}

TEST(GrindingSimulation, DrillAt60DegreesToVAndABuriedCutterViolateVConvexity) {
  const double L = 2.0;
  // Drill: radius 1, length 6, axis 60 degrees from the vertical, lower end 1.5 mm deep.
  const ddf::TriangleMesh cylinder =
      planning::makeCylinderTool({.radiusMm = 1.0, .widthMm = 6.0, .segments = 32});
  const Eigen::Isometry3d tilt(Eigen::AngleAxisd(-kPi / 6.0, Vec3::UnitY()));  // +x end up
  const Vec3 lowEnd = tilt * Vec3(-3.0, 0.0, 0.0);
  ToolPath drill = linePath(Vec3(10.0, 6.0, -1.5) - lowEnd, Vec3(10.0, 6.0, -1.5) - lowEnd, 1);
  drill.poses[0].pose.linear() = tilt.linear();
  ddf::DisplacementField part = zmap(20.0, 12.0, 20, 12, 9, L);
  const GrindingReport drilled = simulateGrinding(part, {cylinder, {}}, drill);
  ASSERT_EQ(drilled.vConvexity.size(), 1u);
  EXPECT_EQ(drilled.vConvexity[0].pose, 0);
  EXPECT_GT(drilled.vConvexity[0].stubbles, 20u);

  // Cutter plunged sideways under the surface: a horizontal cylinder of radius 0.5 and width 4
  // whose top is 0.7 mm deep: every stubble through it has material above the tool.
  ddf::DisplacementField part2 = zmap(20.0, 12.0, 20, 12, 9, L);
  const ddf::TriangleMesh bar =
      planning::makeCylinderTool({.radiusMm = 0.5, .widthMm = 4.0, .segments = 32});
  const GrindingReport buried =
      simulateGrinding(part2, {bar, {}}, linePath({10.0, 6.0, -1.2}, {10.0, 6.0, -1.2}, 1));
  ASSERT_EQ(buried.vConvexity.size(), 1u);
  // Shadow 4 x 1 mm over raster points of 1/64 mm^2 each: ~256 distinct points.
  EXPECT_GT(buried.vConvexity[0].stubbles, 200u);
  EXPECT_LT(buried.vConvexity[0].stubbles, 320u);
}

TEST(GrindingSimulation, ShankBelowTheSurfaceCollidesOnlyAtTheDeepPoses) {
  // Ball-end: ball R = 2 with the tip at the origin, shank radius 1 from z = 2 to z = 10.
  const Eigen::Isometry3d up =
      Eigen::Translation3d(0.0, 0.0, 6.0) * Eigen::AngleAxisd(kPi / 2.0, Vec3::UnitY());
  const ToolMeshes tool{
      placed(planning::makeSphereTool(2.0, 16, 32),
             Eigen::Isometry3d(Eigen::Translation3d(0, 0, 2))),
      placed(planning::makeCylinderTool({.radiusMm = 1.0, .widthMm = 8.0, .segments = 32}), up)};
  ddf::DisplacementField part = zmap(20.0, 12.0, 20, 12, 9, 4.0);
  ToolPath path = namedPath("plunges");
  const double tipZ[3] = {-1.0, -3.0, -1.5};  // shank bottom at +1, -1, +0.5
  for (int s = 0; s < 3; ++s) {
    PathPose p;
    p.pose.translation() = Vec3(4.0 + 6.0 * s, 6.0, tipZ[s]);
    path.poses.push_back(p);
  }
  const GrindingReport report = simulateGrinding(part, tool, path);
  ASSERT_EQ(report.collisions.size(), 1u);
  EXPECT_EQ(report.collisions[0].pose, 1);
  // The shank's disc of radius 1 over raster points of 1/64 mm^2: ~200 points.
  EXPECT_GT(report.collisions[0].stubbles, 150u);
  EXPECT_LT(report.collisions[0].stubbles, 260u);
  // The shank never cuts: its footprint keeps the ball's cut, the bottom of the ball at -3.
  double lowest = 0.0;
  forEachPoint(part, 4.0, [&](double, double, double z) { lowest = std::min(lowest, z); });
  EXPECT_NEAR(lowest, -3.0, 1e-4);
}

TEST(GrindingSimulation, LibraryBallEndWithShankCollidesWhenPlungedDeep) {
  // toolMeshes(): ball R 2 with 2.5 mm of flutes above the tip, shank R 1.5 above them.
  const Tool cutter{.name = "ball end",
                    .kind = ToolKind::BallEnd,
                    .radiusMm = 2.0,
                    .widthMm = 2.5,
                    .shankRadiusMm = 1.5,
                    .shankLengthMm = 8.0,
                    .segments = 32};
  const ToolMeshes meshes = toolMeshes(cutter);
  ASSERT_FALSE(meshes.nonCutting.triangles.empty());
  ddf::DisplacementField part = zmap(30.0, 12.0, 30, 12, 9, 4.0);
  // Tips at -1 (flutes end at +1.5: shank clear), -3 (shank from -0.5: collides), -2 (+0.5).
  ToolPath path = namedPath("plunges");
  for (double z : {-1.0, -3.0, -2.0}) {
    PathPose p;
    p.pose.translation() = Vec3(5.0 + 9.0 * path.poses.size(), 6.0, z);
    path.poses.push_back(p);
  }
  const GrindingReport report = simulateGrinding(part, meshes, path);
  ASSERT_EQ(report.collisions.size(), 1u);
  EXPECT_EQ(report.collisions[0].pose, 1);
  EXPECT_GT(report.collisions[0].stubbles, 300u);  // pi 1.5^2 x 64 points per mm^2 ~ 450
  // At pose 1 the whole cutting part is under the surface too: material above its flutes.
  ASSERT_EQ(report.vConvexity.size(), 1u);
  EXPECT_EQ(report.vConvexity[0].pose, 1);
}

TEST(GrindingSimulation, PlaybackInStepsEqualsOneShotAndSurvivesCancel) {
  const BallGroove groove;
  ddf::DisplacementField oneShot = zmap(20.0, 12.0, 20, 12, 9, 2.0);
  ToolPath path = linePath({4.0, 6.0, 1.2}, {16.0, 6.0, 1.2}, 10);
  path.passStarts = {0, 6};
  const GrindingSimulationParams params = simParams(SweepMode::Swept);
  const GrindingReport reference = simulateGrinding(oneShot, groove.ball, path, params);
  GrindingSimulation sim(zmap(20.0, 12.0, 20, 12, 9, 2.0), groove.ball, path, params);
  EXPECT_EQ(sim.advance(1), 1);
  EXPECT_EQ(sim.nextPose(), 1);
  EXPECT_THROW(sim.advance(-1, [](double f) { return f < 0.3; }), Cancelled);
  EXPECT_GT(sim.nextPose(), 1);
  EXPECT_FALSE(sim.finished());
  EXPECT_EQ(sim.report().posesCut, sim.nextPose());
  sim.advance(-1);
  EXPECT_TRUE(sim.finished());
  EXPECT_EQ(sim.advance(5), 0);
  EXPECT_TRUE(sim.workpiece().allHeights() == oneShot.allHeights());
  ASSERT_EQ(sim.report().passes.size(), 2u);
  EXPECT_EQ(sim.report().passes[1].firstPose, 6);
  for (int p = 0; p < 2; ++p)
    EXPECT_NEAR(sim.report().passes[p].removedVolumeMm3, reference.passes[p].removedVolumeMm3,
                1e-9);
  EXPECT_GT(reference.passes[1].removedVolumeMm3, 0.0);
}

TEST(GrindingSimulation, RejectsBadPassesAndNonConvexSweeps) {
  const ToolMeshes ball{planning::makeSphereTool(1.0, 8, 16), {}};
  ToolPath path = linePath({4.0, 6.0, 0.5}, {8.0, 6.0, 0.5}, 4);
  path.passStarts = {0, 3, 2};
  const ddf::DisplacementField part = zmap(20.0, 12.0, 4, 4, 5, 2.0);
  EXPECT_THROW(GrindingSimulation(part, ball, path), InvalidInput);
  path.passStarts = {0};
  ToolMeshes twoBalls = ball;
  const ddf::TriangleMesh other =
      placed(ball.cutting, Eigen::Isometry3d(Eigen::Translation3d(3.0, 0.0, 0.0)));
  const int offset = static_cast<int>(twoBalls.cutting.vertices.size());
  twoBalls.cutting.vertices.insert(twoBalls.cutting.vertices.end(), other.vertices.begin(),
                                   other.vertices.end());
  for (auto t : other.triangles)
    twoBalls.cutting.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  EXPECT_THROW(GrindingSimulation(part, twoBalls, path, simParams(SweepMode::Swept)), InvalidInput);
  EXPECT_NO_THROW(GrindingSimulation(part, twoBalls, path, simParams(SweepMode::Discrete)));
  EXPECT_THROW(GrindingSimulation(part, ToolMeshes{}, path), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
