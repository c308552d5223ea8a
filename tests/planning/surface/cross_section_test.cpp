// SPDX-License-Identifier: MIT
// ddfcam tests: section curves of a sphere, a sine sheet and a plane against analytic truth.
#include <ddfcam/error.h>
#include <ddfcam/planning/surface/cross_section.h>

#include <gtest/gtest.h>

#include "../../support/test_meshes.h"

#include <cmath>
#include <functional>
#include <numbers>

namespace ddfcam::planning {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

ddf::TriangleMesh heightGrid(int n, double half, const std::function<double(double, double)>& z) {
  return test::heightFieldMesh(-half, half, -half, half, n, n, z);
}

// UV sphere of radius r with poles; returns the longest edge through @p longestEdge.
ddf::TriangleMesh uvSphere(double r, int rings, int segments, double& longestEdge) {
  ddf::TriangleMesh mesh;
  mesh.vertices.emplace_back(0, 0, r);
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = std::numbers::pi * i / rings, ph = 2.0 * std::numbers::pi * j / segments;
      mesh.vertices.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                                 r * std::cos(th));
    }
  mesh.vertices.emplace_back(0, 0, -r);
  const int south = static_cast<int>(mesh.vertices.size()) - 1;
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.push_back({0, at(1, j), at(1, j + 1)});
    mesh.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  longestEdge = 0.0;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      longestEdge =
          std::max(longestEdge, (mesh.vertices[t[e]] - mesh.vertices[t[(e + 1) % 3]]).norm());
  return mesh;
}

TEST(CrossSection, SphereThroughCentreGivesCircleWithinSagitta) {
  const double r = 40.0;
  double edge = 0.0;
  const auto sphere = uvSphere(r, 48, 96, edge);
  // An oblique plane through the centre, not aligned with the meshing.
  const auto plane = sectionPlaneFromView({-50, -20, 3}, {50, 20, -3}, {0.1, -0.3, -1});
  ASSERT_LT(std::abs((Vector3d::Zero() - plane.origin).dot(plane.normal)), 1e-12);
  SectionParams params;
  params.clipToSegment = false;
  const auto curves = sectionCurves(sphere, plane, params);
  ASSERT_EQ(curves.size(), 1u);
  const auto& loop = curves[0];
  EXPECT_LT((loop.front() - loop.back()).norm(), 1e-12);  // closed
  // The centre in plane coordinates: its projection onto the plane.
  const Vector2d centre((-plane.origin).dot(plane.sAxis), (-plane.origin).dot(plane.tAxis));
  const double sagitta = r - std::sqrt(r * r - 0.25 * edge * edge);
  for (const auto& p : loop) {
    const double d = (p - centre).norm();
    EXPECT_LE(d, r + 1e-9);
    EXPECT_GE(d, r - sagitta - 1e-9);
  }
  EXPECT_GT(loop.size(), 150u);
}

TEST(CrossSection, SineSheetGivesTEqualsASinS) {
  const double a = 5.0, k = 2.0 * std::numbers::pi / 40.0;
  const auto sheet = heightGrid(120, 60.0, [&](double x, double) { return a * std::sin(k * x); });
  // Line along x at y = 7.3 drawn in a top view; s runs from x = -50.
  const auto plane = sectionPlaneFromView({-50, 7.3, 0}, {50, 7.3, 0}, {0, 0, -1});
  const auto curves = sectionCurves(sheet, plane);
  ASSERT_EQ(curves.size(), 1u);  // one polyline for a simple open surface
  const auto& line = curves[0];
  EXPECT_NEAR(line.front().x(), 0.0, 1e-9);   // clipped at a
  EXPECT_NEAR(line.back().x(), 100.0, 1e-9);  // and at b
  // Grid spacing 1 mm: chord error of A sin within A k^2 h^2 / 8 (plus the diagonal split).
  const double tol = a * k * k * 1.0 * 1.0 / 4.0 + 1e-9;
  for (const auto& p : line) EXPECT_NEAR(p.y(), a * std::sin(k * (p.x() - 50.0)), tol);
  for (std::size_t i = 1; i < line.size(); ++i) EXPECT_GT(line[i].x(), line[i - 1].x());
}

TEST(CrossSection, ClippingSplitsAndSortsPieces) {
  // A plane z = 0 sheet cut along a line that leaves and re-enters nothing: a single straight
  // segment of exactly the drawn length.
  const auto flat = heightGrid(10, 10.0, [](double, double) { return 0.0; });
  const auto plane = sectionPlaneFromView({-3.3, -2, 0}, {4.1, 3, 0}, {0, 0, -1});
  const auto curves = sectionCurves(flat, plane);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_NEAR((curves[0].back() - curves[0].front()).norm(), plane.lengthMm, 1e-9);
  for (const auto& p : curves[0]) EXPECT_NEAR(p.y(), 0.0, 1e-12);
  // Beyond the sheet on both ends: unclipped the curve spans the sheet only.
  const auto longer = sectionPlaneFromView({-30, 0.5, 0}, {30, 0.5, 0}, {0, 0, -1});
  const auto pieces = sectionCurves(flat, longer);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].front().x(), 20.0, 1e-9);
  EXPECT_NEAR(pieces[0].back().x(), 40.0, 1e-9);
  EXPECT_LT((sectionToWorld(longer, pieces[0].front()) - Vector3d(-10, 0.5, 0)).norm(), 1e-9);
}

TEST(CrossSection, BadPlanesAreRefused) {
  EXPECT_THROW(sectionPlaneFromView({0, 0, 0}, {0, 0, 0}, {0, 0, -1}), InvalidInput);
  EXPECT_THROW(sectionPlaneFromView({0, 0, 0}, {0, 0, 5}, {0, 0, -1}), InvalidInput);
  EXPECT_THROW(sectionPlaneFromNormal({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), InvalidInput);
  const auto p = sectionPlaneFromNormal({0, 0, 0}, {3, 0, 4}, {0, 0, 1});
  EXPECT_NEAR(p.lengthMm, 3.0, 1e-12);
  EXPECT_LT((p.tAxis - Vector3d(0, 1, 0)).norm(), 1e-12);
}

}  // namespace
}  // namespace ddfcam::planning
