// SPDX-License-Identifier: MIT
// Tests of the overcut inspection: on a z-map (normals +z, so the depth below the design is
// (h_design - h) L exactly) the largest overcut and the pose that made it equal a brute-force
// comparison of the whole part after every pose, also after seeking back and forth.
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/cut_inspection.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

constexpr double kLengthMm = 1.0;
constexpr double kDesignZ = -0.05;  // the design 0.05 mm below the stock
constexpr double kRasterMm = 2.5 / 8;  // 2.5 mm cells at m = 9

ddf::DisplacementField design() {
  ddf::DisplacementField d = test::zmap(20.0, 10.0, 8, 4, 9, kLengthMm);
  std::fill(d.allHeights().begin(), d.allHeights().end(), static_cast<float>(kDesignZ / kLengthMm));
  return d;
}

// A ball of radius 1 along y = 5 whose bottom dips to z = -0.3 at poses 12..14 and stays at
// z = -0.04 (inside the design's tolerance) elsewhere.
ToolPath dippingPath() {
  ToolPath path;
  path.name = "dips";
  for (int i = 0; i < 30; ++i) {
    const double bottom = (i >= 12 && i <= 14) ? -0.3 + 0.05 * (i - 12) : -0.04;
    const double x = 3.125 + kRasterMm * i;  // on raster points
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    p.translation() = ddf::Vec3(x, 5.0, bottom + 1.0);
    path.poses.push_back({p, ddf::Vec3(x, 5.0, bottom)});
  }
  return path;
}

// Brute force: the deepest point of the whole part below the design after the poses cut.
double deepestBelowDesign(const ddf::DisplacementField& work) {
  double deepest = 0.0;
  for (float h : work.allHeights()) deepest = std::max(deepest, (kDesignZ - h * kLengthMm));
  return deepest;
}

TEST(CutInspection, LargestOvercutAndItsPoseEqualABruteForceComparison) {
  const ToolMeshes ball{makeSphereTool(1.0, 12, 24), {}};
  const ToolPath path = dippingPath();
  GrindingSimulation simulation(test::zmap(20.0, 10.0, 8, 4, 9, kLengthMm), ball, path);
  CutInspection inspection(design(), 0.01);
  double deepest = 0.0;
  int deepestPose = -1, overcut = 0;
  for (int k = 0; k < 30; ++k) {
    simulation.advance(1);
    inspection.follow(simulation);
    const double now = deepestBelowDesign(simulation.workpiece());
    if (now > deepest + 1e-9) deepest = now, deepestPose = k;
    overcut += (k >= 12 && k <= 14) ? 1 : 0;
    const auto largest = inspection.largest();
    if (deepestPose < 0) {
      EXPECT_FALSE(largest) << "pose " << k;
      continue;
    }
    ASSERT_TRUE(largest) << "pose " << k;
    EXPECT_NEAR(largest->depthMm, deepest, 1e-6) << "pose " << k;
    EXPECT_EQ(largest->pose, deepestPose) << "pose " << k;
    EXPECT_EQ(inspection.overcutPoses(), overcut) << "pose " << k;
  }
  // The ball at z = -0.3 reaches 0.25 mm below the design at the raster point under it.
  EXPECT_NEAR(inspection.largest()->depthMm, 0.25, 1e-6);
  EXPECT_EQ(inspection.largest()->pose, 12);
  EXPECT_NEAR(inspection.largest()->point.z(), kDesignZ, 1e-9);
  // Back to pose 13 (poses 0..12 cut) and forward again: the same figures.
  simulation.seek(13);
  inspection.follow(simulation);
  EXPECT_EQ(inspection.poses(), 13);
  EXPECT_EQ(inspection.overcutPoses(), 1);
  simulation.seek(10);
  inspection.follow(simulation);
  EXPECT_FALSE(inspection.largest());
  simulation.seek(30);  // 20 poses at once: each is inspected with the heights it left
  inspection.follow(simulation);
  EXPECT_EQ(inspection.overcutPoses(), 3);
  EXPECT_EQ(inspection.largest()->pose, 12);
  EXPECT_THROW(CutInspection(design(), -1.0), InvalidInput);
}

TEST(CutInspection, TheLiveSimulationPublishesTheInspection) {
  const ToolMeshes ball{makeSphereTool(1.0, 12, 24), {}};
  LiveSimulationParams params;
  params.displayEpsMm = 0.01;
  params.designHeights = design().allHeights();
  LiveSimulation live(test::zmap(20.0, 10.0, 8, 4, 9, kLengthMm), ball, dippingPath(), params);
  EXPECT_TRUE(live.latestFrame()->inspected);
  EXPECT_FALSE(live.latestFrame()->largestOvercut);
  live.seek(20);
  ASSERT_TRUE(live.latestFrame()->largestOvercut);
  EXPECT_EQ(live.latestFrame()->largestOvercut->pose, 12);
  EXPECT_EQ(live.latestFrame()->overcutPoses, 3);
  live.seek(5);
  EXPECT_FALSE(live.latestFrame()->largestOvercut);
  params.designHeights.pop_back();
  EXPECT_THROW(LiveSimulation(test::zmap(20.0, 10.0, 8, 4, 9, kLengthMm), ball, dippingPath(),
                              params),
               InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
