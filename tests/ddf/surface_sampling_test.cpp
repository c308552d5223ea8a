// SPDX-License-Identifier: MIT
// Tests of sampling per-raster-point values on the DDF surface against raster truths.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "../support/random_geometry.h"

namespace ddfcam::ddf {
namespace {

// A plane, a sphere and a saddle: parallel, radial and normal-field vectors.
struct NamedSurface {
  std::string name;
  GeneratedSurface gen;
};

std::vector<NamedSurface> testSurfaces() {
  std::vector<NamedSurface> out;
  out.push_back({"plane", planePatch({.cellsX = 4, .cellsY = 3, .m = 9, .planeZMm = 0.3})});
  out.push_back({"sphere", spherePart({.subdivisions = 1, .m = 9})});
  out.push_back({"saddle", saddlePatch({.grid = {.cellsX = 5, .cellsY = 5, .m = 9}})});
  return out;
}

std::vector<float> randomValues(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  std::vector<float> v(count);
  for (float& x : v) x = u(rng);
  return v;
}

// Lowest-index face holding a copy of every raster point, by brute force over all copies.
std::vector<int> lowestFaces(const DisplacementField& ddf) {
  const int n = ddf.raster().steps();
  std::vector<int> lowest(ddf.topology().pointCount(), std::numeric_limits<int>::max());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        int& l = lowest[ddf.topology().id(f, i, k)];
        l = std::min(l, f);
      }
  return lowest;
}

TEST(SurfaceSampling, InterpolationIsExactAtRasterPoints) {
  std::mt19937 rng(1);
  for (const auto& [name, gen] : testSurfaces()) {
    const DisplacementField& ddf = gen.ddf;
    const std::vector<float> values = randomValues(ddf.allHeights().size(), rng);
    const int n = ddf.raster().steps();
    for (int f = 0; f < ddf.faceCount(); f += 7)
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i) {
          const double expected = values[f * ddf.pointsPerFace() + ddf.raster().index(i, k)];
          const Vec3 bary(double(i) / n, double(n - i - k) / n, double(k) / n);
          ASSERT_EQ(interpolateOnFace(ddf, values, f, bary), expected)
              << name << " face " << f << " (" << i << ", " << k << ")";
          ASSERT_EQ(interpolateOnFace(ddf, values, f, ddf.rasterBary(i, k)), expected);
        }
  }
}

// A linear function of the lattice coordinates (i, k) is reproduced everywhere.
TEST(SurfaceSampling, InterpolationReproducesLinearFunctions) {
  std::mt19937 rng(2);
  const auto gen = spherePart({.subdivisions = 1, .m = 9});
  const DisplacementField& ddf = gen.ddf;
  const int n = ddf.raster().steps();
  auto linear = [](double i, double k) { return 0.5 + 0.25 * i - 0.125 * k; };
  std::vector<float> values(ddf.allHeights().size());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        values[f * ddf.pointsPerFace() + ddf.raster().index(i, k)] =
            static_cast<float>(linear(i, k));
  for (int trial = 0; trial < 2000; ++trial) {
    const int f = trial % ddf.faceCount();
    const Vec3 mu = test::randomBary(rng);
    ASSERT_NEAR(interpolateOnFace(ddf, values, f, mu), linear(mu[0] * n, mu[2] * n), 1e-12);
  }
}

// Piecewise linear over the raster triangles: the centroid of an "up" cell (a,c), (a+1,c),
// (a,c+1) and of a "down" cell (a+1,c+1), (a,c+1), (a+1,c) gets the mean of its corners.
TEST(SurfaceSampling, InterpolationIsLinearOverEachRasterTriangle) {
  std::mt19937 rng(3);
  const auto gen = saddlePatch({.grid = {.cellsX = 3, .cellsY = 3, .m = 7}});
  const DisplacementField& ddf = gen.ddf;
  const std::vector<float> values = randomValues(ddf.allHeights().size(), rng);
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    auto v = [&](int i, int k) {
      return double(values[f * ddf.pointsPerFace() + ddf.raster().index(i, k)]);
    };
    auto at = [&](double i, double k) {
      return interpolateOnFace(ddf, values, f, Vec3(i / n, (n - i - k) / n, k / n));
    };
    for (int c = 0; c < n; ++c)
      for (int a = 0; a + c < n; ++a) {
        const double up = (v(a, c) + v(a + 1, c) + v(a, c + 1)) / 3.0;
        ASSERT_NEAR(at(a + 1.0 / 3, c + 1.0 / 3), up, 1e-12) << "face " << f;
        if (a + c + 2 > n) continue;
        const double down = (v(a + 1, c + 1) + v(a, c + 1) + v(a + 1, c)) / 3.0;
        ASSERT_NEAR(at(a + 2.0 / 3, c + 2.0 / 3), down, 1e-12) << "face " << f;
      }
  }
}

