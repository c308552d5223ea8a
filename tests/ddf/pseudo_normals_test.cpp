// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/pseudo_normals.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

#include "../support/conversion_meshes.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

/// Best margin min_i n_i . u over a dense Fibonacci sphere (the brute-force oracle).
double sampledBestMargin(const std::vector<Vec3>& normals, int samples = 40000) {
  double best = -2.0;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < samples; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / samples, r = std::sqrt(1.0 - z * z);
    const Vec3 u(r * std::cos(golden * k), r * std::sin(golden * k), z);
    double m = 2.0;
    for (const Vec3& n : normals) m = std::min(m, n.dot(u));
    best = std::max(best, m);
  }
  return best;
}

TEST(PseudoNormals, FlatGridIsUp) {
  const auto mesh = test::gridMesh(4, 3, 0.7, 1.3);
  const auto r = pseudoNormals(mesh);
  for (const Vec3& n : r.normals) EXPECT_NEAR((n - Vec3::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_TRUE(r.repairedVertices.empty());
  EXPECT_TRUE(r.infeasibleVertices.empty());
}

TEST(PseudoNormals, CubeCornerIsDiagonalWhateverTheSplit) {
  // Three unit squares meeting at the origin, split into 1, 2 and 4 triangles: angle weights
  // give (1, 1, 1)/sqrt 3 at the corner regardless (area or count weights would not).
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 1, 1}, {0, 0, 1}, {1, 0, 1}, {0.5, 0, 0.5}};
  // Square z = 0 (normal -z): (0,3,2),(0,2,1). Square x = 0 (normal -x): (0,5,4),(0,4,3).
  // Square y = 0 (normal -y), fanned around its centre 7.
  const auto mesh = makeSupportMesh(
      p, {{0, 3, 2}, {0, 2, 1}, {0, 5, 4}, {0, 4, 3}, {0, 1, 7}, {1, 6, 7}, {6, 5, 7}, {5, 0, 7}});
  const auto r = pseudoNormals(mesh);
  EXPECT_NEAR((r.normals[0] - Vec3(-1, -1, -1).normalized()).norm(), 0.0, 1e-12);
}

TEST(PseudoNormals, OctahedronVerticesAreRadial) {
  const auto mesh = test::octahedronMesh(2.0);
  const auto r = pseudoNormals(mesh);
  for (const auto vh : mesh.vertices())
    EXPECT_NEAR((r.normals[vh.idx()] - toEigen(mesh.point(vh)).normalized()).norm(), 0.0, 1e-12);
}

TEST(PseudoNormals, MaximinMatchesSphereSampling) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Vec3> normals;
    const int k = 3 + trial % 7;
    const double spread = trial % 2 ? 0.8 : 2.5;  // some sets have no common front direction
    for (int i = 0; i < k; ++i)
      normals.push_back((Vec3(0, 0, 1) + spread * Vec3(u(rng), u(rng), u(rng))).normalized());
    const auto best = maximinDirection(normals);
    ASSERT_TRUE(best);
    double m = 2.0;
    for (const Vec3& n : normals) m = std::min(m, n.dot(best->first));
    EXPECT_NEAR(m, best->second, 1e-12);
    const double sampled = sampledBestMargin(normals);
    if (sampled > 0.0) {
      EXPECT_GE(best->second, sampled - 1e-9) << trial;  // not worse than any sampled direction
      EXPECT_LT(best->second - sampled, 0.02) << trial;  // nor better than the true optimum
    } else {
      EXPECT_LE(best->second, 1e-3) << trial;  // infeasible sets are recognised as such
    }
  }
}

/// A fan around vertex 0 at the origin: flat wide triangles plus one steep overhang whose
/// normal points down and sideways.
SupportMesh overhangFan() {
  const std::vector<Vec3> p = {{0, 0, 0},   {1, 0, 0},    {0.5, 1, 0},      {-1, 1, 0},
                               {-1, -1, 0}, {0.5, -1, 0}, {0.6, 0.05, -0.5}};
  return makeSupportMesh(p, {{0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 1}, {0, 1, 2}});
}

TEST(PseudoNormals, RepairMakesEveryIncidentFaceFrontFacing) {
  const auto mesh = overhangFan();
  PseudoNormalParams params;
  params.minFrontCosine = 0.05;
  const auto r = pseudoNormals(mesh, params);
  ASSERT_EQ(r.repairedVertices, std::vector<int>{0});
  std::vector<Vec3> faceNormals;
  for (const auto fh : mesh.faces()) {
    std::vector<Vec3> q;
    for (const auto vh : mesh.fv_range(fh)) q.push_back(toEigen(mesh.point(vh)));
    faceNormals.push_back((q[1] - q[0]).cross(q[2] - q[0]).normalized());
  }
  double margin = 2.0, before = 2.0;
  const Vec3 angleWeighted = Vec3(0, 0, 1);  // dominated by the flat faces; z part positive
  for (const Vec3& n : faceNormals) {
    margin = std::min(margin, n.dot(r.normals[0]));
    before = std::min(before, n.dot(angleWeighted));
  }
  EXPECT_LE(before, 0.05);
  EXPECT_GE(margin, std::min(0.05, sampledBestMargin(faceNormals)) - 1e-9);
  EXPECT_NEAR(r.normals[0].norm(), 1.0, 1e-12);
}

TEST(PseudoNormals, FanWithSurroundingNormalsIsInfeasible) {
  // An open fan of four faces around vertex 0 whose unit normals are the corners of a regular
  // tetrahedron: the origin is inside their hull, so no direction is in front of all four.
  const std::vector<Vec3> n = {
      {0, 0, 1}, {0.9428, 0, -0.3333}, {-0.4714, 0.8165, -0.3333}, {-0.4714, -0.8165, -0.3333}};
  const ddf::TriangleMesh fan = test::foldedFanMesh();
  const std::vector<Vec3>& p = fan.vertices;
  const auto mesh = makeSupportMesh(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}});
  std::vector<Vec3> faceNormals;
  for (int i = 1; i <= 4; ++i) faceNormals.push_back(p[i].cross(p[i + 1]).normalized());
  for (int i = 0; i < 4; ++i) ASSERT_NEAR(faceNormals[i].dot(n[i].normalized()), 1.0, 1e-9);
  ASSERT_LT(sampledBestMargin(faceNormals), -0.1);
  const auto r = pseudoNormals(mesh);
  EXPECT_NE(std::find(r.infeasibleVertices.begin(), r.infeasibleVertices.end(), 0),
            r.infeasibleVertices.end());
}

}  // namespace
}  // namespace ddfcam::ddf
