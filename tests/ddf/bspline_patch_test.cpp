// SPDX-License-Identifier: MIT
// The bicubic B-spline patch against Cox-de Boor, finite differences and affine reproduction.
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

/// Cox-de Boor recursion for the B-spline basis of degree p on knot vector t (the textbook
/// definition, independent of the closed-form span polynomials used by BSplinePatch).
double coxDeBoor(const std::vector<double>& t, int i, int p, double x) {
  if (p == 0) return (t[i] <= x && x < t[i + 1]) ? 1.0 : 0.0;
  const double left = (x - t[i]) / (t[i + p] - t[i]) * coxDeBoor(t, i, p - 1, x);
  const double right =
      (t[i + p + 1] - x) / (t[i + p + 1] - t[i + 1]) * coxDeBoor(t, i + 1, p - 1, x);
  return left + right;
}

/// Uniform knots x0 + (i - 3) h, i = 0..spans + 6: basis i is centred at x0 + (i - 1) h.
std::vector<double> uniformKnots(double x0, double h, int spans) {
  std::vector<double> t;
  for (int i = 0; i <= spans + 6; ++i) t.push_back(x0 + (i - 3) * h);
  return t;
}

Eigen::MatrixXd randomControl(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dist(-3.0, 3.0);
  Eigen::MatrixXd c(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) c(i, j) = dist(rng);
  return c;
}

TEST(BSplinePatch, MatchesCoxDeBoorTensorProduct) {
  const int sx = 5, sy = 4;
  const Eigen::Vector2d origin(-3.0, 2.0), size(25.0, 12.0);
  const BSplinePatch patch(origin, size, randomControl(sx + 3, sy + 3, 7));
  const auto tx = uniformKnots(origin.x(), size.x() / sx, sx);
  const auto ty = uniformKnots(origin.y(), size.y() / sy, sy);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(0.0, 1.0);
  for (int s = 0; s < 200; ++s) {
    const double x = origin.x() + ux(rng) * size.x(), y = origin.y() + ux(rng) * size.y();
    double expected = 0.0;
    for (int i = 0; i < sx + 3; ++i)
      for (int j = 0; j < sy + 3; ++j)
        expected += patch.control()(i, j) * coxDeBoor(tx, i, 3, x) * coxDeBoor(ty, j, 3, y);
    EXPECT_NEAR(patch.height(x, y), expected, 1e-12) << "at " << x << ", " << y;
    EXPECT_NEAR(patch.evaluate(x, y).f, expected, 1e-12);
  }
}

TEST(BSplinePatch, DerivativesMatchFiniteDifferences) {
  const BSplinePatch patch({0.0, 0.0}, {40.0, 30.0}, randomControl(9, 8, 3));
  std::mt19937 rng(5);
  // Includes points beyond the rectangle, where the boundary polynomials are continued.
  std::uniform_real_distribution<double> ux(-5.0, 45.0), uy(-5.0, 35.0);
  const double d = 1e-4;
  for (int s = 0; s < 200; ++s) {
    double x = ux(rng), y = uy(rng);
    // Central differences straddling a knot see two polynomial pieces of a C2 spline; the
    // second difference is still O(d) accurate there, so only the tolerance below matters.
    const HeightDerivatives e = patch.evaluate(x, y);
    auto f = [&](double a, double b) { return patch.height(a, b); };
    const double fx = (f(x + d, y) - f(x - d, y)) / (2 * d);
    const double fy = (f(x, y + d) - f(x, y - d)) / (2 * d);
    const double fxx = (f(x + d, y) - 2 * f(x, y) + f(x - d, y)) / (d * d);
    const double fyy = (f(x, y + d) - 2 * f(x, y) + f(x, y - d)) / (d * d);
    const double fxy =
        (f(x + d, y + d) - f(x + d, y - d) - f(x - d, y + d) + f(x - d, y - d)) / (4 * d * d);
    EXPECT_NEAR(e.fx, fx, 1e-7) << x << ", " << y;
    EXPECT_NEAR(e.fy, fy, 1e-7) << x << ", " << y;
    EXPECT_NEAR(e.fxx, fxx, 2e-4) << x << ", " << y;
    EXPECT_NEAR(e.fyy, fyy, 2e-4) << x << ", " << y;
    EXPECT_NEAR(e.fxy, fxy, 2e-4) << x << ", " << y;
  }
}

TEST(BSplinePatch, PartitionOfUnityAndAffineReproduction) {
  const int sx = 7, sy = 5;
  const Eigen::Vector2d origin(10.0, -4.0), size(35.0, 20.0);
  const BSplinePatch probe(origin, size, Eigen::MatrixXd::Zero(sx + 3, sy + 3));
  Eigen::MatrixXd constant = Eigen::MatrixXd::Constant(sx + 3, sy + 3, 2.5);
  Eigen::MatrixXd planar(sx + 3, sy + 3);
  const double a = 1.25, b = -0.3, c = 0.7;
  for (int i = 0; i < sx + 3; ++i)
    for (int j = 0; j < sy + 3; ++j) {
      const Eigen::Vector2d g = probe.controlAbscissa(i, j);
      planar(i, j) = a + b * g.x() + c * g.y();
    }
  const BSplinePatch flat(origin, size, constant), plane(origin, size, planar);
  for (double x = origin.x() - 3.0; x <= origin.x() + size.x() + 3.0; x += 0.37) {
    for (double y = origin.y() - 3.0; y <= origin.y() + size.y() + 3.0; y += 0.41) {
      EXPECT_NEAR(flat.height(x, y), 2.5, 1e-13);
      const HeightDerivatives e = plane.evaluate(x, y);
      EXPECT_NEAR(e.f, a + b * x + c * y, 1e-12) << x << ", " << y;
      EXPECT_NEAR(e.fx, b, 1e-13);
      EXPECT_NEAR(e.fy, c, 1e-13);
      EXPECT_NEAR(e.fxx, 0.0, 1e-13);
      EXPECT_NEAR(e.fxy, 0.0, 1e-13);
      EXPECT_NEAR(e.fyy, 0.0, 1e-13);
    }
  }
}

TEST(BSplinePatch, RejectsBadInput) {
  EXPECT_THROW(BSplinePatch({0, 0}, {0.0, 1.0}, Eigen::MatrixXd::Zero(4, 4)), InvalidInput);
  EXPECT_THROW(BSplinePatch({0, 0}, {1.0, 1.0}, Eigen::MatrixXd::Zero(3, 4)), InvalidInput);
  BumpPatchParams p;
  p.spansY = 0;
  EXPECT_THROW(makeBumpPatch(p), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
