// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/v_projection.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <random>

#include "../support/random_geometry.h"

namespace ddfcam::ddf {
namespace {

using test::randomBary;
using test::randomVec;

/// The 4x4 determinant of sec. 4.1, evaluated by Eigen (the oracle for root counting).
double det4(const Vec3& q, const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& v, double h) {
  Eigen::Matrix4d m;
  for (int i = 0; i < 3; ++i) m.col(i) << p[i] + h * v[i], 1.0;
  m.col(3) << q, 1.0;
  return m.determinant();
}

TEST(RealCubicRoots, SimpleMultipleAndDegenerate) {
  auto near = [](const std::vector<double>& r, const std::vector<double>& e, double tol) {
    ASSERT_EQ(r.size(), e.size());
    for (std::size_t i = 0; i < e.size(); ++i) EXPECT_NEAR(r[i], e[i], tol);
  };
  near(realCubicRoots(-6, 11, -6, 1), {1, 2, 3}, 1e-13);  // (x-1)(x-2)(x-3)
  near(realCubicRoots(2, -3, 0, 1), {-2, 1}, 1e-7);       // (x-1)^2 (x+2)
  near(realCubicRoots(-1, 3, -3, 1), {1}, 1e-5);          // (x-1)^3
  near(realCubicRoots(1, 0, 1, 0), {}, 0);                // x^2 + 1
  near(realCubicRoots(-2, 1, 0, 0), {2}, 1e-15);          // linear
  near(realCubicRoots(-4, 0, 1, 1e-20), {-2, 2}, 1e-12);  // leading coefficient ~ 0
  EXPECT_TRUE(realCubicRoots(0, 0, 0, 0).empty());
}

TEST(RealCubicRoots, WidelySpreadRootsAreAccurate) {
  // (x - 1e-3)(x - 1)(x + 1e4): roots over seven orders of magnitude.
  const double a = 1e-3, b = 1.0, c = -1e4;
  const auto r = realCubicRoots(-a * b * c, a * b + b * c + a * c, -(a + b + c), 1.0);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], c, 1e-9 * 1e4);
  EXPECT_NEAR(r[1], a, 1e-12);
  EXPECT_NEAR(r[2], b, 1e-12);
}

TEST(VProjection, ProjectionOfShotPointReturnsItsOrigin) {
  std::mt19937 rng(3);
  int found = 0, total = 0;
  for (int face = 0; face < 200; ++face) {
    const std::array<Vec3, 3> p = {randomVec(rng), randomVec(rng), randomVec(rng)};
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    std::array<Vec3, 3> v;
    for (auto& vi : v) vi = (n + 0.7 * randomVec(rng)) * (0.3 + std::abs(randomVec(rng)[0]));
    for (int k = 0; k < 25; ++k) {
      const Vec3 mu = randomBary(rng);
      const double h = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
      const Vec3 q =
          mu[0] * (p[0] + h * v[0]) + mu[1] * (p[1] + h * v[1]) + mu[2] * (p[2] + h * v[2]);
      const auto sols = vProject(q, p[0], p[1], p[2], v[0], v[1], v[2]);
      ++total;
      for (const auto& s : sols) {
        if (std::abs(s.h - h) < 1e-8 && (s.mu - mu).norm() < 1e-8) {
          EXPECT_TRUE(s.inside);
          ++found;
          break;
        }
      }
    }
  }
  EXPECT_EQ(found, total);
}

TEST(VProjection, ThreeSolutionsUnderAffineMaps) {
  // a_i = p_i - q = e_i and v_i = -e_i / i: det = (1 - h)(1 - h/2)(1 - h/3), solutions at
  // h = 1, 2, 3 with mu = e_1, e_2, e_3. A linear map L applied to all a_i and v_i scales the
  // determinant by det L and keeps roots and mu; a translation moves nothing.
  std::mt19937 rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Matrix3d l = Eigen::Matrix3d::Identity();
    if (trial > 0)
      for (int c = 0; c < 3; ++c) l.col(c) = randomVec(rng, 2.0);
    if (std::abs(l.determinant()) < 0.1) continue;
    const Vec3 q = randomVec(rng, 100.0);
    const auto sols = vProject(q, q + l.col(0), q + l.col(1), q + l.col(2), -l.col(0),
                               -l.col(1) / 2.0, -l.col(2) / 3.0);
    ASSERT_EQ(sols.size(), 3u) << trial;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(sols[i].h, i + 1.0, 1e-9) << trial;
      EXPECT_NEAR((sols[i].mu - Vec3::Unit(i)).norm(), 0.0, 1e-9) << trial;
      EXPECT_TRUE(sols[i].inside);
    }
  }
}

