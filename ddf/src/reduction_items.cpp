// SPDX-License-Identifier: MIT
// ddfcam: item buffers of the support reduction (sec. 6.2).
#include "reduction_items.h"

#include <ddfcam/ddf/raster.h>
#include <ddfcam/ddf/v_projection.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddfcam::ddf::detail {
namespace {

// Barycentric tolerance of a hit: rays through a shared input edge or vertex hit both sides,
// so boundary raster points on the input's boundary are never lost to rounding.
constexpr double kLambdaTolerance = 1e-7;
// Hits count within |h| <= 1 - kHeightMargin: the depth buffer's fill runs in float and must
// find every hit the reduction relied on.
constexpr double kHeightMargin = 1e-5;
// Heights closer than this count as equal when choosing the nearest item.
constexpr double kTieTolerance = 1e-9;

Vec3 rasterMu(int i, int k, int n) {
  return Vec3(i, n - i - k, k) / static_cast<double>(n);
}

Vec3 vectorAt(const FaceCorners& face, const Vec3& mu) {
  return mu[0] * face.v[0] + mu[1] * face.v[1] + mu[2] * face.v[2];
}

// Takes the hit of @p item at raster point @p idx when it is nearer than the stored one; equal
// heights (a ray through an input edge) go to the item facing the ray best.
void offerHit(const FaceCorners& face, int n, int i, int k, std::size_t idx, double h, int item,
              const ReductionItems& items, FaceItems& out) {
  const double old = std::abs(out.h[idx]), ah = std::abs(h);
  bool take = out.hit[idx] < 0 || ah < old - kTieTolerance;
  if (!take && ah <= old + kTieTolerance) {
    const Vec3 v = vectorAt(face, rasterMu(i, k, n));
    take = v.dot(items.normals[item]) > v.dot(items.normals[out.hit[idx]]);
  }
  if (take) out.hit[idx] = item, out.h[idx] = h;
}

// Rows at least this long are first cut to the index ranges where a hit is possible (the
// roots of the hit conditions, as the cut kernel does); on shorter rows the root finding costs
// more than testing every point.
constexpr int kIntervalRowLength = 24;

// Raster points of a row whose hit test runs in one vectorisable pass.
constexpr int kRowChunk = 32;

// Tests the raster points first..last of row @p k of one (face, item) pair against the linear
// forms of sec. 5.2 and offers the hits. Returns whether any ray hit within |h| <= 1. The
// heights and the smallest lambda of a chunk of points are computed without branches, so the
// compiler vectorises them (the same operations per point, hence the same values); a zero
// denominator gives an infinite or NaN height, which fails the test.
bool shootRow(const FaceCorners& face, int n, const PairForms& f, int k, int first, int last,
              std::size_t rowStart, int item, const ReductionItems& items, FaceItems& out) {
  const double nk = f.n.base + k * f.n.dk, dk = f.d.base + k * f.d.dk;
  const double ni = f.n.di, di = f.d.di;
  const double a0 = f.a[0].base + k * f.a[0].dk, b0 = f.b[0].base + k * f.b[0].dk;
  const double a1 = f.a[1].base + k * f.a[1].dk, b1 = f.b[1].base + k * f.b[1].dk;
  const double a2 = f.a[2].base + k * f.a[2].dk, b2 = f.b[2].base + k * f.b[2].dk;
  const double ai0 = f.a[0].di, ai1 = f.a[1].di, ai2 = f.a[2].di;
  const double bi0 = f.b[0].di, bi1 = f.b[1].di, bi2 = f.b[2].di;
  std::array<double, kRowChunk> height, lambda;
  bool any = false;
  for (int from = first; from <= last; from += kRowChunk) {
    const int count = std::min(last - from + 1, kRowChunk);
    for (int c = 0; c < count; ++c) {
      const double i = from + c;
      const double h = (nk + i * ni) / (dk + i * di);
      const double l0 = a0 + i * ai0 + h * (b0 + i * bi0);
      const double l1 = a1 + i * ai1 + h * (b1 + i * bi1);
      const double l2 = a2 + i * ai2 + h * (b2 + i * bi2);
      height[c] = h, lambda[c] = std::min(l0, std::min(l1, l2));
    }
    // A NaN lambda needs a non-finite height, which the height test refuses first.
    for (int c = 0; c < count; ++c)
      if (std::abs(height[c]) <= 1.0 - kHeightMargin && lambda[c] >= -kLambdaTolerance) {
        any = true;
        offerHit(face, n, from + c, k, rowStart + from + c, height[c], item, items, out);
      }
  }
  return any;
}

// The slopes along a row of the conditions N - D and -N - D of rowRange, and their inverses.
struct HeightSlopes {
  std::array<double, 2> g, perG;
};

HeightSlopes heightSlopes(const PairForms& f) {
  HeightSlopes h;
  h.g = {f.n.di - f.d.di, -f.n.di - f.d.di};
  for (int q = 0; q < 2; ++q) h.perG[q] = h.g[q] != 0.0 ? 1.0 / h.g[q] : 0.0;
  return h;
}

// Narrows the index range first..last of row @p k to where a hit is possible, or returns false
// when none is: where |h| <= 1, and where lambda_j = a_j + h b_j can reach -tol for every j. On
// a range without a pole h is monotone, so it lies between its values at the range's ends; then
// lambda_j is at most a_j + max(h_lo b_j, h_hi b_j), a maximum of two linear functions of i,
// largest at an end of the range. Exact as a necessary condition, and far cheaper than the
// roots; the narrower the range it starts from (the item's window), the tighter.
bool rowRange(const PairForms& f, const HeightSlopes& slopes, int k, int& first, int& last) {
  const double n0 = f.n.base + k * f.n.dk, d0 = f.d.base + k * f.d.dk;
  double lo = first, hi = last;
  const double dLo = d0 + lo * f.d.di, dHi = d0 + hi * f.d.di;
  if (!(dLo * dHi > 0.0)) return true;  // a pole or a zero in the range: no cheap bound
  const double s = dLo > 0.0 ? 1.0 : -1.0;
  // s (N - D) <= 0 and s (-N - D) <= 0, both linear in i.
  for (int q = 0; q < 2; ++q) {
    const double x = (q == 0 ? n0 : -n0) - d0, g0 = s * x, g1 = s * slopes.g[q];
    if (g1 == 0.0) {
      if (g0 > 0.0) return false;
      continue;
    }
    // The root -g0 / g1 by a product: its ulp is far inside the one-step margin.
    const double root = -x * slopes.perG[q];
    if (g1 > 0.0)
      hi = std::min(hi, std::ceil(root) + 1.0);
    else
      lo = std::max(lo, std::floor(root) - 1.0);
  }
  if (lo > hi) return false;
  first = static_cast<int>(lo), last = static_cast<int>(hi);
  const auto hAt = [&](double i) {
    return std::clamp((n0 + i * f.n.di) / (d0 + i * f.d.di), -1.0, 1.0);
  };
  const double hFirst = hAt(first), hLast = hAt(last);
  for (int j = 0; j < 3; ++j) {
    const double a0 = f.a[j].base + k * f.a[j].dk, b0 = f.b[j].base + k * f.b[j].dk;
    const auto bound = [&](double i) {
      const double b = b0 + i * f.b[j].di;
      return a0 + i * f.a[j].di + std::max(hFirst * b, hLast * b);
    };
    if (bound(first) < -2.0 * kLambdaTolerance && bound(last) < -2.0 * kLambdaTolerance)
      return false;
  }
  return true;
}

// What the rays of each raster row (|h| <= 1) can reach, seen along two in-plane axes, across
// the rows and along them. The rays of a row segment lie in the hull of its end points +- their
// vectors (the crust over a segment is affine in the position at a fixed height and affine in
// the height at a fixed position); along the row, the ray of point i lies within `reach` of its
// foot. An item whose projection misses these intervals is hit by no ray there, so a few
// compares per row cull rows and points before the row's exact bounds are computed.
struct RowSlabs {
  Vec3 across, along;
  double acrossNorm = 0.0, alongNorm = 0.0;
  std::vector<double> lo, hi;        // per row, the rays' interval on `across`
  std::vector<double> start, reach;  // per row, point 0 on `along`, and max |v . along|
  double step = 0.0;                 // change on `along` per raster step of a row
  double perStep = 0.0;              // 1 / step (0 when step is 0)
  // The rows' feet lie on `across` at base + k slope; no ray strays further than spread.
  double base = 0.0, slope = 0.0, spread = 0.0;
};

RowSlabs rowSlabs(const FaceCorners& face, int n) {
  const auto& p = face.p;
  const auto& v = face.v;
  RowSlabs s;
  // Rows keep mu_3 = k / n: they run parallel to p[0] - p[1], from p[1]'s side (i = 0).
  s.along = p[0] - p[1];
  s.across = (p[1] - p[0]).cross(p[2] - p[0]).cross(s.along);
  s.acrossNorm = s.across.norm(), s.alongNorm = s.along.norm();
  s.step = s.along.squaredNorm() / n;
  if (s.step > 0.0) s.perStep = 1.0 / s.step;
  for (auto* x : {&s.lo, &s.hi, &s.start, &s.reach}) x->resize(n + 1);
  s.base = p[1].dot(s.across), s.slope = (p[2] - p[1]).dot(s.across) / n;
  for (int j = 0; j < 3; ++j) s.spread = std::max(s.spread, std::abs(v[j].dot(s.across)));
  for (int k = 0; k <= n; ++k) {
    const double c = static_cast<double>(k) / n;
    const Vec3 ps = (1.0 - c) * p[1] + c * p[2], vs = (1.0 - c) * v[1] + c * v[2];
    const Vec3 pe = (1.0 - c) * p[0] + c * p[2], ve = (1.0 - c) * v[0] + c * v[2];
    const double xs = ps.dot(s.across), ys = std::abs(vs.dot(s.across));
    const double xe = pe.dot(s.across), ye = std::abs(ve.dot(s.across));
    s.lo[k] = std::min(xs - ys, xe - ye), s.hi[k] = std::max(xs + ys, xe + ye);
    s.start[k] = ps.dot(s.along);
    s.reach[k] = std::max(std::abs(vs.dot(s.along)), std::abs(ve.dot(s.along)));
  }
  return s;
}

/// An item's intervals on the two slab axes, widened by a margin.
struct ItemWindow {
  double acrossLo, acrossHi, alongLo, alongHi;
};

ItemWindow itemWindow(const RowSlabs& s, const ReductionItems& items, int item) {
  const double inf = std::numeric_limits<double>::infinity();
  ItemWindow w{inf, -inf, inf, -inf};
  for (int j = 0; j < 3; ++j) {
    const double x = items.corner(item, j).dot(s.across), y = items.corner(item, j).dot(s.along);
    w.acrossLo = std::min(w.acrossLo, x), w.acrossHi = std::max(w.acrossHi, x);
    w.alongLo = std::min(w.alongLo, y), w.alongHi = std::max(w.alongHi, y);
  }
  // A hit may lie kLambdaTolerance (barycentric) outside the item, and rounding: widen.
  const double size = 1e-6 * items.diagonals[item];
  const double a = size * s.acrossNorm, b = size * s.alongNorm;
  w.acrossLo -= a, w.acrossHi += a, w.alongLo -= b, w.alongHi += b;
  return w;
}

// The rows first..last (within 0..n) whose rays can reach the item; false when none can.
bool windowRows(const RowSlabs& s, const ItemWindow& w, int n, int& first, int& last) {
  first = 0, last = n;
  if (s.slope == 0.0) return true;
  double a = (w.acrossLo - s.spread - s.base) / s.slope;
  double b = (w.acrossHi + s.spread - s.base) / s.slope;
  if (a > b) std::swap(a, b);
  if (!(a <= n && b >= 0.0)) return false;
  // Clamped before the cast: far items give quotients beyond int.
  first = static_cast<int>(std::max(0.0, std::floor(a) - 1.0));
  last = static_cast<int>(std::min(static_cast<double>(n), std::ceil(b) + 1.0));
  return true;
}

// Row k's points first..last (within 0..length-1) whose rays can reach the item along the
// rows; false when none can.
bool windowRange(const RowSlabs& s, const ItemWindow& w, int k, int length, int& first, int& last) {
  if (s.hi[k] < w.acrossLo || s.lo[k] > w.acrossHi) return false;
  first = 0, last = length - 1;
  if (!(s.step > 0.0)) return true;
  // A product for the quotient: its ulp is far below the window's widening.
  const double lo = std::floor((w.alongLo - s.reach[k] - s.start[k]) * s.perStep);
  const double hi = std::ceil((w.alongHi + s.reach[k] - s.start[k]) * s.perStep);
  if (lo > last || hi < first) return false;
  first = static_cast<int>(std::max(0.0, lo));
  last = static_cast<int>(std::min(static_cast<double>(last), hi));
  return true;
}

// Shoots the raster of one (face, item) pair row by row, within the window of the item.
bool shootPair(const FaceCorners& face, int n, const PairForms& f, int item,
               const ReductionItems& items, const RowSlabs& slabs, const ItemWindow& w, int kFirst,
               int kLast, FaceItems& out) {
  bool any = false;
  const Raster raster{n + 1};
  std::array<std::pair<int, int>, 5> ranges;
  const HeightSlopes slopes = heightSlopes(f);
  for (int k = kFirst; k <= kLast; ++k) {
    const int length = n - k + 1;
    const std::size_t rowStart = raster.rowOffset(k);
    int first = 0, last = 0;
    if (windowRange(slabs, w, k, length, first, last) && rowRange(f, slopes, k, first, last) &&
        first <= last) {
      if (last - first + 1 < kIntervalRowLength) {
        any |= shootRow(face, n, f, k, first, last, rowStart, item, items, out);
      } else {
        const int count = rowIntervals(f, k, length, KernelMode::Fill, kLambdaTolerance, ranges);
        for (int r = 0; r < count; ++r)
          if (const int a = std::max(first, ranges[r].first), b = std::min(last, ranges[r].second);
              a <= b)
            any |= shootRow(face, n, f, k, a, b, rowStart, item, items, out);
      }
    }
  }
  return any;
}

// The hull of the +-1 crust (its six corners p_i +- v_i) with its extent along the axes that
// depend on the face alone (the face normal, the side-wall normals), computed once per face
// rather than once per candidate item.
struct CrustHull {
  std::array<Vec3, 6> corners;
  std::array<Vec3, 4> axes;
  std::array<double, 4> lo, hi;
};

void extentAlong(std::span<const Vec3> points, const Vec3& axis, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& c : points) {
    const double x = c.dot(axis);
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
}

CrustHull crustHull(const FaceCorners& face) {
  const auto& p = face.p;
  CrustHull hull;
  for (int i = 0; i < 3; ++i)
    hull.corners[2 * i] = p[i] + face.v[i], hull.corners[2 * i + 1] = p[i] - face.v[i];
  hull.axes[0] = (p[1] - p[0]).cross(p[2] - p[0]);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    hull.axes[1 + i] = (p[j] - p[i]).cross(face.v[i] + face.v[j]);
  }
  for (int a = 0; a < 4; ++a) extentAlong(hull.corners, hull.axes[a], hull.lo[a], hull.hi[a]);
  return hull;
}

