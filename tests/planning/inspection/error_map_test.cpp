// SPDX-License-Identifier: MIT
// Tests of error maps: normal deviation, area-weighted statistics, histograms, path samples.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// Calls fn(face, flat index, surface point of the raster point) for every raster point copy.
template <class Fn>
void forEachPoint(const ddf::DisplacementField& ddf, Fn&& fn) {
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) fn(f, l, ddf.surfacePoint(f, i, k));
  }
}

TEST(ErrorMap, PlaneOffsetWithTiltedVectorsIsHeightTimesNormalComponent) {
  ddf::PlanePatchParams params;
  params.cellsX = 8;
  params.cellsY = 6;
  params.m = 9;
  ddf::DisplacementField desired = ddf::planePatch(params).ddf;
  // Tilted, varying vectors: a constant height still represents a plane z = h v_z only if v_z is
  // constant, so every vector gets v_z = 0.8 with a varying tangential part.
  std::vector<Vec3> vectors;
  for (int v = 0; v < desired.vertexCount(); ++v)
    vectors.emplace_back(0.3 * std::sin(v), 0.2 * std::cos(0.7 * v), 0.8);
  desired.setVectors(vectors);
  ddf::DisplacementField produced = desired;
  constexpr double kDh = 0.05;
  for (float& h : produced.allHeights()) h += static_cast<float>(kDh);
  const ScalarField map = deviationMap(produced, desired);
  EXPECT_EQ(map.unit, "mm");
  EXPECT_TRUE(map.isSigned);
  for (float d : map.values) EXPECT_NEAR(d, kDh * 0.8, 1e-6);  // plane z offset = dh v_z
  for (float& h : produced.allHeights()) h -= static_cast<float>(2 * kDh);
  for (float d : deviationMap(produced, desired).values) EXPECT_NEAR(d, -kDh * 0.8, 1e-6);
}

TEST(ErrorMap, ConcentricSphereGivesNormalOffset) {
  ddf::SphereParams params;
  params.subdivisions = 2;
  params.m = 9;
  const ddf::GeneratedSurface sphere = ddf::spherePart(params);
  constexpr double kDelta = 0.1;  // produced sphere lies kDelta inside: an overcut
  const ddf::GeneratedSurface smaller =
      ddf::fromAnalytic(sphere.ddf.support(), sphere.ddf.vectors(), params.m,
                        std::make_shared<ddf::SphereSurface>(params.radiusMm - kDelta));
  const ScalarField map = deviationMap(smaller.ddf, sphere.ddf);
  for (float d : map.values) EXPECT_NEAR(d, -kDelta, 2e-4);
}

TEST(ErrorMap, RejectsDifferentSupports) {
  const auto a = ddf::planePatch({}).ddf;
  ddf::PlanePatchParams other;
  other.m = 9;
  const auto b = ddf::planePatch(other).ddf;
  EXPECT_THROW(deviationMap(a, b), InvalidInput);
  EXPECT_THROW(deviationMap(a, std::vector<float>(3, 0.0f)), InvalidInput);
}

TEST(ErrorMap, ClassifiesAgainstTheBand) {
  const ToleranceBand band{-0.01, 0.02};
  EXPECT_EQ(classify(0.03, band), ToleranceClass::MaterialLeft);
  EXPECT_EQ(classify(0.02, band), ToleranceClass::InTolerance);
  EXPECT_EQ(classify(-0.01, band), ToleranceClass::InTolerance);
  EXPECT_EQ(classify(-0.011, band), ToleranceClass::Overcut);
  EXPECT_THROW(validateToleranceBand({0.01, 0.02}), InvalidInput);
  EXPECT_THROW(validateToleranceBand({-0.01, -0.001}), InvalidInput);
}

TEST(ErrorMap, CylinderAreaMatchesAnalyticArea) {
  ddf::CylinderParams params;
  const auto cylinder = ddf::cylinderPart(params).ddf;
  const auto areas = rasterPointAreas(cylinder);
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  const double exact = 2.0 * std::numbers::pi * params.radiusMm * params.lengthMm;
  EXPECT_NEAR(total / exact, 1.0, 1e-4);  // inscribed 768-gon: pi^2/(6 * 768^2) ~ 3e-6
}