TEST(VProjection, ParallelVectorsGiveTheParallelProjection) {
  // Equal vectors: the h^2 and h^3 coefficients vanish; exactly one solution, found by hand:
  // support z = 0, v = (0.5, 0, 2): q = (3, 1, 4) comes from h = 2, foot (2, 1, 0).
  const Vec3 v(0.5, 0, 2);
  const Vec3 p1(0, 0, 0), p2(4, 0, 0), p3(0, 4, 0);
  const auto sols = vProject({3, 1, 4}, p1, p2, p3, v, v, v);
  ASSERT_EQ(sols.size(), 1u);
  EXPECT_NEAR(sols[0].h, 2.0, 1e-13);
  EXPECT_NEAR((sols[0].mu - Vec3(0.25, 0.5, 0.25)).norm(), 0.0, 1e-13);
  // Two equal vectors and a third parallel one of another length: the cubic term vanishes.
  const auto two = vProject({1, 1, 2}, p1, p2, p3, {0, 0, 1}, {0, 0, 1}, {0, 0, 3});
  ASSERT_FALSE(two.empty());
  for (const auto& s : two) {
    const Vec3 x = s.mu[0] * (p1 + s.h * Vec3(0, 0, 1)) + s.mu[1] * (p2 + s.h * Vec3(0, 0, 1)) +
                   s.mu[2] * (p3 + s.h * Vec3(0, 0, 3));
    EXPECT_NEAR((x - Vec3(1, 1, 2)).norm(), 0.0, 1e-12);
  }
}

TEST(VProjection, SolutionCountMatchesDeterminantSignChanges) {
  std::mt19937 rng(23);
  int threeRootCases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::array<Vec3, 3> p = {randomVec(rng), randomVec(rng), randomVec(rng)};
    const std::array<Vec3, 3> v = {randomVec(rng), randomVec(rng), randomVec(rng)};
    const Vec3 q = randomVec(rng, 2.0);
    const auto sols = vProject(q, p[0], p[1], p[2], v[0], v[1], v[2]);
    // Every solution satisfies the defining equations.
    for (const auto& s : sols) {
      const Vec3 x = s.mu[0] * (p[0] + s.h * v[0]) + s.mu[1] * (p[1] + s.h * v[1]) +
                     s.mu[2] * (p[2] + s.h * v[2]);
      EXPECT_NEAR((x - q).norm(), 0.0, 1e-9 * (1.0 + std::abs(s.h)));
      EXPECT_NEAR(s.mu.sum(), 1.0, 1e-12);
    }
    // Sign changes of the 4x4 determinant on a fine h grid count the roots in [-H, H].
    const double range = 20.0;
    int changes = 0;
    double prev = det4(q, p, v, -range);
    for (int k = 1; k <= 8000; ++k) {
      const double cur = det4(q, p, v, -range + 2.0 * range * k / 8000.0);
      if ((prev < 0) != (cur < 0)) ++changes;
      prev = cur;
    }
    int inRange = 0;
    bool resolvable = true;  // the grid separates roots farther apart than its step
    for (std::size_t i = 0; i < sols.size(); ++i) {
      inRange += std::abs(sols[i].h) < range;
      resolvable &= std::abs(std::abs(sols[i].h) - range) > 0.02;
      if (i > 0) resolvable &= sols[i].h - sols[i - 1].h > 0.02;
    }
    if (!resolvable) continue;
    EXPECT_EQ(changes, inRange) << trial;
    threeRootCases += inRange == 3;
  }
  EXPECT_GT(threeRootCases, 5);
}

}  // namespace
}  // namespace ddfcam::ddf
