// SPDX-License-Identifier: MIT
// Tests of the live tolerance classes: kept up to date face by face while a simulation cuts,
// they equal the classes of a full deviationMap() of the current heights at every pose.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/simulation/live_tolerance_map.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "../../support/zmap.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// Classes of a full error map of @p part against @p design, point by point.
std::vector<std::uint8_t> fullClasses(const ddf::DisplacementField& part,
                                      const std::vector<float>& design,
                                      const ToleranceBand& band) {
  const ScalarField map = deviationMap(part, design);
  std::vector<std::uint8_t> out(map.values.size());
  for (std::size_t l = 0; l < out.size(); ++l)
    out[l] = std::isnan(map.values[l]) ? LiveToleranceMap::kNoValue
                                       : static_cast<std::uint8_t>(classify(map.values[l], band));
  return out;
}

// The stock of a dome (surface z = 2 - r^2/40 over a 20 x 10 mm patch, so the normals tilt)
// and its design 0.2 mm below along the vectors.
struct Dome {
  ddf::DisplacementField stock;
  std::vector<float> design;
};

Dome dome() {
  Dome d{test::zmap(20.0, 10.0, 8, 4, 9, 4.0), {}};
  const int n = d.stock.raster().steps();
  for (int f = 0; f < d.stock.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 g = d.stock.basePoint(f, d.stock.rasterBary(i, k));
        const double r2 = (g.x() - 10.0) * (g.x() - 10.0) + (g.y() - 5.0) * (g.y() - 5.0);
        d.stock.heights(f)[d.stock.raster().index(i, k)] =
            static_cast<float>((2.0 - r2 / 40.0) / 4.0);
      }
  d.design = d.stock.allHeights();
  for (float& h : d.design) h -= 0.05f;  // 0.2 mm: 0.05 vector lengths of 4 mm
  return d;
}

// A ball sinking to 0.25 mm below the stock along a line in x: it overcuts the design by
// about 0.05 mm in the middle of its groove and leaves in-tolerance and stock points beside.
ToolPath groove() {
  ToolPath path;
  path.name = "groove";
  path.passStarts = {0};
  for (int i = 0; i < 24; ++i) {
    const double x = 2.0 + 16.0 * i / 23.0, y = 5.0;
    const double z = 4.0 * (2.0 - (x - 10.0) * (x - 10.0) / 40.0) / 4.0 - 0.25;
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    p.translation() = Vec3(x, y, z + 1.5);
    path.poses.push_back({p, Vec3(x, y, z)});
  }
  return path;
}

TEST(LiveToleranceMap, FaceByFaceUpdatesEqualAFullErrorMapAtEveryPose) {
  const Dome d = dome();
  ddf::DisplacementField design = d.stock;
  design.allHeights() = d.design;
  const ToleranceBand band{-0.02, 0.02};
  LiveToleranceMap map(design, band);
  GrindingSimulationParams params;
  params.recordUndo = true;
  GrindingSimulation simulation(d.stock, {makeSphereTool(1.5, 12, 24), {}}, groove(),
                                params);
  map.updateAll(simulation.workpiece());
  EXPECT_EQ(map.classes(), fullClasses(simulation.workpiece(), d.design, band));
  std::set<std::uint8_t> seen;
  while (!simulation.finished()) {
    simulation.advance(1);
    map.update(simulation.workpiece(), simulation.takeChangedFaces());
    ASSERT_EQ(map.classes(), fullClasses(simulation.workpiece(), d.design, band))
        << "after pose " << simulation.nextPose();
    seen.insert(map.classes().begin(), map.classes().end());
  }
  // The groove shows all three classes.
  EXPECT_EQ(seen.size(), 3u);
  // Back to the start by a seek: the faces it restores are reported and re-classified.
  simulation.seek(0);
  map.update(simulation.workpiece(), simulation.takeChangedFaces());
  EXPECT_EQ(map.classes(), fullClasses(simulation.workpiece(), d.design, band));
}

TEST(LiveToleranceMap, RejectsAnotherPartSizeABadFaceAndABadBand) {
  const Dome d = dome();
  LiveToleranceMap map(d.stock, {});
  const ddf::DisplacementField other = test::zmap(20.0, 10.0, 4, 2, 9, 4.0);
  EXPECT_THROW(map.updateAll(other), InvalidInput);
  const std::vector<int> bad{d.stock.faceCount()};
  EXPECT_THROW(map.update(d.stock, bad), InvalidInput);
  EXPECT_THROW(LiveToleranceMap(d.stock, ToleranceBand{0.01, 0.02}), InvalidInput);
}

// The live simulation publishes the classes of its state and, per triangle corner, where it
// lies on the face's raster.
TEST(LiveToleranceMap, LiveFramesCarryTheClassesAndTheCornerParameters) {
  const Dome d = dome();
  LiveSimulationParams params;
  params.displayEpsMm = 0.005;
  params.posesPerSecond = 0.0;
  params.designHeights = d.design;
  params.toleranceBand = {-0.02, 0.02};
  LiveSimulation live(d.stock, {makeSphereTool(1.5, 12, 24), {}}, groove(), params);
  for (const int pose : {10, 24, 3}) {
    live.seek(pose);
    const auto frame = live.latestFrame();
    EXPECT_EQ(frame->toleranceClasses,
              fullClasses(live.simulation().workpiece(), d.design, params.toleranceBand))
        << "pose " << pose;
    ASSERT_EQ(frame->cornerParams.size(), 2 * frame->triangles.size());
    const int n = d.stock.raster().steps();
    for (std::size_t c = 0; c < frame->triangles.size(); ++c) {
      const float u = frame->cornerParams[2 * c], w = frame->cornerParams[2 * c + 1];
      ASSERT_TRUE(u >= 0.0f && w >= 0.0f && u + w <= n + 1e-4f) << "corner " << c;
    }
  }
  LiveSimulationParams plain = params;
  plain.designHeights.clear();
  LiveSimulation uninspected(d.stock, {makeSphereTool(1.5, 12, 24), {}}, groove(), plain);
  EXPECT_TRUE(uninspected.latestFrame()->toleranceClasses.empty());
  EXPECT_TRUE(uninspected.latestFrame()->cornerParams.empty());
}

}  // namespace
}  // namespace ddfcam::planning
