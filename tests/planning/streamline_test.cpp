// SPDX-License-Identifier: MIT
// Tests of RK4 streamlines on DDFs against torus curvature lines and cylinder rulings/circles.
#include "curvature_accuracy.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/curvature.h>
#include <ddfcam/planning/streamline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace ddfcam::planning {
namespace {

using ddf::GeneratedSurface;
using ddf::SurfaceLocation;
using ddf::Vec3;

constexpr double kMajor = 3.0, kMinor = 1.0;

// Mean support edge length / (m - 1), mm.
double rasterSpacing(const ddf::DisplacementField& ddf) {
  const auto& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return sum / mesh.n_edges() / ddf.raster().steps();
}

const GeneratedSurface& torus() {
  static const GeneratedSurface part = ddf::torusPart(
      {.majorRadiusMm = kMajor, .minorRadiusMm = kMinor, .segmentsU = 48, .segmentsV = 24, .m = 9});
  return part;
}

double angleU(const Vec3& p) {
  return std::atan2(p.y(), p.x());
}
double angleV(const Vec3& p) {
  return std::atan2(p.z(), std::hypot(p.x(), p.y()) - kMajor);
}

// The exact principal directions of the torus at every stored raster point: meridians (k_max
// = 1/r) and parallels (k_min = cos v / (R + r cos v) < 1/r).
struct TorusFields {
  LineField meridian, parallel;
};

const TorusFields& exactTorusFields() {
  static const TorusFields fields = [] {
    const ddf::DisplacementField& ddf = torus().ddf;
    TorusFields out;
    const int n = ddf.raster().steps();
    for (int f = 0; f < ddf.faceCount(); ++f)
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= n - k; ++i) {
          const Vec3 q = ddf.surfacePoint(f, i, k);
          const double u = angleU(q), v = angleV(q);
          out.meridian.push_back(
              {-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v)});
          out.parallel.push_back({-std::sin(u), std::cos(u), 0.0});
        }
    return out;
  }();
  return fields;
}

const CurvatureField& estimatedTorusCurvature() {
  static const CurvatureField c = computeCurvature(torus().ddf);
  return c;
}

LineField masked(const std::vector<Vec3>& dirs, const std::vector<std::uint8_t>& umbilic) {
  LineField out = dirs;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (umbilic[i]) out[i] = Vec3::Zero();
  return out;
}

// A seed inside the face whose centroid is nearest to the torus angles (u, v), off the grid.
SurfaceLocation torusSeed(double u, double v) {
  const ddf::DisplacementField& ddf = torus().ddf;
  const Vec3 bary(0.31, 0.33, 0.36);
  const Vec3 target = ddf::TorusSurface(kMajor, kMinor).point(u, v);
  int best = 0;
  for (int f = 1; f < ddf.faceCount(); ++f) {
    if ((ddf.basePoint(f, bary) - target).norm() < (ddf.basePoint(best, bary) - target).norm())
      best = f;
  }
  return {best, bary, 0.0, Vec3::Zero()};
}

// Largest distance of the line's points from the parallel (or meridian) through its seed, mm.
double parallelDrift(const Streamline& line) {
  const Vec3 s = line.points[line.seedIndex].point;
  const double rho0 = std::hypot(s.x(), s.y());
  double worst = 0.0;
  for (const auto& p : line.points)
    worst = std::max(worst,
                     std::hypot(std::hypot(p.point.x(), p.point.y()) - rho0, p.point.z() - s.z()));
  return worst;
}

double meridianDrift(const Streamline& line) {
  const double u0 = angleU(line.points[line.seedIndex].point);
  double worst = 0.0;
  for (const auto& p : line.points) {
    const double du = std::remainder(angleU(p.point) - u0, 2.0 * std::numbers::pi);
    worst = std::max(worst, std::abs(du) * std::hypot(p.point.x(), p.point.y()));
  }
  return worst;
}

void expectOnSurface(const ddf::DisplacementField& ddf, const Streamline& line) {
  for (const auto& p : line.points) {
    ASSERT_GE(p.bary.minCoeff(), 0.0);
    ASSERT_NEAR(p.bary.sum(), 1.0, 1e-12);
    EXPECT_LT((ddf.pointAt(p.face, p.bary, p.h) - p.point).norm(), 1e-12);
    EXPECT_NEAR(p.h, ddf::interpolateOnFace(ddf, ddf.allHeights(), p.face, p.bary), 1e-6);
  }
}

