// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/v_projection.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

struct Face {
  std::array<Vec3, 3> p;
  std::array<Vec3, 3> v;
};

/// A random triangle with vectors leaning up to ~45 degrees off its normal, lengths 0.3..1.5.
Face randomFace(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), len(0.3, 1.5);
  Face f;
  for (auto& p : f.p) p = Vec3(u(rng), u(rng), 0.3 * u(rng));
  const Vec3 n = (f.p[1] - f.p[0]).cross(f.p[2] - f.p[0]).normalized();
  for (auto& v : f.v) {
    do {
      v = n + 0.8 * Vec3(u(rng), u(rng), u(rng));
    } while (v.normalized().dot(n) < 0.5);
    v = v.normalized() * len(rng);
  }
  return f;
}

Vec3 phi(const Face& f, double mu1, double mu2, double h) {
  const double mu3 = 1.0 - mu1 - mu2;
  return mu1 * (f.p[0] + h * f.v[0]) + mu2 * (f.p[1] + h * f.v[1]) + mu3 * (f.p[2] + h * f.v[2]);
}

/// Determinant of the finite-difference Jacobian of Phi(mu1, mu2, h).
double jacobianDet(const Face& f, double mu1, double mu2, double h) {
  const double e = 1e-6;
  Eigen::Matrix3d j;
  j.col(0) = (phi(f, mu1 + e, mu2, h) - phi(f, mu1 - e, mu2, h)) / (2 * e);
  j.col(1) = (phi(f, mu1, mu2 + e, h) - phi(f, mu1, mu2 - e, h)) / (2 * e);
  j.col(2) = (phi(f, mu1, mu2, h + e) - phi(f, mu1, mu2, h - e)) / (2 * e);
  return j.determinant();
}

/// Whether the Jacobian determinant at some grid point of the simplex has left the sign it has
/// at h = 0 (grid of n steps per edge, vertices included).
bool jacobianFlipped(const Face& f, double h, int n) {
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double mu1 = double(i) / n, mu2 = double(j) / n;
      if (jacobianDet(f, mu1, mu2, h) * jacobianDet(f, mu1, mu2, 0.0) <= 0.0) return true;
    }
  return false;
}

/// First h in (0, hMax] (direction sign) where the Jacobian flips: fixed steps, then bisection.
double bruteForceH0(const Face& f, double sign, double hMax) {
  const int steps = 400, grid = 24;
  double lo = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double h = hMax * k / steps;
    if (!jacobianFlipped(f, sign * h, grid)) {
      lo = h;
      continue;
    }
    double hi = h;
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (lo + hi);
      (jacobianFlipped(f, sign * mid, grid) ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
  return std::numeric_limits<double>::infinity();
}

CrustHeights heightsOf(const Face& f) {
  return crustHeights(f.p[0], f.p[1], f.p[2], f.v[0], f.v[1], f.v[2]);
}

TEST(Crust, AnalyticHeights) {
  // Parallel vectors: no bound on either side.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), up(0, 0, 1);
  auto parallel = crustHeights(a, b, c, up, up, up);
  EXPECT_TRUE(std::isinf(parallel.positive) && std::isinf(parallel.negative));
  // Stubbles aimed at the eye e = (0.2, 0.3, 2): they meet there at h = 1; below, they fan.
  const Vec3 e(0.2, 0.3, 2);
  auto perspective = crustHeights(a, b, c, e - a, e - b, e - c);
  EXPECT_NEAR(perspective.positive, 1.0, 1e-6);
  EXPECT_TRUE(std::isinf(perspective.negative));
  // Triangle on a sphere of radius 5 with outward unit radial vectors: they meet at the centre,
  // 5 units below.
  const Vec3 s1 = Vec3(1, 0.2, 0.1).normalized() * 5, s2 = Vec3(0.1, 1, 0.3).normalized() * 5,
             s3 = Vec3(0.2, 0.1, 1).normalized() * 5;
  auto sphere = crustHeights(s1, s2, s3, s1 / 5, s2 / 5, s3 / 5);
  EXPECT_NEAR(sphere.negative, 5.0, 1e-6);
  EXPECT_TRUE(std::isinf(sphere.positive));
  // Constraint 1 violated: a vector on the back side.
  auto bad = crustHeights(a, b, c, up, up, -up + Vec3(0.1, 0, 0));
  EXPECT_EQ(bad.min(), 0.0);
}

TEST(Crust, MatchesFiniteDifferenceJacobianSearch) {
  std::mt19937 rng(101);
  int finite = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Face f = randomFace(rng);
    const auto h0 = heightsOf(f);
    for (double sign : {1.0, -1.0}) {
      const double expected = sign > 0 ? h0.positive : h0.negative;
      const double brute = bruteForceH0(f, sign, 8.0);
      if (std::isinf(brute)) {
        EXPECT_GT(expected, 8.0 * (1 - 1e-9)) << trial << " side " << sign;
        continue;
      }
      ++finite;
      EXPECT_NEAR(expected, brute, 1e-3 * brute) << trial << " side " << sign;
    }
  }
  EXPECT_GE(finite, 8);
}

