// SPDX-License-Identifier: MIT
// Tests of the multilevel flow field solve, region masks and stroke-defined fields (sec. 8.1).
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

// The multilevel solver on a part small enough for the direct one: force coarse levels.
FlowFieldParams multilevelParams() {
  FlowFieldParams p;
  p.directSolveLimit = 200;
  return p;
}

double maxAngleDeg(const LineField& a, const LineField& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::acos(std::min(1.0, std::abs(a[i].dot(b[i])))));
  return worst * kDeg;
}

// Largest angle (deg) between two fields at the points farther than awayMm from every point
// of avoid (the umbilics, where a tiny shift of the singularity turns the lines a lot).
double maxAngleAwayDeg(const ddf::DisplacementField& ddf, const LineField& a, const LineField& b,
                       const std::vector<Vec3>& avoid, double awayMm) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int f = static_cast<int>(i / ddf.pointsPerFace());
    const ddf::RasterCoord rc =
        ddf.topology().coord({f, static_cast<std::uint32_t>(i % ddf.pointsPerFace())});
    const Vec3 q = ddf.surfacePoint(f, rc.i, rc.k);
    if (std::any_of(avoid.begin(), avoid.end(),
                    [&](const Vec3& u) { return (q - u).norm() < awayMm; }))
      continue;
    worst = std::max(worst, std::acos(std::min(1.0, std::abs(a[i].dot(b[i])))));
  }
  return worst * kDeg;
}

TEST(FlowField, MultilevelMatchesTheDirectSolve) {
  FlowFieldParams direct;
  direct.solver = FlowFieldSolver::Direct;
  const ddf::GeneratedSurface ring = torus(5);
  const CurvatureField c = computeCurvature(ring.ddf);
  EXPECT_LT(maxAngleDeg(flowField(ring.ddf, c, multilevelParams()), flowField(ring.ddf, c, direct)),
            0.5);
  const ddf::GeneratedSurface ellipsoid = ddf::ellipsoidPart({.subdivisions = 2, .m = 5});
  const CurvatureField e = computeCurvature(ellipsoid.ddf);
  const double x = 2.3717082451, z = 0.6123724357;
  const std::vector<Vec3> umbilics{Vec3(x, 0, z), Vec3(x, 0, -z), Vec3(-x, 0, z), Vec3(-x, 0, -z)};
  const LineField fast = flowField(ellipsoid.ddf, e, multilevelParams());
  const LineField reference = flowField(ellipsoid.ddf, e, direct);
  EXPECT_LT(maxAngleAwayDeg(ellipsoid.ddf, fast, reference, umbilics, 1.0), 2.0);
}

TEST(FlowField, MultilevelKeepsTheEulerCharacteristic) {
  const ddf::GeneratedSurface ellipsoid = ddf::ellipsoidPart({.subdivisions = 2, .m = 5});
  EXPECT_EQ(indexSum(findSingularities(
                ellipsoid.ddf,
                flowField(ellipsoid.ddf, computeCurvature(ellipsoid.ddf), multilevelParams()))),
            2.0);
  const ddf::GeneratedSurface ring = torus(5);
  EXPECT_EQ(indexSum(findSingularities(
                ring.ddf, flowField(ring.ddf, computeCurvature(ring.ddf), multilevelParams()))),
            0.0);
  ddf::SinSinParams sp;
  sp.grid.cellsX = sp.grid.cellsY = 12;
  sp.grid.m = 5;
  const ddf::GeneratedSurface sinSin = ddf::sinSinPatch(sp);
  const auto s = findSingularities(
      sinSin.ddf, flowField(sinSin.ddf, computeCurvature(sinSin.ddf), multilevelParams()));
  const double h = std::numbers::pi / 2.0;
  double nearPeak = 0.0, nearPlanar = 0.0;
  for (const FieldSingularity& f : s) {
    if (std::hypot(f.point.x() - h, f.point.y() - h) < 0.75) nearPeak += f.index;
    if (std::hypot(f.point.x() - h, f.point.y()) < 0.75) nearPlanar += f.index;
  }
  EXPECT_EQ(nearPeak, 1.0);
  EXPECT_EQ(nearPlanar, -0.5);
}

// Half the torus (faces with x > 0): the rest stays undefined, the half follows the whole.
TEST(FlowField, RegionMaskSolvesOnlyTheRegion) {
  const ddf::GeneratedSurface part = torus(5);
  const ddf::DisplacementField& ddf = part.ddf;
  const CurvatureField c = computeCurvature(ddf);
  FlowFieldParams p;
  p.faceMask.resize(ddf.faceCount());
  for (int f = 0; f < ddf.faceCount(); ++f)
    p.faceMask[f] = ddf.basePoint(f, Vec3::Constant(1.0 / 3.0)).x() > 0.0 ? 1 : 0;
  const LineField whole = flowField(ddf, c);
  const LineField half = flowField(ddf, c, p);
  const ddf::RasterTopology& topo = ddf.topology();
  int inside = 0;
  for (ddf::PointId q = 0; q < topo.pointCount(); ++q) {
    bool inRegion = false;
    topo.forEachCopy(q, [&](ddf::PointCopy pc) { inRegion |= p.faceMask[pc.face] != 0; });
    topo.forEachCopy(q, [&](ddf::PointCopy pc) {
      const std::size_t a = pc.face * ddf.pointsPerFace() + pc.local;
      if (!inRegion) {
        EXPECT_TRUE(half[a].isZero());
        return;
      }
      EXPECT_NEAR(half[a].norm(), 1.0, 1e-9);
      // Away from the region's edge (x near 0) the free boundary no longer matters.
      if (ddf.surfacePoint(pc.face, topo.coord(pc).i, topo.coord(pc).k).x() < 1.5) return;
      EXPECT_GT(std::abs(half[a].dot(whole[a])), std::cos(1.0 / kDeg));
      ++inside;
    });
  }
  EXPECT_GT(inside, 0);
  EXPECT_THROW(flowField(ddf, c,
                         [&] {
                           FlowFieldParams bad = p;
                           bad.faceMask.pop_back();
                           return bad;
                         }()),
               InvalidInput);
}

