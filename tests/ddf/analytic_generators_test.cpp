// SPDX-License-Identifier: MIT
// Generated DDFs of analytic surfaces: every raster point on the exact surface (closed-form
// oracles written out here, independent of the AnalyticSurface classes where one exists).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>

#include "../support/test_meshes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace ddfcam::ddf {
namespace {

/// A generator at a resolution level (0 = coarse, 1 = fine) and its closed-form residual
/// (distance or z-offset to the exact surface, mm) written independently of the library.
struct GeneratorCase {
  std::string name;
  std::function<GeneratedSurface(int level)> make;
  std::function<double(const Vec3&)> residual;
  int expectedFaces[2];
};

std::vector<GeneratorCase> generatorCases() {
  std::vector<GeneratorCase> cases;
  cases.push_back({"plane",
                   [](int level) {
                     return planePatch({.cellsX = 4 + 8 * level,
                                        .cellsY = 3 + 6 * level,
                                        .m = 5 + 12 * level,
                                        .planeZMm = -0.375});
                   },
                   [](const Vec3& q) { return q.z() + 0.375; },
                   {24, 216}});
  cases.push_back({"sphere",
                   [](int level) {
                     return spherePart(
                         {.radiusMm = 12.0, .subdivisions = 1 + level, .m = 5 + 12 * level});
                   },
                   [](const Vec3& q) { return q.norm() - 12.0; },
                   {80, 320}});
  cases.push_back({"cylinder",
                   [](int level) {
                     return cylinderPart({.radiusMm = 6.0,
                                          .segments = 12 + 12 * level,
                                          .rings = 3 + 3 * level,
                                          .m = 5 + 12 * level});
                   },
                   [](const Vec3& q) { return std::hypot(q.x(), q.y()) - 6.0; },
                   {72, 288}});
  cases.push_back(
      {"torus",
       [](int level) {
         return torusPart({.majorRadiusMm = 20.0,
                           .minorRadiusMm = 5.0,
                           .segmentsU = 16 + 16 * level,
                           .segmentsV = 8 + 8 * level,
                           .m = 5 + 12 * level});
       },
       [](const Vec3& q) { return std::hypot(std::hypot(q.x(), q.y()) - 20.0, q.z()) - 5.0; },
       {256, 1024}});
  cases.push_back(
      {"saddle",
       [](int level) {
         return saddlePatch(
             {.a = 0.04,
              .b = 0.07,
              .grid = {.cellsX = 6 + 6 * level, .cellsY = 5 + 5 * level, .m = 5 + 12 * level}});
       },
       [](const Vec3& q) { return q.z() - (0.04 * q.x() * q.x() - 0.07 * q.y() * q.y()); },
       {60, 240}});
  cases.push_back({"sinsin",
                   [](int level) {
                     SinSinParams p;
                     p.grid.cellsX = p.grid.cellsY = 10 + 10 * level;
                     p.grid.m = 5 + 12 * level;
                     return sinSinPatch(p);
                   },
                   [](const Vec3& q) { return q.z() - std::sin(q.x()) * std::sin(q.y()); },
                   {200, 800}});
  // The B-spline itself is verified against Cox-de Boor in bspline_patch_test.cpp.
  cases.push_back({"freeform",
                   [](int level) {
                     FreeformPatchParams p;
                     p.cellsX = 15 + 15 * level;
                     p.cellsY = 12 + 12 * level;
                     p.m = 5 + 12 * level;
                     return freeformPatch(p);
                   },
                   {},
                   {360, 1440}});
  cases.push_back({"demo",
                   [](int level) {
                     return demoPart(
                         {.cellsX = 8 + 24 * level, .cellsY = 6 + 18 * level, .m = 5 + 12 * level});
                   },
                   {},
                   {96, 1536}});
  return cases;
}

/// Largest |residual| over all raster points; also checks |h| <= 1 and that shared copies agree.
double maxResidual(const GeneratedSurface& g, const std::function<double(const Vec3&)>& residual) {
  const DisplacementField& ddf = g.ddf;
  const int n = ddf.raster().steps();
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    for (int k = 0; k <= n; ++k) {
      for (int i = 0; i <= n - k; ++i) {
        const float h = ddf.height(f, i, k);
        EXPECT_LE(std::abs(h), 1.0f);
        worst = std::max(worst, std::abs(residual(ddf.surfacePoint(f, i, k))));
      }
    }
  }
  const RasterTopology& topo = ddf.topology();
  for (PointId p = 0; p < topo.pointCount(); ++p) {
    float first = NAN;
    topo.forEachCopy(p, [&](PointCopy c) {
      const float h = ddf.heights(c.face)[c.local];
      if (std::isnan(first)) first = h;
      EXPECT_EQ(h, first) << "point " << p;
    });
  }
  return worst;
}

