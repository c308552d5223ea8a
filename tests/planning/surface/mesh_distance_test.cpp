// SPDX-License-Identifier: MIT
// Tests of exact signed point-to-mesh distances against brute force and inside/outside oracles.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "../../support/random_geometry.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Distance to a triangle by a different route than the code under test: the plane foot if it
// lies inside (signed areas), else the nearest of the three edges.
double triangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double edges =
      std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
  if (n.squaredNorm() == 0.0) return edges;
  const Vec3 foot = p - n * ((p - a).dot(n) / n.squaredNorm());
  const bool inside = (b - a).cross(foot - a).dot(n) >= 0.0 &&
                      (c - b).cross(foot - b).dot(n) >= 0.0 &&
                      (a - c).cross(foot - c).dot(n) >= 0.0;
  return inside ? std::min(edges, (p - foot).norm()) : edges;
}

double bruteDistance(const ddf::TriangleMesh& mesh, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles)
    best = std::min(
        best, triangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return best;
}

// Inside a closed mesh by ray parity along a fixed irrational direction (Moeller-Trumbore).
bool insideByParity(const ddf::TriangleMesh& mesh, const Vec3& p) {
  const Vec3 dir = Vec3(0.5477, 0.3162, 0.7746).normalized();
  int crossings = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 e1 = b - a, e2 = c - a, s = dir.cross(e2);
    const double det = e1.dot(s);
    if (std::abs(det) < 1e-15) continue;
    const Vec3 r = p - a;
    const double u = r.dot(s) / det;
    const Vec3 q = r.cross(e1);
    const double v = dir.dot(q) / det;
    if (u < 0 || v < 0 || u + v > 1) continue;
    if (e2.dot(q) / det > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

ddf::TriangleMesh icosphere(double radius, int levels) {
  return ddf::extractSupportMesh(
      ddf::spherePart({.radiusMm = radius, .subdivisions = levels, .m = 2}).ddf);
}

// A mesh with slivers, zero-area and repeated triangles and an unused vertex.
ddf::TriangleMesh randomSoup(std::mt19937& rng) {
  ddf::TriangleMesh mesh;
  for (int v = 0; v < 60; ++v) mesh.vertices.push_back(test::randomVec(rng, 3.0));
  mesh.vertices.push_back(mesh.vertices[0] * 0.5 + mesh.vertices[1] * 0.5);  // collinear
  for (int t = 0; t < 80; ++t)
    mesh.triangles.push_back({int(rng() % 60), int(rng() % 60), int(rng() % 60)});
  mesh.triangles.push_back({0, 1, 60});  // zero area
  mesh.triangles.push_back({5, 5, 7});   // repeated vertex
  mesh.triangles.push_back({2, 2, 2});   // a point
  mesh.triangles.push_back(mesh.triangles[3]);
  return mesh;
}

void expectMatchesBruteForce(const MeshDistance& distance, const ddf::TriangleMesh& mesh,
                             const Vec3& p) {
  const auto c = distance.closestPoint(p);
  ASSERT_TRUE(c);
  const double brute = bruteDistance(mesh, p);
  EXPECT_NEAR(c->distance, brute, 1e-12) << p.transpose();
  EXPECT_NEAR((c->point - p).norm(), c->distance, 1e-12);
  EXPECT_EQ(std::abs(c->signedDistance), c->distance);
  ASSERT_GE(c->triangle, 0);
  const auto& t = mesh.triangles[c->triangle];
  EXPECT_NEAR(
      triangleDistance(c->point, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]),
      0.0, 1e-12);
}

TEST(MeshDistance, MatchesBruteForceOnASphere) {
  std::mt19937 rng(21);
  const ddf::TriangleMesh mesh = icosphere(10.0, 3);
  const MeshDistance distance(mesh);
  EXPECT_EQ(distance.triangleCount(), 1280);
  for (int trial = 0; trial < 300; ++trial)
    expectMatchesBruteForce(distance, mesh, test::randomVec(rng, 14.0));
}

TEST(MeshDistance, MatchesBruteForceOnATriangleSoup) {
  std::mt19937 rng(22);
  for (int soup = 0; soup < 5; ++soup) {
    const ddf::TriangleMesh mesh = randomSoup(rng);
    const MeshDistance distance(mesh);
    for (int trial = 0; trial < 200; ++trial)
      expectMatchesBruteForce(distance, mesh, test::randomVec(rng, 4.0));
  }
}

// Convex mesh: inside exactly when behind every face plane.
TEST(MeshDistance, SignIsNegativeInsideAConvexMesh) {
  std::mt19937 rng(23);
  const ddf::TriangleMesh mesh = icosphere(5.0, 2);
  const MeshDistance distance(mesh);
  int inside = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Points near the surface, where the closest feature is often an edge or a vertex.
    const Vec3 dir = test::randomVec(rng).normalized();
    const Vec3 p = dir * (5.0 + std::uniform_real_distribution<double>(-0.4, 0.4)(rng));
    double plane = -std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
      const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      plane = std::max(plane, (p - a).dot((b - a).cross(c - a).normalized()));
    }
    if (std::abs(plane) < 1e-9) continue;
    const auto c = distance.closestPoint(p);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->signedDistance < 0.0, plane < 0.0) << p.transpose();
    inside += plane < 0.0;
  }
  EXPECT_GT(inside, 300);
}

