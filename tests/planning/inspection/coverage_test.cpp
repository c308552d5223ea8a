// SPDX-License-Identifier: MIT
// ddfcam tests: coverage of a part by a tool path and by a comparison, cuts clamped at the crust
// bottom, unresolved faces left out of a comparison's statistics (analytic planes and spheres).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../../support/test_meshes.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kPlaneZ = 0.25;  // planePatch's plane; vectors (0, 0, 1), crust z in [-1, 1]

// 10 x 10 mm plane, raster spacing 10 / 5 / 32 = 0.0625 mm.
ddf::GeneratedSurface plane() {
  return ddf::planePatch({.size = {10.0, 10.0}, .cellsX = 5, .cellsY = 5, .m = 33});
}

Tool ball() {
  return Tool{.name = "ball", .kind = ToolKind::Sphere, .radiusMm = 2.0, .segments = 96};
}

// A ball of radius 2 touching the plane along x = 2 .. 8 at y = 5, every 0.05 mm.
ToolPath touchingPass(const Vec3& shift = Vec3::Zero()) {
  ToolPath path{.name = "pass", .poses = {}, .passStarts = {0}};
  for (int p = 0; p <= 120; ++p) {
    PathPose pose;
    pose.contact = Vec3(2.0 + 0.05 * p, 5.0, kPlaneZ) + shift;
    pose.pose.translation() = pose.contact + Vec3(0, 0, 2.0);
    path.poses.push_back(pose);
  }
  return path;
}

TEST(Coverage, TouchingPassCoversItsAnalyticStrip) {
  const ddf::GeneratedSurface part = plane();
  const PathCoverage c = pathCoverage(part.ddf, ball(), touchingPass());
  // Within reach r of the plane the ball's shadow has radius a = sqrt(2 R r - r^2): a strip of
  // width 2a along the 6 mm pass with two half discs at its ends.
  const double r = PathCoverageParams{}.reachMm, a = std::sqrt(2.0 * 2.0 * r - r * r);
  const double expected = 6.0 * 2.0 * a + std::numbers::pi * a * a;
  EXPECT_NEAR(c.coverage.totalAreaMm2, 100.0, 1e-6);
  // The nodal area weights misplace at most half a spacing along the strip's 16 mm border.
  EXPECT_NEAR(c.coverage.coveredAreaMm2, expected, 0.5 * 0.0625 * 16.0);
  EXPECT_NEAR(c.coverage.percent(), expected, 0.5);
  EXPECT_EQ(c.touched.size(), part.ddf.allHeights().size());
  // The goal itself is not cut.
  EXPECT_EQ(part.ddf.allHeights(), plane().ddf.allHeights());
}

TEST(Coverage, PathTranslatedAwayCoversNothing) {
  const ddf::GeneratedSurface part = plane();
  const PathCoverage c = pathCoverage(part.ddf, ball(), touchingPass(Vec3(5000.0, 0.0, 0.0)));
  EXPECT_EQ(c.coverage.coveredAreaMm2, 0.0);
  EXPECT_EQ(c.coverage.percent(), 0.0);
  EXPECT_NEAR(c.coverage.totalAreaMm2, 100.0, 1e-6);
  EXPECT_TRUE(std::all_of(c.touched.begin(), c.touched.end(), [](auto t) { return t == 0; }));
  // A pass 1 mm above the part is beyond reach too; an empty path touches nothing.
  EXPECT_EQ(pathCoverage(part.ddf, ball(), touchingPass(Vec3(0, 0, 1.0))).coverage.percent(), 0.0);
  EXPECT_EQ(pathCoverage(part.ddf, ball(), ToolPath{}).coverage.coveredAreaMm2, 0.0);
  EXPECT_THROW(pathCoverage(part.ddf, ball(), touchingPass(), {.reachMm = 0.0}), InvalidInput);
}