double maxGap(const Streamline& line) {
  double gap = 0.0;
  for (std::size_t i = 1; i < line.points.size(); ++i)
    gap = std::max(gap, (line.points[i].point - line.points[i - 1].point).norm());
  return gap;
}

struct TorusCase {
  const char* name;
  bool parallel;
  bool estimated;
};

class TorusLines : public ::testing::TestWithParam<TorusCase> {};

TEST_P(TorusLines, CloseAfterOneLoopWithinHalfASpacing) {
  const TorusCase& c = GetParam();
  const ddf::DisplacementField& ddf = torus().ddf;
  const double h = rasterSpacing(ddf);
  const CurvatureField& est = estimatedTorusCurvature();
  const LineField field =
      c.estimated ? masked(c.parallel ? est.dirMin : est.dirMax, est.umbilic)
                  : (c.parallel ? exactTorusFields().parallel : exactTorusFields().meridian);
  for (const double v : {0.4, std::numbers::pi / 2 + 0.1, 2.6}) {
    const Streamline line = traceStreamline(ddf, field, torusSeed(0.7, v));
    const Vec3 s = line.points[line.seedIndex].point;
    const double expected = c.parallel ? 2.0 * std::numbers::pi * std::hypot(s.x(), s.y())
                                       : 2.0 * std::numbers::pi * kMinor;
    const double drift = c.parallel ? parallelDrift(line) : meridianDrift(line);
    std::printf("[ streamline ] %s v=%.2f: drift %.3g mm = %.3g spacings, length %.4f of %.4f\n",
                c.name, v, drift, drift / h, line.lengthMm, expected);
    EXPECT_EQ(line.stop, Streamline::ClosedLoop) << c.name << " v=" << v;
    EXPECT_LE(drift, 0.5 * h) << c.name << " v=" << v;
    EXPECT_NEAR(line.lengthMm, expected, 0.01 * expected) << c.name << " v=" << v;
    EXPECT_LT(maxGap(line), 1.5 * h);
    expectOnSurface(ddf, line);
  }
}

INSTANTIATE_TEST_SUITE_P(Streamline, TorusLines,
                         ::testing::Values(TorusCase{"exact_parallel", true, false},
                                           TorusCase{"exact_meridian", false, false},
                                           TorusCase{"estimated_parallel", true, true},
                                           TorusCase{"estimated_meridian", false, true}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Streamline, NegatingFieldEntriesGivesTheSameLine) {
  const ddf::DisplacementField& ddf = torus().ddf;
  const LineField& field = exactTorusFields().parallel;
  LineField flipped = field;
  std::mt19937 rng(7);
  for (auto& d : flipped)
    if (rng() % 2) d = -d;
  const SurfaceLocation seed = torusSeed(1.9, 2.2);
  // A meridian on the far side stops the parallel from both sides: both halves are traced.
  StreamlineParams params;
  params.existingPaths.emplace_back();
  const ddf::TorusSurface surface(kMajor, kMinor);
  for (int i = 0; i <= 720; ++i)
    params.existingPaths.back().push_back(surface.point(1.9 + 3.0, i * std::numbers::pi / 360));
  params.nearPathDistanceMm = 0.3;
  const Streamline a = traceStreamline(ddf, field, seed, params);
  const Streamline b = traceStreamline(ddf, flipped, seed, params);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.seedIndex, b.seedIndex);
  EXPECT_GT(a.seedIndex, 0u);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    EXPECT_LT((a.points[i].point - b.points[i].point).norm(), 1e-12) << i;
  EXPECT_EQ(a.stop, Streamline::NearExistingPath);
  EXPECT_EQ(a.backwardStop, Streamline::NearExistingPath);
  EXPECT_EQ(b.stop, Streamline::NearExistingPath);
}

