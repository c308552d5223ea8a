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
#include <cmath>
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
                                       const IncrementalTriangulation& live, double eps,
                                       const std::vector<float>& faceEps = {}) {
  AdaptiveTriangulationParams params;
  params.epsMm = eps;
  params.faceEpsMm = faceEps;
  const auto expected = byFace(triangulateAdaptiveWithStats(field, params), field.faceCount());
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
  EXPECT_TRUE(test::withinFaceBounds(field, live, std::vector<float>(field.faceCount(), 0.003f)));
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

// The DDF surface at a parameter position (i, k) in raster steps: the raster mesh (fig. 7.1a),
// piecewise linear over the raster's triangles, from the field's own surface points.
Vec3 rasterMeshAt(const DisplacementField& field, int f, double u, double w) {
  const int n = field.raster().steps();
  const int i0 = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
  const int k0 = std::clamp(static_cast<int>(std::floor(w)), 0, n - 1 - i0);
  const double fi = u - i0, fk = w - k0;
  auto q = [&](int i, int k) { return field.surfacePoint(f, i, k); };
  if (fi + fk <= 1.0 || i0 + k0 + 2 > n)
    return (1.0 - fi - fk) * q(i0, k0) + fi * q(i0 + 1, k0) + fk * q(i0, k0 + 1);
  return (fi + fk - 1.0) * q(i0 + 1, k0 + 1) + (1.0 - fk) * q(i0 + 1, k0) +
         (1.0 - fi) * q(i0, k0 + 1);
}

// Where each corner lies on its face's raster: inside the face, and on the raster mesh there
// within the error bound (DDF points exactly; straight midpoints, which may sit on lattice
// positions too, and centroids approximate it as the triangles do). With a bound well below
// the raster spacing a wrong position would be off by a spacing.
::testing::AssertionResult paramsMatchPositions(const DisplacementField& field,
                                                const IncrementalTriangulation& live,
                                                double eps) {
  const int n = field.raster().steps();
  for (int f = 0; f < field.faceCount(); ++f) {
    const auto& tris = live.faceTriangles(f);
    const auto& params = live.faceTriangleParams(f);
    if (params.size() != tris.size())
      return ::testing::AssertionFailure() << "face " << f << ": " << params.size()
                                           << " parameter triples for " << tris.size();
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int c = 0; c < 3; ++c) {
        const double u = params[t][c][0], w = params[t][c][1];
        if (u < -1e-6 || w < -1e-6 || u + w > n + 1e-5)
          return ::testing::AssertionFailure() << "face " << f << " corner at (" << u << ", "
                                               << w << ") outside the face";
        const Vec3& at = live.vertices()[tris[t][c]];
        const double d = (at - rasterMeshAt(field, f, u, w)).norm();
        if (d > eps + 1e-9)
          return ::testing::AssertionFailure()
                 << "face " << f << " triangle " << t << " corner " << c << " at (" << u << ", "
                 << w << "): " << d << " mm from the raster mesh there";
      }
  }
  return ::testing::AssertionSuccess();
}

TEST(IncrementalTriangulation, CornerParametersPlaceEveryVertexOnItsFacesRaster) {
  for (const int m : {9, 12}) {
    DisplacementField field = icosphereDdf(m);
    CrustHash hash(field);
    // The raster spacing is about 0.07 / m mm on this sphere.
    const double eps = 0.0005;
    IncrementalTriangulation live(field, eps);
    ASSERT_TRUE(paramsMatchPositions(field, live, eps)) << "m = " << m << ", fresh";
    std::mt19937 rng(m + 100);
    for (int cut = 0; cut < 8; ++cut) {
      live.update(cutByMesh(field, hash, randomCutter(rng), Eigen::Isometry3d::Identity())
                      .touchedFaces);
      ASSERT_TRUE(paramsMatchPositions(field, live, eps)) << "m = " << m << ", cut " << cut;
    }
  }
}

// A level of detail per face (as a view sets it): after cuts and bound changes in any order the
// mesh is the fresh build with those bounds, crack-free without T-vertices, every raster point
// within its own face's bound, and coarse bounds give fewer triangles.
TEST(IncrementalTriangulation, PerFaceBoundsGiveTheFreshBuildWithThoseBounds) {
  DisplacementField field = icosphereDdf(9);
  CrustHash hash(field);
  IncrementalTriangulation live(field, 0.002);
  const std::size_t fine = live.triangleCount();
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> level(0, 3);
  std::vector<float> bounds(static_cast<std::size_t>(field.faceCount()));
  for (int round = 0; round < 4; ++round) {
    live.update(cutByMesh(field, hash, randomCutter(rng), Eigen::Isometry3d::Identity())
                    .touchedFaces);
    for (float& b : bounds) b = 0.002f * static_cast<float>(1 << (2 * level(rng)));
    const TriangulationUpdate update = live.setFaceEps(bounds);
    EXPECT_FALSE(update.subdividedFaces.empty());
    ASSERT_TRUE(sameAsFresh(field, live, 0.002, bounds)) << "round " << round;
    EXPECT_EQ(live.faceEps(), bounds);
    const AdaptiveTriangulation snap = live.snapshot();
    ASSERT_TRUE(test::isClosedManifold(snap.mesh, 2)) << "round " << round;
    ASSERT_TRUE(test::withinFaceBounds(field, live, bounds)) << "round " << round;
    ASSERT_TRUE(paramsMatchPositions(field, live, 0.002 * 64)) << "round " << round;
  }
  // All coarse: far fewer triangles than the fine start; the same bounds again change nothing.
  std::fill(bounds.begin(), bounds.end(), 0.128f);
  live.setFaceEps(bounds);
  EXPECT_LT(3 * live.triangleCount(), fine);
  EXPECT_TRUE(live.setFaceEps(bounds).subdividedFaces.empty());
  const std::vector<float> wrongSize(3, 0.01f);
  EXPECT_THROW(live.setFaceEps(wrongSize), InvalidInput);
  bounds[5] = 0.0f;
  EXPECT_THROW(live.setFaceEps(bounds), InvalidInput);
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
