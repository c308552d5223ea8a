// SPDX-License-Identifier: MIT
// Tests of grinding a tool path into a DDF.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace ddfcam::planning {
namespace {

/// Radius of the largest ball about the origin inside the closed convex mesh @p mesh: the
/// smallest distance from the origin to a triangle's plane.
double inradius(const ddf::TriangleMesh& mesh) {
  double r = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const ddf::Vec3& a = mesh.vertices[t[0]];
    const ddf::Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).normalized();
    r = std::min(r, std::abs(n.dot(a)));
  }
  return r;
}

/// Lower surface z of the ball (centre, radius) above (x, y), or +infinity outside its shadow.
double ballBottom(const ddf::Vec3& centre, double radius, double x, double y) {
  const double d2 = (x - centre.x()) * (x - centre.x()) + (y - centre.y()) * (y - centre.y());
  if (d2 >= radius * radius) return std::numeric_limits<double>::infinity();
  return centre.z() - std::sqrt(radius * radius - d2);
}

TEST(PathSimulation, BallPlungeLowersAPlaneToTheSphereCap) {
  // z-map: planar support z = 0, vectors (0, 0, 1), so h is z in mm; the plane sits at z = 0.25.
  ddf::GeneratedSurface plane =
      ddf::planePatch({.size = {10.0, 10.0}, .cellsX = 5, .cellsY = 5, .m = 17});
  const std::vector<float> stock = plane.ddf.allHeights();
  const Tool ball{.name = "ball", .kind = ToolKind::Sphere, .radiusMm = 2.0, .segments = 96};
  ToolPath path{.name = "plunge", .poses = {PathPose{}}, .passStarts = {0}};
  const ddf::Vec3 centre(5.1, 4.7, 0.25 - 0.4 + 2.0);  // 0.4 mm below the plane
  path.poses[0].pose.translation() = centre;
  const PathSimulationReport report = simulatePath(plane.ddf, ball, path);
  EXPECT_EQ(report.poses, 1);
  // The faceted ball lies between its inscribed and its circumscribed sphere, so every height
  // lies between the two analytic caps (float rounding aside).
  const double rIn = inradius(toolMesh(ball));
  ASSERT_GT(rIn, 1.99);
  const ddf::DisplacementField& ddf = plane.ddf;
  std::size_t lowered = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < ddf.resolution(); ++k)
      for (int i = 0; i + k < ddf.resolution(); ++i) {
        const ddf::Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        const std::size_t at = f * ddf.pointsPerFace() + ddf.raster().index(i, k);
        const double h0 = stock[at], h = ddf.allHeights()[at];
        const double outer = std::min(h0, ballBottom(centre, ball.radiusMm, g.x(), g.y()));
        const double inner = std::min(h0, ballBottom(centre, rIn, g.x(), g.y()));
        EXPECT_GE(h, outer - 1e-5) << "face " << f << " (" << i << ", " << k << ")";
        EXPECT_LE(h, inner + 1e-5) << "face " << f << " (" << i << ", " << k << ")";
        if (outer >= h0) {
          EXPECT_EQ(h, h0) << "outside the ball's shadow";
        }
        lowered += h < h0;
      }
  EXPECT_EQ(report.pointsLowered, lowered);
  // sqrt(2 R d - d^2) = 1.2 mm cap radius over a ~0.156 mm raster: several hundred points.
  EXPECT_GT(lowered, 300u);
}

/// A short zigzag of a small roll over a saddle: 2 passes of 70 poses.
struct SaddleRun {
  ddf::GeneratedSurface saddle = ddf::saddlePatch({.grid = {.cellsX = 8, .cellsY = 8, .m = 9}});
  Tool roll{.name = "small roll", .radiusMm = 2.0, .widthMm = 3.0, .segments = 24};
  ToolPath path;

  SaddleRun() {
    const auto& surface = dynamic_cast<const ddf::HeightFieldSurface&>(*saddle.surface);
    for (double x : {-3.0, 2.0}) {
      path.passStarts.push_back(static_cast<int>(path.poses.size()));
      for (int s = 0; s < 70; ++s) {
        PathPose p;
        p.contact = surface.pointAbove(x, -8.0 + 0.23 * s);
        p.pose = rollPoseAtContact(p.contact, surface.normal(p.contact), ddf::Vec3::UnitY(),
                                   roll.radiusMm, 0.3);
        path.poses.push_back(p);
      }
    }
  }
};

TEST(PathSimulation, EqualsCuttingPoseByPose) {
  SaddleRun run;
  ddf::DisplacementField reference = run.saddle.ddf;
  const ddf::CrustHash hash(reference);
  const ddf::TriangleMesh mesh = toolMesh(run.roll);
  std::size_t lowered = 0;
  for (const PathPose& p : run.path.poses)
    lowered += ddf::cutByMesh(reference, hash, mesh, p.pose).pointsLowered;
  ASSERT_GT(lowered, 0u);
  const PathSimulationReport report = simulatePath(run.saddle.ddf, run.roll, run.path);
  EXPECT_EQ(report.poses, 140);
  EXPECT_EQ(report.pointsLowered, lowered);
  EXPECT_GE(report.seconds, 0.0);
  EXPECT_TRUE(run.saddle.ddf.allHeights() == reference.allHeights());
}

TEST(PathSimulation, ProgressIsMonotoneFrequentAndEndsAtOne) {
  SaddleRun run;
  std::vector<double> seen;
  PathSimulationParams params;
  params.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  simulatePath(run.saddle.ddf, run.roll, run.path, params);
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_LE((seen[i] - seen[i - 1]) * 140, 64 + 1e-9) << "more than 64 poses between reports";
  }
}

TEST(PathSimulation, CancelThrowsAndStopsReporting) {
  SaddleRun run;
  int calls = 0, callsAfterCancel = 0;
  bool cancelled = false;
  PathSimulationParams params;
  params.progress = [&](double f) {
    ++calls;
    if (cancelled) ++callsAfterCancel;
    cancelled = cancelled || f > 0.2;
    return !cancelled;
  };
  EXPECT_THROW(simulatePath(run.saddle.ddf, run.roll, run.path, params), Cancelled);
  EXPECT_TRUE(cancelled);
  EXPECT_EQ(callsAfterCancel, 0);
  // Cancelling at the first report leaves the part uncut.
  const std::vector<float> before = run.saddle.ddf.allHeights();
  params.progress = [](double) { return false; };
  EXPECT_THROW(simulatePath(run.saddle.ddf, run.roll, run.path, params), Cancelled);
  EXPECT_TRUE(run.saddle.ddf.allHeights() == before);
}

TEST(PathSimulation, UnusableToolIsRejectedBeforeCutting) {
  SaddleRun run;
  const std::vector<float> before = run.saddle.ddf.allHeights();
  run.roll.widthMm = 0.0;
  EXPECT_THROW(simulatePath(run.saddle.ddf, run.roll, run.path), InvalidInput);
  EXPECT_TRUE(run.saddle.ddf.allHeights() == before);
}

TEST(PathSimulation, EmptyPathReportsCompletion) {
  SaddleRun run;
  std::vector<double> seen;
  PathSimulationParams params;
  params.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  const auto report = simulatePath(run.saddle.ddf, run.roll, ToolPath{}, params);
  EXPECT_EQ(report.poses, 0);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 1.0);
}

}  // namespace
}  // namespace ddfcam::planning
