// SPDX-License-Identifier: MIT
// Tests of the raster-walk and continuous streamlines against torus, ellipsoid and cylinder truth.
#include "../analysis/curvature_accuracy.h"
#include "streamline_test_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_continuous.h>
#include <ddfcam/planning/lines/streamline_raster_walk.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

namespace ddfcam::planning {
namespace {

using namespace streamline_test;

// Both new methods with one signature; the continuous one shares a crust hash per part.
using Tracer = Streamline (*)(const ddf::DisplacementField&, const LineField&,
                              const SurfaceLocation&, const StreamlineParams&);

Streamline rasterWalk(const ddf::DisplacementField& ddf, const LineField& field,
                      const SurfaceLocation& seed, const StreamlineParams& params) {
  return traceStreamlineRasterWalk(ddf, field, seed, params);
}

Streamline continuous(const ddf::DisplacementField& ddf, const LineField& field,
                      const SurfaceLocation& seed, const StreamlineParams& params) {
  static const ddf::DisplacementField* hashed = nullptr;
  static ddf::CrustHash hash;
  if (hashed != &ddf) hash = ddf::CrustHash(ddf), hashed = &ddf;
  return traceStreamlineContinuous(ddf, field, seed, params, {.crustHash = &hash});
}

struct Method {
  const char* name;
  Tracer trace;
};
const Method kMethods[] = {{"raster_walk", rasterWalk}, {"continuous", continuous}};

struct TorusCase {
  int method;
  bool parallel;
};

class MethodTorusLines : public ::testing::TestWithParam<TorusCase> {};

TEST_P(MethodTorusLines, EstimatedFieldCloseAfterOneLoopWithinHalfASpacing) {
  const TorusCase& c = GetParam();
  const Method& method = kMethods[c.method];
  const ddf::DisplacementField& ddf = torus().ddf;
  const double h = rasterSpacing(ddf);
  const CurvatureField& est = estimatedTorusCurvature();
  const LineField field = masked(c.parallel ? est.dirMin : est.dirMax, est.umbilic);
  const ddf::TorusSurface surface(kMajor, kMinor);
  for (const double v : {0.4, std::numbers::pi / 2 + 0.1, 2.6}) {
    const Streamline line = method.trace(ddf, field, seedNear(ddf, surface.point(0.7, v)), {});
    const Vec3 s = line.points[line.seedIndex].point;
    const double expected = c.parallel ? 2.0 * std::numbers::pi * std::hypot(s.x(), s.y())
                                       : 2.0 * std::numbers::pi * kMinor;
    const double drift = c.parallel ? parallelDrift(line) : meridianDrift(line);
    std::printf("[ streamline ] %s %s v=%.2f: drift %.3g mm = %.3g spacings, length %.4f of %.4f\n",
                method.name, c.parallel ? "parallel" : "meridian", v, drift, drift / h,
                line.lengthMm, expected);
    EXPECT_EQ(line.stop, Streamline::ClosedLoop) << method.name << " v=" << v;
    EXPECT_LE(drift, 0.5 * h) << method.name << " v=" << v;
    EXPECT_NEAR(line.lengthMm, expected, 0.02 * expected) << method.name << " v=" << v;
    EXPECT_LT(maxGap(line), 2.0 * h);
    expectOnSurface(ddf, line);
  }
}

INSTANTIATE_TEST_SUITE_P(StreamlineMethods, MethodTorusLines,
                         ::testing::Values(TorusCase{0, true}, TorusCase{0, false},
                                           TorusCase{1, true}, TorusCase{1, false}),
                         [](const auto& info) {
                           return std::string(kMethods[info.param.method].name) +
                                  (info.param.parallel ? "_parallel" : "_meridian");
                         });

TEST(StreamlineMethods, NegatingFieldEntriesGivesTheSameLine) {
  const ddf::DisplacementField& ddf = torus().ddf;
  const LineField field = fieldOf(
      ddf, [](const Vec3& q) { return Vec3(-std::sin(angleU(q)), std::cos(angleU(q)), 0.0); });
  LineField flipped = field;
  std::mt19937 rng(7);
  for (auto& d : flipped)
    if (rng() % 2) d = -d;
  const ddf::TorusSurface surface(kMajor, kMinor);
  const SurfaceLocation seed = seedNear(ddf, surface.point(1.9, 2.2));
  // A meridian on the far side stops the parallel from both sides: both halves are traced.
  StreamlineParams params;
  params.existingPaths.emplace_back();
  for (int i = 0; i <= 720; ++i)
    params.existingPaths.back().push_back(surface.point(1.9 + 3.0, i * std::numbers::pi / 360));
  params.nearPathDistanceMm = 0.3;
  for (const Method& method : kMethods) {
    const Streamline a = method.trace(ddf, field, seed, params);
    const Streamline b = method.trace(ddf, flipped, seed, params);
    ASSERT_EQ(a.points.size(), b.points.size()) << method.name;
    EXPECT_EQ(a.seedIndex, b.seedIndex) << method.name;
    EXPECT_GT(a.seedIndex, 0u) << method.name;
    for (std::size_t i = 0; i < a.points.size(); ++i)
      EXPECT_LT((a.points[i].point - b.points[i].point).norm(), 1e-12) << method.name << " " << i;
    EXPECT_EQ(a.stop, Streamline::NearExistingPath) << method.name;
    EXPECT_EQ(a.backwardStop, Streamline::NearExistingPath) << method.name;
    // The stop lies within the distance (plus one raster move) of the far meridian.
    for (const auto* end : {&a.points.front(), &a.points.back()}) {
      const double du = std::remainder(angleU(end->point) - (1.9 + 3.0), 2.0 * std::numbers::pi);
      EXPECT_LT(std::abs(du) * std::hypot(end->point.x(), end->point.y()),
                0.3 + 2.0 * rasterSpacing(ddf))
          << method.name;
    }
  }
}

// ---- ellipsoid (3, 2, 1): a k_max line stays on its confocal hyperboloid (oracles note) ----

TEST(StreamlineMethods, EllipsoidMaxLineStaysOnItsConfocalQuadric) {
  const GeneratedSurface part =
      ddf::ellipsoidPart({.axesMm = {3.0, 2.0, 1.0}, .subdivisions = 3, .m = 9});
  const ddf::DisplacementField& ddf = part.ddf;
  const LineField dirMax = fieldOf(
      ddf, [&](const Vec3& q) { return test::curvatureTruth(*part.surface, q, 1.0).dirMax; });
  const Vec3 sq(9.0, 4.0, 1.0);
  auto quadric = [&](const Vec3& p, double l) {
    return (p.array().square() / (sq.array() - l)).sum() - 1.0;
  };
  const SurfaceLocation seed =
      seedNear(ddf, Vec3(3.0 * std::sin(1.2) * std::cos(1.0), 2.0 * std::sin(1.2) * std::sin(1.0),
                         std::cos(1.2)));
  const double h = rasterSpacing(ddf);
  for (const Method& method : kMethods) {
    const Streamline line = method.trace(ddf, dirMax, seed, {});
    // l of the seed by bisection in (b^2, a^2), where the quadric value rises from -inf to +inf.
    const Vec3 s = line.points[line.seedIndex].point;
    double lo = 4.0 + 1e-12, hi = 9.0 - 1e-12;
    for (int it = 0; it < 200; ++it)
      (quadric(s, 0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const double l = 0.5 * (lo + hi);
    double drift = 0.0;
    for (const auto& p : line.points) {
      const Vec3 grad = (2.0 * p.point.array() / (sq.array() - l)).matrix();
      drift = std::max(drift, std::abs(quadric(p.point, l)) / grad.norm());
    }
    std::printf(
        "[ streamline ] %s ellipsoid max line l=%.4f: drift %.3g mm = %.3g spacings, "
        "length %.3f, %zu points\n",
        method.name, l, drift, drift / h, line.lengthMm, line.points.size());
    EXPECT_EQ(line.stop, Streamline::ClosedLoop) << method.name;
    EXPECT_LE(drift, 0.5 * h) << method.name;
    expectOnSurface(ddf, line);
  }
}

// ---- cylinder (r 10, length 30): rulings, boundaries, regions, stops ----

LineField axialField() {
  return LineField(cylinder().ddf.allHeights().size(), Vec3::UnitZ());
}

const SurfaceLocation kCylinderSeed{100, Vec3(0.2, 0.3, 0.5)};

TEST(StreamlineMethods, RulingRunsFromBoundaryToBoundary) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  for (const Method& method : kMethods) {
    const Streamline line = method.trace(ddf, axialField(), kCylinderSeed, {});
    EXPECT_EQ(line.stop, Streamline::Boundary) << method.name;
    EXPECT_EQ(line.backwardStop, Streamline::Boundary) << method.name;
    EXPECT_NEAR(line.points.front().point.z(), 0.0, 1e-9) << method.name;
    EXPECT_NEAR(line.points.back().point.z(), 30.0, 1e-9) << method.name;
    EXPECT_NEAR(line.lengthMm, 30.0, 0.01) << method.name;
    const Vec3 s = line.points[line.seedIndex].point;
    // The raster walk reaches the ruling's raster points from the seed within one move.
    for (const auto& p : line.points)
      EXPECT_LT(std::hypot(p.point.x() - s.x(), p.point.y() - s.y()), 0.35) << method.name;
    expectOnSurface(ddf, line);
  }
}

TEST(StreamlineMethods, StopAtARegionBoundaryAndStayInside) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  // The region: faces whose centroid lies at 5 < z < 20 mm (whole rings of 2.5 mm).
  const std::vector<std::uint8_t> mask = zBandMask(ddf, 5.0, 20.0);
  StreamlineParams params;
  params.faceMask = mask;
  const int seedFace = firstFace(mask, true);
  const int outside = firstFace(mask, false);
  for (const Method& method : kMethods) {
    const Streamline line = method.trace(ddf, axialField(), {seedFace, kSeedBary}, params);
    EXPECT_EQ(line.stop, Streamline::RegionBoundary) << method.name;
    EXPECT_EQ(line.backwardStop, Streamline::RegionBoundary) << method.name;
    for (const auto& p : line.points) EXPECT_TRUE(mask[static_cast<std::size_t>(p.face)]);
    EXPECT_NEAR(line.points.front().point.z(), 5.0, 1e-9) << method.name;
    EXPECT_NEAR(line.points.back().point.z(), 20.0, 1e-9) << method.name;
    expectOnSurface(ddf, line);
    const Streamline none = method.trace(ddf, axialField(), {outside, kSeedBary}, params);
    EXPECT_EQ(none.points.size(), 1u) << method.name;
    EXPECT_EQ(none.stop, Streamline::RegionBoundary) << method.name;
  }
}

TEST(StreamlineMethods, StopNearAnExistingPathAtMaxLengthAndAtUndefinedField) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  StreamlineParams params;
  for (int i = 0; i < 360; ++i) {
    const double a = i * std::numbers::pi / 180.0;
    params.existingPaths.push_back({Vec3(10 * std::cos(a), 10 * std::sin(a), 20.0)});
  }
  params.nearPathDistanceMm = 0.5;
  LineField undefinedAbove22 = axialField();
  const int n = ddf.raster().steps();
  std::size_t idx = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i, ++idx)
        if (ddf.surfacePoint(f, i, k).z() > 22.0) undefinedAbove22[idx] = Vec3::Zero();
  for (const Method& method : kMethods) {
    const Streamline near = method.trace(ddf, axialField(), kCylinderSeed, params);
    EXPECT_EQ(near.stop, Streamline::NearExistingPath) << method.name;
    EXPECT_GT(near.points.back().point.z(), 19.4) << method.name;
    EXPECT_LT(near.points.back().point.z(), 20.01) << method.name;
    StreamlineParams capped;
    capped.maxLengthMm = 5.0;
    const Streamline shortLine = method.trace(ddf, axialField(), kCylinderSeed, capped);
    EXPECT_EQ(shortLine.stop, Streamline::MaxLength) << method.name;
    EXPECT_LE(shortLine.lengthMm, 5.0 + 1e-9) << method.name;
    EXPECT_GT(shortLine.lengthMm, 5.0 - 2.0 * rasterSpacing(ddf)) << method.name;
    const Streamline undefined = method.trace(ddf, undefinedAbove22, kCylinderSeed, {});
    EXPECT_EQ(undefined.stop, Streamline::Singularity) << method.name;
    EXPECT_EQ(undefined.backwardStop, Streamline::Boundary) << method.name;
    EXPECT_LT(undefined.points.back().point.z(), 22.0) << method.name;
    EXPECT_GT(undefined.points.back().point.z(), 22.0 - 2.5 - 0.7) << method.name;
  }
}

