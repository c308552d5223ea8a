// SPDX-License-Identifier: MIT
// ddfcam: RK4 streamlines on the open cylinder: stops, seeding, smoothing and bad input.
#include "../analysis/curvature_accuracy.h"
#include "streamline_test_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/streamline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

namespace ddfcam::planning {
namespace {

using namespace streamline_test;

LineField constantField(const ddf::DisplacementField& ddf, const Vec3& d) {
  return LineField(ddf.allHeights().size(), d);
}

LineField circumferentialField(const ddf::DisplacementField& ddf) {
  LineField out;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const Vec3 q = ddf.surfacePoint(f, i, k);
        out.push_back(Vec3(-q.y(), q.x(), 0.0).normalized());
      }
  return out;
}

TEST(Streamline, StopsAtTheBoundaryOfAnOpenPatch) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const Streamline line =
      traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()), {100, Vec3(0.2, 0.3, 0.5)});
  EXPECT_EQ(line.stop, Streamline::Boundary);
  EXPECT_EQ(line.backwardStop, Streamline::Boundary);
  EXPECT_NEAR(line.points.front().point.z(), 0.0, 1e-9);
  EXPECT_NEAR(line.points.back().point.z(), 30.0, 1e-9);
  EXPECT_NEAR(line.lengthMm, 30.0, 1e-3);
  const Vec3 s = line.points[line.seedIndex].point;
  for (const auto& p : line.points)
    EXPECT_LT(std::hypot(p.point.x() - s.x(), p.point.y() - s.y()), 1e-3);
  expectOnSurface(ddf, line);
}

TEST(Streamline, StopsNearAnExistingPathAndAtMaxLength) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const LineField axial = constantField(ddf, Vec3::UnitZ());
  StreamlineParams params;
  for (int i = 0; i < 360; ++i) {
    const double a = i * std::numbers::pi / 180.0;
    params.existingPaths.push_back({Vec3(10 * std::cos(a), 10 * std::sin(a), 20.0)});
  }
  params.nearPathDistanceMm = 0.5;
  const SurfaceLocation seed{100, Vec3(0.2, 0.3, 0.5)};
  const Streamline near = traceStreamline(ddf, axial, seed, params);
  EXPECT_EQ(near.stop, Streamline::NearExistingPath);
  EXPECT_GT(near.points.back().point.z(), 19.4);
  EXPECT_LT(near.points.back().point.z(), 20.01);
  params.nearPathDistanceMm = 0.0;
  params.maxLengthMm = 5.0;
  const Streamline capped = traceStreamline(ddf, axial, seed, params);
  EXPECT_EQ(capped.stop, Streamline::MaxLength);
  EXPECT_NEAR(capped.lengthMm, 5.0, 1e-6);
}

TEST(Streamline, StopsAtARegionBoundaryAndStaysInsideIt) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  // The region: faces whose centroid lies at 5 < z < 20 mm (whole rings of 2.5 mm).
  const std::vector<std::uint8_t> mask = zBandMask(ddf, 5.0, 20.0);
  StreamlineParams params;
  params.faceMask = mask;
  const int seedFace = firstFace(mask, true);
  const Streamline line = traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()),
                                          {seedFace, Vec3(0.2, 0.3, 0.5)}, params);
  EXPECT_EQ(line.stop, Streamline::RegionBoundary);
  EXPECT_EQ(line.backwardStop, Streamline::RegionBoundary);
  for (const auto& p : line.points) EXPECT_TRUE(mask[static_cast<std::size_t>(p.face)]);
  EXPECT_NEAR(line.points.front().point.z(), 5.0, 1e-9);
  EXPECT_NEAR(line.points.back().point.z(), 20.0, 1e-9);
  // A seed outside the region gives a one-point line.
  const int outside = firstFace(mask, false);
  const Streamline none = traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()),
                                          {outside, Vec3(0.2, 0.3, 0.5)}, params);
  EXPECT_EQ(none.points.size(), 1u);
  EXPECT_EQ(none.stop, Streamline::RegionBoundary);
  params.faceMask.pop_back();
  EXPECT_THROW(traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()),
                               {seedFace, Vec3(0.2, 0.3, 0.5)}, params),
               InvalidInput);
}

TEST(Streamline, StopsAtUndefinedField) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  LineField axial = constantField(ddf, Vec3::UnitZ());
  // Undefine every entry at z > 22 mm.
  const int n = ddf.raster().steps();
  std::size_t idx = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i, ++idx)
        if (ddf.surfacePoint(f, i, k).z() > 22.0) axial[idx] = Vec3::Zero();
  const Streamline line = traceStreamline(ddf, axial, {100, Vec3(0.2, 0.3, 0.5)});
  EXPECT_EQ(line.stop, Streamline::Singularity);
  EXPECT_EQ(line.backwardStop, Streamline::Boundary);
  EXPECT_LT(line.points.back().point.z(), 22.0);
  EXPECT_GT(line.points.back().point.z(), 22.0 - 2.5 - 0.5);  // within one ring of 2.5 mm
}

TEST(Streamline, SeedsAlongATransverseLineAreSpacedW) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const double w = 2.0;
  const SurfaceLocation seed{100, Vec3(0.2, 0.3, 0.5)};
  const auto lines = seedAlongTransverse(ddf, constantField(ddf, Vec3::UnitZ()),
                                         circumferentialField(ddf), seed, w);
  // The circle of radius 10 closes: floor(2 pi 10 / w) + 1 seeds from the seed on.
  ASSERT_EQ(lines.size(), 32u);
  const double chord = 2.0 * 10.0 * std::sin(w / 20.0);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i].stop, Streamline::Boundary);
    EXPECT_EQ(lines[i].backwardStop, Streamline::Boundary);
    EXPECT_NEAR(lines[i].lengthMm, 30.0, 1e-3);
    if (i == 0) continue;
    const Vec3 a = lines[i - 1].points[lines[i - 1].seedIndex].point;
    const Vec3 b = lines[i].points[lines[i].seedIndex].point;
    EXPECT_NEAR((b - a).norm(), chord, 0.01 * w) << i;
  }
}

