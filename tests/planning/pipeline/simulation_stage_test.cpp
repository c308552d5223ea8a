// SPDX-License-Identifier: MIT
// Tests of the simulation stage: contact normals against the analytic cylinder normal, and
// penetration correction and Preston removal with normals that point away from the tool (as
// the CLI passes a file's) against the same with no normals (as the workbench passes), both
// checked against the plane's brute-force distance and the Preston formula.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/pipeline/simulation_stage.h>
#include <ddfcam/planning/placement/tool_orientation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "../../support/removed_cross_section.h"

namespace ddfcam::planning {
namespace {

constexpr double kPlaneZ = 0.25;

ddf::GeneratedSurface plane() {
  return ddf::planePatch(
      {.size = {40.0, 30.0}, .cellsX = 20, .cellsY = 15, .m = 17, .planeZMm = kPlaneZ});
}

Tool roll(double widthMm, int segments) {
  return {.name = "roll", .radiusMm = 5.0, .widthMm = widthMm, .segments = segments};
}

/// Every normal of @p path's poses: -z, pointing from the plane into the material.
std::vector<ddf::Vec3> awayFromTheTool(const ToolPath& path) {
  return std::vector<ddf::Vec3>(path.poses.size(), -ddf::Vec3::UnitZ());
}

TEST(SimulationStage, ContactNormalsPointFromTheCylinderToTheToolOutsideAndInABore) {
  const double radius = 20.0;
  const auto cylinder = ddf::cylinderPart(
      {.radiusMm = radius, .lengthMm = 30.0, .segments = 48, .rings = 10, .m = 9});
  const Tool tool = roll(10.0, 48);
  const ddf::TriangleMesh mesh = toolMesh(tool);
  for (const double side : {1.0, -1.0}) {  // tool outside (+1) or inside the bore (-1)
    ToolPath path;
    std::vector<ddf::Vec3> radial;  // the analytic normal towards the tool
    for (const double angle : {0.1, 1.3, 2.9, 4.4}) {
      const ddf::Vec3 out(std::cos(angle), std::sin(angle), 0.0);
      const ddf::Vec3 c = radius * out + ddf::Vec3(0, 0, 15.0);
      radial.push_back(side * out);
      path.poses.push_back({placeTool(tool, c, side * out, ddf::Vec3::UnitZ()), c});
    }
    // Missing normals come from the raster (its triangles deviate from radial by less than a
    // raster spacing's turn, 7.5 / 8 deg); given ones pointing away are turned, others kept.
    const std::vector<ddf::Vec3> fromSurface = contactNormals(cylinder.ddf, mesh, path);
    std::vector<ddf::Vec3> given = radial;
    given[0] = -radial[0];
    given[1] = 3.0 * (radial[1] + 0.1 * ddf::Vec3::UnitZ());
    given[2] = ddf::Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    const std::vector<ddf::Vec3> fromGiven = contactNormals(cylinder.ddf, mesh, path, given);
    ASSERT_EQ(fromSurface.size(), radial.size());
    ASSERT_EQ(fromGiven.size(), radial.size());
    const double cosTurn = std::cos(7.5 / 8.0 * std::numbers::pi / 180.0);
    for (std::size_t i = 0; i < radial.size(); ++i) {
      EXPECT_GT(fromSurface[i].dot(radial[i]), cosTurn) << side << " pose " << i;
      EXPECT_NEAR(fromSurface[i].norm(), 1.0, 1e-12);
    }
    EXPECT_LT((fromGiven[0] - radial[0]).norm(), 1e-12) << side;
    EXPECT_LT((fromGiven[1] - (radial[1] + 0.1 * ddf::Vec3::UnitZ()).normalized()).norm(), 1e-12);
    EXPECT_LT((fromGiven[2] - fromSurface[2]).norm(), 1e-12) << side;
    EXPECT_LT((fromGiven[3] - radial[3]).norm(), 1e-12) << side;
  }
  ToolPath one;
  one.poses.push_back({Eigen::Isometry3d::Identity(), ddf::Vec3(radius, 0, 15)});
  EXPECT_THROW(contactNormals(cylinder.ddf, mesh, one, {ddf::Vec3::UnitX(), ddf::Vec3::UnitX()}),
               InvalidInput);
  EXPECT_THROW(contactNormals(cylinder.ddf, ddf::TriangleMesh{}, one), InvalidInput);
}

/// A roll fed along x over the plane, the pose at contact (x, 15) sunk by depth[i] into it.
ToolPath sunkRolls(const Tool& tool, const std::vector<double>& depthMm) {
  ToolPath path;
  path.name = "sunk";
  for (std::size_t i = 0; i < depthMm.size(); ++i) {
    const ddf::Vec3 c(8.0 + 2.0 * static_cast<double>(i), 15.0, kPlaneZ);
    Eigen::Isometry3d pose = placeTool(tool, c, ddf::Vec3::UnitZ(), ddf::Vec3::UnitX());
    pose.pretranslate(-depthMm[i] * ddf::Vec3::UnitZ());
    path.poses.push_back({pose, c});
  }
  path.passStarts = {0};
  return path;
}

/// Lowest point of @p mesh at @p pose above the plane, mm (< 0: it penetrates).
double clearanceAbovePlane(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const ddf::Vec3& v : mesh.vertices) lowest = std::min(lowest, (pose * v).z());
  return lowest - kPlaneZ;
}

TEST(SimulationStage, CorrectionWithNormalsAwayFromTheToolMatchesNoneAndEndsThePenetration) {
  const auto goal = plane();
  const Tool tool = roll(10.0, 48);
  const ddf::TriangleMesh mesh = toolMesh(tool);
  const std::vector<double> depth{0.3, 0.0, 0.15, -0.2, 0.45, 0.05, 0.3, 0.2, -0.05, 0.4, 0.1};
  const ToolPath path = sunkRolls(tool, depth);
  for (const int every : {1, 3}) {
    PenetrationCorrectionParams params;
    params.every = every;
    const CorrectedPath workbench = correctPathPenetrations(goal.ddf, tool, path, params);
    params.normals = awayFromTheTool(path);
    const CorrectedPath cli = correctPathPenetrations(goal.ddf, tool, path, params);
    ASSERT_EQ(cli.path.poses.size(), path.poses.size());
    ASSERT_EQ(workbench.path.poses.size(), path.poses.size());
    // The z-buffer samples the inscribed 48-gon at cell centres, which lie above its lowest
    // vertex by at most R (1 - cos(pi / 48)): the lift may fall short of the depth by that.
    const double facetSag = tool.radiusMm * (1.0 - std::cos(std::numbers::pi / 48.0));
    for (std::size_t i = 0; i < path.poses.size(); ++i) {
      const Eigen::Isometry3d& a = cli.path.poses[i].pose;
      const Eigen::Isometry3d& b = workbench.path.poses[i].pose;
      EXPECT_LT((a.matrix() - b.matrix()).norm(), 1e-12) << "pose " << i << " every " << every;
      const double after = clearanceAbovePlane(mesh, a);
      EXPECT_GE(after, -facetSag - params.toleranceMm - 1e-9) << "pose " << i << " penetrates";
      // Exact lifts end the penetration and no more (interpolated ones may lift more).
      if (every == 1 && depth[i] > 0.0) {
        EXPECT_LE(after, 1e-9) << "pose " << i << " lifted more than the penetration";
      } else if (every == 1) {
        EXPECT_NEAR(after, -depth[i], 1e-9) << "pose " << i << " moved without penetrating";
      }
      // Lifted straight up, along the plane's normal towards the tool.
      const ddf::Vec3 moved = a.translation() - path.poses[i].pose.translation();
      EXPECT_LT(moved.head<2>().norm(), 1e-12) << "pose " << i;
      EXPECT_NEAR(moved.z(), cli.report.liftMm[i], 1e-12) << "pose " << i;
      EXPECT_TRUE(cli.path.poses[i].contact == path.poses[i].contact) << "pose " << i;
    }
    EXPECT_EQ(cli.report.penetratingPoses, workbench.report.penetratingPoses);
  }
}

double crossSectionAtMid(const ddf::DisplacementField& field) {
  return test::removedCrossSection(field, 20.0, kPlaneZ);
}

TEST(SimulationStage, PrestonWithNormalsAwayFromTheToolMatchesNoneAndThePrestonFormula) {
  const Tool tool = roll(6.0, 128);
  ToolPath path;
  for (int k = 0; k <= 240; ++k) {  // x from 8 to 32 mm at 0.1 mm steps
    const ddf::Vec3 c(8.0 + 0.1 * k, 15.0, kPlaneZ);
    path.poses.push_back({placeTool(tool, c, ddf::Vec3::UnitZ(), ddf::Vec3::UnitX()), c});
  }
  path.passStarts = {0};
  PrestonParams params;
  params.feedMmPerS = 5.0;
  params.infeedMm = 0.2;
  const PrestonStageResult workbench = prestonStage(plane().ddf, tool, path, params);
  params.normals = awayFromTheTool(path);
  const PrestonStageResult cli = prestonStage(plane().ddf, tool, path, params);
  const std::vector<float>& a = cli.workpiece.allHeights();
  const std::vector<float>& b = workbench.workpiece.allHeights();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], 1e-6) << "height " << i;
  // depth = K_p p v_s dt with dt = step / v_f at every inner pose of the pass.
  const double dt = 0.1 / params.feedMmPerS;
  const PrestonReport& r = cli.report;
  EXPECT_EQ(r.posesWithoutContact, 0);
  for (std::size_t p = 1; p + 1 < path.poses.size(); ++p) {
    const double expected =
        params.prestonCoefficientMm2PerN * r.maxPressure[p] * params.surfaceSpeedMmPerS * dt;
    ASSERT_GT(r.maxDepthMm[p], 0.0) << "pose " << p;
    EXPECT_NEAR(r.maxDepthMm[p], expected, 1e-6 * expected) << "pose " << p;
  }
  // Summed over a long pass: the cross-section K_p F v_s / v_f whatever the contact shape.
  const double section = params.prestonCoefficientMm2PerN * params.forceN *
                         params.surfaceSpeedMmPerS / params.feedMmPerS;
  EXPECT_NEAR(crossSectionAtMid(cli.workpiece), section, 0.01 * section);
}

}  // namespace
}  // namespace ddfcam::planning
