// SPDX-License-Identifier: MIT
// Tests of the tool flow field and its singularities against analytic truth (sec. 8.1).
#include "flow_field_test_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/flow_field.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace ddfcam::planning {
namespace {

using namespace flow_field_test;
using ddf::Vec3;

// Largest angle (deg) between the field and the torus meridian (the analytic k_max direction
// with the tube normals pointing outwards): the meridian is orthogonal to the parallel (-y, x, 0).
double maxMeridianDeviationDeg(const ddf::DisplacementField& ddf, const LineField& field) {
  const int n = ddf.raster().steps();
  double worst = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const Vec3 q = ddf.surfacePoint(f, i, k);
        const Vec3 parallel = Vec3(-q.y(), q.x(), 0.0).normalized();
        const Vec3& l = field[f * ddf.pointsPerFace() + ddf.raster().index(i, k)];
        EXPECT_NEAR(l.norm(), 1.0, 1e-9);
        worst = std::max(worst, std::asin(std::min(1.0, std::abs(l.dot(parallel)))) * kDeg);
      }
  return worst;
}

// Sum over lattice edges inside the faces of sin^2 of the angle between neighbouring lines.
double roughness(const ddf::DisplacementField& ddf, const LineField& field) {
  const int n = ddf.raster().steps();
  const ddf::Raster& r = ddf.raster();
  double e = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const std::size_t base = f * ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k < n; ++i) {
        const Vec3& a = field[base + r.index(i, k)];
        for (const Vec3& b : {field[base + r.index(i + 1, k)], field[base + r.index(i, k + 1)]})
          e += 1.0 - std::pow(a.dot(b), 2);
      }
  }
  return e;
}

TEST(FlowField, TorusMaxFieldFollowsMeridians) {
  const ddf::GeneratedSurface part = torus(7);
  const CurvatureField c = computeCurvature(part.ddf);
  EXPECT_LT(maxMeridianDeviationDeg(part.ddf, flowField(part.ddf, c, rawParams())), 0.5);
  EXPECT_LT(maxMeridianDeviationDeg(part.ddf, flowField(part.ddf, c)), 1.5);
}

TEST(FlowField, SignFlipsDoNotChangeTheField) {
  const ddf::GeneratedSurface part = torus(5);
  const CurvatureField c = computeCurvature(part.ddf);
  CurvatureField flipped = c;
  std::mt19937 rng(7);
  std::bernoulli_distribution coin(0.5);
  for (std::size_t a = 0; a < flipped.size(); ++a) {
    if (coin(rng)) flipped.dirMax[a] = -flipped.dirMax[a];
    if (coin(rng)) flipped.dirMin[a] = -flipped.dirMin[a];
  }
  for (bool smoothing : {false, true})
    for (auto source :
         {FlowFieldSource::MaxCurvatureDirection, FlowFieldSource::MinCurvatureDirection}) {
      FlowFieldParams p = rawParams(source);
      p.smoothing = smoothing;
      const LineField a = flowField(part.ddf, c, p), b = flowField(part.ddf, flipped, p);
      for (std::size_t i = 0; i < a.size(); ++i) ASSERT_GT(std::abs(a[i].dot(b[i])), 1.0 - 1e-9);
    }
}

TEST(FlowField, CopiesOfAPointShareTheirLine) {
  const ddf::GeneratedSurface part = torus(5);
  const LineField field = flowField(part.ddf, computeCurvature(part.ddf));
  const ddf::RasterTopology& topo = part.ddf.topology();
  for (ddf::PointId p = 0; p < topo.pointCount(); ++p) {
    Vec3 first = Vec3::Zero();
    topo.forEachCopy(p, [&](ddf::PointCopy c) {
      const Vec3& l = field[c.face * part.ddf.pointsPerFace() + c.local];
      if (first.isZero()) first = l;
      EXPECT_GT(std::abs(first.dot(l)), 1.0 - 1e-12);
    });
  }
}

TEST(FlowField, FixedDirectionOnAPlaneIsThatDirection) {
  const ddf::GeneratedSurface part = ddf::planePatch({.cellsX = 4, .cellsY = 3, .m = 5});
  const CurvatureField c = computeCurvature(part.ddf);
  const Vec3 expected = Vec3(1.0, 2.0, 0.0).normalized();
  for (bool smoothing : {false, true}) {
    FlowFieldParams p = rawParams(FlowFieldSource::FixedDirection);
    p.fixedDirection = {1.0, 2.0, 0.5};
    p.smoothing = smoothing;
    const LineField field = flowField(part.ddf, c, p);
    for (const Vec3& l : field) ASSERT_GT(std::abs(l.dot(expected)), 1.0 - 1e-12);
    EXPECT_TRUE(findSingularities(part.ddf, field).empty());
  }
}

TEST(FlowField, TorusIndicesSumToZero) {
  const ddf::GeneratedSurface part = torus(5);
  const CurvatureField c = computeCurvature(part.ddf);
  for (bool smoothing : {false, true}) {
    FlowFieldParams p = rawParams();
    p.smoothing = smoothing;
    const auto s = findSingularities(part.ddf, flowField(part.ddf, c, p));
    EXPECT_EQ(indexSum(s), 0.0);
    EXPECT_TRUE(s.empty());  // the curvature lines of a torus have no singularity
  }
}