TEST(Streamline, MovingAverageKeepsEndsAndLines) {
  std::vector<Vec3> line, zigzag;
  for (int i = 0; i < 11; ++i) {
    line.push_back(Vec3(i, 2.0 * i, -i));
    zigzag.push_back(Vec3(i, i % 2 ? 0.3 : -0.3, 0.0));
  }
  const auto smoothLine = smoothMovingAverage(line, 3);
  for (std::size_t i = 0; i < line.size(); ++i) EXPECT_LT((smoothLine[i] - line[i]).norm(), 1e-12);
  const auto smoothZig = smoothMovingAverage(zigzag, 1);
  EXPECT_EQ(smoothZig.front(), zigzag.front());
  EXPECT_EQ(smoothZig.back(), zigzag.back());
  for (std::size_t i = 1; i + 1 < zigzag.size(); ++i)
    EXPECT_NEAR(std::abs(smoothZig[i].y()), 0.1, 1e-12);  // (-0.3 + 0.3 - 0.3) / 3
  EXPECT_EQ(smoothMovingAverage(zigzag, 0), zigzag);
  EXPECT_THROW(smoothMovingAverage(zigzag, -1), InvalidInput);
}

TEST(Streamline, RejectsBadInput) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const LineField axial = constantField(ddf, Vec3::UnitZ());
  EXPECT_THROW(traceStreamline(ddf, LineField(3), {0, Vec3(0.3, 0.3, 0.4)}), InvalidInput);
  EXPECT_THROW(traceStreamline(ddf, axial, {-1, Vec3(0.3, 0.3, 0.4)}), InvalidInput);
  EXPECT_THROW(seedAlongTransverse(ddf, axial, axial, {0, Vec3(0.3, 0.3, 0.4)}, 0.0), InvalidInput);
}

TEST(Streamline, CancelThrows) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const LineField axial = constantField(ddf, Vec3::UnitZ());
  StreamlineParams params;
  params.progress = [](double) { return false; };
  EXPECT_THROW(traceStreamline(ddf, axial, {100, Vec3(0.2, 0.3, 0.5)}, params), Cancelled);
  EXPECT_THROW(seedAlongTransverse(ddf, axial, circumferentialField(ddf),
                                   {100, Vec3(0.2, 0.3, 0.5)}, 2.0, params),
               Cancelled);
}

// Zig-zag (axial +-0.3 mm) points of a circle arc on the cylinder, located on the DDF, in the
// middle of a ring of faces (rings are 2.5 mm high) so each smoothed point has its foot on a
// face of its window (elsewhere smoothOnSurface clamps it onto the nearest window face).
Streamline zigzagArc(const ddf::DisplacementField& ddf) {
  Streamline line;
  for (int i = 0; i < 60; ++i) {
    const double t = 0.025 * i;
    line.points.push_back(
        locateNear(ddf, {10.0 * std::cos(t), 10.0 * std::sin(t), 16.25 + (i % 2 ? 0.3 : -0.3)}));
  }
  line.seedIndex = 7;
  line.stop = Streamline::Boundary;
  line.backwardStop = Streamline::RegionBoundary;
  return line;
}

TEST(Streamline, SmoothOnSurfaceIsTheRadialProjectionOfTheMovingAverage) {
  const ddf::DisplacementField& ddf = cylinder().ddf;
  const Streamline raw = zigzagArc(ddf);
  for (const int k : {0, 1, 3}) {
    const Streamline smooth = smoothOnSurface(ddf, raw, k);
    const std::vector<Vec3> average = smoothMovingAverage(raw.polyline(), k);
    ASSERT_EQ(smooth.points.size(), raw.points.size());
    double worst = 0.0, length = 0.0;
    for (std::size_t i = 0; i < average.size(); ++i) {
      // The cylinder's closest point to a point off it: radial projection.
      const Vec3& a = average[i];
      const double rho = std::hypot(a.x(), a.y());
      const Vec3 truth(10.0 * a.x() / rho, 10.0 * a.y() / rho, a.z());
      worst = std::max(worst, (smooth.points[i].point - truth).norm());
      if (i > 0) length += (smooth.points[i].point - smooth.points[i - 1].point).norm();
    }
    std::printf("[ streamline ] smoothOnSurface k=%d: %.3g mm from the radial projection\n", k,
                worst);
    EXPECT_LT(worst, 0.005) << "k=" << k;
    EXPECT_NEAR(smooth.lengthMm, length, 1e-9);
    EXPECT_EQ(smooth.seedIndex, raw.seedIndex);
    EXPECT_EQ(smooth.stop, Streamline::Boundary);
    EXPECT_EQ(smooth.backwardStop, Streamline::RegionBoundary);
    expectOnSurface(ddf, smooth);
  }
  // The overload for many lines smooths each one alone.
  const std::vector<Streamline> both = smoothOnSurface(ddf, std::vector<Streamline>{raw, raw}, 3);
  const Streamline one = smoothOnSurface(ddf, raw, 3);
  ASSERT_EQ(both.size(), 2u);
  for (const Streamline& line : both) {
    ASSERT_EQ(line.points.size(), one.points.size());
    for (std::size_t i = 0; i < one.points.size(); ++i)
      EXPECT_EQ(line.points[i].point, one.points[i].point);
  }
  EXPECT_THROW(smoothOnSurface(ddf, raw, -1), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
