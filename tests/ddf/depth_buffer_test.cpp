// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

// A box whose bottom face is the plane through the point c with the unit normal -up, i.e. the
// half-space "above" the plane, as a closed mesh: a large box rotated so its -z face lies on
// the plane.
TriangleMesh halfSpaceAbove(const Vec3& point, const Vec3& up, double size = 100.0) {
  const TriangleMesh box = test::boxMesh({-size, -size, 0.0}, {size, size, 2 * size});
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), up.normalized()).toRotationMatrix();
  pose.translation() = point;
  return box.transformed(pose);
}

TEST(DepthBuffer, PlanarZMapCutByPlaneMatchesAnalyticHeights) {
  // Planar support, parallel vectors (0, 0, 2): a z-map; heights start at the crust top.
  const auto mesh = test::gridMesh(4, 3, 10.0, 10.0);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 2}), 33, 1.0f);
  const CrustHash hash(ddf);
  const Vec3 up = Vec3(0.1, -0.05, 1.0).normalized();
  const Vec3 through(20.0, 15.0, 0.3);
  const auto stats =
      cutByMesh(ddf, hash, halfSpaceAbove(through, up), Eigen::Isometry3d::Identity());
  EXPECT_GT(stats.pointsLowered, 0u);
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < 33; ++k)
      for (int i = 0; i < 33 - k; ++i) {
        const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        // Plane: up . (x - through) = 0 along x = g + t (0,0,2).
        const double zPlane = (up.dot(through - g)) / up.z();
        const double expected = std::clamp(zPlane / 2.0, -1.0, 1.0);
        worst = std::max(worst, std::abs(ddf.height(f, i, k) - expected));
      }
  EXPECT_LT(worst, 2e-6) << "z-map cut differs from the analytic plane";
}

// Octahedron support with radial vectors v = 0.9 p: every stubble is a ray from the origin and
// the +-1 crust spans radii 0.1 |g| .. 1.9 |g|.
struct RadialSphere {
  SupportMesh mesh = test::octahedronMesh(1.0);
  DisplacementField ddf{mesh, test::radialVectors(mesh, 0.9), 25};
  double radius = 0.9;
  RadialSphere() {
    for (int f = 0; f < ddf.faceCount(); ++f)
      for (int k = 0; k < 25; ++k)
        for (int i = 0; i < 25 - k; ++i) {
          const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
          ddf.heights(f)[ddf.raster().index(i, k)] =
              static_cast<float>((radius / g.norm() - 1.0) / 0.9);
        }
  }
};

TEST(DepthBuffer, SphereCutByPlanesMatchesAnalyticHeights) {
  RadialSphere s;
  const CrustHash hash(s.ddf);
  const std::vector<std::pair<Vec3, Vec3>> planes = {
      {{0, 0, 0.6}, {0, 0, 1}}, {{0.5, 0.1, 0}, {1, 0.2, 0.1}}, {{0, -0.4, -0.3}, {0, -1, -1}}};
  for (const auto& [point, up] : planes)
    cutByMesh(s.ddf, hash, halfSpaceAbove(point, up), Eigen::Isometry3d::Identity());
  double worst = 0.0;
  for (int f = 0; f < s.ddf.faceCount(); ++f)
    for (int k = 0; k < 25; ++k)
      for (int i = 0; i < 25 - k; ++i) {
        const Vec3 g = s.ddf.basePoint(f, s.ddf.rasterBary(i, k));
        const Vec3 d = g.normalized();
        double r = s.radius;
        for (const auto& [point, up] : planes) {
          const Vec3 u = up.normalized();
          // Ray t d enters the half-space {u.(x - point) >= 0} at t = u.point / u.d when u.d > 0.
          if (u.dot(d) > 0) r = std::min(r, std::max(u.dot(point) / u.dot(d), 0.0));
        }
        const double expected = std::max(-1.0, (r / g.norm() - 1.0) / 0.9);
        worst = std::max(worst, std::abs(s.ddf.height(f, i, k) - expected));
      }
  EXPECT_LT(worst, 1e-5);
}

