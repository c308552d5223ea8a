// SPDX-License-Identifier: MIT
// Tests of the crust reach and of fitting the crust to a stock allowance: closed forms on
// analytic planes, spheres and cylinders, the concave limit of the inside of a cylinder, and
// the represented surface before and after the fit by brute-force distance to the input.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <vector>

#include "../support/brute_force_distance.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

constexpr double kPi = std::numbers::pi;

double medianOf(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Reach above and below along the exact unit normal @p normal(q) at every raster point.
void exactReach(const DisplacementField& ddf, const std::function<Vec3(const Vec3&)>& normal,
                std::vector<double>& above, std::vector<double>& below) {
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= ddf.raster().steps(); ++k)
      for (int i = 0; i < ddf.raster().rowLength(k); ++i) {
        const Vec3 v = ddf.vectorAt(f, ddf.rasterBary(i, k));
        const double vn = v.dot(normal(ddf.surfacePoint(f, i, k)));
        const double h = ddf.height(f, i, k);
        above.push_back((1.0 - h) * vn);
        below.push_back((1.0 + h) * vn);
      }
}

void expectReachMatches(const DisplacementField& ddf,
                        const std::function<Vec3(const Vec3&)>& normal, double relTol) {
  std::vector<double> above, below;
  exactReach(ddf, normal, above, below);
  const CrustReach reach = crustReach(ddf);
  const double scale = medianOf(above);
  EXPECT_NEAR(reach.minAboveMm, *std::min_element(above.begin(), above.end()), relTol * scale);
  EXPECT_NEAR(reach.minBelowMm, *std::min_element(below.begin(), below.end()), relTol * scale);
  EXPECT_NEAR(reach.medianAboveMm, medianOf(above), relTol * scale);
  EXPECT_NEAR(reach.medianBelowMm, medianOf(below), relTol * scale);
}

TEST(CrustReach, PlaneIsTheRoomAboveAndBelowTheHeight) {
  const auto plane = planePatch({});  // z = 0.25 over z = 0, vectors (0, 0, 1)
  const CrustReach reach = crustReach(plane.ddf);
  EXPECT_NEAR(reach.minAboveMm, 0.75, 1e-6);
  EXPECT_NEAR(reach.medianAboveMm, 0.75, 1e-6);
  EXPECT_NEAR(reach.minBelowMm, 1.25, 1e-6);
  EXPECT_NEAR(reach.medianBelowMm, 1.25, 1e-6);
  EXPECT_GE(reach.minAboveFace, 0);
  EXPECT_NEAR(reach.minAbovePoint.z(), 0.25, 1e-6);
}

TEST(CrustReach, SphereAndCylinderMatchTheExactNormal) {
  SphereParams sp;
  sp.subdivisions = 2;
  sp.m = 9;
  const auto sphere = spherePart(sp);
  expectReachMatches(
      sphere.ddf, [](const Vec3& q) { return q.normalized(); }, 2e-3);
  // At the support vertices h = 0 and v is the radial vector of length R / 2.
  EXPECT_NEAR(crustReach(sphere.ddf).minAboveMm, 5.0, 0.5);
  CylinderParams cp;
  cp.m = 9;
  const auto cylinder = cylinderPart(cp);
  expectReachMatches(
      cylinder.ddf, [](const Vec3& q) { return Vec3(q.x(), q.y(), 0.0).normalized(); }, 2e-3);
}

// The inside (@p inside) or outside of a cylinder of radius r around z, 0 <= z <= length.
TriangleMesh cylinderMesh(double r, double length, int segments, int rings, bool inside) {
  TriangleMesh mesh;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * kPi * i / segments;
      mesh.vertices.emplace_back(r * std::cos(a), r * std::sin(a), length * j / rings);
    }
  const auto at = [segments](int i, int j) { return j * segments + i % segments; };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      std::array<int, 3> t1{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
      std::array<int, 3> t2{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
      if (inside) std::swap(t1[1], t1[2]), std::swap(t2[1], t2[2]);
      mesh.triangles.push_back(t1);
      mesh.triangles.push_back(t2);
    }
  return mesh;
}

