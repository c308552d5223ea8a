// SPDX-License-Identifier: MIT
// Tests of GrindingSimulation's timeline: seek() backwards and forwards against fresh runs of
// the truncated path, takeChangedFaces() against a brute-force diff, and the incremental pass
// volume against volumeBetween().
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/workpiece.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

using test::zmap;

/// The part of the timeline tests: 30 x 12 mm, 1 mm cells, raster 0.125 mm, crust +-2 mm
/// (so the plunge to -3 mm clamps).
const ddf::DisplacementField& stock() {
  static const ddf::DisplacementField part = zmap(30.0, 12.0, 30, 12, 9, 2.0);
  return part;
}

/// Library ball end (R 2, flutes to 2.5 mm above the tip, shank R 1.5 above): deep poses
/// collide with the shank and bury the flutes (V-convexity).
const ToolMeshes& ballEnd() {
  static const Tool cutter{.name = "ball end",
                           .kind = ToolKind::BallEnd,
                           .radiusMm = 2.0,
                           .widthMm = 2.5,
                           .shankRadiusMm = 1.5,
                           .shankLengthMm = 8.0,
                           .segments = 16};
  static const ToolMeshes meshes = toolMeshes(cutter);
  return meshes;
}

/// Appends a straight pass of @p poses tool-tip positions from @p from to @p to.
void addPass(ToolPath& path, const Vec3& from, const Vec3& to, int poses) {
  path.passStarts.push_back(static_cast<int>(path.poses.size()));
  for (int s = 0; s < poses; ++s) {
    PathPose p;
    p.pose.translation() = from + (to - from) * (double(s) / (poses - 1));
    path.poses.push_back(p);
  }
}

/// Three overlapping passes (so later passes lower heights earlier ones lowered), with one
/// plunge to -3 mm in the second pass, where the shank collides.
ToolPath threePasses() {
  ToolPath path;
  path.name = "three passes";
  addPass(path, {4.0, 6.0, -1.0}, {26.0, 6.0, -1.0}, 7);
  addPass(path, {26.0, 6.8, -2.0}, {4.0, 6.8, -2.0}, 6);
  path.poses[path.passStarts[1] + 2].pose.translation().z() = -3.0;
  addPass(path, {6.0, 5.5, -1.5}, {24.0, 5.5, -1.5}, 5);
  return path;
}

/// The first @p k poses of @p path with the pass starts among them.
ToolPath truncated(const ToolPath& path, int k) {
  ToolPath out = path;
  out.poses.resize(static_cast<std::size_t>(k));
  std::erase_if(out.passStarts, [k](int s) { return s >= k; });
  return out;
}

GrindingSimulationParams params(SweepMode mode) {
  GrindingSimulationParams p;
  p.mode = mode;
  return p;
}

/// A fresh one-shot run of the first @p k poses.
struct Fresh {
  ddf::DisplacementField part;
  GrindingReport report;
};
Fresh freshRun(const ToolPath& path, int k, SweepMode mode) {
  Fresh f{stock(), {}};
  f.report = simulateGrinding(f.part, ballEnd(), truncated(path, k), params(mode));
  return f;
}

void expectRelNear(double a, double b, double rel, const char* what) {
  EXPECT_LE(std::abs(a - b), rel * std::max(std::abs(a), std::abs(b)))
      << what << ": " << a << " vs " << b;
}

