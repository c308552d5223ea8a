// SPDX-License-Identifier: MIT
#include "cut_kernel.h"

#include <algorithm>
#include <cmath>

namespace ddfcam::ddf::detail {
namespace {

// Linear form of sum mu_i c_i over the raster: mu = (i, n - i - k, k) / n.
LinearForm formOf(double c1, double c2, double c3, int n) {
  return {c2, (c3 - c2) / n, (c1 - c2) / n};
}

// Real roots of c2 x^2 + c1 x + c0 inside (lo, hi), appended to roots.
void quadraticRoots(double c2, double c1, double c0, double lo, double hi, double* roots,
                    int& count) {
  auto push = [&](double x) {
    if (x > lo && x < hi) roots[count++] = x;
  };
  const double scale = std::max({std::abs(c2), std::abs(c1), std::abs(c0)});
  if (scale == 0.0) return;
  if (std::abs(c2) <= 1e-14 * scale) {
    if (c1 != 0.0) push(-c0 / c1);
    return;
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc < 0.0) return;
  // Numerically stable pair of roots.
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  push(q / c2);
  if (q != 0.0) push(c0 / q);
}

struct RowPoly {
  double n0, n1, d0, d1;
  std::array<double, 3> a0, a1, b0, b1;
};

RowPoly rowPoly(const PairForms& f, int k) {
  RowPoly r{};
  r.n0 = f.n.base + k * f.n.dk, r.n1 = f.n.di;
  r.d0 = f.d.base + k * f.d.dk, r.d1 = f.d.di;
  for (int j = 0; j < 3; ++j) {
    r.a0[j] = f.a[j].base + k * f.a[j].dk, r.a1[j] = f.a[j].di;
    r.b0[j] = f.b[j].base + k * f.b[j].dk, r.b1[j] = f.b[j].di;
  }
  return r;
}

// Whether the stubble at continuous row position x can be hit (exact predicate, no tolerance).
bool hitPossible(const RowPoly& r, double x, KernelMode mode, double tol) {
  const double n = r.n0 + x * r.n1, d = r.d0 + x * r.d1;
  if (mode == KernelMode::Cut) {
    if (!(d < 0.0) || n < d) return false;  // entry only, and h <= 1
  } else {
    if (d == 0.0 || std::abs(n) > std::abs(d)) return false;
  }
  for (int j = 0; j < 3; ++j) {
    const double q = (r.a0[j] + x * r.a1[j]) * d + n * (r.b0[j] + x * r.b1[j]) + tol * d;
    if (q * d < 0.0) return false;  // (lambda_j + tol) = q / d must be >= 0
  }
  return true;
}

}  // namespace

std::optional<PairForms> makePairForms(const FaceCorners& s, const Vec3& q1, const Vec3& q2,
                                       const Vec3& q3, int n, KernelMode mode) {
  const Vec3 normal = (q2 - q1).cross(q3 - q1);
  const double nn = normal.squaredNorm();
  const double size2 =
      std::max({(q2 - q1).squaredNorm(), (q3 - q2).squaredNorm(), (q1 - q3).squaredNorm()});
  if (!(nn > 1e-24 * size2 * size2) || !(size2 > 0.0)) return std::nullopt;
  std::array<double, 3> b{};
  for (int i = 0; i < 3; ++i) b[i] = s.v[i].dot(normal);
  if (mode == KernelMode::Cut && b[0] >= 0.0 && b[1] >= 0.0 && b[2] >= 0.0) return std::nullopt;
  PairForms f;
  std::array<double, 3> a{};
  for (int i = 0; i < 3; ++i) a[i] = -(s.p[i] - q1).dot(normal);
  f.n = formOf(a[0], a[1], a[2], n);
  f.d = formOf(b[0], b[1], b[2], n);
  // lambda_j(x) = G_j . (x - r_j), the barycentric coordinates on the tool triangle's plane.
  const std::array<Vec3, 3> g = {normal.cross(q3 - q2) / nn, normal.cross(q1 - q3) / nn,
                                 normal.cross(q2 - q1) / nn};
  const std::array<const Vec3*, 3> ref = {&q2, &q3, &q1};
  for (int j = 0; j < 3; ++j) {
    std::array<double, 3> c{}, dd{};
    for (int i = 0; i < 3; ++i) {
      c[i] = g[j].dot(s.p[i] - *ref[j]);
      dd[i] = g[j].dot(s.v[i]);
    }
    f.a[j] = formOf(c[0], c[1], c[2], n);
    f.b[j] = formOf(dd[0], dd[1], dd[2], n);
  }
  return f;
}

RowForms rowForms(const PairForms& f, int k) {
  RowForms r{};
  r.nb = static_cast<float>(f.n.base + k * f.n.dk), r.ns = static_cast<float>(f.n.di);
  r.db = static_cast<float>(f.d.base + k * f.d.dk), r.ds = static_cast<float>(f.d.di);
  for (int j = 0; j < 3; ++j) {
    r.ab[j] = static_cast<float>(f.a[j].base + k * f.a[j].dk);
    r.as[j] = static_cast<float>(f.a[j].di);
    r.bb[j] = static_cast<float>(f.b[j].base + k * f.b[j].dk);
    r.bs[j] = static_cast<float>(f.b[j].di);
  }
  return r;
}

namespace {

// Row positions in (lo, hi) where a condition of the hit predicate can change sign: roots of
// d, of n - d (h = 1), of n + d (h = -1, fill only) and of (lambda_j + tol) d, sorted.
int criticalPoints(const RowPoly& r, KernelMode mode, double tol, double lo, double hi,
                   double* cuts) {
  int count = 0;
  quadraticRoots(0.0, r.d1, r.d0, lo, hi, cuts, count);
  quadraticRoots(0.0, r.n1 - r.d1, r.n0 - r.d0, lo, hi, cuts, count);
  if (mode == KernelMode::Fill) quadraticRoots(0.0, r.n1 + r.d1, r.n0 + r.d0, lo, hi, cuts, count);
  for (int j = 0; j < 3; ++j) {
    const double c2 = r.a1[j] * r.d1 + r.n1 * r.b1[j];
    // (lambda_j + tol) d: the same tolerance band as the kernel, so both agree on edges.
    const double c1 =
        r.a0[j] * r.d1 + r.a1[j] * r.d0 + r.n0 * r.b1[j] + r.n1 * r.b0[j] + tol * r.d1;
    const double c0 = r.a0[j] * r.d0 + r.n0 * r.b0[j] + tol * r.d0;
    quadraticRoots(c2, c1, c0, lo, hi, cuts, count);
  }
  std::sort(cuts, cuts + count);
  return count;
}

// Clamps the one-point safety margins to the row and merges ranges they made overlap.
int clampAndMerge(int written, int rowLength, std::array<std::pair<int, int>, 5>& out) {
  int merged = 0;
  for (int w = 0; w < written; ++w) {
    auto range = out[w];
    range.first = std::max(range.first, 0);
    range.second = std::min(range.second, rowLength - 1);
    if (merged > 0 && range.first <= out[merged - 1].second + 1) {
      out[merged - 1].second = std::max(out[merged - 1].second, range.second);
    } else {
      out[merged++] = range;
    }
  }
  return merged;
}

}  // namespace

int rowIntervals(const PairForms& forms, int k, int rowLength, KernelMode mode, double tol,
                 std::array<std::pair<int, int>, 5>& out) {
  const RowPoly r = rowPoly(forms, k);
  const double lo = 0.0, hi = rowLength - 1;
  double cuts[16];  // at most 9 roots; 16 keeps std::sort's small-array path in bounds
  const int count = criticalPoints(r, mode, tol, lo, hi, cuts);
  // The predicate is constant between critical points: test each piece at its middle.
  int written = 0;
  double start = lo, openAt = 0.0;
  bool open = false;
  for (int c = 0; c <= count; ++c) {
    const double end = c < count ? cuts[c] : hi;
    const bool pass = hitPossible(r, 0.5 * (start + end), mode, tol);
    if (pass && !open) open = true, openAt = start;
    if (!pass && open) {
      open = false;
      out[written++] = {static_cast<int>(std::floor(openAt)) - 1,
                        static_cast<int>(std::ceil(start)) + 1};
    }
    start = end;
  }
  if (open) out[written++] = {static_cast<int>(std::floor(openAt)) - 1, rowLength};
  return clampAndMerge(written, rowLength, out);
}

namespace {

// The cut kernel; counting hits (for growing row ranges) is optional because it costs a vector
// compare and add per step on the long rows that do not need it.
template <bool kCountHits>
[[gnu::always_inline]] inline void cutRowImpl(float* heights, int first, int last,
                                              const RowForms& r, float tol, KernelCounts& counts) {
  unsigned lowered = 0, clamped = 0, hits = 0;  // 32-bit lanes keep the loop vectorisable
  for (int i = first; i <= last; ++i) {
    const float x = static_cast<float>(i);
    const float n = r.nb + x * r.ns, d = r.db + x * r.ds;
    const float h = n / d;
    const float l1 = r.ab[0] + x * r.as[0] + h * (r.bb[0] + x * r.bs[0]);
    const float l2 = r.ab[1] + x * r.as[1] + h * (r.bb[1] + x * r.bs[1]);
    const float l3 = r.ab[2] + x * r.as[2] + h * (r.bb[2] + x * r.bs[2]);
    const bool hit = (d < 0.0f) & (l1 >= -tol) & (l2 >= -tol) & (l3 >= -tol);
    const float hc = h < -1.0f ? -1.0f : h;
    const float old = heights[i];
    const bool lower = hit & (hc < old);
    heights[i] = lower ? hc : old;
    lowered += lower;
    clamped += lower & (h < -1.0f);
    if constexpr (kCountHits) hits += hit & (h <= 1.0f);
  }
  counts.lowered += lowered;
  counts.clamped += clamped;
  counts.hits += hits;
}

// The build stays portable (x86-64 baseline); on x86 these hot loops are also compiled for
// AVX2/FMA and picked at load time when the CPU has them (GCC function multiversioning).
#if defined(__x86_64__) && !defined(DDFCAM_NATIVE_BUILD)
#define DDFCAM_KERNEL_CLONES [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define DDFCAM_KERNEL_CLONES
#endif

DDFCAM_KERNEL_CLONES void cutRowCounting(float* heights, int first, int last, const RowForms& r,
                                         float tol, KernelCounts& counts) {
  cutRowImpl<true>(heights, first, last, r, tol, counts);
}

DDFCAM_KERNEL_CLONES void cutRowPlain(float* heights, int first, int last, const RowForms& r,
                                      float tol, KernelCounts& counts) {
  cutRowImpl<false>(heights, first, last, r, tol, counts);
}

}  // namespace

void cutRow(float* heights, int first, int last, const RowForms& r, float tol, KernelCounts& counts,
            bool countHits) {
  if (countHits) {
    cutRowCounting(heights, first, last, r, tol, counts);
  } else {
    cutRowPlain(heights, first, last, r, tol, counts);
  }
}

// The lambda arithmetic repeats cutRowImpl's on purpose: sharing it through a helper that
// returns a small struct stopped GCC 12 from vectorising both loops (0.4 -> 2.3 ns per point).
void fillRow(float* heights, int first, int last, const RowForms& r, float tol,
             KernelCounts& counts) {
  unsigned hits = 0;
  for (int i = first; i <= last; ++i) {
    const float x = static_cast<float>(i);
    const float n = r.nb + x * r.ns, d = r.db + x * r.ds;
    const float h = n / d;
    const float l1 = r.ab[0] + x * r.as[0] + h * (r.bb[0] + x * r.bs[0]);
    const float l2 = r.ab[1] + x * r.as[1] + h * (r.bb[1] + x * r.bs[1]);
    const float l3 = r.ab[2] + x * r.as[2] + h * (r.bb[2] + x * r.bs[2]);
    const float old = heights[i];
    // NaN marks "no hit yet"; !(|old| <= |h|) is true for NaN and for a nearer hit.
    const bool hit =
        (d != 0.0f) & (l1 >= -tol) & (l2 >= -tol) & (l3 >= -tol) & (std::abs(h) <= 1.0f);
    const bool take = hit & !(std::abs(old) <= std::abs(h));
    heights[i] = take ? h : old;
    hits += hit;
  }
  counts.hits += hits;
}

}  // namespace ddfcam::ddf::detail
