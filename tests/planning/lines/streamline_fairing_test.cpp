// SPDX-License-Identifier: MIT
// Tests of the Ceres streamline fairing against noisy geodesics of an analytic cylinder and torus.
#include "streamline_test_support.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_fairing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::GeneratedSurface;
using ddf::SurfaceLocation;
using ddf::Vec3;
using streamline_test::fieldOf;
using streamline_test::locateNear;
using streamline_test::torus;
using streamline_test::torusParallel;

constexpr double kCylRadius = 10.0;
constexpr double kTorusMajor = streamline_test::kMajor, kTorusMinor = streamline_test::kMinor;
constexpr double kNoise = 0.02;      // zig-zag amplitude, mm
constexpr double kDeviation = 0.05;  // fairing bound, mm
constexpr double kPi = std::numbers::pi;

const GeneratedSurface& cylinder() {
  static const GeneratedSurface part = ddf::cylinderPart({.radiusMm = kCylRadius});
  return part;
}

// Largest distance to the analytic surface of the DDF surface on the faces a line uses, sampled
// 8x finer than the raster: the representation error of the part where the line runs.
double representationError(const GeneratedSurface& part, const Streamline& line) {
  const ddf::DisplacementField& ddf = part.ddf;
  std::vector<int> faces;
  for (const auto& p : line.points) faces.push_back(p.face);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  const int s = 8 * ddf.raster().steps();
  double worst = 0.0;
  for (int f : faces)
    for (int k = 0; k <= s; ++k)
      for (int i = 0; i <= s - k; ++i) {
        const Vec3 mu(double(i) / s, double(s - i - k) / s, double(k) / s);
        const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), f, mu);
        worst = std::max(worst, std::abs(part.surface->value(ddf.pointAt(f, mu, h))));
      }
  return worst;
}

double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - q).norm();
}

// Largest distance of a faired point to the raw polyline, over all raw segments.
double maxDeviation(const Streamline& raw, const Streamline& faired) {
  double worst = 0.0;
  for (const auto& q : faired.points) {
    double best = INFINITY;
    for (std::size_t j = 0; j + 1 < raw.points.size(); ++j)
      best = std::min(best, segmentDistance(q.point, raw.points[j].point, raw.points[j + 1].point));
    worst = std::max(worst, best);
  }
  return worst;
}

// Sum of squared in-surface (geodesic) components of the second differences, with the normal
// of the analytic surface: the bending a fairing can remove.
double geodesicBending(const Streamline& line, const ddf::AnalyticSurface& surface, bool closed) {
  const auto& p = line.points;
  const std::size_t n = closed ? p.size() - 1 : p.size();
  double sum = 0.0;
  for (std::size_t i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i) {
    const Vec3& a = p[(i + n - 1) % n].point;
    const Vec3& b = p[i].point;
    const Vec3& c = p[(i + 1) % n].point;
    const Vec3 binormal = surface.normal(b).cross((c - a).normalized());
    sum += std::pow((a - 2.0 * b + c).dot(binormal), 2);
  }
  return sum;
}

void expectOnDdf(const ddf::DisplacementField& ddf, const Streamline& line) {
  for (const auto& p : line.points) {
    ASSERT_GE(p.bary.minCoeff(), 0.0);
    ASSERT_NEAR(p.bary.sum(), 1.0, 1e-12);
    const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), p.face, p.bary);
    ASSERT_NEAR(p.h, h, 1e-6);
    ASSERT_LT((ddf.pointAt(p.face, p.bary, h) - p.point).norm(), 1e-9);
  }
}

double maxSurfaceDistance(const Streamline& line, const ddf::AnalyticSurface& surface) {
  double worst = 0.0;
  for (const auto& p : line.points) worst = std::max(worst, std::abs(surface.value(p.point)));
  return worst;
}

// Helix of pitch angle 30 deg on the cylinder, unrolled (r theta, z) = s (cos a, sin a), with a
// zig-zag of +-kNoise across it in the unrolled plane (so within the surface) except at the ends.
constexpr double kHelixAngle = kPi / 6.0;
constexpr double kHelixLength = 40.0;
constexpr double kHelixZ0 = 5.0;
// Start angle, so that the helix's angles stay inside (-pi, pi).
constexpr double kHelixTheta0 = -1.7;

Vec3 helixPoint(double s, double lateral) {
  const double ca = std::cos(kHelixAngle), sa = std::sin(kHelixAngle);
  const double arc = s * ca - lateral * sa, z = kHelixZ0 + s * sa + lateral * ca;
  const double theta = kHelixTheta0 + arc / kCylRadius;
  return {kCylRadius * std::cos(theta), kCylRadius * std::sin(theta), z};
}

// Signed lateral offset of @p p from the helix in the unrolled plane, mm.
double helixOffset(const Vec3& p) {
  const double arc = kCylRadius * (std::atan2(p.y(), p.x()) - kHelixTheta0), z = p.z() - kHelixZ0;
  return -arc * std::sin(kHelixAngle) + z * std::cos(kHelixAngle);
}

