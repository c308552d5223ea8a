// SPDX-License-Identifier: MIT
// ddfcam tests: compareSurfaces against analytic deviations (sine sheet, concentric spheres).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/surface_comparison.h>

#include <gtest/gtest.h>

#include "../../support/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

/// Grid mesh of z = height(x, y) over [x0, x1] x [y0, y1] with cells of @p cell mm.
ddf::TriangleMesh gridMesh(double x0, double x1, double y0, double y1, double cell,
                           const std::function<double(double, double)>& height) {
  const int nx = static_cast<int>(std::lround((x1 - x0) / cell));
  const int ny = static_cast<int>(std::lround((y1 - y0) / cell));
  return test::heightFieldMesh(x0, x1, y0, y1, nx, ny, height);
}

constexpr double kA = 1.0;   // sine amplitude, mm
constexpr double kL = 40.0;  // sine wavelength, mm (one full period on the mould)

ddf::TriangleMesh flatMould() {
  return gridMesh(0.0, kL, 0.0, 10.0, 0.5, [](double, double) { return 0.0; });
}

// Slightly larger than the mould so every stubble, also on the mould's border, meets it.
ddf::TriangleMesh sineSheet() {
  return gridMesh(-1.0, kL + 1.0, -1.0, 11.0, 0.25,
                  [](double x, double) { return kA * std::sin(2.0 * std::numbers::pi * x / kL); });
}

ddf::TriangleMesh icosphere(double radius) {
  ddf::SphereParams params;
  params.subdivisions = 3;
  params.m = 2;
  ddf::TriangleMesh mesh = ddf::extractSupportMesh(ddf::spherePart(params).ddf);
  for (Vec3& v : mesh.vertices) v *= radius / params.radiusMm;
  return mesh;
}

ComparisonParams sineParams() {
  ComparisonParams params;
  params.resolution = 4;
  params.band = {-0.5, 0.5};
  params.sequence.reachMm = 1.5;  // > A: the crust holds the sheet (keeps the test fast)
  return params;
}

TEST(SurfaceComparison, SineSheetStatisticsMatchAnalyticArea) {
  const SurfaceComparison cmp = compareSurfaces(flatMould(), sineSheet(), sineParams());
  const ErrorStatistics& s = cmp.statistics;
  // Oracle: share of one period with |A sin| <= tol is (2/pi) asin(tol/A) = 33.33 %. Raster
  // spacing on the mould is 0.5/3 mm; each of the 4 class boundaries per period misplaces at
  // most one spacing of area: 4 x (1/6) / 40 = 1.7 % of the area.
  const double expected = 100.0 * 2.0 / std::numbers::pi * std::asin(0.5 / kA);
  EXPECT_NEAR(expected, 33.333, 1e-3);
  EXPECT_NEAR(s.inTolerancePercent, expected, 1.7);
  EXPECT_NEAR(s.materialLeftPercent, s.overcutPercent, 1.7);  // symmetric about 0
  EXPECT_NEAR(s.meanMm, 0.0, 0.01);
  EXPECT_NEAR(s.sigmaMm, kA / std::sqrt(2.0), 0.01);
  // Peaks at x = 10, 30 are raster points; the sheet's chords lose A (2 pi/L)^2 (0.25)^2/8 ~ 2e-4.
  EXPECT_NEAR(s.maxMm, kA, 2e-3);
  EXPECT_NEAR(s.minMm, -kA, 2e-3);
  EXPECT_NEAR(s.areaMm2, kL * 10.0, 1e-6 * kL * 10.0);
  EXPECT_EQ(cmp.sequence.missingPoints, 0u);
  EXPECT_TRUE(cmp.sequence.crossingFaces.empty());
}

// Oracle: a full recomputation with the new band and orientation.
TEST(SurfaceComparison, NewBandAndFlippedNormalEqualAFullRecomputation) {
  SurfaceComparison cmp = compareSurfaces(flatMould(), sineSheet(), sineParams());
  ComparisonParams other = sineParams();
  other.band = {-0.1, 0.9};
  other.flipNormal = true;
  const SurfaceComparison full = compareSurfaces(flatMould(), sineSheet(), other);
  updateComparisonBand(cmp, other.band, true);
  // A sine spends (asin(0.9) + asin(0.1)) / pi of its period in [-0.1, 0.9] (33.3 % in +-0.5).
  const double share = 100.0 * (std::asin(0.9) + std::asin(0.1)) / std::numbers::pi;
  EXPECT_NEAR(cmp.statistics.inTolerancePercent, share, 1.7);
  EXPECT_EQ(cmp.deviation, full.deviation);
  EXPECT_EQ(cmp.band.lowerMm, -0.1);
  EXPECT_EQ(cmp.statistics.inTolerancePercent, full.statistics.inTolerancePercent);
  EXPECT_EQ(cmp.statistics.overcutPercent, full.statistics.overcutPercent);
  EXPECT_EQ(cmp.statistics.sigmaMm, full.statistics.sigmaMm);
  EXPECT_THROW(updateComparisonBand(cmp, {0.1, 0.2}, false), InvalidInput);
}