TEST(ConcaveRadius, EstimatesTheRadiusOfAnalyticCylinders) {
  for (const double r : {2.0, 5.0}) {
    const TriangleMesh inside = cylinderMesh(r, 8.0, 64, 16, true);
    const Vec3 point(r, 0.0, 4.0);
    // The centroids of the 64 facets lie at r cos(pi / 64) (+- the facet's sag).
    EXPECT_NEAR(concaveRadiusNear(inside, point, 1.0), r, 0.01 * r) << "r = " << r;
    EXPECT_NEAR(concaveRadiusNear(inside, point, 3.0 * r), r, 0.01 * r) << "r = " << r;
    // Convex: no concave curvature beyond what the diagonals' shear leaves (radius >> r).
    EXPECT_GT(concaveRadiusNear(cylinderMesh(r, 8.0, 64, 16, false), point, 1.0), 20.0 * r);
  }
  const TriangleMesh flat =
      test::heightFieldMesh(0, 10, 0, 10, 10, 10, [](double, double) { return 0.0; });
  EXPECT_TRUE(std::isinf(concaveRadiusNear(flat, Vec3(5, 5, 0), 2.0)));
  EXPECT_THROW(concaveRadiusNear(flat, Vec3(5, 5, 0), 0.0), InvalidInput);
}

DisplacementField converted(const TriangleMesh& mesh, int resolution = 5) {
  ConversionParams params;
  params.resolution = resolution;
  return convertMeshToDdf(mesh, params).ddf;
}

// Largest brute-force distance of every @p stride-th raster point of @p ddf to @p mesh, and of
// every input vertex to the raster mesh of @p ddf.
double surfaceDeviation(const DisplacementField& ddf, const TriangleMesh& mesh, int stride = 1) {
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); f += stride)
    for (int k = 0; k <= ddf.raster().steps(); ++k)
      for (int i = 0; i < ddf.raster().rowLength(k); ++i)
        worst = std::max(worst, test::meshDistance(mesh, ddf.surfacePoint(f, i, k)));
  const TriangleMesh surface = extractRasterMesh(ddf).mesh;
  for (std::size_t v = 0; v < mesh.vertices.size(); v += stride)
    worst = std::max(worst, test::meshDistance(surface, mesh.vertices[v]));
  return worst;
}

void expectValid(const DisplacementField& ddf) {
  const ValidationReport report = validate(ddf);
  EXPECT_TRUE(report.ok()) << (report.issues.empty() ? "suppressed issues"
                                                     : report.issues.front().message);
}

TEST(StockCrust, ConcaveCylinderRefusesAStockBeyondItsRadius) {
  const TriangleMesh input = cylinderMesh(2.0, 8.0, 48, 16, true);
  DisplacementField ddf = converted(input);
  StockCrustParams params;
  params.stockMm = 3.0;
  const StockFit fit = fitCrustToStock(ddf, input, params);
  EXPECT_FALSE(fit.holds);
  ASSERT_TRUE(fit.limit.has_value());
  EXPECT_NEAR(fit.limit->concaveRadiusMm, 2.0, 0.2) << fit.limit->message;
  EXPECT_LT(fit.limit->largestAllowanceMm, 2.0);
  EXPECT_GT(fit.limit->largestAllowanceMm, 1.0);
  EXPECT_NE(fit.limit->message.find("concave there with radius"), std::string::npos)
      << fit.limit->message;
  EXPECT_NE(fit.limit->message.find("a stock of 3 mm"), std::string::npos) << fit.limit->message;
  std::cout << "refusal: " << fit.limit->message << "\n";
  expectValid(ddf);
  EXPECT_LT(surfaceDeviation(ddf, input, 3), 1e-4);
  // The largest allowance the refusal names is one the fitted crust does hold.
  EXPECT_NO_THROW(planning::workpieceWithAllowance(ddf, fit.limit->largestAllowanceMm));
  EXPECT_THROW(planning::workpieceWithAllowance(ddf, 3.0), InvalidInput);
}

TEST(StockCrust, ConcaveCylinderHoldsAStockBelowItsRadius) {
  const TriangleMesh input = cylinderMesh(2.0, 8.0, 48, 16, true);
  DisplacementField ddf = converted(input);
  const CrustReach before = crustReach(ddf);
  EXPECT_THROW(planning::workpieceWithAllowance(ddf, 1.0), InvalidInput);
  StockCrustParams params;
  params.stockMm = 1.0;
  const StockFit fit = fitCrustToStock(ddf, input, params);
  EXPECT_TRUE(fit.holds) << (fit.limit ? fit.limit->message : "");
  EXPECT_GE(fit.reach.minAboveMm, 1.0);
  EXPECT_GE(fit.reach.minBelowMm, before.minBelowMm * (1.0 - 1e-3));
  expectValid(ddf);
  EXPECT_LT(surfaceDeviation(ddf, input, 3), 1e-4);
  EXPECT_NO_THROW(planning::workpieceWithAllowance(ddf, 1.0));
}

struct ConvexCase {
  const char* name;
  TriangleMesh mesh;
  double stockMm;
};