FlowFieldParams strokeParams(std::vector<std::vector<Vec3>> strokes) {
  FlowFieldParams p;
  p.source = FlowFieldSource::UserStrokes;
  p.strokes = std::move(strokes);
  return p;
}

// Two parallel straight strokes on the plane z = 0.25: the harmonic fill is their direction.
TEST(FlowField, ParallelStrokesOnAPlaneGiveAParallelField) {
  const ddf::GeneratedSurface part = ddf::planePatch({.cellsX = 8, .cellsY = 6, .m = 5});
  const CurvatureField c = computeCurvature(part.ddf);
  const Vec3 dir = Vec3(2.0, 1.0, 0.0).normalized();
  const FlowFieldParams p = strokeParams({{Vec3(5, 5, 0.25), Vec3(5, 5, 0.25) + 20.0 * dir},
                                          {Vec3(15, 2, 0.25), Vec3(15, 2, 0.25) + 20.0 * dir}});
  for (bool smoothing : {true, false}) {
    FlowFieldParams q = p;
    q.smoothing = smoothing;
    const LineField field = flowField(part.ddf, c, q);
    for (const Vec3& l : field) ASSERT_GT(std::abs(l.dot(dir)), std::cos(0.5 / kDeg));
  }
}

// A helix on the developable cylinder is a geodesic of constant slope: the field filled in
// from one turn of it is the helix direction everywhere.
TEST(FlowField, HelixStrokeOnACylinderSetsItsSlope) {
  const double r = 10.0, length = 30.0, pitch = 20.0;  // mm per turn
  const ddf::GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = r, .lengthMm = length, .segments = 24, .rings = 6, .m = 5});
  std::vector<Vec3> helix;
  for (int i = 0; i <= 200; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 200.0;
    helix.emplace_back(r * std::cos(t), r * std::sin(t),
                       5.0 + pitch * t / (2.0 * std::numbers::pi));
  }
  const LineField field = flowField(part.ddf, computeCurvature(part.ddf), strokeParams({helix}));
  const double slope = pitch / (2.0 * std::numbers::pi * r);  // dz per arc length
  double worst = 0.0;
  const int n = part.ddf.raster().steps();
  for (int f = 0; f < part.ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const Vec3 x = part.ddf.surfacePoint(f, i, k);
        const Vec3 expected =
            (Vec3(-x.y(), x.x(), 0.0).normalized() + slope * Vec3::UnitZ()).normalized();
        const Vec3& l = field[f * part.ddf.pointsPerFace() + part.ddf.raster().index(i, k)];
        worst = std::max(worst, std::acos(std::min(1.0, std::abs(l.dot(expected)))));
      }
  EXPECT_LT(worst * kDeg, 3.0);
}

TEST(FlowField, StrokeOrderDoesNotMatter) {
  const ddf::GeneratedSurface part = torus(5);
  const CurvatureField c = computeCurvature(part.ddf);
  std::vector<Vec3> a, b;
  for (int i = 0; i <= 30; ++i) {
    const double t = 0.1 * i;
    a.emplace_back(4.0 * std::cos(t), 4.0 * std::sin(t), 0.1 * t);
    b.emplace_back(3.0 * std::cos(t + 3.0), 3.0 * std::sin(t + 3.0), 1.0);
  }
  for (bool smoothing : {true, false}) {
    FlowFieldParams p = strokeParams({a, b});
    p.smoothing = smoothing;
    FlowFieldParams reversed = strokeParams({{b.rbegin(), b.rend()}, {a.rbegin(), a.rend()}});
    reversed.smoothing = smoothing;
    const LineField x = flowField(part.ddf, c, p), y = flowField(part.ddf, c, reversed);
    for (std::size_t i = 0; i < x.size(); ++i) ASSERT_GT(std::abs(x[i].dot(y[i])), 1.0 - 1e-9);
  }
}

TEST(FlowField, RejectsMissingStrokes) {
  const ddf::GeneratedSurface part = ddf::planePatch({.cellsX = 2, .cellsY = 2, .m = 5});
  const CurvatureField c = computeCurvature(part.ddf);
  EXPECT_THROW(flowField(part.ddf, c, strokeParams({})), InvalidInput);
  EXPECT_THROW(flowField(part.ddf, c, strokeParams({{Vec3(1, 1, 0)}, {}})), InvalidInput);
  EXPECT_THROW(flowField(part.ddf, c, strokeParams({{Vec3(1, 1, 0), Vec3(std::nan(""), 0, 0)}})),
               InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
