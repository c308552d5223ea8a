// SPDX-License-Identifier: MIT
// Tests of the built-in scalar fields against analytic heights and distances.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/builtin_fields.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

TEST(BuiltinFields, HeightFieldIsTheHeights) {
  const auto gen = ddf::planePatch({.cellsX = 3, .cellsY = 2, .m = 5, .planeZMm = 0.4});
  const ScalarField field = heightField(gen.ddf);
  EXPECT_EQ(field.values, gen.ddf.allHeights());
  EXPECT_TRUE(field.isSigned);
  EXPECT_EQ(field.unit, "");
}

// A z-map with vectors (0, 0, L): h |v| is the height above the support plane, z of q.
TEST(BuiltinFields, HeightInMmIsTheHeightAboveThePlaneSupport) {
  const double length = 2.5;
  auto gen = ddf::planePatch(
      {.cellsX = 3, .cellsY = 2, .m = 7, .planeZMm = 0.5, .vectorLengthMm = length});
  ScalarField field = heightMmField(gen.ddf);
  ASSERT_EQ(field.values.size(), gen.ddf.allHeights().size());
  for (float v : field.values) EXPECT_NEAR(v, 0.5, 1e-6);
  EXPECT_EQ(field.unit, "mm");
  EXPECT_TRUE(field.isSigned);

  std::mt19937 rng(31);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (float& h : gen.ddf.allHeights()) h = u(rng);
  field = heightMmField(gen.ddf);
  const int n = gen.ddf.raster().steps();
  for (int f = 0; f < gen.ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const std::size_t l = f * gen.ddf.pointsPerFace() + gen.ddf.raster().index(i, k);
        EXPECT_NEAR(field.values[l], gen.ddf.surfacePoint(f, i, k).z(), 1e-6);
        EXPECT_NEAR(field.values[l], gen.ddf.allHeights()[l] * length, 1e-6);
      }
}

TEST(BuiltinFields, MaterialRemovedIsTheLoweringInMm) {
  const double length = 2.0;
  auto gen = ddf::planePatch(
      {.cellsX = 3, .cellsY = 2, .m = 5, .planeZMm = 0.6, .vectorLengthMm = length});
  const std::vector<float> stock = gen.ddf.allHeights();
  // Lower face f by 0.05 f (in h), i.e. by 0.1 f mm; raise face 0 by 0.1 mm.
  for (int f = 0; f < gen.ddf.faceCount(); ++f)
    for (float& h : gen.ddf.heights(f)) h -= f == 0 ? -0.05f : 0.05f * f;
  const ScalarField field = materialRemovedField(gen.ddf, stock);
  EXPECT_FALSE(field.isSigned);
  EXPECT_EQ(field.unit, "mm");
  for (int f = 0; f < gen.ddf.faceCount(); ++f)
    for (std::size_t l = 0; l < gen.ddf.pointsPerFace(); ++l)
      EXPECT_NEAR(field.values[f * gen.ddf.pointsPerFace() + l], f == 0 ? -0.1 : 0.1 * f, 1e-6);
  EXPECT_THROW(materialRemovedField(gen.ddf, std::span(stock).first(7)), InvalidInput);
}

struct SphereCase {
  ddf::GeneratedSurface part;
  ddf::TriangleMesh reference;  // inscribed icosphere of the same radius
  double sagMm = 0.0;           // largest distance between the reference and the sphere
};

SphereCase sphereCase() {
  const double r = 10.0;
  SphereCase c{
      ddf::spherePart({.radiusMm = r, .subdivisions = 2, .m = 5}),
      ddf::extractSupportMesh(ddf::spherePart({.radiusMm = r, .subdivisions = 5, .m = 2}).ddf)};
  // The mesh is convex: its nearest point to the centre lies on the nearest face plane.
  for (const auto& t : c.reference.triangles) {
    const Vec3 &a = c.reference.vertices[t[0]], &b = c.reference.vertices[t[1]],
               &d = c.reference.vertices[t[2]];
    c.sagMm = std::max(c.sagMm, r - std::abs(a.dot((b - a).cross(d - a).normalized())));
  }
  // Points on both sides of the sphere.
  std::mt19937 rng(32);
  std::uniform_real_distribution<float> u(-0.08f, 0.08f);
  for (float& h : c.part.ddf.allHeights()) h += u(rng);
  return c;
}

// Against an inscribed sphere mesh, deviation lies between |q| - R and |q| - R + sag.
TEST(BuiltinFields, DeviationFromASphereMeshIsTheRadialError) {
  const SphereCase c = sphereCase();
  ASSERT_LT(c.sagMm, 0.005);
  const ddf::DisplacementField& ddf = c.part.ddf;
  const ScalarField field = deviationField(ddf, c.reference);
  EXPECT_TRUE(field.isSigned);
  EXPECT_EQ(field.unit, "mm");
  ASSERT_EQ(field.values.size(), ddf.allHeights().size());
  const int n = ddf.raster().steps();
  int inside = 0, outside = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const double radial = ddf.surfacePoint(f, i, k).norm() - 10.0;
        const double d = field.values[f * ddf.pointsPerFace() + ddf.raster().index(i, k)];
        ASSERT_GE(d, radial - 1e-5) << "face " << f;
        ASSERT_LE(d, radial + c.sagMm + 1e-5) << "face " << f;
        if (radial < -c.sagMm - 1e-4) {
          ++inside;
          EXPECT_LT(d, 0.0);
        }
        if (radial > 1e-4) {
          ++outside;
          EXPECT_GT(d, 0.0);
        }
      }
  EXPECT_GT(inside, 500);
  EXPECT_GT(outside, 500);
}

TEST(BuiltinFields, DeviationReportsProgressAndCancels) {
  const SphereCase c = sphereCase();
  std::vector<double> seen;
  const auto caller = std::this_thread::get_id();
  bool otherThread = false;
  const ScalarField withProgress = deviationField(c.part.ddf, c.reference, [&](double x) {
    otherThread |= std::this_thread::get_id() != caller;
    seen.push_back(x);
    return true;
  });
  EXPECT_FALSE(otherThread);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(withProgress, deviationField(c.part.ddf, c.reference));

  int calls = 0;
  EXPECT_THROW(deviationField(c.part.ddf, c.reference, [&](double) { return ++calls < 2; }),
               Cancelled);
  EXPECT_EQ(calls, 2);
  EXPECT_THROW(deviationField(c.part.ddf, ddf::TriangleMesh{}), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
