// SPDX-License-Identifier: MIT
// ddfcam: the per-face subdivision of the adaptive triangulation (dissertation ch. 7).
#include "adaptive_face.h"

#include <algorithm>
#include <cstdlib>

#include "canonical_points.h"

namespace ddfcam::ddf::detail {
namespace {

// One formula for every point on an edge, so a straight midpoint equals the value E_e measured.
Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  return (1.0 - t) * a + t * b;
}

// Parameter of (xi, xk) on the straight edge a -> b.
double along(const FaceVertex& a, const FaceVertex& b, std::int64_t xi, std::int64_t xk) {
  return a.I != b.I ? static_cast<double>(xi - a.I) / static_cast<double>(b.I - a.I)
                    : static_cast<double>(xk - a.K) / static_cast<double>(b.K - a.K);
}

}  // namespace

double AdaptiveContext::edgeEps(int face, int side) const {
  if (!faceEps) return eps;
  double out = (*faceEps)[face];
  for (int g : ddf->topology().edgeFaces(ddf->topology().faceEdge(face, side)))
    if (g >= 0) out = std::min(out, static_cast<double>((*faceEps)[g]));
  return out;
}

int borderSide(std::int64_t I, std::int64_t K, std::int64_t steps) {
  const bool s0 = K == 0, s1 = I == 0, s2 = I + K == steps;
  if (static_cast<int>(s0) + static_cast<int>(s1) + static_cast<int>(s2) != 1) return -1;
  return s0 ? 0 : s1 ? 1 : 2;
}

std::int64_t canonicalT(const DisplacementField& ddf, int face, int side, std::int64_t I,
                        std::int64_t K, std::int64_t steps) {
  const auto& fv = ddf.faceVertices(face);
  const std::int64_t t = side == 0 ? steps - I - K : side == 1 ? K : I;
  return fv[side] < fv[(side + 1) % 3] ? t : steps - t;
}

int FaceSubdivider::addVertex(std::int64_t I, std::int64_t K, const Vec3& position) {
  verts_.push_back({I, K, position});
  return static_cast<int>(verts_.size()) - 1;
}

std::int64_t FaceSubdivider::edgeT(int slot, int support) const {
  return canonicalT(*ctx_->ddf, face_, support, verts_[slot].I, verts_[slot].K, NS_);
}

// The DDF surface at a parameter position: q at raster points, elsewhere the raster mesh
// (fig. 7.1a). On a support edge only the edge's own raster points count, taken in canonical
// order, so both faces compute bitwise identical points.
Vec3 FaceSubdivider::ddfPoint(std::int64_t I, std::int64_t K, int support) const {
  const Raster& raster = ctx_->ddf->raster();
  auto q = [&](std::int64_t i, std::int64_t k) {
    return q_[raster.index(static_cast<int>(i), static_cast<int>(k))];
  };
  if (I % S_ == 0 && K % S_ == 0) return q(I / S_, K / S_);
  if (support >= 0) {
    const std::int64_t T = canonicalT(*ctx_->ddf, face_, support, I, K, NS_);
    const auto& fv = ctx_->ddf->faceVertices(face_);
    const bool forward = fv[support] < fv[(support + 1) % 3];
    auto onEdge = [&](std::int64_t t) {
      const std::int64_t tl = forward ? t : n_ - t;
      return support == 0 ? q(n_ - tl, 0) : support == 1 ? q(0, tl) : q(tl, n_ - tl);
    };
    const std::int64_t t0 = T / S_;
    return lerp(onEdge(t0), onEdge(t0 + 1), static_cast<double>(T - t0 * S_) / S_);
  }
  const std::int64_t i0 = I / S_, k0 = K / S_, ri = I - i0 * S_, rk = K - k0 * S_;
  const double fi = static_cast<double>(ri) / S_, fk = static_cast<double>(rk) / S_;
  if (ri + rk <= S_) return (1.0 - fi - fk) * q(i0, k0) + fi * q(i0 + 1, k0) + fk * q(i0, k0 + 1);
  const double gi = 1.0 - fi, gk = 1.0 - fk;
  return (1.0 - gi - gk) * q(i0 + 1, k0 + 1) + gi * q(i0, k0 + 1) + gk * q(i0 + 1, k0);
}

