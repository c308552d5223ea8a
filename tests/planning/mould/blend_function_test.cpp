// SPDX-License-Identifier: MIT
// Tests of the blending functions d(u, v) (ch. 9) on a flat plate against Euclidean geometry.
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/blend_function.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "../../support/test_meshes.h"

namespace ddfcam::planning {
namespace {

using ddf::PointId;
using ddf::Vec3;

constexpr double kSize = 100.0;  // the plate [0, 100]^2 at z = 0

ddf::DisplacementField plate(int m = 5) {
  const auto mesh = test::gridMesh(10, 10, 10.0, 10.0);
  return ddf::DisplacementField(mesh, test::constantVectors(mesh), m);
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// One weight and one support point per raster point; fails if copies disagree.
struct PointValues {
  std::vector<double> w;
  std::vector<Vec3> g;
};

PointValues perPoint(const ddf::DisplacementField& field, const std::vector<float>& weights) {
  EXPECT_EQ(weights.size(), field.allHeights().size());
  PointValues out{std::vector<double>(field.topology().pointCount(), NAN),
                  std::vector<Vec3>(field.topology().pointCount())};
  const int n = field.raster().steps();
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const PointId id = field.topology().id(f, i, k);
        const double w = weights[f * field.pointsPerFace() + field.raster().index(i, k)];
        if (!std::isnan(out.w[id])) {
          EXPECT_EQ(out.w[id], w) << "copies of point " << id;
        }
        out.w[id] = w;
        out.g[id] = field.basePoint(f, field.rasterBary(i, k));
      }
  return out;
}

BlendParams boundaryParams(double value, double widthMm) {
  BlendParams params;
  params.kind = BlendKind::Boundary;
  params.value = value;
  params.widthMm = widthMm;
  return params;
}

// |d(p) - d(q)| <= max slope x |g_p - g_q| between lattice neighbours (C1 smoothstep: 1.5 / w).
void expectLipschitz(const ddf::DisplacementField& field, const PointValues& v, double slope) {
  std::vector<PointId> nbrs;
  for (PointId p = 0; p < v.w.size(); ++p) {
    field.topology().neighbors(p, nbrs);
    for (const PointId q : nbrs)
      ASSERT_LE(std::abs(v.w[p] - v.w[q]), slope * (v.g[p] - v.g[q]).norm() + 1e-6);
  }
}

TEST(BlendFunction, ConstantIsTheValueEverywhere) {
  const auto field = plate();
  BlendParams params;
  params.value = 0.7;
  for (const float w : blendWeights(field, params)) ASSERT_FLOAT_EQ(w, 0.7f);
}

TEST(BlendFunction, RadialFallsOffMonotonicallyAndContinuously) {
  const auto field = plate();
  const Vec3 centre(50, 50, 0);  // a support vertex
  BlendParams params;
  params.kind = BlendKind::Radial;
  params.value = 2.0;
  params.centreMm = centre;
  params.radiusMm = 30.0;
  const PointValues v = perPoint(field, blendWeights(field, params));
  for (std::size_t p = 0; p < v.w.size(); ++p) {
    const double d = (v.g[p] - centre).norm();
    ASSERT_NEAR(v.w[p], 2.0 * (1 - smoothstep(d / 30.0)), 1e-6);
    if (d == 0.0) {
      EXPECT_FLOAT_EQ(v.w[p], 2.0f);
    }
    if (d >= 30.0) {
      EXPECT_EQ(v.w[p], 0.0);
    }
  }
  for (std::size_t a = 0; a < v.w.size(); a += 7)
    for (std::size_t b = 0; b < v.w.size(); b += 5)
      if ((v.g[a] - centre).norm() < (v.g[b] - centre).norm()) {
        ASSERT_GE(v.w[a], v.w[b] - 1e-6);
      }
  expectLipschitz(field, v, 1.5 * 2.0 / 30.0);
}

TEST(BlendFunction, BrushFindsTheFacesWithinTheRadius) {
  const auto field = plate();
  const Vec3 centre(47, 52, 3);
  const double r = 21.0;
  const std::vector<int> faces = facesWithinRadius(field, centre, r);
  ASSERT_TRUE(std::is_sorted(faces.begin(), faces.end()));
  const std::set<int> got(faces.begin(), faces.end());
  // Brute force: the nearest of a dense barycentric sample (spacing < 0.3 mm) of each face.
  for (int f = 0; f < field.faceCount(); ++f) {
    double best = 1e30;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; i + j <= 60; ++j)
        best = std::min(best, (field.basePoint(f, Vec3(i, j, 60 - i - j) / 60.0) - centre).norm());
    if (best <= r) {
      EXPECT_TRUE(got.count(f)) << "face " << f;
    }
    if (best > r + 0.3) {
      EXPECT_FALSE(got.count(f)) << "face " << f;
    }
  }
  EXPECT_THROW(facesWithinRadius(field, centre, -1.0), InvalidInput);
}

TEST(BlendFunction, RegionIsValueDeepInsideAndZeroOutside) {
  const auto field = plate();
  const Vec3 centre(50, 50, 0);
  const std::vector<int> faces = facesWithinRadius(field, centre, 25.0);
  const double width = 5.0;
  const BlendParams params{.kind = BlendKind::Region, .faces = faces, .edgeWidthMm = width};
  const std::vector<float> weights = blendWeights(field, params);
  const PointValues v = perPoint(field, weights);
  // The painted faces cover the disc of radius 25; the lattice distance to the region's border
  // is at least the Euclidean one, so the disc of radius 25 - width is at full value.
  for (std::size_t p = 0; p < v.w.size(); ++p)
    if ((v.g[p] - centre).norm() <= 25.0 - width) {
      ASSERT_FLOAT_EQ(v.w[p], 1.0f);
    }
  const std::set<int> painted(faces.begin(), faces.end());
  for (int f = 0; f < field.faceCount(); ++f)
    if (!painted.count(f)) {
      for (std::size_t c = 0; c < field.pointsPerFace(); ++c)
        ASSERT_EQ(weights[f * field.pointsPerFace() + c], 0.0f);
    }
  expectLipschitz(field, v, 1.5 / width);
  EXPECT_THROW(blendWeights(field, {.kind = BlendKind::Region, .faces = {999}}), InvalidInput);
}

// On the plate the lattice holds the axis directions, so the lattice distance to the boundary
// is exactly min(x, 100 - x, y, 100 - y).
TEST(BlendFunction, BoundaryRisesFromZeroToValueWithinTheWidth) {
  const auto field = plate();
  const double width = 12.0;
  const PointValues v = perPoint(field, blendWeights(field, boundaryParams(0.5, width)));
  for (std::size_t p = 0; p < v.w.size(); ++p) {
    const Vec3& g = v.g[p];
    const double d = std::min({g.x(), kSize - g.x(), g.y(), kSize - g.y()});
    ASSERT_NEAR(v.w[p], 0.5 * smoothstep(d / width), 1e-6) << "at " << g.transpose();
    if (d == 0.0) {
      EXPECT_EQ(v.w[p], 0.0);
    }
    if (d >= width) {
      EXPECT_FLOAT_EQ(v.w[p], 0.5f);
    }
  }
  expectLipschitz(field, v, 1.5 * 0.5 / width);
}

TEST(BlendFunction, ClosedSupportHasNoBoundary) {
  const auto morph = ddf::cubeSphereMorph({.subdivisions = 6, .resolution = 2, .sphereLevel = 3});
  for (const float w : blendWeights(morph.ddf, boundaryParams(0.3, BlendParams{}.widthMm)))
    ASSERT_FLOAT_EQ(w, 0.3f);
}

TEST(BlendFunction, LatticeDistancesBoundTheEuclideanOnes) {
  const auto field = plate(3);
  const PointValues v = perPoint(field, std::vector<float>(field.allHeights().size(), 0.0f));
  const PointId source = 60;  // support vertex 60 = 5 x 11 + 5: (50, 50)
  const std::vector<double> d = latticeDistances(field, std::vector<PointId>{source});
  for (std::size_t p = 0; p < d.size(); ++p) {
    const double e = (v.g[p] - v.g[source]).norm();
    ASSERT_GE(d[p], e - 1e-9);
    // Paths along the axes and the one diagonal direction: at most the L1-like octile bound.
    const Vec3 a = (v.g[p] - v.g[source]).cwiseAbs();
    ASSERT_LE(d[p], a.x() + a.y() + 1e-9);
  }
  EXPECT_THROW(latticeDistances(field, std::vector<PointId>{1u << 30}), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
