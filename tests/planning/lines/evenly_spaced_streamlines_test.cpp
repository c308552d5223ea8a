// SPDX-License-Identifier: MIT
// Tests of Jobard-Lefer evenly spaced streamlines: separation, coverage, masks, sign, spacing.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;

const ddf::GeneratedSurface& plane() {
  static const ddf::GeneratedSurface part = ddf::planePatch({.m = 9});  // 40 x 30 mm, z = 0.25
  return part;
}

const ddf::GeneratedSurface& cylinder() {
  static const ddf::GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = 10.0, .lengthMm = 20.0, .segments = 48, .rings = 8, .m = 7});
  return part;
}

// A line field from a direction function of the raster point, laid out like allHeights().
template <typename Fn>
LineField fieldOf(const ddf::DisplacementField& ddf, Fn&& dir) {
  LineField out;
  const int n = ddf.raster().steps();
  out.reserve(ddf.allHeights().size());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) out.push_back(dir(ddf.surfacePoint(f, i, k)));
  return out;
}

// Arcs around a centre left of the patch: curved, nowhere singular on the patch.
Vec3 arcDirection(const Vec3& p) {
  return Vec3(-(p.y() - 15.0), p.x() + 25.0, 0.0).normalized();
}

double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((q - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - q).norm();
}

// Axis-aligned bounds of a line, to skip lines that cannot hold a nearer point (exact pruning).
struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  double distance(const Vec3& q) const { return (lo - q).cwiseMax(q - hi).cwiseMax(0.0).norm(); }
};

std::vector<Box> boxes(const std::vector<Streamline>& lines) {
  std::vector<Box> out(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (const auto& p : lines[l].points)
      out[l].lo = out[l].lo.cwiseMin(p.point), out[l].hi = out[l].hi.cwiseMax(p.point);
  return out;
}

// Brute force: smallest distance between points of different lines.
double minSeparation(const std::vector<Streamline>& lines) {
  const std::vector<Box> box = boxes(lines);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (const auto& p : lines[a].points)
      for (std::size_t b = a + 1; b < lines.size(); ++b) {
        if (box[b].distance(p.point) >= best) continue;
        for (const auto& q : lines[b].points) best = std::min(best, (p.point - q.point).norm());
      }
  return best;
}

// Brute force: largest distance from a raster point of an allowed face to the nearest line.
double maxCoverageGap(const ddf::DisplacementField& ddf, const std::vector<Streamline>& lines,
                      const std::vector<std::uint8_t>& mask = {}) {
  const std::vector<Box> box = boxes(lines);
  double worst = 0.0;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    if (!mask.empty() && !mask[f]) continue;
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const Vec3 q = ddf.surfacePoint(f, i, k);
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t l = 0; l < lines.size(); ++l) {
          if (box[l].distance(q) >= best) continue;
          const auto& pts = lines[l].points;
          for (std::size_t s = 0; s + 1 < pts.size(); ++s)
            best = std::min(best, segmentDistance(q, pts[s].point, pts[s + 1].point));
        }
        worst = std::max(worst, best);
      }
  }
  return worst;
}

void expectSeparatedAndCovering(const ddf::DisplacementField& ddf,
                                const std::vector<Streamline>& lines, const EvenSpacingParams& p,
                                const char* name) {
  const double step = 0.1 * p.separationMm;
  const double sep = minSeparation(lines);
  const double gap = maxCoverageGap(ddf, lines, p.faceMask);
  std::printf(
      "[ even ] %s: %zu lines, min separation %.4f (d_test %.3f), max gap %.4f (d_sep %.3f)\n",
      name, lines.size(), sep, p.testRatio * p.separationMm, gap, p.separationMm);
  EXPECT_GE(sep, p.testRatio * p.separationMm - step) << name;
  EXPECT_LE(gap, p.separationMm + step) << name;
}

