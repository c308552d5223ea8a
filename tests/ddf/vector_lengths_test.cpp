// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/vector_lengths.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

/// Every pair of faces sharing no vertex whose crusts intersect, by an O(F^2) loop.
std::vector<std::array<int, 2>> bruteForceConflicts(const DisplacementField& ddf) {
  std::vector<std::array<int, 2>> out;
  for (int s = 0; s < ddf.faceCount(); ++s)
    for (int t = s + 1; t < ddf.faceCount(); ++t)
      if (!facesShareVertex(ddf, s, t) && crustsIntersect(ddf, s, t)) out.push_back({s, t});
  return out;
}

TEST(VectorLengths, FlatGridGetsTheMeanEdgeLength) {
  const auto mesh = test::gridMesh(4, 4);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 2}), 3);
  const auto report = chooseVectorLengths(ddf);
  // 40 unit edges and 16 diagonals; parallel vectors never bound the crust.
  const double mean = (40.0 + 16.0 * std::sqrt(2.0)) / 56.0;
  for (const Vec3& v : ddf.vectors()) EXPECT_NEAR((v - Vec3(0, 0, mean)).norm(), 0.0, 1e-12);
  EXPECT_TRUE(std::isinf(report.minH0));
  EXPECT_EQ(report.shortenedVertices, 0);
  EXPECT_EQ(report.remainingConflicts, 0);
}

TEST(VectorLengths, OctahedronIsLimitedByItsCentre) {
  // Radial stubbles of an octahedron of radius 2 meet at the centre: h0- = 2 / length, so the
  // lengths become safety x 2 = 1.9.
  const auto mesh = test::octahedronMesh(2.0);
  DisplacementField ddf(mesh, test::radialVectors(mesh, 0.1), 3);
  VectorLengthParams params;
  params.maxLengthMm = 5.0;
  const auto report = chooseVectorLengths(ddf, params);
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    EXPECT_NEAR(ddf.vector(v).norm(), 1.9, 1e-9) << v;
    EXPECT_NEAR(ddf.vector(v).normalized().dot(ddf.position(v).normalized()), 1.0, 1e-12);
  }
  // A double root of D_i (all stubbles meet in one point) is only accurate to ~sqrt(eps).
  EXPECT_NEAR(report.minH0, 2.0 / 1.9, 1e-7);
}

/// 8 x 8 grid with random heights and directions tilted by up to @p tilt horizontally.
DisplacementField bumpyField(std::vector<Vec3>& dirs, double tilt = 0.4) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto mesh = test::gridMesh(8, 8);
  for (const auto vh : mesh.vertices()) mesh.point(vh)[2] = 0.5 * u(rng);
  dirs.clear();
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
    dirs.push_back(Vec3(0, 0, 1) + tilt * Vec3(u(rng), u(rng), 0));
  return DisplacementField(mesh, dirs, 3);
}

TEST(VectorLengths, BumpyMeshEndsWithUniqueCrusts) {
  std::vector<Vec3> dirs;
  DisplacementField ddf = bumpyField(dirs);
  VectorLengthParams params;
  params.maxLengthMm = 3.0;  // long enough that both per-face and pair limits bite
  const auto report = chooseVectorLengths(ddf, params);
  EXPECT_GE(report.minH0, 1.0);
  for (int f = 0; f < ddf.faceCount(); ++f) EXPECT_GE(crustHeights(ddf, f).min(), 1.0) << f;
  EXPECT_TRUE(bruteForceConflicts(ddf).empty());
  EXPECT_EQ(report.remainingConflicts, 0);
  EXPECT_TRUE(report.constraint1Faces.empty());
  for (int v = 0; v < ddf.vertexCount(); ++v)
    EXPECT_NEAR(ddf.vector(v).normalized().dot(dirs[v].normalized()), 1.0, 1e-12);
}

TEST(VectorLengths, UniformShrinkAndFallbackAlsoReachH0AboveOne) {
  std::vector<Vec3> dirs;
  for (int maxIterations : {50, 1}) {
    // Strong tilts: a few faces violate constraint 1 (skipped), the rest need 2 fixing passes.
    DisplacementField ddf = bumpyField(dirs, 1.2);
    VectorLengthParams params;
    params.maxLengthMm = 3.0;
    params.uniformShrink = true;  // sec. 4.4 verbatim
    params.checkNonAdjacent = false;
    params.maxIterations = maxIterations;  // 1 pass cannot settle: the fallback must step in
    const auto report = chooseVectorLengths(ddf, params);
    EXPECT_EQ(report.usedFallback, maxIterations == 1);
    EXPECT_FALSE(report.constraint1Faces.empty());
    const auto& skip = report.constraint1Faces;
    for (int f = 0; f < ddf.faceCount(); ++f)
      if (std::find(skip.begin(), skip.end(), f) == skip.end())
        EXPECT_GE(crustHeights(ddf, f).min(), 1.0) << f << " " << maxIterations;
  }
}

TEST(VectorLengths, StackedSheetsAreShrunkApart) {
  // Two parallel unit squares 1.5 apart, all vectors +z: no per-face bound, but the crusts of
  // faces above each other meet until 2 length < 1.5. Conflict rounds shrink by 0.8:
  // 2 -> 1.6 -> 1.28 -> 1.024 -> 0.8192 -> 0.65536.
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) points.push_back(points[i] + Vec3(0, 0, 1.5));
  const auto mesh = makeSupportMesh(points, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  DisplacementField ddf(mesh, test::constantVectors(mesh), 2);
  VectorLengthParams params;
  params.maxLengthMm = 2.0;
  const auto report = chooseVectorLengths(ddf, params);
  for (const Vec3& v : ddf.vectors()) EXPECT_NEAR(v.z(), 0.65536, 1e-9);
  EXPECT_TRUE(bruteForceConflicts(ddf).empty());
  EXPECT_GT(report.nonAdjacentConflictsResolved, 0);
  EXPECT_EQ(report.remainingConflicts, 0);
  EXPECT_EQ(report.shortenedVertices, 8);
}

TEST(VectorLengths, RejectsZeroVectorsAndBadParameters) {
  const auto mesh = test::gridMesh(2, 2);
  auto vectors = test::constantVectors(mesh);
  vectors[4] = Vec3::Zero();
  DisplacementField ddf(mesh, vectors, 2);
  try {
    chooseVectorLengths(ddf);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 4"), std::string::npos) << e.what();
  }
  DisplacementField ok(mesh, test::constantVectors(mesh), 2);
  VectorLengthParams bad;
  bad.safety = 1.5;
  EXPECT_THROW(chooseVectorLengths(ok, bad), InvalidInput);
}

TEST(VectorLengths, CancelLeavesVectorsUnchanged) {
  const auto mesh = test::octahedronMesh(2.0);
  DisplacementField ddf(mesh, test::radialVectors(mesh, 0.1), 3);
  const auto before = ddf.vectors();
  VectorLengthParams params;
  params.progress = [](double) { return false; };
  EXPECT_THROW(chooseVectorLengths(ddf, params), Cancelled);
  EXPECT_EQ(ddf.vectors(), before);
}

}  // namespace
}  // namespace ddfcam::ddf