int FaceSubdivider::makeEdge(int u, int v, int support) {
  const bool swap = support >= 0 ? edgeT(u, support) > edgeT(v, support) : u > v;
  Edge e;
  e.a = swap ? v : u;
  e.b = swap ? u : v;
  e.support = static_cast<std::int8_t>(support);
  edges_.push_back(e);
  return static_cast<int>(edges_.size()) - 1;
}

int FaceSubdivider::makeChild(int parent, int a, int b) {
  const Edge& p = edges_[parent];
  Edge e;
  e.a = a, e.b = b, e.support = p.support;
  if (p.state == 1) {  // E_e is inherited by sub-edges (ch. 7)
    e.state = 1;
    e.topA = p.topA, e.topB = p.topB, e.maxErr = p.maxErr;
  }
  edges_.push_back(e);
  return static_cast<int>(edges_.size()) - 1;
}

// E_e: the straight edge against the DDF surface at every kink of the raster mesh strictly
// inside it (the raster points, for edges on lattice lines; a check at raster points alone
// would pass edges off the lattice vacuously). Support sub-edges only reach here with end points
// computed canonically (a good parent makes its children good) and are measured from their
// canonical first end, so both faces decide identically.
bool FaceSubdivider::edgeGood(int index) {
  Edge& e = edges_[index];
  if (e.state >= 0) return e.state == 1;
  const FaceVertex& A = verts_[e.a];
  const FaceVertex& B = verts_[e.b];
  double worst = 0.0;
  bool ok = true;
  const double eps = e.support >= 0 ? ctx_->edgeEps(face_, e.support) : ctx_->epsOf(face_);
  forEachSampleOnEdge(e.a, e.b, [&](std::int64_t I, std::int64_t K) {
    const Vec3 truth = ddfPoint(I, K, e.support);
    const double d = (lerp(A.position, B.position, along(A, B, I, K)) - truth).norm();
    ok = d <= eps;  // NaN fails, so broken heights get refined instead of hidden
    worst = std::max(worst, d);
    return ok;
  });
  e.state = ok ? 1 : 0;
  if (ok) e.topA = e.a, e.topB = e.b, e.maxErr = worst;
  return ok;
}

// Exact midpoint: the straight point s_ij on the top good ancestor if E_e holds, else the DDF
// point q_ij (ch. 7).
int FaceSubdivider::splitEdge(int index) {
  if (edges_[index].mid >= 0) return edges_[index].mid;
  const bool good = edgeGood(index);
  const Edge& e = edges_[index];
  const FaceVertex& A = verts_[e.a];
  const FaceVertex& B = verts_[e.b];
  const std::int64_t I = (A.I + B.I) / 2, K = (A.K + B.K) / 2;
  const Vec3 position = good ? lerp(verts_[e.topA].position, verts_[e.topB].position,
                                    along(verts_[e.topA], verts_[e.topB], I, K))
                             : ddfPoint(I, K, e.support);
  const int mid = addVertex(I, K, position);
  const int a = e.a, b = e.b;
  const int c0 = makeChild(index, a, mid);
  const int c1 = makeChild(index, mid, b);
  edges_[index].mid = mid;
  edges_[index].child = {c0, c1};
  return mid;
}

int FaceSubdivider::childAt(int index, int vertex) const {
  const Edge& e = edges_[index];
  return e.a == vertex ? e.child[0] : e.child[1];
}

// E_t: all three edges hold E_e (so a failing edge fails the triangle) and the flat triangle
// meets q within eps at every raster point strictly inside.
bool FaceSubdivider::accept(const Tri& t, double& err) {
  double worst = 0.0;
  for (int s = 0; s < 3; ++s) {
    if (!edgeGood(t.e[s])) return false;
    worst = std::max(worst, edges_[t.e[s]].maxErr);
  }
  const Vec3& qa = verts_[t.v[0]].position;
  const Vec3& qb = verts_[t.v[1]].position;
  const Vec3& qc = verts_[t.v[2]].position;
  const double eps = ctx_->epsOf(face_);
  bool ok = true;
  forEachRasterInside(t.v, [&](int local, std::int64_t, std::int64_t, std::int64_t wa,
                               std::int64_t wb, std::int64_t wc, std::int64_t area) {
    const Vec3 approx = (static_cast<double>(wa) * qa + static_cast<double>(wb) * qb +
                         static_cast<double>(wc) * qc) /
                        static_cast<double>(area);
    const double d = (approx - q_[local]).norm();
    ok = d <= eps;
    worst = std::max(worst, d);
    return ok;
  });
  err = worst;
  return ok;
}