/// Number of V-projections of x onto f with mu inside and h' in [0, h] (h > 0).
int projectionsInCrust(const Face& f, const Vec3& x, double h) {
  const auto sols = vProject(x, f.p[0], f.p[1], f.p[2], f.v[0], f.v[1], f.v[2]);
  int n = 0;
  for (const auto& s : sols) n += s.mu.minCoeff() >= -1e-7 && s.h >= -1e-7 && s.h <= h + 1e-7;
  return n;
}

/// Sample barycentric points: a regular grid plus points refined geometrically towards the
/// three corners, where a fold of the crust starts (the Jacobian first vanishes at a corner).
std::vector<Vec3> densePoints() {
  std::vector<Vec3> out;
  const int n = 16;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) out.emplace_back(double(i) / n, double(j) / n, 0.0);
  for (int c = 0; c < 3; ++c)
    for (double s : {1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.2})
      for (double a = 0.1; a < 1.0; a += 0.2) {
        Vec3 mu = Vec3::Zero();
        mu[c] = 1.0 - s, mu[(c + 1) % 3] = s * a, mu[(c + 2) % 3] = s * (1.0 - a);
        out.push_back(mu);
      }
  for (Vec3& mu : out) mu[2] = 1.0 - mu[0] - mu[1];
  return out;
}

/// Largest number of crust projections over a dense sample of points of the h-crust.
int maxProjectionsInCrust(const Face& f, double h) {
  static const std::vector<Vec3> points = densePoints();
  int worst = 0;
  const int levels = 16;
  for (const Vec3& mu : points)
    for (int l = 0; l <= levels; ++l) {
      const Vec3 x = phi(f, mu[0], mu[1], h * l / levels);
      worst = std::max(worst, projectionsInCrust(f, x, h));
    }
  return worst;
}

/// Largest number of crust projections (h' in [0, h]) of points just past the fold of the
/// h-crust: along each sampled stubble, the first sign change of the finite-difference Jacobian
/// is bracketed and points slightly above it are tested. A fold doubles the cover on one side,
/// but only in a thin layer that uniform sampling misses.
int maxProjectionsPastFold(const Face& f, double h) {
  static const std::vector<Vec3> points = densePoints();
  int worst = 0;
  for (const Vec3& mu : points) {
    if (mu.minCoeff() <= 0.0) continue;  // interior stubbles only
    const double j0 = jacobianDet(f, mu[0], mu[1], 0.0);
    double lo = 0.0, hi = -1.0;
    for (int k = 1; k <= 64 && hi < 0; ++k) {
      const double hk = h * k / 64;
      (jacobianDet(f, mu[0], mu[1], hk) * j0 > 0.0 ? lo : hi) = hk;
    }
    if (hi < 0) continue;
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (jacobianDet(f, mu[0], mu[1], mid) * j0 > 0.0 ? lo : hi) = mid;
    }
    for (double delta : {1e-4, 1e-3, 1e-2}) {
      const double hf = std::min(hi * (1.0 + delta), h);
      worst = std::max(worst, projectionsInCrust(f, phi(f, mu[0], mu[1], hf), h));
    }
  }
  return worst;
}

TEST(Crust, UniqueProjectionBelowH0AndFoldAbove) {
  std::mt19937 rng(7);
  int tested = 0;
  for (int trial = 0; trial < 40 && tested < 10; ++trial) {
    Face f = randomFace(rng);
    const double h0 = heightsOf(f).positive;
    if (!std::isfinite(h0) || h0 > 20) continue;
    ++tested;
    EXPECT_EQ(maxProjectionsInCrust(f, 0.97 * h0), 1) << trial;
    EXPECT_GT(maxProjectionsPastFold(f, 1.3 * h0), 1) << trial;
  }
  EXPECT_EQ(tested, 10);
}

TEST(Crust, AllHeightsOfDdfMatchPerFace) {
  const auto mesh = test::octahedronMesh(2.0);
  DisplacementField ddf(mesh, test::radialVectors(mesh, 0.5), 3);
  const auto all = allCrustHeights(ddf);
  ASSERT_EQ(all.size(), 8u);
  for (int f = 0; f < 8; ++f) {
    // Radial vectors of a polyhedron around the origin: stubbles meet at the centre, 4 units
    // of 0.5 mm below the 2 mm vertices.
    EXPECT_NEAR(all[f].negative, 4.0, 1e-7);  // a double root: ~sqrt(eps) accuracy
    EXPECT_TRUE(std::isinf(all[f].positive));
  }
}

}  // namespace
}  // namespace ddfcam::ddf