TEST(StreamlineMethods, DispatcherAndOptions) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const Streamline rk4 = traceStreamline(ddf, axialField(), kCylinderSeed);
  const Streamline viaRk4 =
      traceStreamlineWith(StreamlineMethod::Rk4, ddf, axialField(), kCylinderSeed);
  ASSERT_EQ(rk4.points.size(), viaRk4.points.size());
  EXPECT_EQ(rk4.points.back().point, viaRk4.points.back().point);
  const Streamline walk =
      traceStreamlineWith(StreamlineMethod::RasterWalk, ddf, axialField(), kCylinderSeed);
  EXPECT_EQ(walk.points.size(), rasterWalk(ddf, axialField(), kCylinderSeed, {}).points.size());
  const Streamline cont =
      traceStreamlineWith(StreamlineMethod::Continuous, ddf, axialField(), kCylinderSeed);
  EXPECT_EQ(cont.points.size(), continuous(ddf, axialField(), kCylinderSeed, {}).points.size());
  const ddf::CrustHash hash(ddf);
  const Streamline withOptions = traceStreamlineWith(
      StreamlineMethod::Continuous, ddf, axialField(), kCylinderSeed, {}, {}, {.crustHash = &hash});
  EXPECT_EQ(withOptions.points.size(), cont.points.size());
  const Streamline unfiltered = traceStreamlineWith(StreamlineMethod::RasterWalk, ddf, axialField(),
                                                    kCylinderSeed, {}, {.filterHalfWindow = 0}, {});
  EXPECT_EQ(unfiltered.points.size(), walk.points.size());
  EXPECT_STREQ(streamlineMethodName(StreamlineMethod::RasterWalk), "raster-walk");
  // Every integrator follows the ruling.
  for (const auto integrator : {ContinuousIntegrator::Euler, ContinuousIntegrator::Rk4}) {
    const Streamline line =
        traceStreamlineContinuous(ddf, axialField(), kCylinderSeed, {}, {.integrator = integrator});
    EXPECT_NEAR(line.lengthMm, 30.0, 0.01);
    EXPECT_EQ(line.stop, Streamline::Boundary);
  }
  EXPECT_THROW(
      traceStreamlineRasterWalk(ddf, axialField(), kCylinderSeed, {}, {.filterHalfWindow = -1}),
      InvalidInput);
  EXPECT_THROW(traceStreamlineContinuous(ddf, LineField(3), kCylinderSeed), InvalidInput);
  StreamlineParams cancel;
  cancel.progress = [](double) { return false; };
  EXPECT_THROW(traceStreamlineRasterWalk(ddf, axialField(), kCylinderSeed, cancel), Cancelled);
  EXPECT_THROW(traceStreamlineContinuous(ddf, axialField(), kCylinderSeed, cancel), Cancelled);
}

}  // namespace
}  // namespace ddfcam::planning