void FaceSubdivider::split4(const Tri& t) {
  const int m01 = splitEdge(t.e[0]);
  const int m12 = splitEdge(t.e[1]);
  const int m20 = splitEdge(t.e[2]);
  const int x0 = makeEdge(m01, m20, -1);
  const int x1 = makeEdge(m01, m12, -1);
  const int x2 = makeEdge(m12, m20, -1);
  stack_.push_back({{t.v[0], m01, m20}, {childAt(t.e[0], t.v[0]), x0, childAt(t.e[2], t.v[0])}});
  stack_.push_back({{m01, t.v[1], m12}, {childAt(t.e[0], t.v[1]), childAt(t.e[1], t.v[1]), x1}});
  stack_.push_back({{m20, m12, t.v[2]}, {x2, childAt(t.e[1], t.v[2]), childAt(t.e[2], t.v[2])}});
  stack_.push_back({{m01, m12, m20}, {x1, x2, x0}});
}

// Vertices inside edge e in order from its end point `from`, through all recorded splits.
void FaceSubdivider::expandChain(int index, int from, std::vector<int>& out) const {
  const Edge& e = edges_[index];
  if (e.mid < 0) return;
  const int first = childAt(index, from);
  const int second = e.child[0] == first ? e.child[1] : e.child[0];
  expandChain(first, from, out);
  out.push_back(e.mid);
  expandChain(second, e.mid, out);
}

void FaceSubdivider::emit(FaceResult& out) const {
  out.vertices = verts_;
  out.finals = finals_;
  out.maxError = maxError_;
  out.leaves.clear();
  out.chain.clear();
  out.leaves.reserve(leaves_.size());
  for (const Tri& t : leaves_) {
    AdaptiveLeaf leaf;
    leaf.corner = t.v;
    for (int s = 0; s < 3; ++s) {
      leaf.chainBegin[s] = static_cast<int>(out.chain.size());
      if (edges_[t.e[s]].support >= 0) {
        leaf.supportMask |= static_cast<std::uint8_t>(1u << s);
      } else if (ctx_->collectChains) {
        expandChain(t.e[s], t.v[s], out.chain);
      }
      leaf.chainEnd[s] = static_cast<int>(out.chain.size());
    }
    out.leaves.push_back(leaf);
  }
}

void FaceSubdivider::run(int face, FaceResult& out) {
  const DisplacementField& ddf = *ctx_->ddf;
  face_ = face;
  n_ = ddf.raster().steps();
  S_ = ctx_->scale;
  NS_ = n_ * S_;
  faceSurfacePoints(ddf, *ctx_->boundary, face, q_);
  verts_.clear();
  edges_.clear();
  rasterSlots_.clear();
  stack_.clear();
  leaves_.clear();
  finals_.clear();
  maxError_ = 0.0;

  const Raster& raster = ddf.raster();
  const std::array<int, 3> corner{addVertex(NS_, 0, q_[raster.index(n_, 0)]),
                                  addVertex(0, 0, q_[raster.index(0, 0)]),
                                  addVertex(0, NS_, q_[raster.index(0, n_)])};
  Tri root{corner, {}};
  for (int s = 0; s < 3; ++s) root.e[s] = makeEdge(corner[s], corner[(s + 1) % 3], s);
  stack_.push_back(root);
  while (!stack_.empty()) {
    const Tri t = stack_.back();
    stack_.pop_back();
    double err = 0.0;
    const FaceVertex& a = verts_[t.v[0]];
    const FaceVertex& b = verts_[t.v[1]];
    const std::int64_t side = std::max(std::abs(b.I - a.I), std::abs(b.K - a.K));
    if (accept(t, err)) {
      leaves_.push_back(t);
      maxError_ = std::max(maxError_, err);
    } else if (side < 2 * S_) {
      terminal(t);  // smaller than two raster steps: no dyadic midpoints left
    } else {
      split4(t);
    }
  }
  emit(out);
}

}  // namespace ddfcam::ddf::detail
