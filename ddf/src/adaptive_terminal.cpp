// SPDX-License-Identifier: MIT
// ddfcam: adaptive triangulation below the raster spacing, where dyadic midpoints run out.
//
// A sub-triangle shorter than two raster steps that still fails E_t takes raster points as
// vertices: those inside its failing edges (the same decision from both sides of every edge,
// so neighbours stay conforming) and, greedily, the worst inner raster point until every inner
// point is within eps. The small result is kept Delaunay in the parameter plane.
#include <algorithm>
#include <cmath>
#include <limits>

#include "adaptive_face.h"

namespace ddfcam::ddf::detail {
namespace {

// The parameter plane with the raster lattice made equilateral, in raster steps.
std::array<double, 2> embed(const FaceVertex& v, double invScale) {
  return {(static_cast<double>(v.I) + 0.5 * static_cast<double>(v.K)) * invScale,
          0.8660254037844386 * static_cast<double>(v.K) * invScale};
}

// > 0 when d lies inside the circumcircle of the counter-clockwise triangle (a, b, c).
double inCircle(std::array<double, 2> a, std::array<double, 2> b, std::array<double, 2> c,
                std::array<double, 2> d) {
  for (auto* p : {&a, &b, &c}) (*p)[0] -= d[0], (*p)[1] -= d[1];
  const double la = a[0] * a[0] + a[1] * a[1], lb = b[0] * b[0] + b[1] * b[1];
  const double lc = c[0] * c[0] + c[1] * c[1];
  return la * (b[0] * c[1] - c[0] * b[1]) - lb * (a[0] * c[1] - c[0] * a[1]) +
         lc * (a[0] * b[1] - b[0] * a[1]);
}

}  // namespace

// Splits a failing sub-cell edge at its raster points (DDF points, canonical on support edges).
void FaceSubdivider::rasterSplit(int index) {
  if (edges_[index].rasterSplit) return;
  const int begin = static_cast<int>(rasterSlots_.size());
  const int a = edges_[index].a, b = edges_[index].b;
  const Raster& raster = ctx_->ddf->raster();
  forEachSampleOnEdge(a, b, [&](std::int64_t I, std::int64_t K) {
    if (I % S_ == 0 && K % S_ == 0) {
      const auto local = raster.index(static_cast<int>(I / S_), static_cast<int>(K / S_));
      rasterSlots_.push_back(addVertex(I, K, q_[local]));
    }
    return true;
  });
  // forEachSampleOnEdge walks by increasing coordinate; store in a -> b order.
  const FaceVertex& A = verts_[a];
  const FaceVertex& B = verts_[b];
  if (A.I != B.I ? B.I < A.I : B.K < A.K)
    std::reverse(rasterSlots_.begin() + begin, rasterSlots_.end());
  Edge& e = edges_[index];
  e.rasterSplit = true;
  e.rasterBegin = begin;
  e.rasterEnd = static_cast<int>(rasterSlots_.size());
}

// Inserts vertex `slot` into the small triangulation: into the triangle containing it, or into
// the two triangles sharing the edge it lies on.
void FaceSubdivider::insertPoint(std::vector<std::array<int, 3>>& tris, int slot) const {
  const FaceVertex& x = verts_[slot];
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const auto [a, b, c] = tris[t];
    const std::int64_t sign =
        orientScaled(verts_[a], verts_[b], verts_[c].I, verts_[c].K) > 0 ? 1 : -1;
    const std::array<std::int64_t, 3> o{sign * orientScaled(verts_[a], verts_[b], x.I, x.K),
                                        sign * orientScaled(verts_[b], verts_[c], x.I, x.K),
                                        sign * orientScaled(verts_[c], verts_[a], x.I, x.K)};
    if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
    const int zero = o[0] == 0 ? 0 : o[1] == 0 ? 1 : o[2] == 0 ? 2 : -1;
    if (zero < 0) {
      tris[t] = {a, b, slot};
      tris.push_back({b, c, slot});
      tris.push_back({c, a, slot});
      return;
    }
    const int p = tris[t][zero], q = tris[t][(zero + 1) % 3], r = tris[t][(zero + 2) % 3];
    tris[t] = {p, slot, r};
    tris.push_back({slot, q, r});
    for (auto& other : tris) {  // the neighbour across (q, p), if inside this sub-triangle
      for (int s = 0; s < 3; ++s) {
        if (other[s] != q || other[(s + 1) % 3] != p) continue;
        const int u = other[(s + 2) % 3];
        other = {q, slot, u};
        tris.push_back({slot, p, u});
        return;
      }
    }
    return;
  }
}

