// SPDX-License-Identifier: MIT
// ddfcam tests: rigid alignment by point pairs (Kabsch) and by trimmed point-to-plane ICP.
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/surface_alignment.h>

#include <gtest/gtest.h>

#include "../../support/test_meshes.h"

#include <cmath>
#include <numbers>
#include <random>

namespace ddfcam::planning {
namespace {

using Eigen::Vector3d;

Eigen::Isometry3d knownTransform(double angleRad, const Vector3d& axis, const Vector3d& shift) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(angleRad, axis.normalized()).toRotationMatrix();
  t.translation() = shift;
  return t;
}

double transformError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double radius) {
  // Largest displacement difference over a ball of @p radius (rotation part times radius).
  return (a.linear() - b.linear()).norm() * radius + (a.translation() - b.translation()).norm();
}

// z = 8 sin(x / 15) + 0.004 (x - 10) y^2 + 3 cos(y / 11) on a 90 x 70 mm grid: no symmetry
// that would let ICP slide.
ddf::TriangleMesh analyticSurface(int n) {
  return test::heightFieldMesh(-45.0, 45.0, -35.0, 35.0, n, n, [](double x, double y) {
    return 8.0 * std::sin(x / 15.0) + 0.004 * (x - 10.0) * y * y + 3.0 * std::cos(y / 11.0);
  });
}

TEST(SurfaceAlignment, ThreePairsRecoverKnownTransformExactly) {
  const auto truth = knownTransform(0.7, {1, 2, -0.5}, {12.0, -4.0, 30.0});
  const std::vector<Vector3d> from = {{0, 0, 0}, {100, 0, 5}, {20, 60, -3}};
  std::vector<std::array<Vector3d, 2>> pairs;
  for (const auto& p : from) pairs.push_back({p, truth * p});
  const RigidAlignment a = alignByPointPairs(pairs);
  EXPECT_LT(transformError(a.transform, truth, 100.0), 1e-9);
  EXPECT_LT(a.rmsMm, 1e-9);
  EXPECT_GT(a.rmsBeforeMm, 1.0);
  EXPECT_NEAR(rotationAngleDeg(a.transform), 0.7 * 180.0 / std::numbers::pi, 1e-9);
}

TEST(SurfaceAlignment, ManyNoisyPairsRecoverTransformWithinNoise) {
  const auto truth = knownTransform(-0.3, {0.2, -1, 0.4}, {-5.0, 8.0, 2.0});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<std::array<Vector3d, 2>> pairs;
  for (int i = 0; i < 400; ++i) {
    const Vector3d p(coord(rng), coord(rng), coord(rng));
    pairs.push_back({p, truth * p + Vector3d(noise(rng), noise(rng), noise(rng))});
  }
  const RigidAlignment a = alignByPointPairs(pairs);
  // Estimation error of a least-squares fit ~ sigma / sqrt(N) per parameter.
  EXPECT_LT(transformError(a.transform, truth, 100.0), 0.05);
  EXPECT_NEAR(a.rmsMm, 0.05 * std::sqrt(3.0), 0.01);
}

TEST(SurfaceAlignment, MirroredPairsGiveARotationNotAReflection) {
  std::vector<std::array<Vector3d, 2>> pairs;
  for (const Vector3d& p :
       {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1), Vector3d(1, 1, 1)})
    pairs.push_back({p, Vector3d(-p.x(), p.y(), p.z())});
  const RigidAlignment a = alignByPointPairs(pairs);
  EXPECT_NEAR(a.transform.linear().determinant(), 1.0, 1e-12);
}

TEST(SurfaceAlignment, CollinearOrTooFewPairsAreRefused) {
  std::vector<std::array<Vector3d, 2>> collinear;
  for (int i = 0; i < 5; ++i)
    collinear.push_back({Vector3d(i, 2.0 * i, -i), Vector3d(i, 0, 3.0 * i)});
  EXPECT_THROW(alignByPointPairs(collinear), InvalidInput);
  collinear.resize(2);
  EXPECT_THROW(alignByPointPairs(collinear), InvalidInput);
}

TEST(SurfaceAlignment, BestFitRecoversSmallTransformOfAnalyticSurface) {
  const ddf::TriangleMesh fixed = analyticSurface(60);
  const auto truth = knownTransform(0.04, {0.3, 1.0, 0.2}, {1.5, -1.0, 0.8});
  // moving = truth^-1 (fixed), so aligning moving onto fixed must return truth.
  const ddf::TriangleMesh moving = analyticSurface(37).transformed(truth.inverse());
  BestFitParams params;
  params.trimFraction = 0.05;
  params.toleranceMm = 1e-6;
  params.maxIterations = 100;
  const RigidAlignment a = alignBestFit(moving, fixed, params);
  EXPECT_TRUE(a.converged);
  EXPECT_LT(transformError(a.transform, truth, 50.0), 0.05);
  EXPECT_LT(a.rmsMm, 0.05);  // residual = the two samplings' chord errors
  EXPECT_GT(a.rmsBeforeMm, 0.5);
}

TEST(SurfaceAlignment, BestFitRefusesBadParametersAndCancels) {
  const ddf::TriangleMesh mesh = analyticSurface(10);
  BestFitParams bad;
  bad.trimFraction = 0.95;
  EXPECT_THROW(alignBestFit(mesh, mesh, bad), InvalidInput);
  BestFitParams cancel;
  cancel.progress = [](double) { return false; };
  EXPECT_THROW(alignBestFit(mesh, mesh, cancel), Cancelled);
}

TEST(SurfaceAlignment, RowMajorRoundTrip) {
  const auto t = knownTransform(1.1, {1, 1, 0}, {3, 4, 5});
  const auto m = toRowMajor(t);
  EXPECT_EQ(m[3], 3.0);
  EXPECT_EQ(m[15], 1.0);
  EXPECT_LT((fromRowMajor(m).matrix() - t.matrix()).norm(), 1e-15);
}

}  // namespace
}  // namespace ddfcam::planning
