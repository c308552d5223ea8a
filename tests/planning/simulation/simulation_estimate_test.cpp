// SPDX-License-Identifier: MIT
// Tests of estimateSimulation: the sample it times and the extrapolation to the whole path.
#include <ddfcam/planning/simulation/simulation_estimate.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

ToolPath linePath(int poses) {
  ToolPath path;
  path.name = "line";
  for (int i = 0; i < poses; ++i) {
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    p.translation() = ddf::Vec3(2.0 + 16.0 * i / (poses - 1.0), 5.0, 0.8);
    path.poses.push_back({p, ddf::Vec3(p.translation().x(), 5.0, -0.2)});
  }
  return path;
}

TEST(SimulationEstimate, TimesAnEvenSampleOnACopyAndExtrapolates) {
  const ddf::DisplacementField stock = test::zmap(20.0, 10.0, 8, 4, 9, 1.0);
  const ToolMeshes ball{makeSphereTool(1.0, 12, 24), {}};
  SimulationEstimateParams params;
  params.samplePoses = 8;
  const SimulationEstimate e = estimateSimulation(stock, ball, linePath(40), {}, params);
  EXPECT_EQ(e.poses, 40);
  EXPECT_EQ(e.sampled, 8);
  EXPECT_GT(e.secondsPerPose, 0.0);
  EXPECT_DOUBLE_EQ(e.seconds, 40 * e.secondsPerPose);
  // A path shorter than the sample is timed whole; an empty one costs nothing.
  EXPECT_EQ(estimateSimulation(stock, ball, linePath(5), {}, params).sampled, 5);
  const SimulationEstimate none = estimateSimulation(stock, ball, ToolPath{}, {}, params);
  EXPECT_EQ(none.sampled, 0);
  EXPECT_EQ(none.seconds, 0.0);
}

}  // namespace
}  // namespace ddfcam::planning
