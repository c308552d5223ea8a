// SPDX-License-Identifier: MIT
// ddfcam tests: the curvature of a part converted with a reduced support, taken from its design
// mesh, against the analytic curvature of a torus.
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/design_curvature.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "../../support/test_meshes.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;
constexpr double kR = 20.0, kTube = 6.0;  // torus radii, mm

ddf::TriangleMesh torusMesh(int nu, int nv) {
  return test::torusMesh(kR, kTube, nu, nv);
}

std::pair<double, double> torusCurvature(const Vec3& p) {
  return test::torusCurvature(kR, kTube, p);
}

struct Errors {
  double max = 0.0, mean = 0.0;
};

Errors errorsOf(const ddf::DisplacementField& part, const CurvatureField& c) {
  Errors e;
  std::size_t count = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= part.raster().steps(); ++k)
      for (int i = 0; i < part.raster().rowLength(k); ++i) {
        const std::size_t at = f * part.pointsPerFace() + part.raster().index(i, k);
        const auto [k1, k2] = torusCurvature(part.surfacePoint(f, i, k));
        const double d = std::max(std::abs(c.kMax[at] - k1), std::abs(c.kMin[at] - k2));
        e.max = std::max(e.max, d), e.mean += d, ++count;
      }
  e.mean /= std::max<std::size_t>(count, 1);
  return e;
}

TEST(DesignCurvature, ReducedTorusHasTheTorusCurvatureWhereRasterDifferencesSeeFacets) {
  const ddf::TriangleMesh mesh = torusMesh(120, 48);
  ddf::ConversionParams params;
  params.support = ddf::SupportChoice::Reduced;
  const ddf::DisplacementField part = ddf::convertMeshToDdf(mesh, params).ddf;
  ASSERT_LT(part.faceCount(), static_cast<int>(mesh.triangles.size()) / 2);
  CurvatureParams design;
  design.designMesh = std::make_shared<const ddf::TriangleMesh>(mesh);
  const CurvatureField fitted = computeCurvature(part, design);
  EXPECT_EQ(fitted.method, CurvatureMethod::DesignMeshFit);
  CurvatureParams own;
  own.method = CurvatureMethod::RasterDifferences;
  const CurvatureField differences = computeCurvature(part, own);
  const Errors a = errorsOf(part, fitted), b = errorsOf(part, differences);
  std::printf(
      "torus %zu triangles -> %d faces (m = %d): |dk| design fit max %.3g mean %.3g, "
      "raster differences max %.3g mean %.3g 1/mm (1/r = %.3g)\n",
      mesh.triangles.size(), part.faceCount(), part.resolution(), a.max, a.mean, b.max, b.mean,
      1.0 / kTube);
  // A 2-ring quadric fit at vertices spaced h ~ 2 pi r / 48 ~ 0.8 mm is exact up to
  // O((h / r)^2) ~ 2 % of 1/r; the raster differences see the facets' edges.
  EXPECT_LT(a.max, 0.02 / kTube);
  EXPECT_LT(a.mean, 0.01 / kTube);
  EXPECT_GT(b.max, 1.0 / kTube);
  // Labels that are all the same change nothing.
  design.faceLabels.assign(static_cast<std::size_t>(part.faceCount()), 7);
  const CurvatureField labelled = computeCurvature(part, design);
  EXPECT_EQ(labelled.kMax, fitted.kMax);
  EXPECT_EQ(labelled.kMin, fitted.kMin);
}

TEST(DesignCurvature, FaceCutBelowTheDesignGetsItsOwnRasterDifferences) {
  const ddf::TriangleMesh mesh = torusMesh(120, 48);
  ddf::ConversionParams params;
  params.support = ddf::SupportChoice::Reduced;
  ddf::DisplacementField part = ddf::convertMeshToDdf(mesh, params).ddf;
  // Face 0 lowered by half its crust: far below the design mesh, as after a deep cut.
  for (float& h : part.heights(0)) h -= 0.5f;
  CurvatureParams design;
  design.designMesh = std::make_shared<const ddf::TriangleMesh>(mesh);
  const CurvatureField fitted = computeCurvature(part, design);
  CurvatureParams own;
  own.method = CurvatureMethod::RasterDifferences;
  const CurvatureField differences = computeCurvature(part, own);
  const std::size_t per = part.pointsPerFace();
  for (std::size_t at = 0; at < per; ++at) {
    EXPECT_EQ(fitted.kMax[at], differences.kMax[at]) << at;
    EXPECT_EQ(fitted.kMin[at], differences.kMin[at]) << at;
  }
  // A face far from face 0 still follows the design (tube curvature 1/r within 2 %).
  const int far = part.faceCount() / 2;
  const auto [k1, k2] = torusCurvature(part.surfacePoint(far, 1, 1));
  const std::size_t at = far * per + part.raster().index(1, 1);
  EXPECT_NEAR(fitted.kMax[at], k1, 0.02 / kTube);
  EXPECT_NEAR(fitted.kMin[at], k2, 0.02 / kTube);
}

TEST(DesignCurvature, RefusesLabelsThatDoNotMatchTheFacesAndAMissingMesh) {
  const ddf::TriangleMesh mesh = torusMesh(24, 12);
  const ddf::DisplacementField part = ddf::convertMeshToDdf(mesh, {}).ddf;
  CurvatureParams params;
  params.faceLabels = {1, 2, 3};
  EXPECT_THROW(computeDesignCurvature(part, mesh, params), InvalidInput);
  EXPECT_THROW(computeDesignCurvature(part, ddf::TriangleMesh{}, {}), InvalidInput);
  CurvatureParams fit;
  fit.method = CurvatureMethod::DesignMeshFit;
  EXPECT_THROW(computeCurvature(part, fit), InvalidInput);
}

TEST(DesignCurvature, PartCurvatureParamsUseTheDesignMeshOfAPartReadFromAFile) {
  Project project;
  const ddf::TriangleMesh mesh = torusMesh(24, 12);
  project.part = ddf::convertMeshToDdf(mesh, {}).ddf;
  project.designMesh = mesh;
  // A generated part (no source file): its heights are smooth, the raster differences see them.
  EXPECT_EQ(partCurvatureParams(project).designMesh, nullptr);
  project.sourcePath = "torus.stl";
  const CurvatureParams read = partCurvatureParams(project);
  ASSERT_NE(read.designMesh, nullptr);
  EXPECT_EQ(read.designMesh->triangles, mesh.triangles);
  EXPECT_TRUE(read.faceLabels.empty());
  project.cadFaceOfSupportFace.assign(static_cast<std::size_t>(project.part->faceCount()), 3);
  EXPECT_EQ(partCurvatureParams(project).faceLabels, project.cadFaceOfSupportFace);
  project.cadFaceOfSupportFace.pop_back();  // not one per face: not used
  EXPECT_TRUE(partCurvatureParams(project).faceLabels.empty());
}

}  // namespace
}  // namespace ddfcam::planning