TEST(FlowField, EllipsoidHasFourHalfIndexUmbilics) {
  const ddf::GeneratedSurface part = ddf::ellipsoidPart({.subdivisions = 2, .m = 5});
  const CurvatureField c = computeCurvature(part.ddf);
  const LineField raw = flowField(part.ddf, c, rawParams());
  const LineField smooth = flowField(part.ddf, c);
  EXPECT_EQ(indexSum(findSingularities(part.ddf, raw)), 2.0);
  const auto s = findSingularities(part.ddf, smooth);
  EXPECT_EQ(indexSum(s), 2.0);
  const double x = 2.3717082451, z = 0.6123724357;
  for (const Vec3& umbilic : {Vec3(x, 0, z), Vec3(x, 0, -z), Vec3(-x, 0, z), Vec3(-x, 0, -z)}) {
    double near = 0.0;
    for (const FieldSingularity& f : s)
      if ((f.point - umbilic).norm() < 0.5) near += f.index;
    EXPECT_EQ(near, 0.5) << umbilic.transpose();
  }
  // Away from the umbilics the smoothed field keeps to the principal direction.
  double worst = 0.0;
  for (std::size_t a = 0; a < smooth.size(); ++a) {
    const int f = static_cast<int>(a / part.ddf.pointsPerFace());
    const ddf::RasterCoord rc =
        part.ddf.topology().coord({f, static_cast<std::uint32_t>(a % part.ddf.pointsPerFace())});
    const Vec3 q = part.ddf.surfacePoint(f, rc.i, rc.k);
    bool far = true;
    for (double sx : {-x, x})
      for (double sz : {-z, z}) far &= (q - Vec3(sx, 0, sz)).norm() > 1.0;
    if (far)
      worst = std::max(worst, std::acos(std::min(1.0, std::abs(smooth[a].dot(c.dirMax[a])))));
  }
  EXPECT_LT(worst * kDeg, 10.0);
}

// z = sin x sin y: peaks and pits are umbilics of index +1, the planar points (+-pi/2, 0) and
// (0, +-pi/2) umbilics of index -1/2 (the oracles note); the net index near each must match.
// A +1 umbilic of a line field is unstable: the discrete field splits it into two +1/2.
TEST(FlowField, SinSinUmbilicIndices) {
  ddf::SinSinParams sp;
  sp.grid.cellsX = sp.grid.cellsY = 12;
  sp.grid.m = 5;
  const ddf::GeneratedSurface part = ddf::sinSinPatch(sp);
  const CurvatureField c = computeCurvature(part.ddf);
  const double h = std::numbers::pi / 2.0;
  const std::array<std::array<double, 3>, 8> umbilics{{{h, h, 1.0},
                                                       {-h, -h, 1.0},
                                                       {h, -h, 1.0},
                                                       {-h, h, 1.0},
                                                       {h, 0.0, -0.5},
                                                       {-h, 0.0, -0.5},
                                                       {0.0, h, -0.5},
                                                       {0.0, -h, -0.5}}};
  for (bool smoothing : {false, true}) {
    FlowFieldParams p = rawParams();
    p.smoothing = smoothing;
    const auto s = findSingularities(part.ddf, flowField(part.ddf, c, p));
    for (const auto& [x, y, index] : umbilics) {
      double near = 0.0;
      for (const FieldSingularity& f : s)
        if (std::hypot(f.point.x() - x, f.point.y() - y) < 0.75) near += f.index;
      EXPECT_EQ(near, index) << "umbilic (" << x << ", " << y << "), smoothing " << smoothing;
    }
  }
}

TEST(FlowField, SmoothingCalmsAnUmbilicSphere) {
  const ddf::GeneratedSurface part = ddf::spherePart({.subdivisions = 1, .m = 5});
  const CurvatureField c = computeCurvature(part.ddf);
  const LineField raw = flowField(part.ddf, c, rawParams());
  const LineField smooth = flowField(part.ddf, c);
  EXPECT_LT(roughness(part.ddf, smooth), 0.3 * roughness(part.ddf, raw));
  EXPECT_EQ(indexSum(findSingularities(part.ddf, smooth)), 2.0);
}

TEST(FlowField, RejectsBadInputAndCancels) {
  const ddf::GeneratedSurface part = torus(5);
  const CurvatureField c = computeCurvature(part.ddf);
  FlowFieldParams p;
  p.iterations = 0;
  EXPECT_THROW(flowField(part.ddf, c, p), InvalidInput);
  p = {};
  p.source = FlowFieldSource::FixedDirection;
  p.fixedDirection = Vec3::Zero();
  EXPECT_THROW(flowField(part.ddf, c, p), InvalidInput);
  EXPECT_THROW(flowField(part.ddf, CurvatureField{}), InvalidInput);
  EXPECT_THROW(findSingularities(part.ddf, LineField(3)), InvalidInput);
  p = {};
  p.progress = [](double f) { return f < 0.5; };
  EXPECT_THROW(flowField(part.ddf, c, p), Cancelled);
}

}  // namespace
}  // namespace ddfcam::planning