// Ellipsoid (3, 2, 1): a line of maximum curvature stays on its confocal hyperboloid
// x^2/(a^2 - l) + y^2/(b^2 - l) + z^2/(c^2 - l) = 1 with l in (b^2, a^2) (oracles note).
TEST(Streamline, EllipsoidMaxLineStaysOnItsConfocalQuadric) {
  const GeneratedSurface part =
      ddf::ellipsoidPart({.axesMm = {3.0, 2.0, 1.0}, .subdivisions = 3, .m = 9});
  const ddf::DisplacementField& ddf = part.ddf;
  LineField dirMax;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i)
        dirMax.push_back(
            test::curvatureTruth(*part.surface, ddf.surfacePoint(f, i, k), 1.0).dirMax);
  const Vec3 sq(9.0, 4.0, 1.0);
  auto quadric = [&](const Vec3& p, double l) {
    return (p.array().square() / (sq.array() - l)).sum() - 1.0;
  };
  const Vec3 bary(0.31, 0.33, 0.36);
  const Vec3 target(3.0 * std::sin(1.2) * std::cos(1.0), 2.0 * std::sin(1.2) * std::sin(1.0),
                    std::cos(1.2));
  int best = 0;
  for (int f = 1; f < ddf.faceCount(); ++f)
    if ((ddf.basePoint(f, bary) - target).norm() < (ddf.basePoint(best, bary) - target).norm())
      best = f;
  const Streamline line = traceStreamline(ddf, dirMax, {best, bary});
  // l of the seed by bisection in (b^2, a^2), where the quadric value rises from -inf to +inf.
  const Vec3 s = line.points[line.seedIndex].point;
  double lo = 4.0 + 1e-12, hi = 9.0 - 1e-12;
  for (int it = 0; it < 200; ++it) (quadric(s, 0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double l = 0.5 * (lo + hi);
  double drift = 0.0;
  for (const auto& p : line.points) {
    const Vec3 grad = (2.0 * p.point.array() / (sq.array() - l)).matrix();
    drift = std::max(drift, std::abs(quadric(p.point, l)) / grad.norm());
  }
  const double h = rasterSpacing(ddf);
  std::printf(
      "[ streamline ] ellipsoid max line l=%.4f: drift %.3g mm = %.3g spacings, length %.3f\n", l,
      drift, drift / h, line.lengthMm);
  EXPECT_EQ(line.stop, Streamline::ClosedLoop);
  EXPECT_LE(drift, 0.5 * h);
  expectOnSurface(ddf, line);
}

const GeneratedSurface& cylinder() {
  static const GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 30.0, .segments = 48, .rings = 12, .m = 5});
  return part;
}

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
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(ddf.faceCount()), 0);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const double z = ddf.pointAt(f, Vec3::Constant(1.0 / 3.0), 0.0).z();
    mask[static_cast<std::size_t>(f)] = (z > 5.0 && z < 20.0) ? 1 : 0;
  }
  StreamlineParams params;
  params.faceMask = mask;
  int seedFace = 0;
  while (!mask[static_cast<std::size_t>(seedFace)]) ++seedFace;
  const Streamline line =
      traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()), {seedFace, Vec3(0.2, 0.3, 0.5)}, params);
  EXPECT_EQ(line.stop, Streamline::RegionBoundary);
  EXPECT_EQ(line.backwardStop, Streamline::RegionBoundary);
  for (const auto& p : line.points) EXPECT_TRUE(mask[static_cast<std::size_t>(p.face)]);
  EXPECT_NEAR(line.points.front().point.z(), 5.0, 1e-9);
  EXPECT_NEAR(line.points.back().point.z(), 20.0, 1e-9);
  // A seed outside the region gives a one-point line.
  int outside = 0;
  while (mask[static_cast<std::size_t>(outside)]) ++outside;
  const Streamline none =
      traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()), {outside, Vec3(0.2, 0.3, 0.5)}, params);
  EXPECT_EQ(none.points.size(), 1u);
  EXPECT_EQ(none.stop, Streamline::RegionBoundary);
  params.faceMask.pop_back();
  EXPECT_THROW(traceStreamline(ddf, constantField(ddf, Vec3::UnitZ()), {seedFace, Vec3(0.2, 0.3, 0.5)},
                               params),
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

}  // namespace
}  // namespace ddfcam::planning