// d(x) = A sin(2 pi x / lambda) on a 40 x 30 plane: the area fraction within +-t is
// (2/pi) asin(t/A) (oracles note), the rest splits evenly into material left and overcut.
class SineErrorMap : public ::testing::Test {
 protected:
  void SetUp() override {
    ddf::PlanePatchParams params;
    params.m = 33;
    desired = ddf::planePatch(params).ddf;
    ddf::DisplacementField produced = desired;
    forEachPoint(produced, [&](int, std::size_t l, const Vec3& p) {
      produced.allHeights()[l] +=
          static_cast<float>(kA * std::sin(2 * std::numbers::pi * p.x() / 10.0));
    });
    map = deviationMap(produced, desired);
  }
  static constexpr double kA = 0.05;
  ddf::DisplacementField desired;
  ScalarField map;
};

TEST_F(SineErrorMap, StatisticsMatchAreaFractions) {
  const ErrorStatistics stats = errorStatistics(map, desired, {-0.025, 0.025});
  const double inside = 100.0 * 2.0 / std::numbers::pi * std::asin(0.5);  // 33.33 %
  EXPECT_NEAR(stats.inTolerancePercent, inside, 0.5);
  EXPECT_NEAR(stats.materialLeftPercent, (100.0 - inside) / 2.0, 0.5);
  EXPECT_NEAR(stats.overcutPercent, (100.0 - inside) / 2.0, 0.5);
  EXPECT_NEAR(stats.areaMm2, 1200.0, 1e-6);
  EXPECT_NEAR(stats.maxMm, kA, 1e-6);
  EXPECT_NEAR(stats.minMm, -kA, 1e-6);
  EXPECT_NEAR(stats.meanMm, 0.0, 1e-5);
  EXPECT_NEAR(stats.rmsMm, kA / std::sqrt(2.0), 2e-4);
  EXPECT_EQ(stats.points, desired.topology().pointCount());
}

TEST_F(SineErrorMap, RegionMaskRestrictsArea) {
  std::vector<int> left;  // faces with all vertices at x <= 10: one full period
  for (int f = 0; f < desired.faceCount(); ++f) {
    bool inside = true;
    for (int v : desired.faceVertices(f)) inside = inside && desired.position(v).x() <= 10.0 + 1e-9;
    if (inside) left.push_back(f);
  }
  const ErrorStatistics stats = errorStatistics(map, desired, {-0.025, 0.025}, left);
  EXPECT_NEAR(stats.areaMm2, 300.0, 1e-6);
  EXPECT_NEAR(stats.meanMm, 0.0, 1e-4);
  EXPECT_THROW(errorStatistics(map, desired, {}, std::vector<int>{desired.faceCount()}),
               InvalidInput);
}

TEST_F(SineErrorMap, HistogramAreasSumToTheTotal) {
  const AreaHistogram all = errorHistogram(map, desired, 20, -0.06, 0.06);
  EXPECT_NEAR(std::accumulate(all.areaMm2.begin(), all.areaMm2.end(), 0.0), 1200.0, 1e-6);
  EXPECT_EQ(all.belowMm2, 0.0);
  const AreaHistogram part = errorHistogram(map, desired, 4, -0.025, 0.025);
  const double sum = std::accumulate(part.areaMm2.begin(), part.areaMm2.end(), 0.0);
  EXPECT_NEAR(sum + part.belowMm2 + part.aboveMm2, 1200.0, 1e-6);
  EXPECT_NEAR(sum / 12.0, 100.0 * 2.0 / std::numbers::pi * std::asin(0.5), 0.5);
  EXPECT_THROW(errorHistogram(map, desired, 0, -1.0, 1.0), InvalidInput);
  EXPECT_THROW(errorHistogram(map, desired, 4, 1.0, 1.0), InvalidInput);
}

