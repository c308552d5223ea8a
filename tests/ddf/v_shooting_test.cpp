// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/v_shooting.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

#include "../support/random_geometry.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

using test::randomBary;
using test::randomVec;

TEST(VShooting, HitsPlaneParallelToSupportAtKnownHeight) {
  // Support in z = 0 with vectors (0, 0, 0.5); target in z = 2 above: h = 2 / 0.5 = 4.
  const Vec3 p1(0, 0, 0), p2(2, 0, 0), p3(0, 2, 0), v(0, 0, 0.5);
  const Vec3 q1(-1, -1, 2), q2(3, -1, 2), q3(-1, 3, 2);
  const Vec3 mu(0.5, 0.25, 0.25);  // the point (0.5, 0.5, 0)
  const auto shot = vShoot(p1, p2, p3, v, v, v, mu, q1, q2, q3);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->h, 4.0, 1e-14);
  // (0.5, 0.5, 2) = q1 + 0.375 (q2 - q1) + 0.375 (q3 - q1).
  EXPECT_NEAR(shot->lambda[0], 0.25, 1e-14);
  EXPECT_NEAR(shot->lambda[1], 0.375, 1e-14);
  EXPECT_NEAR(shot->lambda[2], 0.375, 1e-14);
}

TEST(VShooting, HitPointLiesOnTargetAndOnStubble) {
  std::mt19937 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p1 = randomVec(rng), p2 = randomVec(rng), p3 = randomVec(rng);
    const Vec3 v1 = randomVec(rng), v2 = randomVec(rng), v3 = randomVec(rng);
    const Vec3 q1 = randomVec(rng, 3), q2 = randomVec(rng, 3), q3 = randomVec(rng, 3);
    const Vec3 mu = randomBary(rng);
    const auto shot = vShoot(p1, p2, p3, v1, v2, v3, mu, q1, q2, q3);
    const Vec3 p = mu[0] * p1 + mu[1] * p2 + mu[2] * p3;
    const Vec3 v = mu[0] * v1 + mu[1] * v2 + mu[2] * v3;
    const Vec3 n = (q2 - q1).cross(q3 - q1);
    if (std::abs(v.normalized().dot(n.normalized())) < 1e-3) continue;  // ill-conditioned
    ASSERT_TRUE(shot) << trial;
    const Vec3 q = p + shot->h * v;
    const Vec3 fromLambda = shot->lambda[0] * q1 + shot->lambda[1] * q2 + shot->lambda[2] * q3;
    const double scale = 1.0 + q.norm();
    EXPECT_NEAR(shot->lambda.sum(), 1.0, 1e-9) << trial;
    EXPECT_NEAR((q - fromLambda).norm() / scale, 0.0, 1e-8) << trial;
    EXPECT_NEAR((q - q1).dot(n.normalized()) / scale, 0.0, 1e-8) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 1900);
}

TEST(VShooting, ParallelOrDegenerateGivesNoHit) {
  const Vec3 p1(0, 0, 0), p2(1, 0, 0), p3(0, 1, 0), v(0, 0, 1);
  const Vec3 mu = Vec3::Constant(1.0 / 3.0);
  // Target plane x = 5 contains the direction (0, 0, 1).
  EXPECT_FALSE(vShoot(p1, p2, p3, v, v, v, mu, {5, 0, 0}, {5, 1, 0}, {5, 0, 1}));
  // Collinear target.
  EXPECT_FALSE(vShoot(p1, p2, p3, v, v, v, mu, {0, 0, 1}, {1, 1, 1}, {2, 2, 1}));
  EXPECT_FALSE(VShooter::make(p1, p2, p3, v, v, v, {0, 0, 1}, {1, 1, 1}, {2, 2, 1}));
}

TEST(VShooting, TargetPlaneThroughOriginAndFarTranslationAgree) {
  // The dissertation's |q1 q2 q3| vanishes for a target plane through the origin; the affine
  // form does not care, and a translation by 1e6 mm changes nothing beyond rounding.
  const Vec3 p1(0, 0, -1), p2(1, 0, -1), p3(0, 1, -1);
  const Vec3 v1(0, 0, 1), v2(0.1, 0, 1), v3(0, 0.1, 1);
  const Vec3 q1(-2, -2, 0), q2(2, -2, 0), q3(0, 3, 0);  // plane z = 0 through the origin
  const Vec3 mu(0.2, 0.3, 0.5);
  // Analytic: p = (0.3, 0.5, -1), v = (0.03, 0.05, 1): h = 1, q = (0.33, 0.55, 0).
  const auto shot = vShoot(p1, p2, p3, v1, v2, v3, mu, q1, q2, q3);
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->h, 1.0, 1e-14);
  const Vec3 q = shot->lambda[0] * q1 + shot->lambda[1] * q2 + shot->lambda[2] * q3;
  EXPECT_NEAR((q - Vec3(0.33, 0.55, 0)).norm(), 0.0, 1e-14);
  const Vec3 t(1e6, -2e6, 3e6);
  const auto far = vShoot(p1 + t, p2 + t, p3 + t, v1, v2, v3, mu, q1 + t, q2 + t, q3 + t);
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->h, 1.0, 1e-9);
  EXPECT_NEAR((far->lambda - shot->lambda).norm(), 0.0, 1e-9);
}

TEST(VShooting, PreparedShooterMatchesDirectShots) {
  std::mt19937 rng(5);
  const Vec3 p1 = randomVec(rng), p2 = randomVec(rng), p3 = randomVec(rng);
  const Vec3 v1(0.1, 0, 1), v2(0, 0.2, 1), v3(-0.1, 0.1, 1);
  const Vec3 q1(-3, -3, 4), q2(3, -3, 5), q3(0, 3, 4.5);
  const auto shooter = VShooter::make(p1, p2, p3, v1, v2, v3, q1, q2, q3);
  ASSERT_TRUE(shooter);
  for (int k = 0; k < 100; ++k) {
    const Vec3 mu = randomBary(rng);
    const auto a = vShoot(p1, p2, p3, v1, v2, v3, mu, q1, q2, q3);
    const auto b = shooter->shoot(mu);
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(a->h, b->h, 1e-12);
    EXPECT_NEAR((a->lambda - b->lambda).norm(), 0.0, 1e-12);
  }
}

TEST(VShooting, DdfOverloadUsesFaceVertexOrder) {
  const auto mesh = test::gridMesh(1, 1, 2.0, 2.0);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 0.25}), 3);
  const Vec3 mu(0.2, 0.3, 0.5);
  const Vec3 p = ddf.basePoint(1, mu);
  const auto shot = vShoot(ddf, 1, mu, {-5, -5, 1}, {5, -5, 1}, {0, 5, 1});
  ASSERT_TRUE(shot);
  EXPECT_NEAR(shot->h, 4.0, 1e-14);
  const auto line = vShootLine(p, {0, 0, 0.25}, {-5, -5, 1}, {5, -5, 1}, {0, 5, 1});
  ASSERT_TRUE(line);
  EXPECT_NEAR((line->lambda - shot->lambda).norm(), 0.0, 1e-14);
}

}  // namespace
}  // namespace ddfcam::ddf