/// Constraint 1 (ch. 3): every vertex vector points to the front side of each incident face.
void expectVectorsToFront(const DisplacementField& ddf) {
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    const Vec3 normal = (ddf.position(fv[1]) - ddf.position(fv[0]))
                            .cross(ddf.position(fv[2]) - ddf.position(fv[0]));
    for (int v : fv) ASSERT_GT(ddf.vector(v).dot(normal), 0.0) << "face " << f;
  }
}

TEST(AnalyticGenerators, RasterPointsLieOnTheExactSurface) {
  for (const GeneratorCase& c : generatorCases()) {
    for (int level = 0; level < 2; ++level) {
      SCOPED_TRACE(c.name + " level " + std::to_string(level));
      const GeneratedSurface g = c.make(level);
      ASSERT_TRUE(g.surface && g.design);
      EXPECT_EQ(g.ddf.faceCount(), c.expectedFaces[level]);
      EXPECT_EQ(g.ddf.resolution(), 5 + 12 * level);
      expectVectorsToFront(g.ddf);
      const auto& surface = *g.surface;
      EXPECT_LT(maxResidual(g, [&](const Vec3& q) { return surface.value(q); }), 1e-5);
      if (c.residual) {
        EXPECT_LT(maxResidual(g, c.residual), 1e-5);
      }
    }
  }
}

TEST(AnalyticGenerators, PlanePatchIsAZMapWithConstantHeight) {
  const GeneratedSurface g = planePatch();
  EXPECT_EQ(g.ddf.faceCount(), 600);
  for (int v = 0; v < g.ddf.vertexCount(); ++v) {
    EXPECT_EQ(g.ddf.position(v).z(), 0.0);
    EXPECT_EQ(g.ddf.vector(v), Vec3(0.0, 0.0, 1.0));
  }
  for (float h : g.ddf.allHeights()) EXPECT_EQ(h, 0.25f);
}

TEST(AnalyticGenerators, DemoPartCarriesTheAllowanceAboveTheDesign) {
  const GeneratedSurface g = demoPart();
  EXPECT_EQ(g.ddf.faceCount(), 1536);
  EXPECT_EQ(g.ddf.resolution(), 17);
  ASSERT_NE(g.surface, g.design);
  const auto* design = dynamic_cast<const BSplinePatch*>(g.design.get());
  ASSERT_NE(design, nullptr);
  double lo = 1e9, hi = -1e9;
  for (int f = 0; f < g.ddf.faceCount(); f += 7) {
    for (int k = 0; k <= 16; k += 3) {
      for (int i = 0; i <= 16 - k; i += 2) {
        const Vec3 q = g.ddf.surfacePoint(f, i, k);
        EXPECT_NEAR(q.z() - design->height(q.x(), q.y()), 0.2, 1e-5);
        const float h = g.ddf.height(f, i, k);
        lo = std::min(lo, double(h)), hi = std::max(hi, double(h));
      }
    }
  }
  // The stock is a / W <= 0.2 mm above the design along the normal, plus the chord sag of the
  // support triangles (< 0.02 mm here); L = 1 mm.
  EXPECT_GT(lo, 0.1);
  EXPECT_LT(hi, 0.22);
  EXPECT_THROW(demoPart({.allowanceMm = 0.95}), InvalidInput);
  EXPECT_THROW(demoPart({.allowanceMm = -0.1}), InvalidInput);
}