TEST(Coverage, MaskCoverageOfARegion) {
  const ddf::GeneratedSurface part = plane();
  std::vector<std::uint8_t> all(part.ddf.allHeights().size(), 1);
  const std::vector<int> faces = {0, 1};
  const Coverage c = maskCoverage(part.ddf, all, faces);
  EXPECT_NEAR(c.totalAreaMm2, 4.0, 1e-9);  // two triangles of a 2 x 2 mm cell
  EXPECT_NEAR(c.percent(), 100.0, 1e-9);
  EXPECT_EQ(Coverage{}.percent(), 0.0);
  EXPECT_THROW(maskCoverage(part.ddf, std::vector<std::uint8_t>(3, 1)), InvalidInput);
}

// The ball pass of touchingPass() @p depthMm below the plane; returns the simulated part. (A
// single plunge would not do: tool triangles wholly below the crust are not localized, so only
// the moving ring where the ball crosses the crust bottom cuts the stubbles under it.)
ddf::DisplacementField plunge(double depthMm, PathSimulationReport* report = nullptr) {
  ddf::DisplacementField part = plane().ddf;
  const PathSimulationReport r = simulatePath(part, ball(), touchingPass(Vec3(0, 0, -depthMm)));
  if (report) *report = r;
  return part;
}

TEST(CrustClamping, CutsDeeperThanTheCrustAreCountedAndBoundTheMinimum) {
  const std::vector<float> desired = plane().ddf.allHeights();
  PathSimulationReport shallowReport, deepReport, deeperReport;
  const ddf::DisplacementField shallow = plunge(0.4, &shallowReport);
  const ddf::DisplacementField deep = plunge(1.5, &deepReport);      // 0.25 mm below the crust
  const ddf::DisplacementField deeper = plunge(2.0, &deeperReport);  // 0.75 mm below it
  const ScalarField dShallow = deviationMap(shallow, desired);
  const ScalarField dDeep = deviationMap(deep, desired);
  const ScalarField dDeeper = deviationMap(deeper, desired);
  EXPECT_EQ(crustClamping(dShallow, shallow).points, 0u);
  EXPECT_EQ(shallowReport.pointsClamped, 0u);
  EXPECT_GT(shallowReport.pointsLowered, 0u);
  // Clamped on the strip where the ball reaches below z = -1, |y - 5| < rho = sqrt(R^2 -
  // (c + 1)^2) for the centre height c: 0.97 mm deep, 1.56 mm deeper. Both show the crust
  // bottom as their minimum, so only the clamped points tell them apart.
  const CrustClamping cDeep = crustClamping(dDeep, deep), cDeeper = crustClamping(dDeeper, deeper);
  const auto strip = [](double rho) { return 6.0 * 2.0 * rho + std::numbers::pi * rho * rho; };
  const double rhoDeep = std::sqrt(4.0 - 1.75 * 1.75), rhoDeeper = std::sqrt(4.0 - 1.25 * 1.25);
  EXPECT_NEAR(cDeep.areaMm2, strip(rhoDeep), 0.1 * strip(rhoDeep));
  EXPECT_NEAR(cDeeper.areaMm2, strip(rhoDeeper), 0.1 * strip(rhoDeeper));
  EXPECT_GT(cDeeper.points, cDeep.points);
  EXPECT_GT(cDeep.points, 0u);
  EXPECT_GT(deepReport.pointsClamped, 0u);
  EXPECT_GT(deeperReport.pointsClamped, deepReport.pointsClamped);
  const ToleranceBand band{};
  const ErrorStatistics sDeep = errorStatistics(dDeep, plane().ddf, band);
  const ErrorStatistics sDeeper = errorStatistics(dDeeper, plane().ddf, band);
  EXPECT_NEAR(sDeep.minMm, -1.0 - kPlaneZ, 1e-6);
  EXPECT_NEAR(sDeeper.minMm, sDeep.minMm, 1e-6);
  // The grinding simulation keeps the count as well.
  ddf::DisplacementField part = plane().ddf;
  GrindingSimulationParams params;
  params.checkCollisions = false;
  params.checkVConvexity = false;
  EXPECT_EQ(simulateGrinding(part, toolMeshes(ball()), touchingPass(Vec3(0, 0, -2.0)), params)
                .pointsClamped,
            deeperReport.pointsClamped);
}