TEST(SurfaceComparison, SineSheetDeviationIsHeightAndVectorsAreVertical) {
  const SurfaceComparison cmp = compareSurfaces(flatMould(), sineSheet(), sineParams());
  ASSERT_EQ(cmp.deviationVectors.size(), cmp.deviation.values.size());
  const ddf::DisplacementField& ddf = cmp.sequence.stages.at(0).ddf;
  const int n = ddf.raster().steps();
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        const Vec3& d = cmp.deviationVectors[l];
        ASSERT_TRUE(d.allFinite());
        EXPECT_GE(d.norm() + 1e-6, std::abs(cmp.deviation.values[l]));
        EXPECT_NEAR(d.x(), 0.0, 1e-6);
        EXPECT_NEAR(d.y(), 0.0, 1e-6);
        worst = std::max(worst, std::abs(cmp.deviation.values[l] -
                                         kA * std::sin(2.0 * std::numbers::pi * g.x() / kL)));
      }
  }
  EXPECT_LT(worst, 2e-3);  // chord error of the 0.25 mm sheet plus float rounding
  const ScalarField region = crossingRegionField(cmp);
  EXPECT_EQ(region.values.size(), cmp.deviation.values.size());
  for (float v : region.values) EXPECT_EQ(v, 0.0f);
}

TEST(SurfaceComparison, ConcentricSpheresDeviateByTheRadiusDifference) {
  const double radius = 10.0, d = 0.5;
  ComparisonParams params;
  params.resolution = 3;
  params.sequence.reachMm = 2.0 * d;
  const ddf::TriangleMesh mould = icosphere(radius);
  // Facets: g lies up to the sagitta s below the sphere, so |q - g| = d |g| / R, and the face
  // normal leans from the radius by at most ~edge/R (0.13 rad): 1 - cos < 1 %. Bound 2 % of d.
  for (const double sign : {1.0, -1.0}) {
    const SurfaceComparison cmp = compareSurfaces(mould, icosphere(radius + sign * d), params);
    EXPECT_EQ(cmp.sequence.missingPoints, 0u);
    for (float v : cmp.deviation.values) ASSERT_NEAR(v, sign * d, 0.02 * d);
    EXPECT_NEAR(cmp.statistics.meanMm, sign * d, 0.02 * d);
    EXPECT_LT(cmp.statistics.sigmaMm, 0.01 * d);
    params.flipNormal = true;
    const SurfaceComparison flipped = compareSurfaces(mould, icosphere(radius + sign * d), params);
    for (float v : flipped.deviation.values) ASSERT_NEAR(v, -sign * d, 0.02 * d);
    params.flipNormal = false;
  }
}

TEST(SurfaceComparison, RasterPointNormalsOfSphereAreRadial) {
  ddf::SphereParams sphere;
  sphere.subdivisions = 2;
  sphere.m = 4;
  const ddf::DisplacementField ddf = ddf::spherePart(sphere).ddf;
  const std::vector<Vec3> normals = rasterPointNormals(ddf);
  ASSERT_EQ(normals.size(), ddf.allHeights().size());
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        EXPECT_NEAR(normals[l].norm(), 1.0, 1e-9);
        // Raster points lie on the sphere; the surrounding raster triangles' chords tilt the
        // normal by at most about one raster spacing over R (edge ~2.6 mm / 3 / 10 mm).
        EXPECT_GT(normals[l].dot(ddf.surfacePoint(f, i, k).normalized()), std::cos(0.1));
      }
  }
}

TEST(SurfaceComparison, ConversionWithoutLengthsKeepsUnitDirectionsAndZeroHeights) {
  ddf::ConversionParams params;
  params.resolution = 3;
  params.chooseLengths = false;
  const ddf::ConversionResult converted = ddf::convertMeshToDdf(icosphere(10.0), params);
  for (int v = 0; v < converted.ddf.vertexCount(); ++v) {
    EXPECT_NEAR(converted.ddf.vector(v).norm(), 1.0, 1e-9);
    // Outward: the icosphere's vertices are radial, so is its pseudo-normal up to the facets.
    EXPECT_GT(converted.ddf.vector(v).dot(converted.ddf.position(v).normalized()), 0.99);
  }
  for (float h : converted.ddf.allHeights()) EXPECT_EQ(h, 0.0f);
  EXPECT_EQ(converted.filledPoints, 0u);
}

TEST(SurfaceComparison, RejectsBadInput) {
  const ddf::TriangleMesh mould = flatMould();
  const ddf::TriangleMesh empty;
  EXPECT_THROW(compareSurfaces(empty, sineSheet()), InvalidInput);
  EXPECT_THROW(compareSurfaces(mould, empty), InvalidInput);
  ComparisonParams bad;
  bad.resolution = 1;
  EXPECT_THROW(compareSurfaces(mould, sineSheet(), bad), InvalidInput);
  bad = {};
  bad.band = {0.1, 0.5};
  EXPECT_THROW(compareSurfaces(mould, sineSheet(), bad), InvalidInput);
  // A sheet 1000 mm to the side: no stubble of the mould can meet it.
  const ddf::TriangleMesh away =
      gridMesh(1000.0, 1040.0, 0.0, 10.0, 1.0, [](double, double) { return 0.5; });
  ComparisonParams near;
  near.sequence.reachMm = 2.0;
  try {
    compareSurfaces(mould, away, near);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("do not overlap"), std::string::npos) << what;
    EXPECT_NE(what.find("3200 triangles"), std::string::npos) << what;  // the mould
    EXPECT_NE(what.find("800 triangles"), std::string::npos) << what;   // the sheet
  }
}

}  // namespace
}  // namespace ddfcam::planning
