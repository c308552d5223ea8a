// SPDX-License-Identifier: MIT
// ddfcam: analytic parts, fields and line checks shared by the streamline tests.
#pragma once

#include "../../support/surface_locate.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

namespace ddfcam::planning::streamline_test {

using ddf::GeneratedSurface;
using ddf::SurfaceLocation;
using ddf::Vec3;

inline constexpr double kMajor = 3.0, kMinor = 1.0;

/// Mean support edge length / (m - 1), mm.
inline double rasterSpacing(const ddf::DisplacementField& ddf) {
  const auto& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return sum / mesh.n_edges() / ddf.raster().steps();
}

/// One analytic direction per stored raster point, laid out like ddf.allHeights().
template <class Fn>
LineField fieldOf(const ddf::DisplacementField& ddf, Fn&& direction) {
  LineField out;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) out.push_back(direction(ddf.surfacePoint(f, i, k)));
  return out;
}

// ---- torus (R 3, r 1): meridians and parallels are the lines of curvature ----

inline const GeneratedSurface& torus() {
  static const GeneratedSurface part = ddf::torusPart(
      {.majorRadiusMm = kMajor, .minorRadiusMm = kMinor, .segmentsU = 48, .segmentsV = 24, .m = 9});
  return part;
}

inline double angleU(const Vec3& p) {
  return std::atan2(p.y(), p.x());
}
inline double angleV(const Vec3& p) {
  return std::atan2(p.z(), std::hypot(p.x(), p.y()) - kMajor);
}

/// The exact parallel direction (-sin u, cos u, 0) of the torus at @p q.
inline Vec3 torusParallel(const Vec3& q) {
  const double u = angleU(q);
  return {-std::sin(u), std::cos(u), 0.0};
}

/// The exact meridian direction of the torus at @p q.
inline Vec3 torusMeridian(const Vec3& q) {
  const double u = angleU(q), v = angleV(q);
  return {-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v)};
}

inline const CurvatureField& estimatedTorusCurvature() {
  static const CurvatureField c = computeCurvature(torus().ddf);
  return c;
}

inline LineField masked(const std::vector<Vec3>& dirs, const std::vector<std::uint8_t>& umbilic) {
  LineField out = dirs;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (umbilic[i]) out[i] = Vec3::Zero();
  return out;
}

/// Largest distance of the line's points from the parallel through its seed, mm.
inline double parallelDrift(const Streamline& line) {
  const Vec3 s = line.points[line.seedIndex].point;
  const double rho0 = std::hypot(s.x(), s.y());
  double worst = 0.0;
  for (const auto& p : line.points)
    worst = std::max(worst,
                     std::hypot(std::hypot(p.point.x(), p.point.y()) - rho0, p.point.z() - s.z()));
  return worst;
}

/// Largest distance of the line's points from the meridian through its seed, mm.
inline double meridianDrift(const Streamline& line) {
  const double u0 = angleU(line.points[line.seedIndex].point);
  double worst = 0.0;
  for (const auto& p : line.points) {
    const double du = std::remainder(angleU(p.point) - u0, 2.0 * std::numbers::pi);
    worst = std::max(worst, std::abs(du) * std::hypot(p.point.x(), p.point.y()));
  }
  return worst;
}

// ---- line checks ----

inline void expectOnSurface(const ddf::DisplacementField& ddf, const Streamline& line) {
  for (const auto& p : line.points) {
    ASSERT_GE(p.bary.minCoeff(), 0.0);
    ASSERT_NEAR(p.bary.sum(), 1.0, 1e-12);
    EXPECT_LT((ddf.pointAt(p.face, p.bary, p.h) - p.point).norm(), 1e-12);
    EXPECT_NEAR(p.h, ddf::interpolateOnFace(ddf, ddf.allHeights(), p.face, p.bary), 1e-6);
  }
}

inline double maxGap(const Streamline& line) {
  double gap = 0.0;
  for (std::size_t i = 1; i < line.points.size(); ++i)
    gap = std::max(gap, (line.points[i].point - line.points[i - 1].point).norm());
  return gap;
}

/// The face whose point at kSeedBary is nearest @p target, with that seed (off the raster).
inline const Vec3 kSeedBary(0.31, 0.33, 0.36);
inline SurfaceLocation seedNear(const ddf::DisplacementField& ddf, const Vec3& target) {
  int best = 0;
  for (int f = 1; f < ddf.faceCount(); ++f)
    if ((ddf.basePoint(f, kSeedBary) - target).norm() <
        (ddf.basePoint(best, kSeedBary) - target).norm())
      best = f;
  return {best, kSeedBary, 0.0, Vec3::Zero()};
}

using ::ddfcam::test::locateNear;

// ---- cylinder (r 10, length 30) ----

inline const GeneratedSurface& cylinder() {
  static const GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 30.0, .segments = 48, .rings = 12, .m = 5});
  return part;
}

/// Mask of the faces of @p ddf whose centroid lies at zLo < z < zHi, mm.
inline std::vector<std::uint8_t> zBandMask(const ddf::DisplacementField& ddf, double zLo,
                                           double zHi) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(ddf.faceCount()), 0);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const double z = ddf.pointAt(f, Vec3::Constant(1.0 / 3.0), 0.0).z();
    mask[static_cast<std::size_t>(f)] = (z > zLo && z < zHi) ? 1 : 0;
  }
  return mask;
}

/// The first face whose mask entry is (non-zero == @p inside); the mask must hold one.
inline int firstFace(const std::vector<std::uint8_t>& mask, bool inside) {
  int f = 0;
  while ((mask[static_cast<std::size_t>(f)] != 0) != inside) ++f;
  return f;
}

}  // namespace ddfcam::planning::streamline_test
