// SPDX-License-Identifier: MIT
// Analytic surfaces: curvature oracles, finite-difference gradients, distances along normals.
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/ddf/bspline_patch.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace ddfcam::ddf {
namespace {

TEST(AnalyticSurface, SinSinCurvaturesMatchOracle) {
  // Reference values from docs (oracles.md), upward normal: (k1, k2).
  const SinSinSurface s;
  const struct {
    double x, y, k1, k2;
  } cases[] = {{0.0, 0.0, 1.0, -1.0},
               {std::numbers::pi / 2, std::numbers::pi / 2, -1.0, -1.0},
               {std::numbers::pi / 4, std::numbers::pi / 4, 0.0, -0.8164965809},
               {1.0, 0.5, 0.0372723271, -0.6406069216},
               {0.3, -1.2, 0.3813562401, -0.0354175195}};
  for (const auto& c : cases) {
    const auto [k1, k2] = s.principalCurvatures(c.x, c.y);
    EXPECT_NEAR(k1, c.k1, 1e-9) << c.x << ", " << c.y;
    EXPECT_NEAR(k2, c.k2, 1e-9) << c.x << ", " << c.y;
  }
  const auto [a1, a2] = SaddleSurface(0.3, 0.2).principalCurvatures(0.0, 0.0);
  EXPECT_NEAR(a1, 0.6, 1e-15);
  EXPECT_NEAR(a2, -0.4, 1e-15);
}

TEST(AnalyticSurface, GradientsMatchFiniteDifferencesAndNormalsAreUnit) {
  auto bump = std::make_shared<BSplinePatch>(makeBumpPatch({}));
  const std::vector<std::shared_ptr<const AnalyticSurface>> surfaces = {
      std::make_shared<PlaneSurface>(1.5),
      std::make_shared<SphereSurface>(7.0),
      std::make_shared<CylinderSurface>(4.0),
      std::make_shared<TorusSurface>(9.0, 3.0),
      std::make_shared<SaddleSurface>(0.1, 0.2),
      std::make_shared<SinSinSurface>(2.0, 3.0),
      bump,
      std::make_shared<RaisedHeightField>(bump, 0.4)};
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-12.0, 12.0);
  const double d = 1e-6;
  for (const auto& s : surfaces) {
    for (int n = 0; n < 50; ++n) {
      const Vec3 x(u(rng) + 1.0, u(rng) + 2.0, u(rng) + 0.5);  // off the axes (singular sets)
      Vec3 fd;
      for (int a = 0; a < 3; ++a)
        fd[a] = (s->value(x + d * Vec3::Unit(a)) - s->value(x - d * Vec3::Unit(a))) / (2 * d);
      EXPECT_LT((s->gradient(x) - fd).norm(), 1e-6) << s->name();
      Vec3 grad;
      EXPECT_DOUBLE_EQ(s->valueAndGradient(x, grad), s->value(x)) << s->name();
      EXPECT_LT((grad - s->gradient(x)).norm(), 1e-14) << s->name();
      EXPECT_NEAR(s->normal(x).norm(), 1.0, 1e-14);
      if (s->isDistance()) {
        EXPECT_NEAR(s->gradient(x).norm(), 1.0, 1e-12) << s->name();
      }
    }
    EXPECT_FALSE(s->name().empty());
  }
}

TEST(AnalyticSurface, DistanceSurfacesMeasureDistanceAlongTheNormal) {
  const TorusSurface torus(5.0, 2.0);
  const SphereSurface sphere(3.0);
  const CylinderSurface cylinder(2.5);
  for (double t : {-1.5, -0.3, 0.0, 0.7, 2.0}) {
    for (double u = 0.1; u < 6.2; u += 0.9) {
      for (double v = 0.2; v < 6.2; v += 0.8) {
        const Vec3 n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        EXPECT_NEAR(torus.value(torus.point(u, v) + t * n), t, 1e-12);
        EXPECT_NEAR(sphere.value(3.0 * n + t * n), t, 1e-12);
      }
      const Vec3 radial(std::cos(u), std::sin(u), 0.0);
      EXPECT_NEAR(cylinder.value((2.5 + t) * radial + Vec3(0, 0, u)), t, 1e-12);
    }
  }
  EXPECT_THROW(TorusSurface(2.0, 2.0), InvalidInput);
  EXPECT_THROW(SphereSurface(0.0), InvalidInput);
  EXPECT_THROW(CylinderSurface(-1.0), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
