// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/validation.h>

#include <gtest/gtest.h>

#include <algorithm>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

bool mentions(const ValidationIssue& issue, const std::vector<int>& vertices,
              const std::vector<int>& faces) {
  auto contains = [](const std::vector<int>& set, int x) {
    return std::find(set.begin(), set.end(), x) != set.end();
  };
  return std::all_of(vertices.begin(), vertices.end(),
                     [&](int v) { return contains(issue.vertices, v); }) &&
         std::all_of(faces.begin(), faces.end(), [&](int f) { return contains(issue.faces, f); });
}

TEST(Validation, FlatGridWithShortVectorsIsValid) {
  const auto mesh = test::gridMesh(5, 5);
  const DisplacementField ddf(mesh, test::constantVectors(mesh, {0.1, 0, 0.5}), 4);
  const auto report = validate(ddf);
  EXPECT_TRUE(report.ok());
  EXPECT_TRUE(std::isinf(report.minCrustHeight));
}

TEST(Validation, BackFacingVectorNamesVertexAndFaces) {
  const auto mesh = test::gridMesh(2, 2);
  auto vectors = test::constantVectors(mesh, {0, 0, 0.5});
  vectors[4] = {0.3, 0, -0.2};  // the centre vertex, shared by six faces
  const DisplacementField ddf(mesh, vectors, 3);
  const auto report = validate(ddf);
  EXPECT_FALSE(report.ok());
  const auto& faces = ddf.topology().vertexFaces(4);
  EXPECT_EQ(report.count(1), static_cast<int>(faces.size()));
  for (int f : faces)
    EXPECT_TRUE(std::any_of(report.issues.begin(), report.issues.end(), [&](const auto& i) {
      return i.constraint == 1 && mentions(i, {4}, {f});
    })) << f;
  EXPECT_NE(report.issues[0].message.find("vertex 4"), std::string::npos);
}

TEST(Validation, ZeroVectorIsReported) {
  const auto mesh = test::gridMesh(1, 1);
  auto vectors = test::constantVectors(mesh);
  vectors[2] = Vec3::Zero();
  const auto report = validate(DisplacementField(mesh, vectors, 2));
  ASSERT_GE(report.count(1), 1);
  EXPECT_TRUE(mentions(report.issues[0], {2}, {}));
}

TEST(Validation, UnweldedVerticesWithDifferentVectorsViolateConstraint2) {
  // A unit square as two triangles with their own vertices (as read from an STL): vertices 0/3
  // and 2/4 coincide.
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                    {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const auto mesh = makeSupportMesh(points, {{0, 1, 2}, {3, 4, 5}});
  auto vectors = test::constantVectors(mesh, {0, 0, 0.5});
  EXPECT_TRUE(validate(DisplacementField(mesh, vectors, 3)).ok());
  vectors[4] = {0.1, 0, 0.5};
  const auto report = validate(DisplacementField(mesh, vectors, 3));
  ASSERT_EQ(report.count(2), 1);
  EXPECT_TRUE(mentions(report.issues[0], {2, 4}, {}));
}

TEST(Validation, LongRadialVectorsFailCrustHeights) {
  // Octahedron of radius 2: radial stubbles meet at the centre, h0- = 2 / length.
  const auto mesh = test::octahedronMesh(2.0);
  EXPECT_TRUE(validate(DisplacementField(mesh, test::radialVectors(mesh, 1.5), 3)).ok());
  const DisplacementField tooLong(mesh, test::radialVectors(mesh, 3.0), 3);
  // The stubbles also pass the centre into the opposite octant: the four pairs of opposite
  // faces (the only pairs sharing no vertex) have intersecting crusts.
  EXPECT_EQ(validate(tooLong).count(3), 8 + 4);
  ValidationParams perFace;
  perFace.checkNonAdjacent = false;
  const auto report = validate(tooLong, perFace);
  EXPECT_EQ(report.count(3), 8);
  EXPECT_NEAR(report.minCrustHeight, 2.0 / 3.0, 1e-7);
  for (int f = 0; f < 8; ++f)
    EXPECT_TRUE(std::any_of(report.issues.begin(), report.issues.end(),
                            [&](const auto& i) { return mentions(i, {}, {f}); }));
}

TEST(Validation, IntersectingCrustsOfStackedSheetsAreNamed) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) points.push_back(points[i] + Vec3(0, 0, 1.5));
  const auto mesh = makeSupportMesh(points, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  const auto report = validate(DisplacementField(mesh, test::constantVectors(mesh), 2));
  EXPECT_GE(report.count(3), 2);
  for (std::vector<int> pair : {std::vector<int>{0, 2}, std::vector<int>{1, 3}})
    EXPECT_TRUE(std::any_of(report.issues.begin(), report.issues.end(),
                            [&](const auto& i) { return mentions(i, {}, pair); }));
  ValidationParams params;
  params.checkNonAdjacent = false;
  EXPECT_TRUE(validate(DisplacementField(mesh, test::constantVectors(mesh), 2), params).ok());
}

TEST(Validation, IssueListIsCapped) {
  const auto mesh = test::octahedronMesh(2.0);
  ValidationParams params;
  params.maxIssues = 3;
  params.checkNonAdjacent = false;
  const auto report = validate(DisplacementField(mesh, test::radialVectors(mesh, 3.0), 3), params);
  EXPECT_EQ(report.issues.size(), 3u);
  EXPECT_EQ(report.suppressedIssues, 5);
  EXPECT_FALSE(report.ok());
}

}  // namespace
}  // namespace ddfcam::ddf
