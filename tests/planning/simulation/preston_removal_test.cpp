// SPDX-License-Identifier: MIT
// Tests of the Preston removal model: the conservation check of the oracles note.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/simulation/preston_removal.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "../../support/removed_cross_section.h"

namespace ddfcam::planning {
namespace {

constexpr double kPlaneZ = 0.25;

ddf::GeneratedSurface plane() {
  return ddf::planePatch(
      {.size = {40.0, 30.0}, .cellsX = 20, .cellsY = 15, .m = 17, .planeZMm = kPlaneZ});
}

/// One straight pass along x at y = 15 with contact step 0.1 mm; @p ball or a roll across.
ToolPath straightPass(bool ball) {
  ToolPath path;
  const ddf::Vec3 n(0, 0, 1);
  for (double x = 8.0; x <= 32.0 + 1e-9; x += 0.1) {
    const ddf::Vec3 c(x, 15.0, kPlaneZ);
    Eigen::Isometry3d pose = rollPoseAtContact(c, n, {1, 0, 0}, 5.0, 0.0);
    if (ball) pose = Eigen::Translation3d(c + 5.0 * n) * Eigen::Isometry3d::Identity();
    path.poses.push_back({pose, c});
  }
  path.passStarts = {0};
  return path;
}

double crossSectionAtMid(const ddf::DisplacementField& field) {
  return test::removedCrossSection(field, 20.0, kPlaneZ);
}

TEST(PrestonRemoval, RemovedCrossSectionIsKpFVsOverVfForBallAndRoll) {
  const ddf::TriangleMesh ball = makeSphereTool(5.0, 48, 96);
  const ddf::TriangleMesh roll =
      makeCylinderTool({.radiusMm = 5.0, .widthMm = 6.0, .segments = 128});
  for (const bool isBall : {true, false})
    for (const double force : {10.0, 40.0}) {
      auto part = plane();
      PrestonParams p;
      p.forceN = force;
      p.feedMmPerS = 5.0;
      p.infeedMm = 0.2;
      p.normals.assign(straightPass(isBall).poses.size(), ddf::Vec3::UnitZ());
      const PrestonReport report =
          applyPrestonRemoval(part.ddf, isBall ? ball : roll, straightPass(isBall), p);
      const double expected =
          p.prestonCoefficientMm2PerN * force * p.surfaceSpeedMmPerS / p.feedMmPerS;
      const double measured = crossSectionAtMid(part.ddf);
      EXPECT_NEAR(measured, expected, 0.01 * expected) << (isBall ? "ball " : "roll ") << force;
      EXPECT_EQ(report.posesWithoutContact, 0);
      // Contact patches: a disc of radius sqrt(2 R i) for the ball, a 6 mm wide strip for the roll.
      const double patch = report.contactAreaMm2[report.contactAreaMm2.size() / 2];
      EXPECT_GT(patch, isBall ? 0.5 * 3.14159 * 2.0 : 6.0 * 2.0 * std::sqrt(2.0 * 5.0 * 0.2) * 0.5);
      // The removal stays far inside the crust.
      EXPECT_LT(*std::max_element(report.maxDepthMm.begin(), report.maxDepthMm.end()), 0.05);
    }
}

TEST(PrestonRemoval, RejectsBadParameters) {
  auto part = plane();
  PrestonParams p;
  p.forceN = 0.0;
  EXPECT_THROW(applyPrestonRemoval(part.ddf, makeSphereTool(5.0, 8, 16), straightPass(true), p),
               InvalidInput);
  EXPECT_THROW(applyPrestonRemoval(part.ddf, ddf::TriangleMesh{}, straightPass(true)),
               InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