TEST(DepthBuffer, SharedCopiesAgreeAfterCut) {
  RadialSphere s;
  const CrustHash hash(s.ddf);
  const auto tool = planning::makeSphereTool(0.5, 12, 24);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(0.5, 0.4, 1.0);
  const auto stats = cutByMesh(s.ddf, hash, tool, pose);
  ASSERT_GT(stats.pointsLowered, 0u);
  const auto& topo = s.ddf.topology();
  for (std::size_t p = 0; p < topo.pointCount(); ++p) {
    float first = 0.f;
    bool seen = false;
    topo.forEachCopy(static_cast<PointId>(p), [&](PointCopy c) {
      const float h = s.ddf.heights(c.face)[c.local];
      if (!seen) first = h, seen = true;
      EXPECT_EQ(h, first) << "point " << p << " face " << c.face;
    });
  }
}

TEST(DepthBuffer, BallCutMatchesBallGeometry) {
  // Ball of radius R pressed into a z-map: height = bottom of the ball above each point.
  const auto mesh = test::gridMesh(2, 2, 5.0, 5.0);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 1}), 41, 1.0f);
  const CrustHash hash(ddf);
  const double radius = 3.0;
  const auto ball = planning::makeSphereTool(radius, 64, 128);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(5.0, 5.0, radius - 0.5);
  cutByMesh(ddf, hash, ball, pose);
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < 41; ++k)
      for (int i = 0; i < 41 - k; ++i) {
        const Vec3 g = ddf.basePoint(f, ddf.rasterBary(i, k));
        const double r2 = (g - Vec3(5, 5, 0)).squaredNorm();
        const double expected =
            r2 < radius * radius
                ? std::clamp(pose.translation().z() - std::sqrt(radius * radius - r2), -1.0, 1.0)
                : 1.0;
        worst = std::max(worst, std::abs(ddf.height(f, i, k) - expected));
      }
  // Chord error of a 64 x 128 UV sphere of radius 3: about R (1 - cos(pi/64)) = 3.6e-3.
  EXPECT_LT(worst, 4e-3);
}

TEST(DepthBuffer, FastPathEqualsDirectPerPointEvaluation) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto mesh = test::gridMesh(1, 1, 4.0, 4.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> vectors;
    for (int v = 0; v < 4; ++v)
      vectors.emplace_back(0.3 * u(rng), 0.3 * u(rng), 1.0 + 0.2 * u(rng));
    DisplacementField fast(mesh, vectors, 30, 1.0f), direct = fast, unrestricted = fast;
    const Vec3 c(2.0 + 2.0 * u(rng), 2.0 + 2.0 * u(rng), 0.5 * u(rng));
    const double size = trial % 2 ? 0.3 : 3.0;
    const Vec3 q1 = c + size * Vec3(u(rng), u(rng), u(rng));
    const Vec3 q2 = c + size * Vec3(u(rng), u(rng), u(rng));
    const Vec3 q3 = c + size * Vec3(u(rng), u(rng), u(rng));
    for (int f = 0; f < 2; ++f) {
      cutFaceByTriangle(fast, f, q1, q2, q3);
      cutFaceByTriangle(unrestricted, f, q1, q2, q3, {.restrictIntervals = false});
      cutFaceByTriangleDirect(direct, f, q1, q2, q3);
    }
    int mismatches = 0;
    for (std::size_t i = 0; i < fast.allHeights().size(); ++i) {
      const float a = fast.allHeights()[i], b = direct.allHeights()[i];
      if (std::abs(a - b) > 1e-4f) ++mismatches;
      EXPECT_EQ(a, unrestricted.allHeights()[i]) << "interval restriction changed a result";
    }
    // Only stubbles through a tool-triangle edge may differ (tolerance band), never more.
    EXPECT_LE(mismatches, 2) << "trial " << trial;
  }
}

