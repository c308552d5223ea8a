// SPDX-License-Identifier: MIT
// ddfcam: the per-face subdivision of the adaptive triangulation (private to ddfcam_ddf).
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Read-only inputs shared by all faces of one adaptive triangulation.
///
/// Parameter positions are integers (I, K) on a lattice `scale` times finer than the raster:
/// raster point (i, k) is (i scale, k scale). scale is a power of two >= m - 1, so every
/// midpoint of the dyadic subdivision down to sub-cell triangles is exact.
struct AdaptiveContext {
  const DisplacementField* ddf = nullptr;
  const std::vector<Vec3>* boundary = nullptr;  ///< canonical q of shared points by PointId
  double eps = 0.01;                            ///< error bound, mm
  std::int64_t scale = 1;                       ///< sub-lattice steps per raster step
  bool collectChains = true;  ///< record the vertices on leaf edges (for T-vertex removal)
  /// Error bound per support face, mm; null: eps everywhere. A support edge is held to the
  /// smaller bound of its two faces, so both decide it alike (no cracks between bounds).
  const std::vector<float>* faceEps = nullptr;

  /// @brief The bound of face @p face's interior, mm.
  double epsOf(int face) const { return faceEps ? (*faceEps)[face] : eps; }
  /// @brief The bound of local support side @p side of face @p face, mm.
  double edgeEps(int face, int side) const;
};

/// @brief A vertex of one face: scaled parameter position and surface position (mm).
struct FaceVertex {
  std::int64_t I = 0;
  std::int64_t K = 0;
  Vec3 position = Vec3::Zero();
};

/// @brief A leaf of the subdivision (a triangle accepted by E_t) and the vertices that lie on
/// its edges inside this face.
struct AdaptiveLeaf {
  std::array<int, 3> corner{};  ///< vertex slots, oriented like the support face
  /// Per edge e (corner e -> corner e+1), unless it lies on a support edge: the vertices on it,
  /// a range of FaceResult::chain in edge order.
  std::array<int, 3> chainBegin{};
  std::array<int, 3> chainEnd{};
  std::uint8_t supportMask = 0;  ///< bit e set: edge e lies on a support edge
};

/// @brief Everything one face contributes, and (after assembly) its triangles.
struct FaceResult {
  std::vector<FaceVertex> vertices;           ///< vertex slots of this face
  std::vector<AdaptiveLeaf> leaves;           ///< E_t leaves (may have T-vertices on their edges)
  std::vector<int> chain;                     ///< vertices on the leaves' inner edges (slots)
  std::vector<std::array<int, 3>> finals;     ///< conforming triangles of sub-cell leaves (slots)
  double maxError = 0.0;                      ///< largest accepted error, mm
  std::vector<int> vertexIndex;               ///< mesh vertex of each slot
  std::vector<std::array<int, 3>> triangles;  ///< mesh triangles; -(c+1) refers to centroid c
  std::vector<Vec3> centroids;                ///< added leaf centroids, mm
  /// Sum of the scaled parameter positions (I, K) of each centroid's leaf corners.
  std::vector<std::array<std::int64_t, 2>> centroidSums;
};

/// @brief Side (local support edge 0, 1, 2) of a scaled position on the border of a face, or
/// -1 inside or at a corner. Edge 0 is k = 0, 1 is i = 0, 2 is j = 0 (see RasterTopology).
int borderSide(std::int64_t I, std::int64_t K, std::int64_t steps);

/// @brief Scaled position along the support edge of local side @p side of face @p face, counted
/// from its lower-index vertex as RasterTopology counts edge points.
std::int64_t canonicalT(const DisplacementField& ddf, int face, int side, std::int64_t I,
                        std::int64_t K, std::int64_t steps);

/// @brief Runs the recursive subdivision of one support face (reusable workspace).
class FaceSubdivider {
 public:
  explicit FaceSubdivider(const AdaptiveContext& ctx) : ctx_(&ctx) {}
  /// @brief Subdivides face @p face and stores its vertices, leaves and triangles in @p out.
  void run(int face, FaceResult& out);

 private:
  struct Edge {
    int a = 0, b = 0;  // end slots in canonical order (lower support t, else lower slot)
    int mid = -1;
    std::array<int, 2> child{-1, -1};  // (a, mid), (mid, b)
    int topA = -1, topB = -1;          // top good ancestor, canonical order
    double maxErr = 0.0;
    std::int8_t state = -1;              // -1 unknown, 0 fails E_e, 1 holds
    std::int8_t support = -1;            // local support edge, or -1
    bool rasterSplit = false;            // split at its raster points (sub-cell edges only)
    int rasterBegin = 0, rasterEnd = 0;  // those points in rasterSlots_, a -> b
  };
  struct Tri {
    std::array<int, 3> v;  // vertex slots
    std::array<int, 3> e;  // edge (v[s], v[s+1])
  };

