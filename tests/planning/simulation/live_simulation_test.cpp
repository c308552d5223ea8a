// SPDX-License-Identifier: MIT
// Tests of the live simulation: the state and the published display mesh at a pose are those
// of a fresh simulation of the poses before it and a fresh triangulation of its heights,
// whether the pose was reached by playing, stepping or seeking; the set rate is never exceeded.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kEps = 0.002;

ddf::DisplacementField stock() {
  return test::zmap(20.0, 10.0, 8, 4, 9, 1.0);
}

// A ball of radius 1 mm sinking 0.3 mm into the plane along two passes in x.
ToolPath groovePath(int poses) {
  ToolPath path;
  path.name = "grooves";
  path.passStarts = {0, poses / 2};
  for (int i = 0; i < poses; ++i) {
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    const double y = i < poses / 2 ? 3.0 : 7.0;
    const double x = 2.0 + 16.0 * (i % (poses / 2)) / (poses / 2 - 1.0);
    p.translation() = Vec3(x, y, 1.0 - 0.3);
    path.poses.push_back({p, Vec3(x, y, -0.3)});
  }
  return path;
}

ToolMeshes ball() {
  return {makeSphereTool(1.0, 12, 24), {}};
}

LiveSimulationParams liveParams(double posesPerSecond) {
  LiveSimulationParams p;
  p.displayEpsMm = kEps;
  p.posesPerSecond = posesPerSecond;
  return p;
}

// Heights after a fresh simulation of the first @p poses poses.
std::vector<float> freshHeights(int poses, const ToolPath& path) {
  ToolPath head = path;
  head.poses.resize(static_cast<std::size_t>(poses));
  std::erase_if(head.passStarts, [&](int s) { return s >= poses; });
  ddf::DisplacementField work = stock();
  if (poses > 0) simulateGrinding(work, ball(), head);
  return work.allHeights();
}