TEST(EvenlySpacedStreamlines, StraightFieldOnPlaneGivesParallelLinesAtDsep) {
  const auto& ddf = plane().ddf;
  const LineField field = fieldOf(ddf, [](const Vec3&) { return Vec3::UnitX(); });
  EvenSpacingParams p;
  p.separationMm = 2.0;
  const auto lines = evenlySpacedStreamlines(ddf, field, p);
  expectSeparatedAndCovering(ddf, lines, p, "plane straight");
  // Straight lines y = const across the whole patch, one per d_sep of the 30 mm height.
  EXPECT_GE(lines.size(), 15u);
  EXPECT_LE(lines.size(), 17u);
  for (const auto& line : lines) {
    EXPECT_NEAR(line.lengthMm, 40.0, 0.5);
    for (const auto& pt : line.points) EXPECT_NEAR(pt.point.y(), line.points[0].point.y(), 1e-6);
  }
}

TEST(EvenlySpacedStreamlines, CurvedFieldOnPlaneIsSeparatedAndCovering) {
  const auto& ddf = plane().ddf;
  EvenSpacingParams p;
  p.separationMm = 2.0;
  p.minLengthRatio = 1.0;  // no tiny lines; the coverage bound still holds on this patch
  const auto lines = evenlySpacedStreamlines(ddf, fieldOf(ddf, arcDirection), p);
  expectSeparatedAndCovering(ddf, lines, p, "plane arcs");
  for (const auto& line : lines) EXPECT_GE(line.lengthMm, p.separationMm);
}

TEST(EvenlySpacedStreamlines, CylinderCirclesAreClosedLoopsAtDsep) {
  const auto& ddf = cylinder().ddf;
  const LineField field = fieldOf(ddf, [](const Vec3& q) { return Vec3(-q.y(), q.x(), 0.0); });
  EvenSpacingParams p;
  p.separationMm = 2.5;
  const auto lines = evenlySpacedStreamlines(ddf, field, p);
  expectSeparatedAndCovering(ddf, lines, p, "cylinder circles");
  int loops = 0;
  for (const auto& line : lines) loops += line.stop == Streamline::ClosedLoop;
  // 20 mm of axis at 2.5 mm: 8 or 9 circles, each a closed loop of length 2 pi r (chords).
  EXPECT_GE(loops, 8);
  EXPECT_EQ(loops, static_cast<int>(lines.size()));
}

TEST(EvenlySpacedStreamlines, TorusMeridiansAreSeparatedAndCovering) {
  // Meridians fan out from the inner equator (radius 2) to the outer one (radius 4): lines
  // seeded in between must stop at d_test where the fan closes again.
  static const ddf::GeneratedSurface part = ddf::torusPart(
      {.majorRadiusMm = 3.0, .minorRadiusMm = 1.0, .segmentsU = 48, .segmentsV = 24, .m = 5});
  const auto& ddf = part.ddf;
  const LineField field = fieldOf(ddf, [](const Vec3& q) {
    const double u = std::atan2(q.y(), q.x()),
                 v = std::atan2(q.z(), std::hypot(q.x(), q.y()) - 3.0);
    return Vec3(-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v));
  });
  EvenSpacingParams p;
  p.separationMm = 0.6;
  const auto lines = evenlySpacedStreamlines(ddf, field, p);
  expectSeparatedAndCovering(ddf, lines, p, "torus meridians");
  int loops = 0;
  for (const auto& line : lines) loops += line.stop == Streamline::ClosedLoop;
  // Full meridians at least every d_sep around the inner equator (circumference 4 pi).
  EXPECT_GE(loops, static_cast<int>(4.0 * std::numbers::pi / p.separationMm) - 1);
}

TEST(EvenlySpacedStreamlines, LinesStayInsideTheFaceMask) {
  const auto& ddf = plane().ddf;
  std::vector<std::uint8_t> mask(ddf.faceCount(), 0);
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 c = ddf.basePoint(f, Vec3::Constant(1.0 / 3.0));
    mask[f] = (c.x() < 24.0 && c.y() > 6.0) ? 1 : 0;  // a rectangle of whole cells
  }
  EvenSpacingParams p;
  p.separationMm = 1.5;
  p.faceMask = mask;
  const auto lines = evenlySpacedStreamlines(ddf, fieldOf(ddf, arcDirection), p);
  ASSERT_FALSE(lines.empty());
  for (const auto& line : lines)
    for (const auto& pt : line.points) {
      ASSERT_TRUE(mask[pt.face]);
      EXPECT_LE(pt.point.x(), 24.0 + 1e-9);
      EXPECT_GE(pt.point.y(), 6.0 - 1e-9);
    }
  expectSeparatedAndCovering(ddf, lines, p, "plane masked");
}