bool itemApartAlong(const ReductionItems& items, int item, const Vec3& axis, double lo, double hi) {
  const std::array<Vec3, 3> t{items.corner(item, 0), items.corner(item, 1), items.corner(item, 2)};
  double tLo = 0.0, tHi = 0.0;
  extentAlong(t, axis, tLo, tHi);
  return tHi < lo || hi < tLo;
}

// The +-1 crust lies in the hull of its six corners p_i +- v_i: an axis separating that hull
// from the item (its normal, the face normal, the side-wall normals) proves no ray hits it.
bool itemSeparated(const CrustHull& hull, const ReductionItems& items, int item) {
  double lo = 0.0, hi = 0.0;
  extentAlong(hull.corners, items.normals[item], lo, hi);
  if (itemApartAlong(items, item, items.normals[item], lo, hi)) return true;
  for (int a = 0; a < 4; ++a)
    if (itemApartAlong(items, item, hull.axes[a], hull.lo[a], hull.hi[a])) return true;
  return false;
}

}  // namespace

bool betweenOffsets(const FaceCorners& face, const Vec3& q) {
  const Vec3 g = (face.p[0] + face.p[1] + face.p[2]) / 3.0;
  for (double h : {1.0, -1.0}) {
    const Vec3 a = face.p[0] + h * face.v[0], b = face.p[1] + h * face.v[1],
               c = face.p[2] + h * face.v[2];
    const Vec3 n = (b - a).cross(c - a);
    const double sq = n.dot(q - a), sg = n.dot(g - a);
    if (!(sq * sg > 0.0)) return false;
  }
  return true;
}