TEST(ErrorMap, BallPlungedBelowTheSurfaceIsAnOvercutCap) {
  // Stock 0.3 mm on the plane z = 0.25; a ball of R = 5 sinks d = 0.2 mm below the desired plane.
  constexpr double kR = 5.0, kDepth = 0.2, kStock = 0.3;
  const ddf::DisplacementField desired = ddf::planePatch({}).ddf;
  ddf::DisplacementField produced = desired;
  for (float& h : produced.allHeights()) h += static_cast<float>(kStock);
  Tool ball;
  ball.kind = ToolKind::Sphere;
  ball.radiusMm = kR;
  ball.segments = 256;  // chord error R (1 - cos(pi/256)) = 0.0004 mm
  ToolPath path;
  path.passStarts = {0};
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(20.0, 15.0, 0.25 + kR - kDepth);
  path.poses.push_back({pose, Vec3(20.0, 15.0, 0.25)});
  simulatePath(produced, ball, path);
  const ScalarField map = deviationMap(produced, desired);
  const ToleranceBand band{-0.01, 0.01};
  const ErrorStatistics stats = errorStatistics(map, desired, band);
  EXPECT_NEAR(stats.minMm, -kDepth, 1e-3);
  EXPECT_NEAR(stats.maxMm, kStock, 1e-6);
  // Overcut where the ball lies more than 0.01 below the plane: a disc of radius^2 =
  // R^2 - (R - d + 0.01)^2; in tolerance: the ring out to depth -0.01..0.01 around it.
  const double overcut = std::numbers::pi * (kR * kR - std::pow(kR - kDepth + 0.01, 2));
  EXPECT_NEAR(stats.overcutPercent / 100.0 * stats.areaMm2 / overcut, 1.0, 0.05);
  EXPECT_NEAR(stats.overcutPercent + stats.inTolerancePercent + stats.materialLeftPercent, 100.0,
              1e-9);
}

TEST(ErrorMap, DeviationAlongPathOnARamp) {
  ddf::PlanePatchParams params;
  params.planeZMm = 0.25;
  const ddf::DisplacementField desired = ddf::planePatch(params).ddf;
  ddf::DisplacementField produced = desired;
  forEachPoint(produced, [&](int, std::size_t l, const Vec3& p) {
    produced.allHeights()[l] += static_cast<float>(0.001 * p.x());  // ramp, 1 um per mm
  });
  ToolPath path;
  path.passStarts = {0, 5};
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < 5; ++s) {
      const Vec3 contact(3.0 + 6.0 * s, 4.0 + 3.0 * s + 10.0 * pass, 0.25);
      path.poses.push_back({Eigen::Isometry3d::Identity(), contact});
    }
  const auto samples = deviationAlongPath(produced, desired, path);
  ASSERT_EQ(samples.size(), 10u);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    EXPECT_NEAR(samples[s].deviationMm, 0.001 * path.poses[s].contact.x(), 1e-6);
    EXPECT_EQ(samples[s].pass, s < 5 ? 0 : 1);
    // 5 contacts 6.708 mm apart per pass; the lift to the second pass adds nothing.
    const double step = std::hypot(6.0, 3.0);
    EXPECT_NEAR(samples[s].arcLengthMm, step * (s < 5 ? s : s - 1), 1e-9);
  }
  const ScalarField map = deviationMap(produced, desired);
  const std::vector<ddf::SurfaceLocation> locations = {
      {0, Vec3(1.0, 0.0, 0.0), 0.25, desired.pointAt(0, Vec3(1.0, 0.0, 0.0), 0.25)},
      {0, Vec3(0.2, 0.3, 0.5), 0.25, desired.pointAt(0, Vec3(0.2, 0.3, 0.5), 0.25)}};
  const auto along = deviationAlongLocations(map, desired, locations);
  ASSERT_EQ(along.size(), 2u);
  EXPECT_NEAR(along[0].deviationMm, 0.001 * locations[0].point.x(), 1e-6);
  EXPECT_NEAR(along[1].deviationMm, 0.001 * locations[1].point.x(), 1e-6);
  EXPECT_NEAR(along[1].arcLengthMm, (locations[1].point - locations[0].point).norm(), 1e-12);
}

}  // namespace
}  // namespace ddfcam::planning
