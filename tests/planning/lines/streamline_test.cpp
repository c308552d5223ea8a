// SPDX-License-Identifier: MIT
// ddfcam: RK4 streamlines on the torus and the ellipsoid against their analytic lines of curvature.
#include "../analysis/curvature_accuracy.h"
#include "streamline_test_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/streamline.h>

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

// The exact principal directions of the torus at every stored raster point: meridians (k_max
// = 1/r) and parallels (k_min = cos v / (R + r cos v) < 1/r).
struct TorusFields {
  LineField meridian, parallel;
};

const TorusFields& exactTorusFields() {
  static const TorusFields fields{fieldOf(torus().ddf, torusMeridian),
                                  fieldOf(torus().ddf, torusParallel)};
  return fields;
}

// A seed inside the face whose centroid is nearest to the torus angles (u, v), off the grid.
SurfaceLocation torusSeed(double u, double v) {
  return seedNear(torus().ddf, ddf::TorusSurface(kMajor, kMinor).point(u, v));
}

struct TorusCase {
  const char* name;
  bool parallel;
  bool estimated;
};

class TorusLines : public ::testing::TestWithParam<TorusCase> {};

TEST_P(TorusLines, CloseAfterOneLoopWithinHalfASpacing) {
  const TorusCase& c = GetParam();
  const ddf::DisplacementField& ddf = torus().ddf;
  const double h = rasterSpacing(ddf);
  const CurvatureField& est = estimatedTorusCurvature();
  const LineField field =
      c.estimated ? masked(c.parallel ? est.dirMin : est.dirMax, est.umbilic)
                  : (c.parallel ? exactTorusFields().parallel : exactTorusFields().meridian);
  for (const double v : {0.4, std::numbers::pi / 2 + 0.1, 2.6}) {
    const Streamline line = traceStreamline(ddf, field, torusSeed(0.7, v));
    const Vec3 s = line.points[line.seedIndex].point;
    const double expected = c.parallel ? 2.0 * std::numbers::pi * std::hypot(s.x(), s.y())
                                       : 2.0 * std::numbers::pi * kMinor;
    const double drift = c.parallel ? parallelDrift(line) : meridianDrift(line);
    std::printf("[ streamline ] %s v=%.2f: drift %.3g mm = %.3g spacings, length %.4f of %.4f\n",
                c.name, v, drift, drift / h, line.lengthMm, expected);
    EXPECT_EQ(line.stop, Streamline::ClosedLoop) << c.name << " v=" << v;
    EXPECT_LE(drift, 0.5 * h) << c.name << " v=" << v;
    EXPECT_NEAR(line.lengthMm, expected, 0.01 * expected) << c.name << " v=" << v;
    EXPECT_LT(maxGap(line), 1.5 * h);
    expectOnSurface(ddf, line);
  }
}

INSTANTIATE_TEST_SUITE_P(Streamline, TorusLines,
                         ::testing::Values(TorusCase{"exact_parallel", true, false},
                                           TorusCase{"exact_meridian", false, false},
                                           TorusCase{"estimated_parallel", true, true},
                                           TorusCase{"estimated_meridian", false, true}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Streamline, NegatingFieldEntriesGivesTheSameLine) {
  const ddf::DisplacementField& ddf = torus().ddf;
  const LineField& field = exactTorusFields().parallel;
  LineField flipped = field;
  std::mt19937 rng(7);
  for (auto& d : flipped)
    if (rng() % 2) d = -d;
  const SurfaceLocation seed = torusSeed(1.9, 2.2);
  // A meridian on the far side stops the parallel from both sides: both halves are traced.
  StreamlineParams params;
  params.existingPaths.emplace_back();
  const ddf::TorusSurface surface(kMajor, kMinor);
  for (int i = 0; i <= 720; ++i)
    params.existingPaths.back().push_back(surface.point(1.9 + 3.0, i * std::numbers::pi / 360));
  params.nearPathDistanceMm = 0.3;
  const Streamline a = traceStreamline(ddf, field, seed, params);
  const Streamline b = traceStreamline(ddf, flipped, seed, params);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.seedIndex, b.seedIndex);
  EXPECT_GT(a.seedIndex, 0u);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    EXPECT_LT((a.points[i].point - b.points[i].point).norm(), 1e-12) << i;
  EXPECT_EQ(a.stop, Streamline::NearExistingPath);
  EXPECT_EQ(a.backwardStop, Streamline::NearExistingPath);
  EXPECT_EQ(b.stop, Streamline::NearExistingPath);
}

// Ellipsoid (3, 2, 1): a line of maximum curvature stays on its confocal hyperboloid
// x^2/(a^2 - l) + y^2/(b^2 - l) + z^2/(c^2 - l) = 1 with l in (b^2, a^2) (oracles note).
TEST(Streamline, EllipsoidMaxLineStaysOnItsConfocalQuadric) {
  const GeneratedSurface part =
      ddf::ellipsoidPart({.axesMm = {3.0, 2.0, 1.0}, .subdivisions = 3, .m = 9});
  const ddf::DisplacementField& ddf = part.ddf;
  LineField dirMax;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i)
        dirMax.push_back(
            test::curvatureTruth(*part.surface, ddf.surfacePoint(f, i, k), 1.0).dirMax);
  const Vec3 sq(9.0, 4.0, 1.0);
  auto quadric = [&](const Vec3& p, double l) {
    return (p.array().square() / (sq.array() - l)).sum() - 1.0;
  };
  const Vec3 bary(0.31, 0.33, 0.36);
  const Vec3 target(3.0 * std::sin(1.2) * std::cos(1.0), 2.0 * std::sin(1.2) * std::sin(1.0),
                    std::cos(1.2));
  int best = 0;
  for (int f = 1; f < ddf.faceCount(); ++f)
    if ((ddf.basePoint(f, bary) - target).norm() < (ddf.basePoint(best, bary) - target).norm())
      best = f;
  const Streamline line = traceStreamline(ddf, dirMax, {best, bary});
  // l of the seed by bisection in (b^2, a^2), where the quadric value rises from -inf to +inf.
  const Vec3 s = line.points[line.seedIndex].point;
  double lo = 4.0 + 1e-12, hi = 9.0 - 1e-12;
  for (int it = 0; it < 200; ++it) (quadric(s, 0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double l = 0.5 * (lo + hi);
  double drift = 0.0;
  for (const auto& p : line.points) {
    const Vec3 grad = (2.0 * p.point.array() / (sq.array() - l)).matrix();
    drift = std::max(drift, std::abs(quadric(p.point, l)) / grad.norm());
  }
  const double h = rasterSpacing(ddf);
  std::printf(
      "[ streamline ] ellipsoid max line l=%.4f: drift %.3g mm = %.3g spacings, length %.3f\n", l,
      drift, drift / h, line.lengthMm);
  EXPECT_EQ(line.stop, Streamline::ClosedLoop);
  EXPECT_LE(drift, 0.5 * h);
  expectOnSurface(ddf, line);
}

}  // namespace
}  // namespace ddfcam::planning