ReductionItems ReductionItems::fromMesh(const SupportMesh& mesh) {
  ReductionItems out;
  out.points.reserve(mesh.n_vertices());
  for (const auto vh : mesh.vertices()) out.points.push_back(toEigen(mesh.point(vh)));
  out.vertices.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) t[k++] = vh.idx();
    out.vertices.push_back(t);
    const Vec3 &a = out.points[t[0]], &b = out.points[t[1]], &c = out.points[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    out.normals.push_back(n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero());
    Eigen::AlignedBox3d box(a);
    box.extend(b), box.extend(c);
    out.boxes.push_back(box);
    out.diagonals.push_back(box.diagonal().norm());
  }
  return out;
}

Eigen::AlignedBox3d crustBox(const FaceCorners& face) {
  Eigen::AlignedBox3d box(face.p[0] + face.v[0]);
  for (int i = 0; i < 3; ++i) box.extend(face.p[i] + face.v[i]), box.extend(face.p[i] - face.v[i]);
  return box;
}

void rasterFace(const FaceCorners& face, int m, const ReductionItems& items,
                std::span<const int> candidates, FaceItems& out) {
  const int n = m - 1;
  const std::size_t points = Raster{m}.pointCount();
  out.hit.assign(points, -1);
  out.h.assign(points, 0.0);
  out.items.clear();
  const Eigen::AlignedBox3d box = crustBox(face);
  const RowSlabs slabs = rowSlabs(face, n);
  const CrustHull hull = crustHull(face);
  for (int t : candidates) {
    if (!box.intersects(items.boxes[t])) continue;
    const ItemWindow w = itemWindow(slabs, items, t);
    int kFirst = 0, kLast = 0;
    if (!windowRows(slabs, w, n, kFirst, kLast) || itemSeparated(hull, items, t)) continue;
    const auto forms = makePairForms(face, items.corner(t, 0), items.corner(t, 1),
                                     items.corner(t, 2), n, KernelMode::Fill);
    if (forms && shootPair(face, n, *forms, t, items, slabs, w, kFirst, kLast, out))
      out.items.push_back(t);
  }
  std::sort(out.items.begin(), out.items.end());
}

bool everyRayHits(const FaceItems& f) {
  return std::none_of(f.hit.begin(), f.hit.end(), [](int t) { return t < 0; });
}

bool anglesBounded(const FaceCorners& face, int m, const FaceItems& f, const ReductionItems& items,
                   double minCosine) {
  const int n = m - 1;
  const Raster raster{m};
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) {
      const int t = f.hit[raster.index(i, k)];
      if (t < 0) continue;
      const Vec3 v = vectorAt(face, rasterMu(i, k, n));
      if (v.dot(items.normals[t]) < minCosine * v.norm()) return false;
    }
  return true;
}

VertexPlace placeVertex(const Vec3& q, std::span<const FaceCorners> faces) {
  VertexPlace place = VertexPlace::Outside;
  for (const FaceCorners& f : faces) {
    const auto sols = vProject(q, f.p[0], f.p[1], f.p[2], f.v[0], f.v[1], f.v[2]);
    for (const VProjection& s : sols) {
      if (!s.inside) continue;
      if (std::abs(s.h) <= 1.0 + 1e-9) return VertexPlace::Inside;
      place = VertexPlace::Beyond;
    }
  }
  return place;
}

}  // namespace ddfcam::ddf::detail
