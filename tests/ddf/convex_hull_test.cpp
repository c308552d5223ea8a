// SPDX-License-Identifier: MIT
// Tests of the 3D convex hull against analytic volumes and brute-force containment.
#include <ddfcam/ddf/convex_hull.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace ddfcam::ddf {
namespace {

using Vec = Eigen::Vector3d;

/// Every directed edge appears once and its reverse once: a closed, consistently oriented
/// 2-manifold; returns V - E + F.
int checkClosedAndEuler(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++edges[{t[e], t[(e + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second;
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "->" << edge.second << " has no twin";
  }
  return static_cast<int>(mesh.vertices.size()) - static_cast<int>(edges.size() / 2) +
         static_cast<int>(mesh.triangles.size());
}

/// Largest signed distance of any point above any hull face plane (<= ~0 for a true hull).
double maxOutside(const TriangleMesh& hull, const std::vector<Vec>& points) {
  double worst = -1e300;
  for (const auto& t : hull.triangles) {
    const Vec& a = hull.vertices[t[0]];
    const Vec n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
    for (const Vec& p : points) worst = std::max(worst, n.dot(p - a));
  }
  return worst;
}

TEST(ConvexHull, CubeWithInteriorAndFacePointsIsTheCube) {
  std::vector<Vec> points;
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 500; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  // Points exactly on the faces (coplanar with hull facets) must not break the topology.
  for (int i = 0; i < 200; ++i) {
    Vec p(u(rng), u(rng), u(rng));
    p[i % 3] = (i % 2) ? 1.0 : -1.0;
    points.push_back(p);
  }
  const TriangleMesh hull = convexHull(points);
  EXPECT_EQ(checkClosedAndEuler(hull), 2);
  EXPECT_NEAR(hull.signedVolume(), 8.0, 1e-12);
  EXPECT_LE(maxOutside(hull, points), 1e-12);
  EXPECT_EQ(hull.vertices.size(), 8u);
}

TEST(ConvexHull, PointsOnASphereAreAllOnTheHull) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec> points;
  for (int i = 0; i < 2000; ++i) points.push_back(Vec(g(rng), g(rng), g(rng)).normalized() * 5.0);
  const TriangleMesh hull = convexHull(points);
  EXPECT_EQ(checkClosedAndEuler(hull), 2);
  EXPECT_EQ(hull.vertices.size(), points.size());  // every point is extreme
  EXPECT_LE(maxOutside(hull, points), 1e-9);
  const double ball = 4.0 / 3.0 * std::numbers::pi * 125.0;
  EXPECT_LT(hull.signedVolume(), ball);
  EXPECT_GT(hull.signedVolume(), 0.98 * ball);
}

TEST(ConvexHull, TwoTranslatedRollsGiveTheMinkowskiSumWithTheSegment) {
  // A roll (axis x) translated by d along y: hull = cross-section polygon swept by d, times
  // the width; the polygon's area and its extent across the motion come from the vertices.
  const TriangleMesh roll =
      planning::makeCylinderTool({.radiusMm = 5.0, .widthMm = 10.0, .segments = 40});
  const double d = 3.7;
  std::vector<Vec> points;
  for (const Vec& v : roll.vertices) points.push_back(v);
  for (const Vec& v : roll.vertices) points.push_back(v + Vec(0.0, d, 0.0));
  double zMin = 1e300, zMax = -1e300;
  for (const Vec& v : roll.vertices) zMin = std::min(zMin, v.z()), zMax = std::max(zMax, v.z());
  const double area = roll.signedVolume() / 10.0;
  const TriangleMesh hull = convexHull(points);
  EXPECT_EQ(checkClosedAndEuler(hull), 2);
  EXPECT_NEAR(hull.signedVolume(), 10.0 * (area + d * (zMax - zMin)), 1e-9);
  EXPECT_LE(maxOutside(hull, points), 1e-9);
}

TEST(ConvexHull, RotatedAndFarFromTheOriginStaysValid) {
  // The swept-mode situation: two nearly identical instances far from the origin.
  const TriangleMesh ball = planning::makeSphereTool(2.0, 12, 24);
  const Eigen::Isometry3d a = Eigen::Translation3d(1000.0, -500.0, 20.0) *
                              Eigen::AngleAxisd(0.3, Vec(1.0, 2.0, 3.0).normalized());
  const Eigen::Isometry3d b =
      a * Eigen::Translation3d(1e-4, 0.0, 0.0) * Eigen::AngleAxisd(1e-5, Vec::UnitZ());
  std::vector<Vec> points;
  for (const Vec& v : ball.vertices) points.push_back(a * v);
  for (const Vec& v : ball.vertices) points.push_back(b * v);
  const TriangleMesh hull = convexHull(points);
  EXPECT_EQ(checkClosedAndEuler(hull), 2);
  EXPECT_NEAR(hull.signedVolume(), ball.signedVolume(), 1e-3 * ball.signedVolume());
  EXPECT_LE(maxOutside(hull, points), 1e-6);
}

TEST(ConvexHull, FlatOrTooFewPointsAreRejected) {
  const std::vector<Vec> three = {Vec(0, 0, 0), Vec(1, 0, 0), Vec(0, 1, 0)};
  EXPECT_THROW(convexHull(three), InvalidInput);
  std::vector<Vec> flat;
  for (int i = 0; i < 20; ++i) flat.emplace_back(i % 5, i / 5, 0.0);
  EXPECT_THROW(convexHull(flat), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