  // adaptive_face.cpp: the recursion of ch. 7
  int addVertex(std::int64_t I, std::int64_t K, const Vec3& position);
  Vec3 ddfPoint(std::int64_t I, std::int64_t K, int support) const;
  std::int64_t edgeT(int slot, int support) const;
  int makeEdge(int u, int v, int support);
  int makeChild(int parent, int a, int b);
  bool edgeGood(int e);
  int splitEdge(int e);
  int childAt(int e, int vertex) const;
  bool accept(const Tri& t, double& err);
  void split4(const Tri& t);
  void expandChain(int e, int from, std::vector<int>& out) const;
  void emit(FaceResult& out) const;
  template <class Fn>
  void forEachSampleOnEdge(int a, int b, Fn&& fn) const;
  template <class Fn>
  void forEachRasterInside(const std::array<int, 3>& v, Fn&& fn) const;
  // adaptive_terminal.cpp: sub-cell triangles that fail E_t
  void terminal(const Tri& t);
  void rasterSplit(int e);
  void insertPoint(std::vector<std::array<int, 3>>& tris, int slot) const;
  void delaunayFlips(std::vector<std::array<int, 3>>& tris) const;
  double worstInner(const std::vector<std::array<int, 3>>& tris, const std::vector<int>& inner,
                    int& worstIndex) const;

  const AdaptiveContext* ctx_;
  int face_ = 0;
  int n_ = 1;
  std::int64_t S_ = 1;   // scale
  std::int64_t NS_ = 1;  // n * scale
  std::vector<Vec3> q_;  // surface points of the face's raster, canonical on its border
  std::vector<FaceVertex> verts_;
  std::vector<Edge> edges_;
  std::vector<int> rasterSlots_;
  std::vector<Tri> stack_;
  std::vector<Tri> leaves_;
  std::vector<std::array<int, 3>> finals_;
  std::vector<std::array<int, 3>> scratchTris_;
  std::vector<int> scratchInner_;
  double maxError_ = 0.0;
};

/// @brief Twice the signed area of (p, q, x) in scaled parameter coordinates.
inline std::int64_t orientScaled(const FaceVertex& p, const FaceVertex& q, std::int64_t xi,
                                 std::int64_t xk) {
  return (q.I - p.I) * (xk - p.K) - (q.K - p.K) * (xi - p.I);
}

// Calls fn(I, K) for the kinks of the raster mesh strictly inside edge a-b (an edge of the
// subdivision, so parallel to a side of the support face): its crossings with the lattice
// lines of the two other directions, which are the raster points when the edge runs on a
// lattice line. Stops when fn returns false.
template <class Fn>
void FaceSubdivider::forEachSampleOnEdge(int a, int b, Fn&& fn) const {
  const FaceVertex A = verts_[a], B = verts_[b];  // copies: fn may add vertices
  const bool alongI = A.I != B.I;                 // I varies (k or j constant), else K varies
  const std::int64_t lo = alongI ? std::min(A.I, B.I) : std::min(A.K, B.K);
  const std::int64_t hi = alongI ? std::max(A.I, B.I) : std::max(A.K, B.K);
  // Residues mod S of the varying coordinate at crossings: 0 (its own lines) and the one
  // where the third coordinate is a multiple of S.
  const std::int64_t other = A.K == B.K ? -A.K : A.I == B.I ? -A.I : A.I + A.K;
  const std::int64_t r2 = ((other % S_) + S_) % S_;
  for (const std::int64_t r : {std::int64_t{0}, r2}) {
    std::int64_t x = lo - ((lo - r) % S_ + S_) % S_ + S_;  // first x > lo with x = r mod S
    for (; x < hi; x += S_) {
      const std::int64_t I = alongI ? x : A.I;
      const std::int64_t K = alongI ? (A.K == B.K ? A.K : A.I + A.K - x) : x;
      if (!fn(I, K)) return;
    }
    if (r2 == 0) break;  // both families meet at the raster points
  }
}

// Calls fn(local, wa, wb, wc, area) for the raster points strictly inside triangle v, with
// integer barycentric weights, until fn returns false.
template <class Fn>
void FaceSubdivider::forEachRasterInside(const std::array<int, 3>& v, Fn&& fn) const {
  const FaceVertex& a = verts_[v[0]];
  const FaceVertex& b = verts_[v[1]];
  const FaceVertex& c = verts_[v[2]];
  std::int64_t area = orientScaled(a, b, c.I, c.K);
  const std::int64_t sign = area > 0 ? 1 : -1;
  area *= sign;
  const std::int64_t iLo = (std::min({a.I, b.I, c.I}) + S_ - 1) / S_;
  const std::int64_t iHi = std::max({a.I, b.I, c.I}) / S_;
  const std::int64_t kLo = (std::min({a.K, b.K, c.K}) + S_ - 1) / S_;
  const std::int64_t kHi = std::max({a.K, b.K, c.K}) / S_;
  const Raster& raster = ctx_->ddf->raster();
  for (std::int64_t k = kLo; k <= kHi; ++k) {
    for (std::int64_t i = iLo; i <= iHi && i + k <= n_; ++i) {
      const std::int64_t xi = i * S_, xk = k * S_;
      const std::int64_t wa = sign * orientScaled(b, c, xi, xk);
      if (wa <= 0) continue;
      const std::int64_t wb = sign * orientScaled(c, a, xi, xk);
      if (wb <= 0) continue;
      const std::int64_t wc = area - wa - wb;
      if (wc <= 0) continue;
      const int local = static_cast<int>(raster.index(static_cast<int>(i), static_cast<int>(k)));
      if (!fn(local, xi, xk, wa, wb, wc, area)) return;
    }
  }
}

}  // namespace ddfcam::ddf::detail