void expectSameReport(const GrindingReport& a, const GrindingReport& b) {
  EXPECT_EQ(a.posesCut, b.posesCut);
  ASSERT_EQ(a.passes.size(), b.passes.size());
  for (std::size_t p = 0; p < a.passes.size(); ++p) {
    EXPECT_EQ(a.passes[p].firstPose, b.passes[p].firstPose) << "pass " << p;
    EXPECT_EQ(a.passes[p].poseCount, b.passes[p].poseCount) << "pass " << p;
    expectRelNear(a.passes[p].removedVolumeMm3, b.passes[p].removedVolumeMm3, 1e-12, "pass");
  }
  expectRelNear(a.removedVolumeMm3, b.removedVolumeMm3, 1e-12, "total volume");
  EXPECT_EQ(a.pointsLowered, b.pointsLowered);
  EXPECT_EQ(a.pointsClamped, b.pointsClamped);
  ASSERT_EQ(a.vConvexity.size(), b.vConvexity.size());
  for (std::size_t i = 0; i < a.vConvexity.size(); ++i) {
    EXPECT_EQ(a.vConvexity[i].pose, b.vConvexity[i].pose);
    EXPECT_EQ(a.vConvexity[i].stubbles, b.vConvexity[i].stubbles);
  }
  EXPECT_EQ(a.vConvexityStubbles, b.vConvexityStubbles);
  ASSERT_EQ(a.collisions.size(), b.collisions.size());
  for (std::size_t i = 0; i < a.collisions.size(); ++i) {
    EXPECT_EQ(a.collisions[i].pose, b.collisions[i].pose);
    EXPECT_EQ(a.collisions[i].stubbles, b.collisions[i].stubbles);
  }
}

/// Poses to stop at: 0, inside the first pass, both later pass starts, just after one, the end.
std::vector<int> stops(const ToolPath& path) {
  const int n = static_cast<int>(path.poses.size());
  return {n, path.passStarts[2] + 1, path.passStarts[2], path.passStarts[1], 3, 0};
}

/// Heights after seek(k) from the end, seek(k) from 0, uneven advance() batches to k and a
/// fresh run of the first k poses, compared bit for bit. The checks do not change heights, so
/// they are off to keep the test fast.
void expectBitIdenticalTimelines(SweepMode mode) {
  const ToolPath path = threePasses();
  GrindingSimulationParams cutOnly = params(mode);
  cutOnly.checkVConvexity = cutOnly.checkCollisions = false;
  auto fresh = [&](int k) {
    ddf::DisplacementField part = stock();
    simulateGrinding(part, ballEnd(), truncated(path, k), cutOnly);
    return part.allHeights();
  };
  std::vector<int> ks = stops(path);  // descending
  std::vector<std::vector<float>> expected;
  for (int k : ks) expected.push_back(fresh(k));

  GrindingSimulation fromEnd(stock(), ballEnd(), path, cutOnly);
  fromEnd.advance(-1);
  for (std::size_t s = 0; s < ks.size(); ++s) {
    SCOPED_TRACE("k = " + std::to_string(ks[s]));
    fromEnd.seek(ks[s]);  // descending stops: always backwards
    EXPECT_EQ(fromEnd.nextPose(), ks[s]);
    EXPECT_TRUE(fromEnd.workpiece().allHeights() == expected[s]) << "back";
    GrindingSimulation forward(stock(), ballEnd(), path, cutOnly);
    forward.seek(ks[s]);
    EXPECT_TRUE(forward.workpiece().allHeights() == expected[s]) << "forward";
  }
  // Cutting again after going back to 0 reproduces the whole run.
  fromEnd.seek(ks.front());
  EXPECT_TRUE(fromEnd.workpiece().allHeights() == expected.front()) << "re-cut";
  // Back to 0 in one step, over the passes' overlaps.
  fromEnd.seek(0);
  EXPECT_TRUE(fromEnd.workpiece().allHeights() == stock().allHeights()) << "back to 0";

  GrindingSimulation batches(stock(), ballEnd(), path, cutOnly);
  int batch = 1;
  for (std::size_t s = ks.size(); s-- > 0;) {
    SCOPED_TRACE("batches to k = " + std::to_string(ks[s]));
    while (batches.nextPose() < ks[s])
      batches.advance(std::min(batch++, ks[s] - batches.nextPose()));
    EXPECT_TRUE(batches.workpiece().allHeights() == expected[s]);
  }
}

TEST(GrindingSimulationSeek, DiscreteSeekBatchesAndTruncatedRunsGiveBitIdenticalHeights) {
  expectBitIdenticalTimelines(SweepMode::Discrete);
}

