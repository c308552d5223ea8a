// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/v_projection.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

Vec3 randomVec(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

/// Independent oracle: cut triangle a with the plane of b, then clip the cut segment against
/// b's edges inside that plane (Cyrus-Beck).
bool clipOracle(const SpaceTriangle& a, const SpaceTriangle& b) {
  const Vec3 n = (b[1] - b[0]).cross(b[2] - b[0]);
  std::array<double, 3> d;
  for (int i = 0; i < 3; ++i) d[i] = (a[i] - b[0]).dot(n);
  std::vector<Vec3> cut;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if ((d[i] < 0) != (d[j] < 0)) cut.push_back(a[i] + d[i] / (d[i] - d[j]) * (a[j] - a[i]));
  }
  if (cut.size() != 2) return false;
  double t0 = 0.0, t1 = 1.0;
  const Vec3 dir = cut[1] - cut[0];
  for (int e = 0; e < 3; ++e) {
    const Vec3 inward = n.cross(b[(e + 1) % 3] - b[e]);  // points into b
    const double num = (cut[0] - b[e]).dot(inward), den = dir.dot(inward);
    if (den == 0.0) {
      if (num < 0) return false;
      continue;
    }
    const double t = -num / den;
    if (den > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

TEST(CrustIntersection, TriangleTestMatchesClippingOracle) {
  std::mt19937 rng(31);
  int hits = 0;
  for (int k = 0; k < 20000; ++k) {
    const SpaceTriangle a = {randomVec(rng), randomVec(rng), randomVec(rng)};
    const Vec3 shift = randomVec(rng, 0.8);
    const SpaceTriangle b = {randomVec(rng) + shift, randomVec(rng) + shift,
                             randomVec(rng) + shift};
    const bool oracle = clipOracle(a, b);
    ASSERT_EQ(trianglesIntersect(a, b), oracle) << k;
    hits += oracle;
  }
  EXPECT_GT(hits, 2000);
  EXPECT_LT(hits, 18000);
}

TEST(CrustIntersection, PlanarGridHasNoNonAdjacentConflicts) {
  const auto mesh = test::gridMesh(6, 6);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 1.5}), 3);
  int adjacentTouching = 0;
  for (int s = 0; s < ddf.faceCount(); ++s)
    for (int t = s + 1; t < ddf.faceCount(); ++t) {
      const bool hit = crustsIntersect(ddf, s, t);
      if (facesShareVertex(ddf, s, t)) {
        adjacentTouching += hit;
      } else {
        EXPECT_FALSE(hit) << s << " " << t;
      }
    }
  EXPECT_GT(adjacentTouching, 0);
  EXPECT_TRUE(findAllCrustConflicts(ddf, CrustHash(ddf)).empty());
}

/// Two parallel unit squares at z = 0 and z = gap, vectors (0, 0, length) everywhere.
DisplacementField twoSheets(double gap, double length) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) points.push_back(points[i] + Vec3(0, 0, gap));
  const auto mesh = makeSupportMesh(points, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  return DisplacementField(mesh, test::constantVectors(mesh, {0, 0, length}), 3);
}

TEST(CrustIntersection, ParallelSheetsOverlapExactlyWhenCrustsReach) {
  // Crusts [-l, l] and [gap - l, gap + l] overlap iff 2 l >= gap.
  for (double length : {0.5, 0.7, 0.76, 1.0}) {
    const auto ddf = twoSheets(1.5, length);
    const bool expected = 2 * length >= 1.5;
    EXPECT_EQ(crustsIntersect(ddf, 0, 2), expected) << length;
    EXPECT_EQ(crustsIntersect(ddf, 1, 3), expected) << length;
    // Faces 0 and 3 (and 1 and 2) only touch along the diagonal plane: left open.
    const auto conflicts = findAllCrustConflicts(ddf, CrustHash(ddf));
    const auto has = [&](int a, int b) {
      return std::find(conflicts.begin(), conflicts.end(), std::array<int, 2>{a, b}) !=
             conflicts.end();
    };
    EXPECT_EQ(has(0, 2), expected) << length;
    EXPECT_EQ(has(1, 3), expected) << length;
    if (!expected) EXPECT_TRUE(conflicts.empty()) << length;
  }
}