// The frame's triangles per face equal a fresh triangulation of @p heights, corner by corner
// (with per-face bounds @p faceEps if given).
::testing::AssertionResult frameIsFreshMesh(const LiveFrame& frame,
                                            const std::vector<float>& heights,
                                            const std::vector<float>& faceEps = {}) {
  ddf::DisplacementField field = stock();
  field.allHeights() = heights;
  ddf::AdaptiveTriangulationParams params;
  params.epsMm = kEps;
  params.faceEpsMm = faceEps;
  const ddf::AdaptiveTriangulation fresh = ddf::triangulateAdaptiveWithStats(field, params);
  if (fresh.mesh.triangles.size() * 3 != frame.triangles.size())
    return ::testing::AssertionFailure() << frame.triangles.size() / 3 << " triangles, fresh "
                                         << fresh.mesh.triangles.size();
  for (std::size_t t = 0; t < fresh.mesh.triangles.size(); ++t) {
    if (fresh.triangleFace[t] != frame.triangleFace[t])
      return ::testing::AssertionFailure() << "triangle " << t << " in another face";
    for (int c = 0; c < 3; ++c) {
      const Vec3& expected = fresh.mesh.vertices[fresh.mesh.triangles[t][c]];
      const int slot = frame.triangles[3 * t + c];
      for (int a = 0; a < 3; ++a)
        if (frame.positions[3 * slot + a] != static_cast<float>(expected[a]))
          return ::testing::AssertionFailure() << "triangle " << t << " corner " << c;
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(LiveSimulation, PlayingPausingSteppingAndSeekingGiveTheStateOfThatPose) {
  const ToolPath path = groovePath(40);
  LiveSimulation live(stock(), ball(), path, liveParams(0.0));
  ASSERT_TRUE(live.play());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  live.pause();
  EXPECT_FALSE(live.isPlaying());
  const int paused = live.simulation().nextPose();
  auto frame = live.latestFrame();
  EXPECT_EQ(frame->posesCut, paused);
  EXPECT_EQ(live.simulation().workpiece().allHeights(), freshHeights(paused, path));
  EXPECT_TRUE(frameIsFreshMesh(*frame, freshHeights(paused, path)));
  if (paused < 40) {
    ASSERT_TRUE(live.step());
    EXPECT_EQ(live.latestFrame()->posesCut, paused + 1);
    EXPECT_EQ(live.simulation().workpiece().allHeights(), freshHeights(paused + 1, path));
  }
  for (const int k : {25, 3, 20, 0, 40}) {
    live.seek(k);
    frame = live.latestFrame();
    ASSERT_EQ(frame->posesCut, k);
    const std::vector<float> expected = freshHeights(k, path);
    EXPECT_EQ(live.simulation().workpiece().allHeights(), expected) << "seek to " << k;
    EXPECT_TRUE(frameIsFreshMesh(*frame, expected)) << "seek to " << k;
    EXPECT_EQ(frame->report.posesCut, k);
  }
  EXPECT_TRUE(live.finished());
  EXPECT_FALSE(live.play());
  EXPECT_THROW(live.seek(41), InvalidInput);
}

TEST(LiveSimulation, PlaysToTheEndAndPublishesTheFinalState) {
  const ToolPath path = groovePath(30);
  LiveSimulation live(stock(), ball(), path, liveParams(0.0));
  ASSERT_TRUE(live.play());
  for (int wait = 0; wait < 1000 && live.isPlaying(); ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(live.finished());
  EXPECT_EQ(live.takeError(), nullptr);
  const auto frame = live.latestFrame();
  EXPECT_EQ(frame->posesCut, 30);
  EXPECT_EQ(frame->report.passes.size(), 2u);
  EXPECT_GT(frame->report.removedVolumeMm3, 0.0);
  EXPECT_TRUE(frameIsFreshMesh(*frame, freshHeights(30, path)));
}

TEST(LiveSimulation, NeverCutsFasterThanTheSetRate) {
  const ToolPath path = groovePath(200);
  LiveSimulation live(stock(), ball(), path, liveParams(50.0));
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(live.play());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  live.pause();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // At 50 poses/s: the first pose at once, then one every 20 ms, and at most kMaxCredit owed.
  EXPECT_LE(live.simulation().nextPose(), 1 + static_cast<int>(50.0 * seconds) + 2);
  EXPECT_GE(live.simulation().nextPose(), 1);
  EXPECT_THROW(LiveSimulation(stock(), ball(), path, liveParams(0.0)).seek(-1),
               InvalidInput);
}

// A view-dependent level of detail: from far away the display is coarser, and it is exactly
// the fresh triangulation with the bounds the view gives; over the triangle budget the pixel
// error is raised.
TEST(LiveSimulation, AViewSetsTheLevelOfDetailWithinTheTriangleBudget) {
  const ToolPath path = groovePath(20);
  LiveSimulation live(stock(), ball(), path, liveParams(0.0));
  live.seek(12);
  const std::size_t uniform = live.latestFrame()->triangleFace.size();
  ddf::ViewBoundsParams view;
  view.eyeMm = Vec3(10.0, 5.0, 400.0);  // 400 mm above the 20 x 10 mm patch
  view.direction = -Vec3::UnitZ();
  view.viewAngleDeg = 30.0;
  view.viewportHeightPx = 600;
  view.pixelError = 0.5;
  live.setView(view);
  auto frame = live.latestFrame();
  EXPECT_DOUBLE_EQ(frame->viewPixelError, 0.5);
  EXPECT_LT(frame->triangleFace.size(), uniform);
  ddf::ViewBoundsParams bounds = view;
  bounds.minEpsMm = kEps;
  bounds.maxEpsMm = kEps * 128.0;
  const std::vector<float> faceEps =
      ddf::viewDependentBounds(live.simulation().workpiece(), bounds);
  EXPECT_TRUE(frameIsFreshMesh(*frame, freshHeights(12, path), faceEps));
  // Cutting on under the view keeps its bounds.
  live.seek(20);
  EXPECT_TRUE(frameIsFreshMesh(*live.latestFrame(), freshHeights(20, path), faceEps));
  // A budget below the coarsest mesh: the pixel error is raised to its limit of 16 times.
  LiveSimulationParams tight = liveParams(0.0);
  tight.triangleBudget = 10;
  LiveSimulation budget(stock(), ball(), path, tight);
  budget.setView(view);
  EXPECT_DOUBLE_EQ(budget.latestFrame()->viewPixelError, 8.0);
  view.viewportHeightPx = 0;
  EXPECT_THROW(live.setView(view), InvalidInput);
}

TEST(LiveSimulation, RejectsANonPositiveDisplayBound) {
  LiveSimulationParams p;
  p.displayEpsMm = 0.0;
  EXPECT_THROW(LiveSimulation(stock(), ball(), groovePath(4), p), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
