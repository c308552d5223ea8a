// SPDX-License-Identifier: MIT
// Tests of the vector and support warps (fig. 9.2) and of the morph mesh against analytic truth.
#include <ddfcam/ddf/ddf_warp.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "surface_fixtures.h"

namespace ddfcam::ddf {
namespace {

// Surface points q of every copy, computed from the DDF's accessors (allHeights() layout).
std::vector<Vec3> copyPoints(const DisplacementField& ddf) {
  std::vector<Vec3> out;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) out.push_back(ddf.surfacePoint(f, i, k));
  return out;
}

// Groove profile as the header documents it: cos^2(pi d / w) x depth inside |d| < w / 2.
double documentedDepth(const EngravedPlateParams& p, double x, double y) {
  auto groove = [&](double d) {
    return std::abs(d) < p.grooveWidthMm / 2
               ? p.depthMm * std::pow(std::cos(std::numbers::pi * d / p.grooveWidthMm), 2)
               : 0.0;
  };
  double depth = p.straightGroove ? groove(y) : 0.0;
  for (int k = 1; k <= p.ringCount; ++k)
    depth = std::max(depth, groove(std::hypot(x, y) - k * p.ringSpacingMm));
  return depth;
}

TEST(DdfWarp, EngravedPlateFollowsTheDocumentedProfile) {
  const EngravedPlateParams params;
  const DisplacementField plate = engravedPlate(params);
  double deepest = 0.0;
  for (const Vec3& q : copyPoints(plate)) {
    ASSERT_NEAR(q.z(), -documentedDepth(params, q.x(), q.y()), 1e-5);
    // The straight groove's centre line y = 0 is a grid line (even subdivision).
    if (std::abs(q.y()) < 1e-12) { EXPECT_NEAR(q.z(), -params.depthMm, 1e-6); }
    deepest = std::min(deepest, q.z());
  }
  EXPECT_NEAR(deepest, -params.depthMm, 1e-6);
}

TEST(DdfWarp, ScalingByThreeTriplesAndMinusThreeReversesTheEngravings) {
  const DisplacementField plate = engravedPlate();
  const std::vector<Vec3> before = copyPoints(plate);
  for (const double factor : {3.0, -3.0}) {
    DisplacementField scaled = plate;
    scaleVectors(scaled, factor);
    const std::vector<Vec3> after = copyPoints(scaled);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t c = 0; c < after.size(); ++c) {
      EXPECT_DOUBLE_EQ(after[c].x(), before[c].x());
      EXPECT_DOUBLE_EQ(after[c].y(), before[c].y());
      ASSERT_NEAR(after[c].z(), factor * before[c].z(), 1e-12);  // z = factor h |v|
    }
  }
}

TEST(DdfWarp, ScalingByZeroOrNanIsRejected) {
  DisplacementField plate = engravedPlate();
  EXPECT_THROW(scaleVectors(plate, 0.0), InvalidInput);
  EXPECT_THROW(scaleVectors(plate, std::numeric_limits<double>::quiet_NaN()), InvalidInput);
}