TEST(GrindingSimulationSeek, SweptSeekBatchesAndTruncatedRunsGiveBitIdenticalHeights) {
  expectBitIdenticalTimelines(SweepMode::Swept);
}

TEST(GrindingSimulationSeek, ReportAfterSeekEqualsTheTruncatedRunsReport) {
  const ToolPath path = threePasses();
  const Fresh whole = freshRun(path, static_cast<int>(path.poses.size()), SweepMode::Discrete);
  // The path exercises every list of the report.
  ASSERT_EQ(whole.report.passes.size(), 3u);
  ASSERT_EQ(whole.report.collisions.size(), 1u);
  EXPECT_EQ(whole.report.collisions[0].pose, path.passStarts[1] + 2);
  ASSERT_FALSE(whole.report.vConvexity.empty());
  EXPECT_GT(whole.report.pointsClamped, 0u);
  for (const PassRemoval& p : whole.report.passes) EXPECT_GT(p.removedVolumeMm3, 0.0);

  GrindingSimulation sim(stock(), ballEnd(), path, params(SweepMode::Discrete));
  sim.advance(-1);
  expectSameReport(sim.report(), whole.report);
  for (int k : stops(path)) {
    SCOPED_TRACE("back to k = " + std::to_string(k));
    sim.seek(k);
    expectSameReport(sim.report(), freshRun(path, k, SweepMode::Discrete).report);
  }
  // Forwards again, with a back step in between.
  for (int k : {5, 2, 9, static_cast<int>(path.poses.size())}) {
    SCOPED_TRACE("seek to k = " + std::to_string(k));
    sim.seek(k);
    expectSameReport(sim.report(), freshRun(path, k, SweepMode::Discrete).report);
  }
}

TEST(GrindingSimulationSeek, ChangedFacesCoverEveryFaceWhoseHeightsChanged) {
  const ToolPath path = threePasses();
  GrindingSimulation sim(stock(), ballEnd(), path, params(SweepMode::Swept));
  EXPECT_TRUE(sim.takeChangedFaces().empty());
  const int n = static_cast<int>(path.poses.size());
  // Positive: advance by that many poses; negative: seek to -value - 1.
  const std::vector<int> steps = {2, 5, -4, 1, -(n + 1), -1, 7, -(n + 1)};
  const std::size_t perFace = sim.workpiece().pointsPerFace();
  for (int step : steps) {
    SCOPED_TRACE("step " + std::to_string(step));
    const std::vector<float> before = sim.workpiece().allHeights();
    if (step > 0)
      sim.advance(step);
    else
      sim.seek(-step - 1);
    const std::vector<float>& after = sim.workpiece().allHeights();
    const std::vector<int> faces = sim.takeChangedFaces();
    EXPECT_TRUE(std::is_sorted(faces.begin(), faces.end()));
    EXPECT_EQ(std::adjacent_find(faces.begin(), faces.end()), faces.end()) << "duplicates";
    int differing = 0;
    for (int f = 0; f < sim.workpiece().faceCount(); ++f) {
      const auto b = before.begin() + f * perFace, a = after.begin() + f * perFace;
      if (std::equal(b, b + perFace, a)) continue;
      ++differing;
      EXPECT_TRUE(std::binary_search(faces.begin(), faces.end(), f)) << "face " << f;
    }
    EXPECT_GT(differing, 0);  // every step cuts or restores something
    EXPECT_TRUE(sim.takeChangedFaces().empty()) << "second call";
  }
}

TEST(GrindingSimulationSeek, SeekOutsideThePathThrows) {
  const ToolPath path = threePasses();
  const int n = static_cast<int>(path.poses.size());
  GrindingSimulation sim(stock(), ballEnd(), path);
  EXPECT_THROW(sim.seek(-1), InvalidInput);
  EXPECT_THROW(sim.seek(n + 1), InvalidInput);
  EXPECT_EQ(sim.nextPose(), 0);
  EXPECT_NO_THROW(sim.seek(n));
  EXPECT_TRUE(sim.finished());
  EXPECT_NO_THROW(sim.seek(0));

  GrindingSimulationParams noUndo;
  noUndo.recordUndo = false;
  GrindingSimulation oneWay(stock(), ballEnd(), path, noUndo);
  EXPECT_NO_THROW(oneWay.seek(4));
  EXPECT_THROW(oneWay.seek(3), InvalidInput);
  EXPECT_EQ(oneWay.nextPose(), 4);
}