// ---- comparisons ----------------------------------------------------------------------------

ddf::TriangleMesh flatMould() {  // 40 x 10 mm in z = 0, 0.5 mm cells
  return test::heightFieldMesh(0.0, 40.0, 0.0, 10.0, 80, 20, [](double, double) { return 0.0; });
}

TEST(SurfaceComparison, PatchOverAPlaneCoversItsShareOfTheMould) {
  // A 10 x 10 mm patch 0.1 mm above the 40 x 10 mm mould: every deviation is in the band, but
  // they cover a quarter of the mould.
  const ddf::TriangleMesh patch =
      test::heightFieldMesh(10.0, 20.0, 0.0, 10.0, 40, 40, [](double, double) { return 0.1; });
  ComparisonParams params;
  params.sequence.reachMm = 1.0;
  const SurfaceComparison cmp = compareSurfaces(flatMould(), patch, params);
  EXPECT_NEAR(cmp.statistics.inTolerancePercent, 100.0, 1e-9);
  const ComparisonCoverage c = comparisonCoverage(cmp);
  EXPECT_NEAR(c.compared.totalAreaMm2, 400.0, 1e-6);
  // The patch's border at x = 10 and 20 runs along raster points: their half-spacing weights
  // (0.5 / 3 / 2 mm) may fall on either side.
  EXPECT_NEAR(c.compared.percent(), 25.0, 100.0 * 2.0 * 10.0 * (0.5 / 6.0) / 400.0);
  EXPECT_NEAR(c.compared.coveredAreaMm2, cmp.statistics.areaMm2, 1e-9);
  EXPECT_NEAR(c.missingAreaMm2 + c.compared.coveredAreaMm2, 400.0, 1e-6);
  EXPECT_EQ(c.unresolvedFaces, 0u);
  EXPECT_LT(c.compared.percent(), kLowComparisonCoveragePercent);
}

ddf::TriangleMesh icosphere(double radius, const Vec3& centre, bool inward) {
  ddf::SphereParams params;
  params.subdivisions = 3;
  params.m = 2;
  ddf::TriangleMesh mesh = ddf::extractSupportMesh(ddf::spherePart(params).ddf);
  for (Vec3& v : mesh.vertices) v = centre + v * (radius / params.radiusMm);
  if (inward)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

TEST(SurfaceComparison, UnresolvedFacesAreLeftOutOfTheStatisticsAndCounted) {
  // A sphere of radius 2 about (1.5, 0, 0) inside the mould sphere of radius 4: along the
  // inward vectors the far side lies 3.5 mm deep, beyond the crust (h0 = R / |v|), and with a
  // single stage allowed those faces stay unresolved; the near side (0.5 mm) resolves.
  ComparisonParams params;
  params.resolution = 3;
  params.band = {-0.5, 0.5};
  params.sequence.maxStages = 1;
  const SurfaceComparison cmp = compareSurfaces(icosphere(4.0, Vec3::Zero(), false),
                                                icosphere(2.0, Vec3(1.5, 0, 0), true), params);
  const int faces = cmp.sequence.stages[0].ddf.faceCount();
  ASSERT_FALSE(cmp.sequence.unresolvedFaces.empty());
  ASSERT_LT(static_cast<int>(cmp.sequence.unresolvedFaces.size()), faces);
  const ComparisonCoverage c = comparisonCoverage(cmp);
  EXPECT_EQ(c.unresolvedFaces, cmp.sequence.unresolvedFaces.size());
  EXPECT_GT(c.unresolvedAreaMm2, 0.0);
  EXPECT_NEAR(cmp.statistics.areaMm2, c.compared.coveredAreaMm2, 1e-9 * c.compared.totalAreaMm2);
  EXPECT_NEAR(c.compared.coveredAreaMm2 + c.unresolvedAreaMm2 + c.missingAreaMm2,
              c.compared.totalAreaMm2, 1e-9 * c.compared.totalAreaMm2);
  // Oracle: the statistics over the resolved faces only; with the unresolved ones averaged in
  // the deepest deviation (~ -3.5 mm) would show.
  ddf::DisplacementField flat = cmp.sequence.stages[0].ddf;
  std::fill(flat.allHeights().begin(), flat.allHeights().end(), 0.0f);
  const std::vector<int> resolved = resolvedFaces(cmp);
  EXPECT_EQ(resolved.size() + cmp.sequence.unresolvedFaces.size(), static_cast<std::size_t>(faces));
  const ErrorStatistics expected = errorStatistics(cmp.deviation, flat, params.band, resolved);
  const ErrorStatistics everything = errorStatistics(cmp.deviation, flat, params.band);
  EXPECT_EQ(cmp.statistics.minMm, expected.minMm);
  EXPECT_EQ(cmp.statistics.meanMm, expected.meanMm);
  EXPECT_EQ(cmp.statistics.areaMm2, expected.areaMm2);
  EXPECT_GT(cmp.statistics.minMm, everything.minMm + 0.1);
  EXPECT_LT(cmp.statistics.areaMm2, everything.areaMm2);
  // A new band keeps them out too.
  SurfaceComparison rebanded = cmp;
  updateComparisonBand(rebanded, {-1.0, 1.0}, false);
  EXPECT_EQ(rebanded.statistics.areaMm2, expected.areaMm2);
}

TEST(SurfaceComparison, AllDeviationsOnUnresolvedFacesFailTheComparison) {
  // Concentric: every face crosses at stage 0 (the inward crust collapses at 0.8 R), and one
  // stage cannot resolve any: nothing trustworthy is left.
  ComparisonParams params;
  params.resolution = 3;
  params.sequence.maxStages = 1;
  try {
    compareSurfaces(icosphere(4.0, Vec3::Zero(), false), icosphere(0.4, Vec3::Zero(), true),
                    params);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("unresolved"), std::string::npos) << e.what();
  }
}