// The plate (x along the bend, +z vectors) wrapped onto the cylinder of radius R about the axis
// x = 0, z = -R: vertices at radius R, surface points at R + h |v|, arc length R phi = x.
TEST(DdfWarp, CylinderWarpKeepsRadiusArcLengthAndDepth) {
  EngravedPlateParams plateParams;
  plateParams.resolution = 5;
  const DisplacementField plate = engravedPlate(plateParams);
  DisplacementField bent = plate;
  const double r = 40.0;  // the 100 mm plate covers 2.5 rad
  mapSupportOntoCylinder(bent, {.radiusMm = r});
  const Vec3 axis(0.0, 0.0, -r);
  auto radial = [&](const Vec3& p) { return std::hypot(p.x() - axis.x(), p.z() - axis.z()); };
  const int n = plate.raster().steps();
  for (int f = 0; f < plate.faceCount(); ++f) {
    const auto& fv = plate.faceVertices(f);
    // Local vertex p1 is raster point (n, 0).
    const Vec3 p0 = plate.position(fv[0]), p1 = bent.position(fv[0]);
    ASSERT_NEAR(radial(p1), r, 1e-9);
    EXPECT_NEAR(p1.y(), p0.y(), 1e-12);
    EXPECT_NEAR(r * std::atan2(p1.x(), p1.z() + r), p0.x(), 1e-9);
    const double h = plate.height(f, n, 0);
    EXPECT_NEAR(radial(bent.surfacePoint(f, n, 0)), r + h * plateParams.vectorLengthMm, 1e-9);
    // Raster points between vertices lie on chords: at most the sagitta inside the cylinder.
    const double cell = plateParams.sizeMm / plateParams.subdivisions;
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i + k <= n; ++i) {
        const double rg = radial(bent.basePoint(f, bent.rasterBary(i, k)));
        ASSERT_LE(rg, r + 1e-9);
        ASSERT_GE(rg, r * std::cos(cell / (2.0 * r)) - 1e-9);
      }
    }
  }
}

TEST(DdfWarp, CylinderWarpRejectsImpossibleBends) {
  DisplacementField plate = engravedPlate();
  EXPECT_THROW(mapSupportOntoCylinder(plate, {.radiusMm = 0.0}), InvalidInput);
  EXPECT_THROW(mapSupportOntoCylinder(plate, {.radiusMm = 10.0}), InvalidInput);  // > 2 pi R
  EXPECT_THROW(mapSupportOntoCylinder(plate, {.axisDirection = Vec3::UnitX()}), InvalidInput);
}

TEST(DdfWarp, MorphMeshOfSurfacePointsEqualsTheRasterMesh) {
  for (const int m : {2, 4}) {
    // Disagreeing shared copies: both must take the lowest-index face's copy.
    const DisplacementField field = test::bumpyOctahedronDdf(m, 0.01);
    const RasterMesh expected = extractRasterMesh(field);
    const TriangleMesh got = morphMesh(field, copyPoints(field));
    ASSERT_EQ(got.vertices.size(), expected.mesh.vertices.size());
    for (std::size_t v = 0; v < got.vertices.size(); ++v)
      EXPECT_EQ(got.vertices[v], expected.mesh.vertices[v]);
    EXPECT_EQ(got.triangles, expected.mesh.triangles);
  }
}

TEST(DdfWarp, MorphMeshOfZeroHeightsIsTheRasterMeshOfTheSupport) {
  DisplacementField plate = engravedPlate({.resolution = 4});
  std::fill(plate.allHeights().begin(), plate.allHeights().end(), 0.0f);
  const std::vector<float> zeros(plate.allHeights().size(), 0.0f);
  const TriangleMesh got = morphMesh(plate, heightPositions(plate, zeros));
  const RasterMesh expected = extractRasterMesh(plate);
  EXPECT_EQ(got.triangles, expected.mesh.triangles);
  ASSERT_EQ(got.vertices.size(), expected.mesh.vertices.size());
  for (std::size_t v = 0; v < got.vertices.size(); ++v)
    EXPECT_EQ(got.vertices[v], expected.mesh.vertices[v]);
}

TEST(DdfWarp, MorphMeshDropsTrianglesAtNanPoints) {
  const DisplacementField field = test::bumpyOctahedronDdf(5);
  std::vector<Vec3> points = copyPoints(field);
  // Raster point (1, 1) of face 0 is interior (m = 5): one vertex, six lattice triangles.
  points[field.raster().index(1, 1)] = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const TriangleMesh got = morphMesh(field, points);
  const RasterMesh full = extractRasterMesh(field);
  EXPECT_EQ(got.vertices.size(), full.mesh.vertices.size() - 1);
  EXPECT_EQ(got.triangles.size(), full.mesh.triangles.size() - 6);
  for (const Vec3& v : got.vertices) EXPECT_TRUE(v.allFinite());
  EXPECT_THROW(morphMesh(field, std::span(points).first(3)), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