TEST(CrustIntersection, CrustInsideAnotherIsFoundByContainment) {
  // A small triangle with tiny vectors floating inside the thick crust of a big one.
  const std::vector<Vec3> points = {{-5, -5, 0}, {5, -5, 0},  {0, 5, 0},
                                    {0, 0, 1},   {0.1, 0, 1}, {0, 0.1, 1}};
  const auto mesh = makeSupportMesh(points, {{0, 1, 2}, {3, 4, 5}});
  std::vector<Vec3> vectors(6, Vec3(0, 0, 3));
  for (int i = 3; i < 6; ++i) vectors[i] = {0, 0, 0.01};
  const DisplacementField ddf(mesh, vectors, 2);
  EXPECT_TRUE(crustContains(ddf, 0, {0.03, 0.03, 1.0}));
  EXPECT_FALSE(crustContains(ddf, 0, {0.03, 0.03, 3.5}));
  EXPECT_TRUE(crustsIntersect(ddf, 0, 1));
  EXPECT_TRUE(crustsIntersect(ddf, 1, 0));
}

/// Grid with random heights and random tilted vectors long enough to make crusts collide.
DisplacementField bumpyField(std::mt19937& rng, double length) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto mesh = test::gridMesh(7, 7);
  for (const auto vh : mesh.vertices()) mesh.point(vh)[2] = 0.6 * u(rng);
  std::vector<Vec3> vectors;
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
    vectors.push_back((Vec3(0, 0, 1) + 0.5 * Vec3(u(rng), u(rng), 0)).normalized() * length);
  return DisplacementField(mesh, vectors, 3);
}

TEST(CrustIntersection, HashedConflictsMatchBruteForcePairs) {
  std::mt19937 rng(8);
  for (double length : {0.6, 1.5}) {
    const auto ddf = bumpyField(rng, length);
    std::vector<std::array<int, 2>> brute;
    for (int s = 0; s < ddf.faceCount(); ++s)
      for (int t = s + 1; t < ddf.faceCount(); ++t)
        if (!facesShareVertex(ddf, s, t) && crustsIntersect(ddf, s, t)) brute.push_back({s, t});
    EXPECT_EQ(findAllCrustConflicts(ddf, CrustHash(ddf)), brute) << length;
    if (length > 1.0) EXPECT_FALSE(brute.empty());
  }
}

TEST(CrustIntersection, SampledCommonPointsImplyIntersection) {
  // Soundness against sampling: a sampled point of crust t found inside crust s (by
  // V-projection) must make the pair intersect; disjoint verdicts must have no such sample.
  std::mt19937 rng(4);
  const auto ddf = bumpyField(rng, 1.5);
  int sampledOverlaps = 0;
  for (int s = 0; s < ddf.faceCount(); s += 3)
    for (int t = 0; t < ddf.faceCount(); t += 2) {
      if (s == t || facesShareVertex(ddf, s, t)) continue;
      bool sampleInside = false;
      for (int i = 0; i <= 4 && !sampleInside; ++i)
        for (int j = 0; i + j <= 4 && !sampleInside; ++j)
          for (double h : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
            const Vec3 mu(i / 4.0, j / 4.0, (4 - i - j) / 4.0);
            if (crustContains(ddf, s, ddf.pointAt(t, mu, h))) {
              sampleInside = true;
              break;
            }
          }
      if (sampleInside) {
        ++sampledOverlaps;
        EXPECT_TRUE(crustsIntersect(ddf, s, t)) << s << " " << t;
      }
    }
  EXPECT_GT(sampledOverlaps, 0);
}

}  // namespace
}  // namespace ddfcam::ddf
