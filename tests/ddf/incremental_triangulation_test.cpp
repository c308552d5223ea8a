// SPDX-License-Identifier: MIT
// Tests of the incremental adaptive triangulation: after random cut sequences it equals a fresh
// triangulateAdaptive() of the same heights face by face (bitwise), is crack-free without
// T-vertices, keeps the error bound, and its normals are those of the fresh mesh.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "../support/test_meshes.h"
#include "surface_fixtures.h"

namespace ddfcam::ddf {
namespace {

using Corners = std::array<Vec3, 3>;

// Triangles of every face as corner positions, in their order.
std::vector<std::vector<Corners>> byFace(const AdaptiveTriangulation& t, int faces) {
  std::vector<std::vector<Corners>> out(faces);
  for (std::size_t i = 0; i < t.mesh.triangles.size(); ++i) {
    const auto& tri = t.mesh.triangles[i];
    out[t.triangleFace[i]].push_back(
        {t.mesh.vertices[tri[0]], t.mesh.vertices[tri[1]], t.mesh.vertices[tri[2]]});
  }
  return out;
}

std::vector<std::vector<Corners>> byFace(const IncrementalTriangulation& t, int faces) {
  std::vector<std::vector<Corners>> out(faces);
  for (int f = 0; f < faces; ++f)
    for (const auto& tri : t.faceTriangles(f))
      out[f].push_back({t.vertices()[tri[0]], t.vertices()[tri[1]], t.vertices()[tri[2]]});
  return out;
}

AdaptiveTriangulation fresh(const DisplacementField& field, double eps) {
  AdaptiveTriangulationParams params;
  params.epsMm = eps;
  return triangulateAdaptiveWithStats(field, params);
}

::testing::AssertionResult sameAsFresh(const DisplacementField& field,
                                       const IncrementalTriangulation& live, double eps) {
  const auto expected = byFace(fresh(field, eps), field.faceCount());
  const auto actual = byFace(live, field.faceCount());
  for (int f = 0; f < field.faceCount(); ++f) {
    if (expected[f].size() != actual[f].size())
      return ::testing::AssertionFailure() << "face " << f << ": " << actual[f].size()
                                           << " triangles, fresh build " << expected[f].size();
    for (std::size_t t = 0; t < expected[f].size(); ++t)
      for (int c = 0; c < 3; ++c)
        if (expected[f][t][c] != actual[f][t][c])
          return ::testing::AssertionFailure() << "face " << f << " triangle " << t << " corner "
                                               << c << " differs from the fresh build";
  }
  return ::testing::AssertionSuccess();
}

// Area-weighted unit normals of a welded mesh, brute force over its triangles.
std::vector<Vec3> meshNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> sum(mesh.vertices.size(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    for (int v : t) sum[v] += n;
  }
  for (Vec3& n : sum) n.normalize();
  return sum;
}

// A box of random size and place reaching into the unit sphere from outside.
TriangleMesh randomCutter(std::mt19937& rng) {
  std::uniform_real_distribution<double> dir(-1.0, 1.0), size(0.05, 0.3), depth(0.9, 0.99);
  Vec3 d(dir(rng), dir(rng), dir(rng));
  if (d.norm() < 1e-3) d = Vec3::UnitX();
  const Vec3 centre = (depth(rng) + 0.5) * d.normalized();
  const double s = size(rng);
  return test::boxMesh(centre - Vec3(s, s, 0.5), centre + Vec3(s, s, 0.5));
}

// The unit sphere on a 320-face icosphere support.
DisplacementField icosphereDdf(int m) {
  EllipsoidParams params;
  params.axesMm = {1.0, 1.0, 1.0};
  params.subdivisions = 2;
  params.m = m;
  return ellipsoidPart(params).ddf;
}

TEST(IncrementalTriangulation, StartsAsTheFreshBuild) {
  const DisplacementField field = test::sphereDdf(17);
  const IncrementalTriangulation live(field, 0.002);
  EXPECT_TRUE(sameAsFresh(field, live, 0.002));
  EXPECT_EQ(live.triangleCount(), fresh(field, 0.002).mesh.triangles.size());
}

TEST(IncrementalTriangulation, RandomCutSequencesGiveTheFreshBuildFaceByFace) {
  for (const int m : {9, 12}) {
    DisplacementField field = icosphereDdf(m);
    CrustHash hash(field);
    IncrementalTriangulation live(field, 0.003);
    std::mt19937 rng(m);
    for (int cut = 0; cut < 12; ++cut) {
      const CutStats stats = cutByMesh(field, hash, randomCutter(rng), Eigen::Isometry3d::Identity());
      const TriangulationUpdate update = live.update(stats.touchedFaces);
      EXPECT_LE(update.subdividedFaces.size(), update.reassembledFaces.size());
      ASSERT_TRUE(sameAsFresh(field, live, 0.003)) << "m = " << m << ", after cut " << cut;
    }
  }
}

TEST(IncrementalTriangulation, AfterCutsIsClosedWithinTheBoundWithTheFreshNormals) {
  DisplacementField field = icosphereDdf(9);
  CrustHash hash(field);
  IncrementalTriangulation live(field, 0.003);
  std::mt19937 rng(7);
  for (int cut = 0; cut < 10; ++cut)
    live.update(cutByMesh(field, hash, randomCutter(rng), Eigen::Isometry3d::Identity())
                    .touchedFaces);
  const AdaptiveTriangulation snap = live.snapshot();
  EXPECT_TRUE(test::isClosedManifold(snap.mesh, 2));  // no cracks, no T-vertices
  EXPECT_LE(snap.maxErrorMm, 0.003);
  // Every raster point lies within the bound of its face's triangles (brute force).
  const int n = field.raster().steps();
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 q = field.surfacePoint(f, i, k);
        double best = 1e300;
        for (const auto& t : live.faceTriangles(f))
          best = std::min(best, test::pointTriangleDistance(q, live.vertices()[t[0]],
                                                            live.vertices()[t[1]],
                                                            live.vertices()[t[2]]));
        ASSERT_LE(best, 0.003 + 1e-9) << "face " << f << " point (" << i << ", " << k << ")";
      }
  // Normals: those of the welded fresh mesh at the same positions.
  const std::vector<Vec3> expected = meshNormals(snap.mesh);
  std::vector<int> slotOf(snap.mesh.vertices.size(), -1);
  for (int f = 0, at = 0; f < field.faceCount(); ++f)
    for (const auto& t : live.faceTriangles(f)) {
      for (int c = 0; c < 3; ++c) slotOf[snap.mesh.triangles[at][c]] = t[c];
      ++at;
    }
  for (std::size_t v = 0; v < expected.size(); ++v)
    ASSERT_LT((live.normals()[slotOf[v]] - expected[v]).norm(), 1e-9) << "vertex " << v;
}

TEST(IncrementalTriangulation, UpdatesOnlyTheNeighbourhoodOfTheCut) {
  EllipsoidParams params;
  params.subdivisions = 3;
  params.m = 9;
  DisplacementField field = ellipsoidPart(params).ddf;
  CrustHash hash(field);
  IncrementalTriangulation live(field, 0.002);
  const std::vector<float> before = field.allHeights();
  // A small box grazing the ellipsoid at the end of its long axis (3, 0, 0).
  const TriangleMesh box = test::boxMesh({2.98, -0.1, -0.1}, {3.5, 0.1, 0.1});
  const CutStats stats = cutByMesh(field, hash, box, Eigen::Isometry3d::Identity());
  ASSERT_GT(stats.pointsLowered, 0u);
  const TriangulationUpdate update = live.update(stats.touchedFaces);
  // Every face whose heights changed is subdivided again (brute force over all faces) ...
  const std::size_t per = field.pointsPerFace();
  for (int f = 0; f < field.faceCount(); ++f)
    for (std::size_t p = 0; p < per; ++p)
      if (field.allHeights()[f * per + p] != before[f * per + p]) {
        EXPECT_TRUE(std::binary_search(update.subdividedFaces.begin(),
                                       update.subdividedFaces.end(), f))
            << "face " << f;
        break;
      }
  // ... and only a small neighbourhood of the 1280 faces is touched.
  EXPECT_LT(update.reassembledFaces.size(), 100u);
  EXPECT_TRUE(sameAsFresh(field, live, 0.002));
  const TriangulationUpdate none = live.update({});
  EXPECT_TRUE(none.subdividedFaces.empty());
  EXPECT_TRUE(none.touchedSlots.empty());
}

TEST(IncrementalTriangulation, RejectsABadBoundAndABadFace) {
  const DisplacementField field = test::sphereDdf(5);
  EXPECT_THROW(IncrementalTriangulation(field, 0.0), InvalidInput);
  IncrementalTriangulation live(field, 0.01);
  const std::vector<int> bad{field.faceCount()};
  EXPECT_THROW(live.update(bad), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