TEST(DepthBuffer, RowRestrictionNeverChangesACutOnCurvedParts) {
  // The row and interval restriction (projected-corner rows, straight-edge row bounds grown by
  // the exact test, root intervals on long rows) must give bit-identical heights to scanning
  // every raster point, for tools of all sizes at random poses on a curved multi-face part.
  // Short rows (m = 33) take the whole-row and straight-edge paths, long rows (m = 129) the
  // straight-edge and exact-root paths.
  for (const auto& [subdivisions, m] : {std::pair{1, 33}, std::pair{0, 129}}) {
    SphereParams params;
    params.subdivisions = subdivisions;
    params.m = m;
    const auto part = spherePart(params);
    std::mt19937 rng(17 + m);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<TriangleMesh> tools = {planning::makeSphereTool(2.0, 8, 16),
                                             planning::makeCylinderTool({4.0, 12.0, 24}),
                                             planning::makeSphereTool(30.0, 6, 12)};
    DisplacementField restricted = part.ddf, full = part.ddf;
    const CrustHash hash(part.ddf);
    for (int trial = 0; trial < 120; ++trial) {
      const Vec3 dir = Vec3(u(rng), u(rng), u(rng)).normalized();
      const TriangleMesh& tool = tools[trial % tools.size()];
      const double reach = tool.bounds()[1].z();
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
      // Centre so the tool surface dips about 1-4 mm into the 10 mm sphere.
      pose.translation() = dir * (10.0 + reach - 1.0 - 3.0 * std::abs(u(rng)));
      cutByMesh(restricted, hash, tool, pose);
      cutByMesh(full, hash, tool, pose, {.restrictIntervals = false});
    }
    std::size_t differing = 0, lowered = 0;
    for (std::size_t i = 0; i < full.allHeights().size(); ++i) {
      differing += restricted.allHeights()[i] != full.allHeights()[i];
      lowered += full.allHeights()[i] < part.ddf.allHeights()[i];
    }
    EXPECT_GT(lowered, 1000u) << "m = " << m;
    EXPECT_EQ(differing, 0u) << "m = " << m;
  }
}

TEST(DepthBuffer, RowRestrictionNeverChangesResultsAlongASupportEdge) {
  // Tool triangles with an edge almost along raster row 0, a fraction of a row inside the face,
  // on a small face with strongly varying vectors (curved projected edges, as on a reduced
  // support of a thin part): the rows bounded by the projected triangle must still give the
  // heights of scanning every raster point, for fills and cuts.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), p(0.0, 1.0);
  const auto mesh = test::gridMesh(1, 1, 1.6, 1.6);
  constexpr int m = 20;
  std::size_t differing = 0, filled = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Vec3> vectors;
    for (int v = 0; v < 4; ++v)
      vectors.emplace_back(0.6 * u(rng), 0.6 * u(rng), 1.1 + 0.2 * u(rng));
    const DisplacementField ddf(mesh, vectors, m, 0.0f);
    const int f = trial % 2;
    const auto at = [&](double mu1, double mu3, double h) {
      const Vec3 bary(mu1, 1.0 - mu1 - mu3, mu3);
      return Vec3(ddf.basePoint(f, bary) + h * ddf.vectorAt(f, bary));
    };
    const double h = 0.6 * u(rng);
    const double nearRow0 = 0.3 / (m - 1);
    std::array<Vec3, 3> q = {at(-0.4 * p(rng), (0.5 + p(rng)) * nearRow0, h),
                             at(1.0 + 0.4 * p(rng), (0.5 + p(rng)) * nearRow0, h + 0.1 * u(rng)),
                             at(0.3 * p(rng), 0.3 + 0.6 * p(rng), h)};
    if (trial % 4 >= 2) std::swap(q[1], q[2]);
    const TriangleMesh tool{{q[0], q[1], q[2]}, {{0, 1, 2}}};
    const CrustHash hash(ddf);
    DisplacementField restricted = ddf, full = ddf;
    const auto report = fillFromMesh(restricted, hash, tool);
    fillFromMesh(full, hash, tool, {.kernel = {.restrictIntervals = false}});
    DisplacementField cutRestricted(mesh, vectors, m, 1.0f), cutFull = cutRestricted;
    cutFaceByTriangle(cutRestricted, f, q[0], q[1], q[2]);
    cutFaceByTriangle(cutFull, f, q[0], q[1], q[2], {.restrictIntervals = false});
    for (std::size_t i = 0; i < full.allHeights().size(); ++i) {
      differing += restricted.allHeights()[i] != full.allHeights()[i];
      differing += cutRestricted.allHeights()[i] != cutFull.allHeights()[i];
    }
    filled += report.filled;
  }
  EXPECT_GT(filled, 10000u);
  EXPECT_EQ(differing, 0u);
}