Streamline noisyHelix(int points) {
  Streamline line;
  for (int i = 0; i < points; ++i) {
    const double s = kHelixLength * i / (points - 1);
    // The fixed ends lie on the helix, so the fairest line between them is the helix.
    const double lateral = i == 0 || i == points - 1 ? 0.0 : (i % 2 ? kNoise : -kNoise);
    line.points.push_back(locateNear(cylinder().ddf, helixPoint(s, lateral)));
  }
  line.stop = line.backwardStop = Streamline::Boundary;
  return line;
}

// The outer equator of the torus (a geodesic and a line of curvature) as a closed loop with a
// zig-zag of +-kNoise along z (across the line, within the surface).
Streamline noisyEquator(int points) {
  const ddf::TorusSurface exact(kTorusMajor, kTorusMinor);
  Streamline line;
  for (int i = 0; i < points; ++i) {
    const double v = (i % 2 ? kNoise : -kNoise) / kTorusMinor;
    line.points.push_back(locateNear(torus().ddf, exact.point(2.0 * kPi * i / points, v)));
  }
  line.points.push_back(line.points.front());
  line.stop = line.backwardStop = Streamline::ClosedLoop;
  return line;
}

double rms(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v * v;
  return std::sqrt(sum / values.size());
}

TEST(StreamlineFairing, NoisyHelixOnCylinderBecomesTheHelix) {
  const Streamline raw = noisyHelix(1000);
  const Streamline faired = fairStreamline(cylinder().ddf, raw, {.deviationMm = kDeviation});
  ASSERT_EQ(faired.points.size(), raw.points.size());
  expectOnDdf(cylinder().ddf, faired);

  const double ratio = geodesicBending(raw, *cylinder().surface, false) /
                       geodesicBending(faired, *cylinder().surface, false);
  const double deviation = maxDeviation(raw, faired);
  const double surfaceError = maxSurfaceDistance(faired, *cylinder().surface);
  const double representation = representationError(cylinder(), faired);
  std::vector<double> rawOffset, fairedOffset;
  for (std::size_t i = 50; i + 50 < raw.points.size(); ++i) {
    rawOffset.push_back(helixOffset(raw.points[i].point));
    fairedOffset.push_back(helixOffset(faired.points[i].point));
  }
  const double worstMiddle = std::max(-*std::min_element(fairedOffset.begin(), fairedOffset.end()),
                                      *std::max_element(fairedOffset.begin(), fairedOffset.end()));
  std::printf(
      "helix: bending ratio %.3g, max deviation %.4f mm, max surface distance %.2e mm "
      "(DDF error %.2e), RMS offset raw %.4f faired %.5f, max middle %.5f mm\n",
      ratio, deviation, surfaceError, representation, rms(rawOffset), rms(fairedOffset),
      worstMiddle);
  EXPECT_GT(ratio, 100.0);
  EXPECT_LE(deviation, kDeviation + 1e-9);
  EXPECT_LE(surfaceError, 1.05 * representation + 1e-9);
  EXPECT_LT(rms(fairedOffset), 0.1 * rms(rawOffset));
  EXPECT_LT(worstMiddle, 0.25 * kNoise);
  EXPECT_LT((faired.points.front().point - raw.points.front().point).norm(), 1e-12);
  EXPECT_LT((faired.points.back().point - raw.points.back().point).norm(), 1e-12);
  EXPECT_NEAR(faired.lengthMm, kHelixLength, 0.01);
}

TEST(StreamlineFairing, NoisyTorusEquatorStaysClosedAndBecomesTheEquator) {
  const Streamline raw = noisyEquator(800);
  const ddf::TorusSurface exact(kTorusMajor, kTorusMinor);
  const Streamline faired = fairStreamline(torus().ddf, raw, {.deviationMm = kDeviation});
  ASSERT_EQ(faired.points.size(), raw.points.size());
  expectOnDdf(torus().ddf, faired);
  EXPECT_EQ(faired.points.front().point, faired.points.back().point);

  const double ratio = geodesicBending(raw, exact, true) / geodesicBending(faired, exact, true);
  const double deviation = maxDeviation(raw, faired);
  const double surfaceError = maxSurfaceDistance(faired, exact);
  const double representation = representationError(torus(), faired);
  std::vector<double> rawZ, fairedZ;
  for (std::size_t i = 0; i + 1 < raw.points.size(); ++i) {
    rawZ.push_back(raw.points[i].point.z());
    fairedZ.push_back(faired.points[i].point.z());
  }
  std::printf(
      "torus equator: bending ratio %.3g, max deviation %.4f mm, max surface distance "
      "%.2e mm (DDF error %.2e), RMS z raw %.4f faired %.5f mm\n",
      ratio, deviation, surfaceError, representation, rms(rawZ), rms(fairedZ));
  EXPECT_GT(ratio, 100.0);
  EXPECT_LE(deviation, kDeviation + 1e-9);
  EXPECT_LE(surfaceError, 1.05 * representation + 1e-9);
  EXPECT_LT(rms(fairedZ), 0.1 * rms(rawZ));
}

// The exact parallel directions (-sin u, cos u, 0) of the torus at every stored raster point.
LineField exactParallelField() {
  return fieldOf(torus().ddf, torusParallel);
}