TEST(SurfaceSampling, InterpolationClampsAndValidates) {
  std::mt19937 rng(4);
  const auto gen = planePatch({.cellsX = 2, .cellsY = 2, .m = 5});
  const DisplacementField& ddf = gen.ddf;
  const std::vector<float> values = randomValues(ddf.allHeights().size(), rng);
  // Just outside edge i = 0 at its midpoint (a raster point for n = 4): the edge value.
  const double onEdge = values[3 * ddf.pointsPerFace() + ddf.raster().index(0, 2)];
  EXPECT_NEAR(interpolateOnFace(ddf, values, 3, Vec3(-1e-10, 0.5, 0.5 + 1e-10)), onEdge, 1e-8);
  // Beyond vertex p3: the vertex value.
  const double atP3 = values[3 * ddf.pointsPerFace() + ddf.raster().index(0, 4)];
  EXPECT_EQ(interpolateOnFace(ddf, values, 3, Vec3(-0.01, -0.02, 1.03)), atP3);
  EXPECT_THROW(interpolateOnFace(ddf, std::span(values).first(10), 0, Vec3(1, 0, 0)), InvalidInput);
  EXPECT_THROW(interpolateOnFace(ddf, values, ddf.faceCount(), Vec3(1, 0, 0)), InvalidInput);
  EXPECT_THROW(interpolateOnFace(ddf, values, -1, Vec3(1, 0, 0)), InvalidInput);
}

// NaN marks "no value": it reaches only the raster triangles around its point.
TEST(SurfaceSampling, NoValueStaysInItsRasterTriangles) {
  const auto gen = planePatch({.cellsX = 1, .cellsY = 1, .m = 5});
  const DisplacementField& ddf = gen.ddf;
  std::vector<float> values(ddf.allHeights().size(), 2.0f);
  values[ddf.raster().index(1, 1)] = std::numeric_limits<float>::quiet_NaN();  // face 0
  auto at = [&](double i, double k) {
    return interpolateOnFace(ddf, values, 0, Vec3(i / 4, (4 - i - k) / 4, k / 4));
  };
  EXPECT_EQ(at(2, 1), 2.0);
  EXPECT_EQ(at(0, 1), 2.0);
  EXPECT_EQ(at(1.5, 0), 2.0);  // on the lattice edge (1, 0)-(2, 0), away from (1, 1)
  EXPECT_TRUE(std::isnan(at(1, 1)));
  EXPECT_TRUE(std::isnan(at(1 + 1.0 / 3, 1 + 1.0 / 3)));
  EXPECT_EQ(at(2 + 1.0 / 3, 0 + 1.0 / 3), 2.0);
}

TEST(SurfaceSampling, LocatesRasterSurfacePoints) {
  for (const auto& [name, gen] : testSurfaces()) {
    const DisplacementField& ddf = gen.ddf;
    const int n = ddf.raster().steps();
    for (int f = 0; f < ddf.faceCount(); f += 5)
      for (int k = 0; k <= n; k += 2)
        for (int i = 0; i + k <= n; i += 3) {
          const Vec3 q = ddf.surfacePoint(f, i, k);
          const auto loc = locateOnFace(ddf, f, q);
          ASSERT_TRUE(loc) << name << " face " << f;
          EXPECT_EQ(loc->face, f);
          const Vec3 bary(double(i) / n, double(n - i - k) / n, double(k) / n);
          EXPECT_LT((loc->bary - bary).norm(), 1e-9) << name << " face " << f;
          EXPECT_NEAR(loc->h, ddf.height(f, i, k), 1e-9);
          EXPECT_LT((loc->point - q).norm(), 1e-9) << name << " face " << f;
        }
  }
}

// A point moved off the surface along its stubble is located at the stubble's foot, on the
// surface: the interpolated height, not the point's own.
TEST(SurfaceSampling, LocatesPointsOffTheSurfaceAtTheirStubbleFoot) {
  std::mt19937 rng(5);
  for (const auto& [name, gen] : testSurfaces()) {
    const DisplacementField& ddf = gen.ddf;
    for (int trial = 0; trial < 200; ++trial) {
      const int f = trial % ddf.faceCount();
      const Vec3 mu = test::randomBary(rng);
      const double h = interpolateOnFace(ddf, ddf.allHeights(), f, mu);
      const double offset = trial % 2 ? 0.1 : -0.1;
      const auto loc = locateOnFace(ddf, f, ddf.pointAt(f, mu, h + offset));
      ASSERT_TRUE(loc) << name;
      EXPECT_LT((loc->bary - mu).norm(), 1e-9) << name << " face " << f;
      EXPECT_NEAR(loc->h, h, 1e-9) << name;
      EXPECT_LT((loc->point - ddf.pointAt(f, mu, h)).norm(), 1e-9) << name;
    }
  }
}