// Lawson flips of inner edges (edges on the sub-triangle's border have one triangle only).
void FaceSubdivider::delaunayFlips(std::vector<std::array<int, 3>>& tris) const {
  if (tris.size() < 2) return;
  const double inv = 1.0 / static_cast<double>(S_);
  for (int round = 0; round < 64; ++round) {
    bool flipped = false;
    for (std::size_t t = 0; t < tris.size() && !flipped; ++t) {
      for (int s = 0; s < 3 && !flipped; ++s) {
        const int p = tris[t][s], q = tris[t][(s + 1) % 3], r = tris[t][(s + 2) % 3];
        for (std::size_t u = 0; u < tris.size() && !flipped; ++u) {
          for (int w = 0; w < 3; ++w) {
            if (tris[u][w] != q || tris[u][(w + 1) % 3] != p) continue;
            const int o = tris[u][(w + 2) % 3];
            auto P = embed(verts_[p], inv), Q = embed(verts_[q], inv), R = embed(verts_[r], inv);
            const double ccw = (Q[0] - P[0]) * (R[1] - P[1]) - (Q[1] - P[1]) * (R[0] - P[0]);
            if (ccw < 0) std::swap(P, Q);
            if (inCircle(P, Q, R, embed(verts_[o], inv)) > 1e-9) {
              tris[t] = {p, o, r};
              tris[u] = {o, q, r};
              flipped = true;
            }
            break;
          }
        }
      }
    }
    if (!flipped) return;
  }
}

// Largest error of the raster points `inner` (local indices) against the small triangulation.
double FaceSubdivider::worstInner(const std::vector<std::array<int, 3>>& tris,
                                  const std::vector<int>& inner, int& worstIndex) const {
  double worst = -1.0;
  worstIndex = -1;
  const Raster& raster = ctx_->ddf->raster();
  for (std::size_t x = 0; x < inner.size(); ++x) {
    int k = 0;
    while (k < n_ && raster.rowOffset(k + 1) <= static_cast<std::size_t>(inner[x])) ++k;
    const std::int64_t xi = (inner[x] - static_cast<std::int64_t>(raster.rowOffset(k))) * S_;
    const std::int64_t xk = k * S_;
    double d = std::numeric_limits<double>::infinity();
    for (const auto& [a, b, c] : tris) {
      const FaceVertex &A = verts_[a], &B = verts_[b], &C = verts_[c];
      std::int64_t area = orientScaled(A, B, C.I, C.K);
      const std::int64_t sign = area > 0 ? 1 : -1;
      area *= sign;
      const std::int64_t wa = sign * orientScaled(B, C, xi, xk),
                         wb = sign * orientScaled(C, A, xi, xk);
      const std::int64_t wc = area - wa - wb;
      if (wa < 0 || wb < 0 || wc < 0) continue;
      const Vec3 approx =
          (static_cast<double>(wa) * A.position + static_cast<double>(wb) * B.position +
           static_cast<double>(wc) * C.position) /
          static_cast<double>(area);
      const double e = (approx - q_[inner[x]]).norm();
      d = std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
      break;
    }
    if (d > worst) worst = d, worstIndex = static_cast<int>(x);
  }
  return std::max(worst, 0.0);
}

void FaceSubdivider::terminal(const Tri& t) {
  auto& tris = scratchTris_;
  tris.assign(1, t.v);
  double worst = 0.0;
  for (int s = 0; s < 3; ++s) {
    if (edgeGood(t.e[s])) {
      worst = std::max(worst, edges_[t.e[s]].maxErr);
      continue;
    }
    rasterSplit(t.e[s]);
    const Edge& e = edges_[t.e[s]];
    for (int r = e.rasterBegin; r < e.rasterEnd; ++r) insertPoint(tris, rasterSlots_[r]);
  }
  auto& inner = scratchInner_;
  inner.clear();
  forEachRasterInside(t.v, [&](int local, auto...) {
    inner.push_back(local);
    return true;
  });
  delaunayFlips(tris);
  for (;;) {
    int index = -1;
    const double w = worstInner(tris, inner, index);
    if (index < 0 || w <= ctx_->epsOf(face_)) {
      worst = std::max(worst, index < 0 ? 0.0 : w);
      break;
    }
    const int local = inner[index];
    inner.erase(inner.begin() + index);
    int k = 0;
    const Raster& raster = ctx_->ddf->raster();
    while (k < n_ && raster.rowOffset(k + 1) <= static_cast<std::size_t>(local)) ++k;
    const std::int64_t i = local - static_cast<std::int64_t>(raster.rowOffset(k));
    insertPoint(tris, addVertex(i * S_, k * S_, q_[local]));
    delaunayFlips(tris);
  }
  finals_.insert(finals_.end(), tris.begin(), tris.end());
  maxError_ = std::max(maxError_, worst);
}

}  // namespace ddfcam::ddf::detail
