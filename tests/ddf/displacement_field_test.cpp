// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <random>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

TEST(DisplacementField, RepresentedPointIsBasePlusHeightTimesVector) {
  const auto mesh = test::gridMesh(1, 1, 2.0, 2.0);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 0.5}), 5, 0.0f);
  ddf.heights(0)[ddf.raster().index(1, 1)] = 0.8f;
  // Point (i, j, k) = (1, 2, 1) sits at (1 p1 + 2 p2 + 1 p3) / 4 in the face's raster order.
  const auto& fv = ddf.faceVertices(0);
  const Vec3 g = (ddf.position(fv[0]) + 2.0 * ddf.position(fv[1]) + ddf.position(fv[2])) / 4.0;
  const Vec3 q = ddf.surfacePoint(0, 1, 1);
  EXPECT_NEAR((q - (g + 0.8 * Vec3(0, 0, 0.5))).norm(), 0.0, 1e-7);
}

TEST(DisplacementField, RejectsWrongVectorCount) {
  const auto mesh = test::gridMesh(1, 1);
  EXPECT_THROW(DisplacementField(mesh, {}, 4), InvalidInput);
  EXPECT_THROW(DisplacementField(mesh, test::constantVectors(mesh), 1), InvalidInput);
}

TEST(DisplacementField, SharedPointsAgreeAfterSynchronization) {
  const auto mesh = test::octahedronMesh();
  DisplacementField ddf(mesh, test::radialVectors(mesh, 0.3), 7);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (float& h : ddf.allHeights()) h = u(rng);
  const auto before = ddf.allHeights();
  ddf.synchronizeShared(SharedPolicy::Minimum);
  const auto& topo = ddf.topology();
  for (std::size_t p = 0; p < topo.pointCount(); ++p) {
    float minBefore = 1e30f, first = 0.f;
    bool seen = false;
    topo.forEachCopy(static_cast<PointId>(p), [&](PointCopy c) {
      minBefore = std::min(minBefore, before[c.face * ddf.pointsPerFace() + c.local]);
      const float h = ddf.heights(c.face)[c.local];
      if (!seen) first = h, seen = true;
      EXPECT_EQ(h, first) << "point " << p;
    });
    EXPECT_EQ(first, minBefore) << "point " << p;
  }
}

TEST(DisplacementField, CanonicalPolicyTakesLowestFace) {
  const auto mesh = test::gridMesh(1, 1);
  DisplacementField ddf(mesh, test::constantVectors(mesh), 4);
  for (float& h : ddf.heights(0)) h = 0.25f;
  for (float& h : ddf.heights(1)) h = -0.5f;
  ddf.synchronizeShared(SharedPolicy::Canonical);
  // The diagonal is shared: face 1's copies now equal face 0's.
  const auto& topo = ddf.topology();
  for (std::size_t p = 0; p < topo.pointCount(); ++p) {
    int faces = 0;
    topo.forEachCopy(static_cast<PointId>(p), [&](PointCopy) { ++faces; });
    if (faces < 2) continue;
    topo.forEachCopy(static_cast<PointId>(p),
                     [&](PointCopy c) { EXPECT_EQ(ddf.heights(c.face)[c.local], 0.25f); });
  }
}

TEST(DisplacementField, MemoryIsDominatedByHeightsAtM50) {
  const auto mesh = test::gridMesh(10, 10);
  const DisplacementField ddf(mesh, test::constantVectors(mesh), 50);
  const double perPoint =
      static_cast<double>(ddf.memoryBytes()) / (ddf.faceCount() * ddf.pointsPerFace());
  EXPECT_LE(perPoint, 4.5);
  EXPECT_GE(perPoint, 4.0);
}

}  // namespace
}  // namespace ddfcam::ddf