TEST(StockCrust, ConvexPartsHoldALargeStockAndKeepTheirSurface) {
  SphereParams sp;
  sp.subdivisions = 2;
  sp.m = 2;
  SphereParams small = sp;
  small.radiusMm = 3.0;
  const std::vector<ConvexCase> cases = {
      {"sphere r 10", extractSupportMesh(spherePart(sp).ddf), 5.0},
      // The stock exceeds the radius: the inside limits the vectors, the support moves out.
      {"sphere r 3", extractSupportMesh(spherePart(small).ddf), 5.0},
      {"plane", test::heightFieldMesh(0, 20, 0, 20, 8, 8, [](double, double) { return 0.0; }),
       10.0}};
  for (const auto& c : cases) {
    DisplacementField ddf = converted(c.mesh);
    const CrustReach before = crustReach(ddf);
    StockCrustParams params;
    params.stockMm = c.stockMm;
    const StockFit fit = fitCrustToStock(ddf, c.mesh, params);
    EXPECT_TRUE(fit.holds) << c.name << ": " << (fit.limit ? fit.limit->message : "");
    EXPECT_GE(fit.reach.minAboveMm, c.stockMm) << c.name;
    EXPECT_GE(fit.reach.minBelowMm, before.minBelowMm * (1.0 - 1e-3)) << c.name;
    expectValid(ddf);
    EXPECT_LT(surfaceDeviation(ddf, c.mesh), 1e-4) << c.name;
    EXPECT_NO_THROW(planning::workpieceWithAllowance(ddf, c.stockMm)) << c.name;
  }
}

TEST(StockCrust, SharpConcaveCreaseHoldsAStockWithChosenDirections) {
  // A 90 degree concave crease: with vectors near the two sides' normals the stubbles of the
  // faces next to it converge within about an edge length, so only directions that turn
  // gradually towards the bisector let the crust reach far above it.
  const TriangleMesh input =
      test::heightFieldMesh(-6, 6, 0, 4, 12, 4, [](double x, double) { return std::abs(x); });
  StockCrustParams params;
  params.stockMm = 1.5;
  DisplacementField fixedDirections = converted(input);
  const CrustReach before = crustReach(fixedDirections);
  params.chooseDirections = false;
  const StockFit fixedFit = fitCrustToStock(fixedDirections, input, params);
  DisplacementField ddf = converted(input);
  params.chooseDirections = true;
  params.smoothingPasses = 24;
  const StockFit fit = fitCrustToStock(ddf, input, params);
  std::cout << "crease: reach above before " << before.minAboveMm << " mm, converted directions "
            << fixedFit.reach.minAboveMm << " mm, chosen directions " << fit.reach.minAboveMm
            << " mm\n";
  EXPECT_FALSE(fixedFit.holds);
  EXPECT_TRUE(fit.holds) << (fit.limit ? fit.limit->message : "");
  EXPECT_GE(fit.reach.minAboveMm, params.stockMm);
  EXPECT_GE(fit.reach.minBelowMm, before.minBelowMm * (1.0 - 1e-3));
  expectValid(ddf);
  EXPECT_LT(surfaceDeviation(ddf, input), 1e-4);
  EXPECT_NO_THROW(planning::workpieceWithAllowance(ddf, params.stockMm));
}

TEST(StockCrust, RejectsANonPositiveStock) {
  const TriangleMesh input =
      test::heightFieldMesh(0, 4, 0, 4, 2, 2, [](double, double) { return 0.0; });
  DisplacementField ddf = converted(input);
  StockCrustParams params;
  EXPECT_THROW(fitCrustToStock(ddf, input, params), InvalidInput);
  params.stockMm = -1.0;
  EXPECT_THROW(fitCrustToStock(ddf, input, params), InvalidInput);
}

TEST(StockCrust, RejectsAFoldRepairAngleOutsideItsRange) {
  const TriangleMesh input =
      test::heightFieldMesh(0, 4, 0, 4, 2, 2, [](double, double) { return 0.0; });
  StockCrustParams params;
  params.stockMm = 1.0;
  for (const double angleDeg : {30.0, 90.0}) {  // below maxAngleDeg (45), and grazing
    DisplacementField ddf = converted(input);
    params.foldRepairAngleDeg = angleDeg;
    EXPECT_THROW(fitCrustToStock(ddf, input, params), InvalidInput) << angleDeg;
  }
  DisplacementField ddf = converted(input);
  params.foldRepairAngleDeg = params.maxAngleDeg;
  EXPECT_TRUE(fitCrustToStock(ddf, input, params).holds);
}

}  // namespace
}  // namespace ddfcam::ddf