TEST(EvenlySpacedStreamlines, NegatingFieldEntriesGivesTheSameLines) {
  const auto& ddf = plane().ddf;
  const LineField field = fieldOf(ddf, arcDirection);
  LineField flipped = field;
  std::mt19937 rng(11);
  for (auto& d : flipped)
    if (rng() % 2) d = -d;
  EvenSpacingParams p;
  p.separationMm = 3.0;
  const auto a = evenlySpacedStreamlines(ddf, field, p);
  const auto b = evenlySpacedStreamlines(ddf, flipped, p);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t l = 0; l < a.size(); ++l) {
    ASSERT_EQ(a[l].points.size(), b[l].points.size()) << l;
    for (std::size_t i = 0; i < a[l].points.size(); ++i)
      EXPECT_LT((a[l].points[i].point - b[l].points[i].point).norm(), 1e-9) << l << " " << i;
  }
}

TEST(EvenlySpacedStreamlines, HalvedSpacingDoublesTheDensity) {
  const auto& ddf = plane().ddf;
  // Lines along y, spaced in x: 1 mm left of x = 20, 2 mm right of it.
  const LineField field = fieldOf(ddf, [](const Vec3&) { return Vec3::UnitY(); });
  EvenSpacingParams p;
  p.separationMm = 1.0;
  p.separationAt = [](const SurfaceLocation& loc) { return loc.point.x() < 20.0 ? 1.0 : 2.0; };
  const auto lines = evenlySpacedStreamlines(ddf, field, p);
  int left = 0, right = 0;
  for (const auto& line : lines) {
    const double x = line.points[line.seedIndex].point.x();
    EXPECT_GE(line.lengthMm, 29.0);  // every line crosses the patch
    (x < 20.0 ? left : right)++;
  }
  std::printf("[ even ] variable spacing: %d lines in x < 20 (d_sep 1), %d in x > 20 (d_sep 2)\n",
              left, right);
  EXPECT_GE(left, 19);
  EXPECT_LE(left, 21);
  EXPECT_GE(right, 9);
  EXPECT_LE(right, 11);
  EXPECT_GE(minSeparation(lines), 0.5 - 0.1);
}

TEST(EvenlySpacedStreamlines, RejectsBadInput) {
  const auto& ddf = plane().ddf;
  const LineField field = fieldOf(ddf, [](const Vec3&) { return Vec3::UnitX(); });
  EvenSpacingParams p;
  p.separationMm = 0.0;
  EXPECT_THROW(evenlySpacedStreamlines(ddf, field, p), InvalidInput);
  p.separationMm = 1.0;
  p.testRatio = 1.5;
  EXPECT_THROW(evenlySpacedStreamlines(ddf, field, p), InvalidInput);
  p.testRatio = 0.5;
  p.faceMask.assign(3, 1);
  EXPECT_THROW(evenlySpacedStreamlines(ddf, field, p), InvalidInput);
  p.faceMask.clear();
  EXPECT_THROW(evenlySpacedStreamlines(ddf, LineField(5), p), InvalidInput);
  p.separationAt = [](const SurfaceLocation&) { return -1.0; };
  EXPECT_THROW(evenlySpacedStreamlines(ddf, field, p), InvalidInput);
}

TEST(EvenlySpacedStreamlines, ProgressCanCancel) {
  const auto& ddf = plane().ddf;
  const LineField field = fieldOf(ddf, [](const Vec3&) { return Vec3::UnitX(); });
  EvenSpacingParams p;
  p.separationMm = 2.0;
  int calls = 0;
  p.progress = [&](double) { return ++calls < 3; };
  EXPECT_THROW(evenlySpacedStreamlines(ddf, field, p), Cancelled);
}

}  // namespace
}  // namespace ddfcam::planning