// A foot outside the face is clamped onto it: on a plane z-map the nearest face point in x, y.
TEST(SurfaceSampling, ClampsFeetOutsideTheFace) {
  const auto gen = planePatch({.cellsX = 1, .cellsY = 1, .m = 5, .planeZMm = 0.25});
  const DisplacementField& ddf = gen.ddf;
  // Face 0 of the 40 x 30 cell; a point beyond the cell in x lands on the face's boundary.
  const auto loc = locateOnFace(ddf, 0, Vec3(60.0, 15.0, 0.7));
  ASSERT_TRUE(loc);
  EXPECT_GE(loc->bary.minCoeff(), 0.0);
  EXPECT_NEAR(loc->bary.sum(), 1.0, 1e-12);
  EXPECT_NEAR(loc->point.z(), 0.25, 1e-9);
  EXPECT_NEAR(loc->h, 0.25, 1e-7);
  EXPECT_THROW(locateOnFace(ddf, 2, Vec3::Zero()), InvalidInput);
}

TEST(SurfaceSampling, RasterMeshSamplesAreItsRasterPoints) {
  std::mt19937 rng(6);
  for (const auto& [name, gen] : testSurfaces()) {
    DisplacementField ddf = gen.ddf;
    // Copies of shared points that disagree: the mesh and the samples must both take the
    // lowest face's.
    for (float& h : ddf.allHeights()) h += std::uniform_real_distribution<float>(-0.1f, 0.1f)(rng);
    const RasterMesh raster = extractRasterMesh(ddf);
    const SurfaceSamples samples = sampleRasterMesh(ddf, raster);
    const std::vector<int> lowest = lowestFaces(ddf);
    ASSERT_EQ(samples.face.size(), raster.mesh.vertices.size());
    ASSERT_EQ(samples.bary.size(), raster.mesh.vertices.size());
    for (std::size_t v = 0; v < samples.face.size(); ++v) {
      ASSERT_EQ(samples.face[v], lowest[raster.vertexPoint[v]]) << name;
      const double h = interpolateOnFace(ddf, ddf.allHeights(), samples.face[v], samples.bary[v]);
      const Vec3 q = ddf.pointAt(samples.face[v], samples.bary[v], h);
      ASSERT_LT((q - raster.mesh.vertices[v]).norm(), 1e-12) << name << " vertex " << v;
    }
    const std::vector<float> perPoint = valuesPerPoint(ddf, ddf.allHeights());
    const std::vector<float> atSamples = valuesAtSamples(ddf, ddf.allHeights(), samples);
    for (std::size_t v = 0; v < samples.face.size(); ++v)
      ASSERT_EQ(atSamples[v], perPoint[raster.vertexPoint[v]]) << name << " vertex " << v;
    EXPECT_THROW(sampleRasterMesh(planePatch({.cellsX = 1, .cellsY = 1, .m = 3}).ddf, raster),
                 InvalidInput);
  }
}

TEST(SurfaceSampling, AdaptiveMeshVerticesLieOnTheirSamples) {
  const auto gen = spherePart({.subdivisions = 1, .m = 9});
  const DisplacementField& ddf = gen.ddf;
  const double eps = 0.01;
  const AdaptiveTriangulation tri =
      triangulateAdaptiveWithStats(ddf, {.epsMm = eps, .progress = {}});
  const SurfaceSamples samples = sampleMeshVertices(ddf, tri.mesh, tri.triangleFace);
  std::vector<int> firstFace(tri.mesh.vertices.size(), -1);
  for (std::size_t t = 0; t < tri.mesh.triangles.size(); ++t)
    for (int v : tri.mesh.triangles[t])
      if (firstFace[v] < 0) firstFace[v] = tri.triangleFace[t];
  double worst = 0.0;
  for (std::size_t v = 0; v < tri.mesh.vertices.size(); ++v) {
    ASSERT_EQ(samples.face[v], firstFace[v]);
    const double h = interpolateOnFace(ddf, ddf.allHeights(), samples.face[v], samples.bary[v]);
    worst = std::max(
        worst, (ddf.pointAt(samples.face[v], samples.bary[v], h) - tri.mesh.vertices[v]).norm());
  }
  EXPECT_LE(worst, eps);
  std::vector<int> wrong(tri.triangleFace.begin(), tri.triangleFace.end() - 1);
  EXPECT_THROW(sampleMeshVertices(ddf, tri.mesh, wrong), InvalidInput);
}

TEST(SurfaceSampling, ValuesPerPointTakeTheLowestFaceCopy) {
  const auto gen = spherePart({.subdivisions = 1, .m = 6});
  const DisplacementField& ddf = gen.ddf;
  std::vector<float> faceIndex(ddf.allHeights().size());
  for (std::size_t l = 0; l < faceIndex.size(); ++l)
    faceIndex[l] = static_cast<float>(l / ddf.pointsPerFace());
  const std::vector<float> perPoint = valuesPerPoint(ddf, faceIndex);
  const std::vector<int> lowest = lowestFaces(ddf);
  ASSERT_EQ(perPoint.size(), ddf.topology().pointCount());
  for (std::size_t id = 0; id < perPoint.size(); ++id)
    ASSERT_EQ(perPoint[id], static_cast<float>(lowest[id])) << "point " << id;
  EXPECT_THROW(valuesPerPoint(ddf, std::span(faceIndex).first(3)), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