TEST(AnalyticGenerators, FreeformPatchDefaultSizeAndTiming) {
  const auto start = std::chrono::steady_clock::now();
  const GeneratedSurface g = freeformPatch();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("freeform_m10_seconds", std::to_string(seconds));
  std::printf("[ measured ] freeformPatch() default (%d faces, m = %d): %.3f s\n",
              g.ddf.faceCount(), g.ddf.resolution(), seconds);
  EXPECT_GE(g.ddf.faceCount(), 19000);
  EXPECT_LE(g.ddf.faceCount(), 21000);
  EXPECT_EQ(g.ddf.resolution(), 10);
  const auto& surface = *g.surface;
  EXPECT_LT(maxResidual(g, [&](const Vec3& q) { return surface.value(q); }), 1e-5);
}

TEST(AnalyticGenerators, FromAnalyticNamesTheFaceWhoseStubbleMissesTheSurface) {
  // 3 x 1 grid in z = 0; vertices at x >= 2 get short vectors that cannot reach z = 0.5, so
  // the first failing face is the first triangle of cell 1 (face 2).
  const SupportMesh mesh = test::gridMesh(3, 1);
  std::vector<Vec3> vectors;
  for (const auto vh : mesh.vertices())
    vectors.emplace_back(0.0, 0.0, mesh.point(vh)[0] >= 2.0 ? 0.1 : 1.0);
  auto plane = std::make_shared<PlaneSurface>(0.5);
  try {
    fromAnalytic(mesh, vectors, 5, plane);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("support face 2 "), std::string::npos) << e.what();
  }
  EXPECT_THROW(fromAnalytic(mesh, vectors, 5, nullptr), InvalidInput);
  EXPECT_THROW(fromAnalytic(mesh, vectors, 1, plane), InvalidInput);
  vectors.pop_back();
  EXPECT_THROW(fromAnalytic(mesh, vectors, 5, plane), InvalidInput);
}

TEST(AnalyticGenerators, FromAnalyticFindsTheRootNearestTheSupport) {
  // Support in z = -1, vectors of 3 mm, unit sphere at the origin: each stubble near the axis
  // crosses the sphere near z = -1 (h ~ 0) and again near z = 1 (h ~ 0.67).
  auto sphere = std::make_shared<SphereSurface>(1.0);
  const std::vector<Vec3> points = {{-0.1, -0.1, -1.0}, {0.1, -0.1, -1.0}, {0.0, 0.1, -1.0}};
  const SupportMesh mesh = makeSupportMesh(points, {{0, 1, 2}});
  const GeneratedSurface g = fromAnalytic(mesh, test::constantVectors(mesh, {0, 0, 3}), 4, sphere);
  for (float h : g.ddf.allHeights()) EXPECT_LT(std::abs(h), 0.01);  // the lower cap
}

TEST(AnalyticGenerators, RejectInvalidParameters) {
  EXPECT_THROW(planePatch({.planeZMm = 1.5}), InvalidInput);
  EXPECT_THROW(planePatch({.cellsX = 0}), InvalidInput);
  EXPECT_THROW(spherePart({.subdivisions = 9}), InvalidInput);
  EXPECT_THROW(spherePart({.crustFraction = 1.0}), InvalidInput);
  EXPECT_THROW(cylinderPart({.segments = 2}), InvalidInput);
  EXPECT_THROW(torusPart({.majorRadiusMm = 5.0, .minorRadiusMm = 6.0}), InvalidInput);
  EXPECT_THROW(saddlePatch({.grid = {.m = 1}}), InvalidInput);
  EXPECT_THROW(graphPatch(nullptr, {}), InvalidInput);
  EXPECT_THROW(sinSinPatch({.scaleMm = 0.0}), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