// Non-convex closed mesh (a torus): the sign agrees with ray parity, also near saddle vertices.
TEST(MeshDistance, SignAgreesWithRayParityOnATorus) {
  std::mt19937 rng(24);
  const ddf::TriangleMesh mesh = ddf::extractSupportMesh(
      ddf::torusPart(
          {.majorRadiusMm = 3.0, .minorRadiusMm = 1.0, .segmentsU = 16, .segmentsV = 8, .m = 2})
          .ddf);
  const MeshDistance distance(mesh);
  for (int trial = 0; trial < 1500; ++trial) {
    const Vec3 p = trial % 2
                       ? test::randomVec(rng, 4.5)
                       : mesh.vertices[rng() % mesh.vertices.size()] + test::randomVec(rng, 0.3);
    const auto c = distance.closestPoint(p);
    ASSERT_TRUE(c);
    if (c->distance < 1e-9) continue;
    EXPECT_EQ(c->signedDistance < 0.0, insideByParity(mesh, p)) << p.transpose();
  }
}

// Cube [-1, 1]^3 with an inward pyramid of depth @p depth on every face: a closed star-like
// solid whose cube edges are sharp crests and whose pyramid edges are deep valleys, where a
// single face normal gives the wrong side.
ddf::TriangleMesh dentedCube(double depth) {
  ddf::TriangleMesh mesh;
  for (int c = 0; c < 8; ++c)
    mesh.vertices.emplace_back(c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0);
  // Quads counter-clockwise seen from outside, and their outward axis.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const Vec3 axes[6] = {-Vec3::UnitZ(), Vec3::UnitZ(),  -Vec3::UnitY(),
                        Vec3::UnitY(),  -Vec3::UnitX(), Vec3::UnitX()};
  for (int q = 0; q < 6; ++q) {
    const int apex = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(axes[q] * (1.0 - depth));
    for (int s = 0; s < 4; ++s)
      mesh.triangles.push_back({quads[q][s], quads[q][(s + 1) % 4], apex});
  }
  return mesh;
}

TEST(MeshDistance, SignAgreesWithRayParityAtSharpEdges) {
  std::mt19937 rng(26);
  const ddf::TriangleMesh mesh = dentedCube(0.8);
  ASSERT_GT(mesh.signedVolume(), 0.0);
  const MeshDistance distance(mesh);
  int inside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 p = test::randomVec(rng, 1.3);
    const auto c = distance.closestPoint(p);
    ASSERT_TRUE(c);
    if (c->distance < 1e-9) continue;
    const bool expected = insideByParity(mesh, p);
    inside += expected;
    EXPECT_EQ(c->signedDistance < 0.0, expected) << p.transpose();
    EXPECT_NEAR(c->distance, bruteDistance(mesh, p), 1e-12);
  }
  EXPECT_GT(inside, 200);
}

// On an open surface the sign is the side the counter-clockwise normals point to.
TEST(MeshDistance, SignFollowsNormalsOnAnOpenSurface) {
  const auto gen = ddf::planePatch({.cellsX = 4, .cellsY = 3, .m = 2});
  const ddf::TriangleMesh mesh = ddf::extractSupportMesh(gen.ddf);  // z = 0, normals +z
  const MeshDistance distance(mesh);
  std::mt19937 rng(25);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 p(std::uniform_real_distribution<double>(-5.0, 45.0)(rng),
                 std::uniform_real_distribution<double>(-5.0, 35.0)(rng),
                 std::uniform_real_distribution<double>(-2.0, 2.0)(rng));
    const auto c = distance.closestPoint(p);
    ASSERT_TRUE(c);
    if (p.x() >= 0 && p.x() <= 40 && p.y() >= 0 && p.y() <= 30) {
      EXPECT_NEAR(c->signedDistance, p.z(), 1e-12);
    } else if (std::abs(p.z()) > 1e-9) {
      EXPECT_EQ(c->signedDistance < 0.0, p.z() < 0.0);
    }
  }
}

TEST(MeshDistance, HonoursTheDistanceBound) {
  const ddf::TriangleMesh mesh = icosphere(1.0, 1);
  const MeshDistance distance(mesh);
  const Vec3 far(5.0, 0.0, 0.0);
  const double d = distance.closestPoint(far)->distance;
  EXPECT_FALSE(distance.closestPoint(far, d - 1e-9));
  ASSERT_TRUE(distance.closestPoint(far, d + 1e-9));
  EXPECT_EQ(distance.closestPoint(far, d + 1e-9)->distance, d);
  EXPECT_FALSE(distance.closestPoint(Vec3(std::nan(""), 0.0, 0.0)));
}

TEST(MeshDistance, RejectsEmptyAndBrokenMeshes) {
  EXPECT_THROW(MeshDistance{ddf::TriangleMesh{}}, InvalidInput);
  ddf::TriangleMesh broken;
  broken.vertices = {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
  broken.triangles = {{0, 1, 3}};
  EXPECT_THROW(MeshDistance{broken}, InvalidInput);
  broken.triangles = {{0, -1, 2}};
  EXPECT_THROW(MeshDistance{broken}, InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