/// Pass volumes of a run in uneven batches against volumeBetween() of heights saved at the
/// pass boundaries.
void expectPassVolumesMatchVolumeBetween(const ddf::DisplacementField& part, const ToolMeshes& tool,
                                         const ToolPath& path, SweepMode mode) {
  GrindingSimulation sim(part, tool, path, params(mode));
  std::vector<int> bounds = path.passStarts;
  bounds.push_back(static_cast<int>(path.poses.size()));
  for (std::size_t p = 0; p + 1 < bounds.size(); ++p) {
    const std::vector<float> before = sim.workpiece().allHeights();
    for (int batch = 1; sim.nextPose() < bounds[p + 1]; batch += 2)
      sim.advance(std::min(batch, bounds[p + 1] - sim.nextPose()));
    const double expected = volumeBetween(sim.workpiece(), before, sim.workpiece().allHeights());
    ASSERT_GT(expected, 0.0) << "pass " << p;
    expectRelNear(sim.report().passes[p].removedVolumeMm3, expected, 1e-9, "pass volume");
  }
}

TEST(GrindingSimulationSeek, IncrementalPassVolumeEqualsVolumeBetween) {
  // A z-map (constant Jacobian in h) and a sphere (curved support, radial vectors: all three
  // Jacobian terms), swept.
  expectPassVolumesMatchVolumeBetween(stock(), ballEnd(), threePasses(), SweepMode::Swept);
  const ddf::DisplacementField sphere =
      ddf::spherePart({.radiusMm = 10.0, .subdivisions = 2, .m = 9, .crustFraction = 0.3}).ddf;
  const ToolMeshes ball{makeSphereTool(2.0, 12, 24), {}};
  ToolPath arcs;
  arcs.name = "arcs over the sphere";
  for (double y : {0.0, 1.5}) {
    arcs.passStarts.push_back(static_cast<int>(arcs.poses.size()));
    for (int s = 0; s < 8; ++s) {
      // Ball centre 1 mm inside the sphere's surface plus its radius, along a meridian.
      const double a = 0.4 + 0.1 * s, r = 10.0 - 1.0 + 2.0;
      PathPose p;
      p.pose.translation() = Vec3(r * std::sin(a), y, r * std::cos(a));
      arcs.poses.push_back(p);
    }
  }
  expectPassVolumesMatchVolumeBetween(sphere, ball, arcs, SweepMode::Swept);
}

TEST(GrindingSimulationSeek, UndoMemoryGrowsWithTheWorkNotWithThePart) {
  // The same cut on a part of 4 times the area: only the fixed height copy differs.
  const ToolPath path = threePasses();
  GrindingSimulation small(stock(), ballEnd(), path);
  GrindingSimulation large(zmap(60.0, 24.0, 60, 24, 9, 2.0), ballEnd(), path);
  const std::size_t smallStart = small.undoMemoryBytes(), largeStart = large.undoMemoryBytes();
  EXPECT_EQ(smallStart, small.workpiece().allHeights().size() * sizeof(float));
  EXPECT_EQ(largeStart, large.workpiece().allHeights().size() * sizeof(float));
  small.advance(-1);
  large.advance(-1);
  EXPECT_GT(small.undoMemoryBytes(), smallStart);
  EXPECT_EQ(small.undoMemoryBytes() - smallStart, large.undoMemoryBytes() - largeStart);
  EXPECT_TRUE(small.report().pointsLowered == large.report().pointsLowered);
}

}  // namespace
}  // namespace ddfcam::planning
