// SPDX-License-Identifier: MIT
// Tests of workpiece construction (allowance, stock mesh) and of the removed-volume quadrature.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
constexpr double kPi = std::numbers::pi;

/// Largest |f(q)| over the represented points q of @p field.
template <class Fn>
double maxOver(const ddf::DisplacementField& field, Fn&& fn) {
  double worst = 0.0;
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k < field.resolution(); ++k)
      for (int i = 0; i + k < field.resolution(); ++i)
        worst = std::max(worst, std::abs(fn(field.surfacePoint(f, i, k))));
  return worst;
}

TEST(Workpiece, AllowanceOnACylinderIsTheOffsetCylinder) {
  const ddf::GeneratedSurface goal =
      ddf::cylinderPart({.radiusMm = 10.0, .segments = 48, .rings = 6});
  const double a = 0.4;
  const ddf::DisplacementField work = workpieceWithAllowance(goal.ddf, a);
  // Every raster point moves to radius r + a (the goal's points are on radius r).
  EXPECT_LT(maxOver(work, [&](const Vec3& q) { return std::hypot(q.x(), q.y()) - (10.0 + a); }),
            2e-4);
  // Removed-volume quadrature between the two: the shell pi ((r + a)^2 - r^2) x length.
  const double shell = kPi * ((10.0 + a) * (10.0 + a) - 100.0) * 30.0;
  EXPECT_NEAR(volumeBetween(work, work.allHeights(), goal.ddf.allHeights()), shell, 2e-3 * shell);
  EXPECT_NEAR(volumeBetween(work, goal.ddf.allHeights(), work.allHeights()), -shell, 2e-3 * shell);
}

TEST(Workpiece, AllowanceOnASphereIsTheOffsetSphere) {
  const ddf::GeneratedSurface goal = ddf::spherePart({.radiusMm = 10.0, .subdivisions = 2});
  const double a = 0.25;
  const ddf::DisplacementField work = workpieceWithAllowance(goal.ddf, a);
  EXPECT_LT(maxOver(work, [&](const Vec3& q) { return q.norm() - (10.0 + a); }), 5e-4);
  const double shell = 4.0 / 3.0 * kPi * (std::pow(10.0 + a, 3) - 1000.0);
  // The support is a 320-face polyhedron: the quadrature integrates the exact map from it.
  EXPECT_NEAR(volumeBetween(work, work.allHeights(), goal.ddf.allHeights()), shell, 5e-3 * shell);
}

TEST(Workpiece, AllowanceOnATiltedPlaneUsesTheNormalNotTheVector) {
  // Support z = 0 with vectors (0.5, 0, 1): v . n = 1, so dh = a and the surface rises by a.
  ddf::GeneratedSurface plane =
      ddf::planePatch({.size = {10.0, 10.0}, .cellsX = 2, .cellsY = 2, .m = 9, .planeZMm = 0.0});
  std::vector<Vec3> vectors(plane.ddf.vertexCount(), Vec3(0.5, 0.0, 1.0));
  plane.ddf.setVectors(vectors);
  const ddf::DisplacementField work = workpieceWithAllowance(plane.ddf, 0.3);
  EXPECT_LT(maxOver(work, [](const Vec3& q) { return q.z() - 0.3; }), 1e-6);
  EXPECT_NEAR(volumeBetween(work, work.allHeights(), plane.ddf.allHeights()), 0.3 * 100.0, 1e-4);
}

TEST(Workpiece, AllowanceBeyondTheCrustNamesAllowanceAndThickness) {
  const ddf::GeneratedSurface goal =
      ddf::cylinderPart({.radiusMm = 10.0, .segments = 24, .rings = 2, .m = 5});
  try {
    workpieceWithAllowance(goal.ddf, 6.0);  // crust half-thickness 5 mm
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("allowance of 6 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("mm thick"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(workpieceWithAllowance(goal.ddf, 4.5));
}

/// Two triangles covering [x0, x1] x [-5, 15] at height z, facing +z.
ddf::TriangleMesh stockPlane(double x0, double x1, double z) {
  ddf::TriangleMesh m;
  m.vertices = {{x0, -5.0, z}, {x1, -5.0, z}, {x1, 15.0, z}, {x0, 15.0, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(Workpiece, StockMeshFillsTheGoalSupport) {
  const ddf::GeneratedSurface goal =
      ddf::planePatch({.size = {10.0, 10.0}, .cellsX = 4, .cellsY = 4, .m = 9, .planeZMm = 0.0});
  const StockWorkpiece full = workpieceFromStockMesh(goal.ddf, stockPlane(-5.0, 15.0, 0.3));
  EXPECT_EQ(full.missing, 0u);
  for (float h : full.workpiece.allHeights()) EXPECT_NEAR(h, 0.3, 1e-6);
  // Half covered (x < 5.06, between raster columns): error, or a count of the rest.
  EXPECT_THROW(workpieceFromStockMesh(goal.ddf, stockPlane(-5.0, 5.06, 0.3)), InvalidInput);
  const StockWorkpiece half = workpieceFromStockMesh(goal.ddf, stockPlane(-5.0, 5.06, 0.3),
                                                     {.requireFullCoverage = false, .fill = {}});
  std::size_t expected = 0;
  for (int f = 0; f < goal.ddf.faceCount(); ++f)
    for (int k = 0; k < goal.ddf.resolution(); ++k)
      for (int i = 0; i + k < goal.ddf.resolution(); ++i) {
        const bool covered = goal.ddf.basePoint(f, goal.ddf.rasterBary(i, k)).x() < 5.06;
        expected += !covered;
        EXPECT_NEAR(half.workpiece.height(f, i, k), covered ? 0.3 : goal.ddf.height(f, i, k), 1e-6);
      }
  EXPECT_EQ(half.missing, expected);
}

}  // namespace
}  // namespace ddfcam::planning
