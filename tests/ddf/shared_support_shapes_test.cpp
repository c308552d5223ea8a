// SPDX-License-Identifier: MIT
// Tests of the cube/sphere morph on a shared support (figs. 9.1/9.3) against analytic bounds.
#include <ddfcam/ddf/ddf_warp.h>
#include <ddfcam/ddf/shared_support_shapes.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ddfcam::ddf {
namespace {

// Deepest point of a sphere mesh below its sphere: a point x = sum l_i p_i of a triangle with
// corners on the sphere has |x|^2 = R^2 - sum_{i<j} l_i l_j |p_i - p_j|^2 >= R^2 - L^2 / 3.
double sagittaBound(const TriangleMesh& mesh, const Vec3& centre, double r) {
  double longest = 0.0;
  for (const auto& t : mesh.triangles)
    for (int s = 0; s < 3; ++s)
      longest = std::max(longest, (mesh.vertices[t[s]] - mesh.vertices[t[(s + 1) % 3]]).norm());
  for (const Vec3& v : mesh.vertices) EXPECT_NEAR((v - centre).norm(), r, 1e-9);
  return r - std::sqrt(r * r - longest * longest / 3.0);
}

class CubeSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    params_ = CubeSphereParams{.edgeMm = 80.0, .subdivisions = 6, .centreMm = Vec3(5, -3, 2)};
    morph_ = new CubeSphereMorph(cubeSphereMorph(params_));
  }
  static void TearDownTestSuite() { delete morph_; }
  static std::vector<Vec3> at(double t) {
    return heightPositions(morph_->ddf,
                           morphHeights(morph_->cubeHeights, morph_->sphereHeights, t));
  }
  static inline CubeSphereParams params_;
  static inline CubeSphereMorph* morph_ = nullptr;
};

TEST_F(CubeSphere, StartIsTheCube) {
  EXPECT_DOUBLE_EQ(morph_->sphereRadiusMm, params_.edgeMm);  // default R = edge
  for (const Vec3& q : at(0.0))
    ASSERT_NEAR((q - params_.centreMm).cwiseAbs().maxCoeff(), params_.edgeMm / 2, 1e-9);
}

TEST_F(CubeSphere, GoalIsTheSphereWithinTheMeshSagitta) {
  const double r = morph_->sphereRadiusMm;
  const double sag = sagittaBound(morph_->sphereMesh, params_.centreMm, r);
  EXPECT_LT(sag, 0.01 * r);
  for (const Vec3& q : at(1.0)) {
    const double dist = (q - params_.centreMm).norm();
    ASSERT_LE(dist, r + 1e-4);
    ASSERT_GE(dist, r - sag - 1e-4);
  }
  for (const float h : morph_->sphereHeights) ASSERT_TRUE(h > 0.0f && h <= 1.0f);
}

// At a support vertex the stubble is the radial ray, so the morph radius is linear in t.
TEST_F(CubeSphere, VertexRadiusIsLinearInTime) {
  const DisplacementField& ddf = morph_->ddf;
  const int n = ddf.raster().steps();
  const Vec3& c = params_.centreMm;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 p = ddf.position(ddf.faceVertices(f)[0]);  // raster point (n, 0)
    const std::size_t copy = f * ddf.pointsPerFace() + ddf.raster().index(n, 0);
    const double h1 = morph_->sphereHeights[copy];
    const double r1 = (p + h1 * ddf.vector(ddf.faceVertices(f)[0]) - c).norm();
    for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const Vec3 q =
          ddf.pointAt(f, ddf.rasterBary(n, 0), (1 - t) * morph_->cubeHeights[copy] + t * h1);
      ASSERT_NEAR((q - c).norm(), (1 - t) * (p - c).norm() + t * r1, 1e-9);
      ASSERT_NEAR((q - c).normalized().cross((p - c).normalized()).norm(), 0.0, 1e-9);
    }
  }
}

// Every point moves on the segment from its cube point g to its sphere point: by convexity its
// radius is at most (1 - t)|g - c| + t R, and it never comes closer to c than the inscribed
// ball of the cube (the segment stays outside it for nearly radial stubbles).
TEST_F(CubeSphere, IntermediateShapesStayBetweenCubeAndSphere) {
  const std::vector<Vec3> g = at(0.0);
  const Vec3& c = params_.centreMm;
  for (const double t : {0.25, 0.5, 0.75}) {
    const std::vector<Vec3> q = at(t);
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double dist = (q[i] - c).norm();
      ASSERT_LE(dist, (1 - t) * (g[i] - c).norm() + t * morph_->sphereRadiusMm + 1e-4);
      ASSERT_GE(dist, params_.edgeMm / 2 - 1e-9);
    }
  }
}

TEST(CubeSphereMorph, HeightsInterpolateLinearlyAndChecksHold) {
  const std::vector<float> h0{0.0f, 1.0f, -0.5f}, h1{1.0f, 0.0f, 0.5f};
  const std::vector<float> mid = morphHeights(h0, h1, 0.25);
  EXPECT_FLOAT_EQ(mid[0], 0.25f);
  EXPECT_FLOAT_EQ(mid[1], 0.75f);
  EXPECT_FLOAT_EQ(mid[2], -0.25f);
  EXPECT_THROW(morphHeights(h0, std::vector<float>{1.0f}, 0.5), InvalidInput);
  // A radius between the in- and circumradius of the cube would give a zero vector.
  EXPECT_THROW(cubeSphereMorph({.edgeMm = 10.0, .sphereRadiusMm = 6.0}), InvalidInput);
}

TEST(CubeSphereMorph, InscribedSphereWorksWithInwardVectors) {
  const CubeSphereMorph morph = cubeSphereMorph({.edgeMm = 50.0,
                                                 .subdivisions = 3,
                                                 .resolution = 3,
                                                 .sphereRadiusMm = 20.0,
                                                 .sphereLevel = 4});
  const std::vector<Vec3> q = heightPositions(morph.ddf, morph.sphereHeights);
  const double sag = sagittaBound(morph.sphereMesh, Vec3::Zero(), 20.0);
  for (const Vec3& p : q) {
    ASSERT_LE(p.norm(), 20.0 + 1e-4);
    ASSERT_GE(p.norm(), 20.0 - sag - 1e-4);
  }
}

}  // namespace
}  // namespace ddfcam::ddf
