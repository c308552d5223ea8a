// SPDX-License-Identifier: MIT
#include "pair_scan.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

namespace ddfcam::ddf::detail {
namespace {

// V-projection of x onto face s by Newton's method on (mu1, mu2, h), started from the
// projection along the mean vector. Cheaper than the cubic of sec. 4.1 and sufficient near the
// crust, where the projection is unique; nullopt when it does not converge.
std::optional<Vec3> projectNewton(const FaceCorners& s, const Vec3& x, double tolerance,
                                  double& h) {
  const Vec3 mean = (s.v[0] + s.v[1] + s.v[2]) / 3.0;
  Vec3 mu(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
  h = 0.0;
  const double scale = (s.p[1] - s.p[0]).norm() + (s.p[2] - s.p[0]).norm() + mean.norm();
  for (int it = 0; it < 8; ++it) {
    const Vec3 base = mu[0] * s.p[0] + mu[1] * s.p[1] + mu[2] * s.p[2];
    const Vec3 v = mu[0] * s.v[0] + mu[1] * s.v[1] + mu[2] * s.v[2];
    const Vec3 residual = base + h * v - x;
    if (residual.norm() <= tolerance * scale) return mu;
    Eigen::Matrix3d jac;
    jac.col(0) = (s.p[0] + h * s.v[0]) - (s.p[2] + h * s.v[2]);
    jac.col(1) = (s.p[1] + h * s.v[1]) - (s.p[2] + h * s.v[2]);
    jac.col(2) = it == 0 ? mean : v;
    if (!(std::abs(jac.determinant()) > 1e-300)) return std::nullopt;
    const Vec3 step = jac.inverse() * residual;
    mu[0] -= step[0], mu[1] -= step[1], h -= step[2];
    mu[2] = 1.0 - mu[0] - mu[1];
  }
  return std::nullopt;
}

// The projected tool triangle in raster coordinates (i, k) = (mu1, mu3) n.
struct Seed {
  enum class Kind {
    Polygon,  ///< corners project near the face: straight edges bound the rows well
    Far,      ///< a corner projects far beyond the face: rows exact, in the corners' k range
    Outside,  ///< all corners beyond one support edge: nothing to do
    Unknown   ///< a corner does not project uniquely: every row exact
  } kind = Kind::Unknown;
  std::array<Eigen::Vector2d, 3> corner;
  double kMin = 0.0, kMax = 0.0;
};

// Corners of q V-projected onto s. Unknown when a corner lies far outside the crust (|h| > 2),
// where the projection need not be unique; Outside when all corners lie beyond one support edge.
Seed seedOf(const FaceCorners& s, const std::array<Vec3, 3>& q, int n) {
  Seed seed;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int c = 0; c < 3; ++c) {
    double h = 0.0;
    const auto mu = projectNewton(s, q[c], 0.02 / n, h);
    if (!mu || std::abs(h) > 2.0) return seed;
    lo = lo.cwiseMin(*mu), hi = hi.cwiseMax(*mu);
    seed.corner[c] = {(*mu)[0] * n, (*mu)[2] * n};
  }
  const double margin = 2.0 / n + 1e-3;
  for (int j = 0; j < 3; ++j)
    if (hi[j] < -margin || lo[j] > 1.0 + margin) return {Seed::Kind::Outside, {}, 0, 0};
  // Projected edges are curves; over a long run their straight chords drift by more than the
  // widening of polygonRow, so the straight-edge shortcut is kept for corners near the face.
  const bool near = lo.minCoeff() >= -0.5 && hi.maxCoeff() <= 1.5;
  seed.kind = near ? Seed::Kind::Polygon : Seed::Kind::Far;
  seed.kMin = lo[2] * n, seed.kMax = hi[2] * n;
  return seed;
}

// Scalar version of the kernel's hit test (same float arithmetic), restricted to h <= 1.
bool hitAt(const RowForms& r, int i, float tol, KernelMode mode) {
  const float x = static_cast<float>(i);
  const float nn = r.nb + x * r.ns, d = r.db + x * r.ds;
  const float h = nn / d;
  for (int j = 0; j < 3; ++j)
    if (!(r.ab[j] + x * r.as[j] + h * (r.bb[j] + x * r.bs[j]) >= -tol)) return false;
  return mode == KernelMode::Cut ? (d < 0.0f && h <= 1.0f) : (d != 0.0f && std::abs(h) <= 1.0f);
}

void runKernel(float* rowHeights, int first, int last, const RowForms& row, KernelMode mode,
               float tol, KernelCounts& counts, bool countHits = true) {
  if (mode == KernelMode::Cut) {
    cutRow(rowHeights, first, last, row, tol, counts, countHits);
  } else {
    fillRow(rowHeights, first, last, row, tol, counts);
  }
}

// Exact row: intervals from the roots of sec. 5.2. Returns false when the row has none.
bool exactRow(float* heights, const Raster& raster, const PairForms& forms, int k, KernelMode mode,
              const DepthBufferParams& params, KernelCounts& counts) {
  const int length = raster.rowLength(k);
  std::array<std::pair<int, int>, 5> ranges;
  int count = 1;
  if (params.restrictIntervals) {
    count = rowIntervals(forms, k, length, mode, params.lambdaTolerance, ranges);
  } else {
    ranges[0] = {0, length - 1};
  }
  const RowForms row = rowForms(forms, k);
  for (int r = 0; r < count; ++r)
    runKernel(heights + raster.rowOffset(k), ranges[r].first, ranges[r].second, row, mode,
              params.lambdaTolerance, counts, /*countHits=*/false);
  return count > 0;
}

// Rows on either side of a row whose part of the projected triangle bounds the row's span. The
// projected edges are curves and the corners are projected to a tolerance, so an edge almost
// parallel to the rows may be hit a fraction of a row beyond its straight chord, and then
// anywhere along it: a row just outside the corners' k range, or just beyond such an edge,
// must be scanned along all of it (a support edge row of a thin part's reduced support).
constexpr double kRowSlack = 1.0;

/// Span in i of the projected triangle within rows [lo, hi]: its corners there and the
/// crossings of its edges with both bounds (empty, xMin > xMax, when it misses the strip).
std::pair<double, double> stripSpan(const Seed& seed, double lo, double hi) {
  double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
  const auto take = [&](double x) { xMin = std::min(xMin, x), xMax = std::max(xMax, x); };
  for (int e = 0; e < 3; ++e) {
    const auto& a = seed.corner[e];
    const auto& b = seed.corner[(e + 1) % 3];
    if (a.y() >= lo && a.y() <= hi) take(a.x());
    for (const double y : {lo, hi})
      if ((a.y() - y) * (b.y() - y) < 0.0)
        take(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
  }
  return {xMin, xMax};
}

// Row k from the projected triangle: its span within kRowSlack rows of k (that of the nearest
// corner for rows farther outside), widened by two points, then grown while the exact test hits.
void polygonRow(float* heights, const Raster& raster, const PairForms& forms, const Seed& seed,
                int k, KernelMode mode, float tol, KernelCounts& counts) {
  auto [xMin, xMax] = stripSpan(seed, k - kRowSlack, k + kRowSlack);
  if (!(xMax >= xMin)) {
    const double kk = std::clamp(static_cast<double>(k), seed.kMin, seed.kMax);
    std::tie(xMin, xMax) = stripSpan(seed, kk, kk);
  }
  const int length = raster.rowLength(k);
  if (!(xMax >= xMin)) return;
  const double pad = 2.0 + 0.1 * (xMax - xMin);
  int first = std::max(0, static_cast<int>(std::floor(xMin - pad)));
  int last = std::min(length - 1, static_cast<int>(std::ceil(xMax + pad)));
  if (first > last) return;
  const RowForms row = rowForms(forms, k);
  while (first > 0 && hitAt(row, first, tol, mode)) --first;
  while (last < length - 1 && hitAt(row, last, tol, mode)) ++last;
  runKernel(heights + raster.rowOffset(k), first, last, row, mode, tol, counts);
}

// Rows shorter than this are cheaper to run through the vectorised kernel whole than to bound
// by interval roots first.
constexpr int kShortRow = 96;

// One row of the seeded range: bounded by the projected triangle when its corners are near the
// face, else whole when short or bounded by the exact roots when long. Returns whether the row
// meets the triangle.
bool seededRow(float* heights, const Raster& raster, const PairForms& forms, const Seed& seed,
               int k, KernelMode mode, const DepthBufferParams& params, KernelCounts& counts) {
  const int length = raster.rowLength(k);
  const std::size_t before = counts.hits;
  if (seed.kind == Seed::Kind::Polygon) {
    polygonRow(heights, raster, forms, seed, k, mode, params.lambdaTolerance, counts);
  } else if (length <= kShortRow) {
    runKernel(heights + raster.rowOffset(k), 0, length - 1, rowForms(forms, k), mode,
              params.lambdaTolerance, counts);
  } else {
    return exactRow(heights, raster, forms, k, mode, params, counts);
  }
  return counts.hits > before;
}

// Scans one tool triangle over the rows its projected corners span, then grows the range
// while the neighbouring rows still meet it (the projected triangle is connected).
void scanPiece(float* heights, const Raster& raster, const FaceCorners& s,
               const std::array<Vec3, 3>& q, const PairForms& forms, KernelMode mode,
               const DepthBufferParams& params, KernelCounts& counts) {
  const int n = raster.steps();
  Seed seed = params.restrictIntervals ? seedOf(s, q, n) : Seed{};
  if (seed.kind == Seed::Kind::Outside) return;
  if (seed.kind == Seed::Kind::Unknown) {
    seed.kMin = 0.0, seed.kMax = n;  // every row, exact
  }
  const int first = static_cast<int>(std::clamp(std::floor(seed.kMin) - 2.0, 0.0, double(n)));
  const int last = static_cast<int>(std::clamp(std::ceil(seed.kMax) + 2.0, 0.0, double(n)));
  bool lowHit = false, highHit = false;
  for (int k = first; k <= last; ++k) {
    const bool hit = seededRow(heights, raster, forms, seed, k, mode, params, counts);
    if (k == first) lowHit = hit;
    if (k == last) highHit = hit;
  }
  for (int k = first - 1; lowHit && k >= 0; --k)
    lowHit = seededRow(heights, raster, forms, seed, k, mode, params, counts);
  for (int k = last + 1; highHit && k <= n; ++k)
    highHit = seededRow(heights, raster, forms, seed, k, mode, params, counts);
}

}  // namespace

void scanPair(float* heights, const Raster& raster, const FaceCorners& s,
              const std::array<Vec3, 3>& q, const PairForms& forms, KernelMode mode,
              const DepthBufferParams& params, KernelCounts& counts) {
  scanPiece(heights, raster, s, q, forms, mode, params, counts);
}

}  // namespace ddfcam::ddf::detail