TEST(SurfaceComparison, StalledSequenceStopsEarlyAndSaysWhatToChange) {
  // The rough dense mould of DeformationSequence.SplitsWithoutHeadwayStopEarly, a plane 10 mm
  // off: the sequence stops after three stages instead of twelve, the faces still crossing are
  // left out of the statistics, and the advice names what to change.
  const ddf::TriangleMesh rough =
      test::heightFieldMesh(0.0, 20.0, 0.0, 20.0, 40, 40, [](double x, double y) {
        const double s = std::sin(12.9898 * x + 78.233 * y) * 43758.5453;
        return 0.1 * (s - std::floor(s) - 0.5);
      });
  const ddf::SupportMesh support = ddf::makeSupportMesh(rough.vertices, rough.triangles);
  const ddf::DisplacementField mould(support, ddf::pseudoNormals(support).normals, 2);
  const ddf::TriangleMesh plane =
      test::heightFieldMesh(-5.0, 25.0, -5.0, 25.0, 6, 6, [](double, double) { return 10.0; });
  const SurfaceComparison cmp = compareSurfaces(mould, plane);
  EXPECT_TRUE(cmp.sequence.stalled);
  EXPECT_EQ(cmp.sequence.stages.size(), 3u);
  const ComparisonCoverage c = comparisonCoverage(cmp);
  EXPECT_EQ(c.unresolvedFaces, cmp.sequence.unresolvedFaces.size());
  EXPECT_GT(c.unresolvedAreaMm2, 0.0);
  EXPECT_NEAR(cmp.statistics.areaMm2, c.compared.coveredAreaMm2, 1e-9 * c.compared.totalAreaMm2);
  const std::string advice = stallAdvice(cmp);
  EXPECT_NE(advice.find("stalled after 3 stages"), std::string::npos) << advice;
  EXPECT_NE(advice.find("swap mould and formed"), std::string::npos) << advice;
  EXPECT_NE(advice.find("coarser mould support"), std::string::npos) << advice;
  // A sequence that did not stall has no advice.
  ComparisonParams params;
  params.sequence.reachMm = 1.0;
  EXPECT_TRUE(stallAdvice(compareSurfaces(flatMould(), flatMould(), params)).empty());
}

}  // namespace
}  // namespace ddfcam::planning