// Largest distance of the line's points from the torus parallel at tube angle v, mm.
double parallelDistance(const Streamline& line, double v) {
  const double rho = kTorusMajor + kTorusMinor * std::cos(v), z = kTorusMinor * std::sin(v);
  double worst = 0.0;
  for (const auto& p : line.points)
    worst =
        std::max(worst, std::hypot(std::hypot(p.point.x(), p.point.y()) - rho, p.point.z() - z));
  return worst;
}

// A traced line (uneven spacing: extra points where it crosses support edges) of a parallel
// that is not a geodesic: fairing keeps it closed, on the surface and near the parallel.
TEST(StreamlineFairing, TracedTorusParallelStaysClosedAndNearTheParallel) {
  const ddf::DisplacementField& ddf = torus().ddf;
  const double v = 0.7;
  const Vec3 target = ddf::TorusSurface(kTorusMajor, kTorusMinor).point(0.3, v);
  const Streamline raw = traceStreamline(ddf, exactParallelField(), locateNear(ddf, target));
  ASSERT_EQ(raw.stop, Streamline::ClosedLoop);
  const double vSeed = std::atan2(
      raw.points.front().point.z(),
      std::hypot(raw.points.front().point.x(), raw.points.front().point.y()) - kTorusMajor);
  const Streamline faired = fairStreamline(ddf, raw);
  expectOnDdf(ddf, faired);
  EXPECT_EQ(faired.points.front().point, faired.points.back().point);
  double rawMin = INFINITY, rawMax = 0.0, fairMin = INFINITY, fairMax = 0.0;
  for (std::size_t i = 1; i < raw.points.size(); ++i) {
    const double a = (raw.points[i].point - raw.points[i - 1].point).norm();
    const double b = (faired.points[i].point - faired.points[i - 1].point).norm();
    rawMin = std::min(rawMin, a), rawMax = std::max(rawMax, a);
    fairMin = std::min(fairMin, b), fairMax = std::max(fairMax, b);
  }
  std::printf(
      "traced parallel: %zu points, distance to parallel raw %.5f faired %.5f mm, "
      "max deviation %.5f mm, spacing raw [%.4f, %.4f] faired [%.4f, %.4f] mm\n",
      raw.points.size(), parallelDistance(raw, vSeed), parallelDistance(faired, vSeed),
      maxDeviation(raw, faired), rawMin, rawMax, fairMin, fairMax);
  EXPECT_LE(maxDeviation(raw, faired), kDeviation + 1e-9);
  EXPECT_LT(parallelDistance(faired, vSeed), parallelDistance(raw, vSeed) + 0.1 * kDeviation);
  EXPECT_GT(fairMin, rawMin);
}

TEST(StreamlineFairing, ReversingThePointOrderGivesTheSameLine) {
  const Streamline raw = noisyHelix(400);
  Streamline reversed = raw;
  std::reverse(reversed.points.begin(), reversed.points.end());
  const Streamline a = fairStreamline(cylinder().ddf, raw);
  Streamline b = fairStreamline(cylinder().ddf, reversed);
  std::reverse(b.points.begin(), b.points.end());
  ASSERT_EQ(a.points.size(), b.points.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    worst = std::max(worst, (a.points[i].point - b.points[i].point).norm());
  EXPECT_LT(worst, 1e-5);
}

TEST(StreamlineFairing, TightBoundIsHeldExactly) {
  const Streamline raw = noisyHelix(300);
  const double bound = 0.3 * kNoise;
  const Streamline faired = fairStreamline(cylinder().ddf, raw, {.deviationMm = bound});
  expectOnDdf(cylinder().ddf, faired);
  EXPECT_LE(maxDeviation(raw, faired), bound + 1e-9);
  EXPECT_LT(geodesicBending(faired, *cylinder().surface, false),
            geodesicBending(raw, *cylinder().surface, false));
}

TEST(StreamlineFairing, ShortLinesComeBackUnchanged) {
  Streamline raw = noisyHelix(300);
  raw.points.resize(2);
  const Streamline faired = fairStreamline(cylinder().ddf, raw);
  ASSERT_EQ(faired.points.size(), 2u);
  EXPECT_LT((faired.points[1].point - raw.points[1].point).norm(), 1e-12);
}

TEST(StreamlineFairing, RejectsBadInputAndCancels) {
  const Streamline raw = noisyHelix(100);
  EXPECT_THROW(fairStreamline(cylinder().ddf, raw, {.deviationMm = 0.0}), InvalidInput);
  EXPECT_THROW(fairStreamline(cylinder().ddf, raw, {.iterations = 0}), InvalidInput);
  Streamline bad = raw;
  bad.points[7].face = cylinder().ddf.faceCount();
  EXPECT_THROW(fairStreamline(cylinder().ddf, bad), InvalidInput);
  FairingParams cancel;
  cancel.progress = [](double) { return false; };
  EXPECT_THROW(fairStreamline(cylinder().ddf, raw, cancel), Cancelled);
}

}  // namespace
}  // namespace ddfcam::planning