TEST(DepthBuffer, LocalizationIsSupersetOfBruteForce) {
  RadialSphere s;
  const CrustHash hash(s.ddf);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  std::size_t candidates = 0, truth = 0;
  std::vector<int> found;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const Vec3 q1 = c + 0.2 * Vec3(u(rng), u(rng), u(rng)),
               q2 = c + 0.2 * Vec3(u(rng), u(rng), u(rng)),
               q3 = c + 0.2 * Vec3(u(rng), u(rng), u(rng));
    hash.queryTriangle(q1, q2, q3, found);
    candidates += found.size();
    // Brute force: a face is truly affected if some stubble segment [-1, 1] crosses the triangle.
    for (int f = 0; f < s.ddf.faceCount(); ++f) {
      DisplacementField probe = s.ddf;
      std::fill(probe.heights(f).begin(), probe.heights(f).end(), 1.0f);
      const std::size_t hitsUp = cutFaceByTriangleDirect(probe, f, q1, q2, q3);
      std::fill(probe.heights(f).begin(), probe.heights(f).end(), 1.0f);
      const std::size_t hitsDown = cutFaceByTriangleDirect(probe, f, q1, q3, q2);
      bool inCrust = false;
      for (float h : probe.heights(f)) inCrust |= h > -1.0f && h < 1.0f;
      (void)hitsUp, (void)hitsDown;
      if (!inCrust) continue;
      ++truth;
      EXPECT_TRUE(std::binary_search(found.begin(), found.end(), f)) << "missed face " << f;
    }
  }
  ASSERT_GT(truth, 0u);
  RecordProperty("candidate_over_truth", std::to_string(double(candidates) / truth));
  std::printf("localization: %zu candidates for %zu true pairs (%.2fx)\n", candidates, truth,
              double(candidates) / truth);
}

TEST(CrustHash, FollowsVectorChanges) {
  // Lengthen the vectors: a triangle just outside the old crust but inside the new one must be
  // found after updateFaces (and was not a candidate before).
  const auto mesh = test::gridMesh(6, 6, 1.0, 1.0);
  DisplacementField ddf(mesh, test::constantVectors(mesh, {0, 0, 0.2}), 5);
  CrustHash hash(ddf);
  const Vec3 a(2.2, 2.2, 1.5), b(2.6, 2.2, 1.5), c(2.2, 2.6, 1.5);
  std::vector<int> before, after;
  hash.queryTriangle(a, b, c, before);
  ddf.setVectors(test::constantVectors(mesh, {0, 0, 2.0}));
  std::vector<int> all(ddf.faceCount());
  std::iota(all.begin(), all.end(), 0);
  hash.updateFaces(ddf, all);
  hash.queryTriangle(a, b, c, after);
  EXPECT_TRUE(before.empty());
  ASSERT_FALSE(after.empty());
  // The faces under the triangle (x, y in [2, 3]) are among the candidates.
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 centre = ddf.basePoint(f, Vec3(1, 1, 1) / 3.0);
    if (centre.x() > 2 && centre.x() < 3 && centre.y() > 2 && centre.y() < 3) {
      EXPECT_TRUE(std::binary_search(after.begin(), after.end(), f)) << "face " << f;
    }
  }
}

TEST(DepthBuffer, FillFromCubeAndSphereOnSharedSupport) {
  // Fig. 9.3: a cube and a sphere represented on the same radial support by filling.
  RadialSphere s;
  const CrustHash hash(s.ddf);
  const double a = 0.5;
  DisplacementField cube = s.ddf;
  const auto report = fillFromMesh(cube, hash, test::boxMesh({-a, -a, -a}, {a, a, a}));
  EXPECT_EQ(report.missing, 0u);
  DisplacementField sphere = s.ddf;
  std::fill(sphere.allHeights().begin(), sphere.allHeights().end(), 0.0f);
  fillFromMesh(sphere, hash, planning::makeSphereTool(0.9, 96, 192));
  double worstCube = 0.0, worstSphere = 0.0;
  for (int f = 0; f < s.ddf.faceCount(); ++f)
    for (int k = 0; k < 25; ++k)
      for (int i = 0; i < 25 - k; ++i) {
        const Vec3 g = s.ddf.basePoint(f, s.ddf.rasterBary(i, k));
        const double hCube = (a / g.cwiseAbs().maxCoeff() - 1.0) / 0.9;
        worstCube = std::max(worstCube, std::abs(cube.height(f, i, k) - hCube));
        const double hSphere = (0.9 / g.norm() - 1.0) / 0.9;
        worstSphere = std::max(worstSphere, std::abs(sphere.height(f, i, k) - hSphere));
      }
  EXPECT_LT(worstCube, 1e-5);
  // Chord error of the 96 x 192 UV sphere, in height units at the smallest |g|.
  EXPECT_LT(worstSphere, 0.9 * (1 - std::cos(M_PI / 96)) / (0.9 * 0.57));
}

}  // namespace
}  // namespace ddfcam::ddf
