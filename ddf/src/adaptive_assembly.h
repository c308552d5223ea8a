// SPDX-License-Identifier: MIT
// ddfcam: mesh assembly of the adaptive triangulation shared by the full and the incremental
// build: keys of border vertices and T-vertex removal (private to ddfcam_ddf).
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "adaptive_face.h"

namespace ddfcam::ddf::detail {

/// Key bit pattern of a support vertex: (kVertexKey | vertex id).
inline constexpr std::uint64_t kVertexKey = std::uint64_t{0xffffffff} << 32;

/// @brief Where a face vertex lies on the support: support vertex v -> (kVertexKey | v), point
/// t inside support edge e -> (e << 32 | t) with t the canonical scaled position, 0 for a point
/// inside the face. Both faces of a support edge give its points the same key.
std::uint64_t borderKey(const DisplacementField& ddf, std::int64_t scale, int face,
                        const FaceVertex& v);

/// @brief Whether @p key (from borderKey, non-zero) names a support vertex.
inline bool isSupportVertexKey(std::uint64_t key) {
  return (key & kVertexKey) == kVertexKey;
}

/// @brief T-vertex removal of one face: every leaf collects the vertices inside its edges
/// (splits nest, so inside a support edge these are exactly the mesh vertices strictly between
/// its ends, made by either face) and is re-triangulated: fanned from the opposite corner when
/// one edge carries vertices, else around its centroid on the flat leaf triangle.
/// @tparam EdgeChain callable (edge, tFrom, tTo, out) appending the mesh vertices strictly
/// inside (min, max) of support edge @p edge in order from tFrom to tTo.
template <class EdgeChain>
class TVertexRemoval {
 public:
  TVertexRemoval(const DisplacementField& ddf, std::int64_t scale, EdgeChain chain)
      : ddf_(&ddf), scale_(scale), chain_(std::move(chain)) {}

  /// @brief Sets r.triangles and r.centroids from r.leaves, r.finals and r.vertexIndex;
  /// @p vertices are the mesh vertices r.vertexIndex refers to (for the centroids).
  void retriangulate(int f, FaceResult& r, const std::vector<Vec3>& vertices,
                     std::vector<int>& poly) const {
    r.triangles.clear();
    r.centroids.clear();
    r.centroidSums.clear();
    for (const auto& leaf : r.leaves) {
      poly.clear();
      std::array<int, 3> cornerAt{};
      int splitEdges = 0, lastSplit = 0;
      for (int s = 0; s < 3; ++s) {
        cornerAt[s] = static_cast<int>(poly.size());
        poly.push_back(r.vertexIndex[leaf.corner[s]]);
        const std::size_t before = poly.size();
        if (leaf.supportMask & (1u << s)) {
          supportChain(f, r, leaf.corner[s], leaf.corner[(s + 1) % 3], poly);
        } else {
          for (int c = leaf.chainBegin[s]; c < leaf.chainEnd[s]; ++c)
            poly.push_back(r.vertexIndex[r.chain[c]]);
        }
        if (poly.size() > before) ++splitEdges, lastSplit = s;
      }
      emitPolygon(r, vertices, poly, cornerAt, splitEdges, lastSplit, leaf);
    }
    for (const auto& t : r.finals)
      r.triangles.push_back({r.vertexIndex[t[0]], r.vertexIndex[t[1]], r.vertexIndex[t[2]]});
  }

 private:
  // Local support side (see detail::borderSide) shared by two border vertices of a face.
  static int supportSide(const FaceVertex& a, const FaceVertex& b) {
    if (a.K == 0 && b.K == 0) return 0;
    if (a.I == 0 && b.I == 0) return 1;
    return 2;
  }

  void supportChain(int f, const FaceResult& r, int from, int to, std::vector<int>& out) const {
    const std::int64_t NS = ddf_->raster().steps() * scale_;
    const FaceVertex& a = r.vertices[from];
    const FaceVertex& b = r.vertices[to];
    const int side = supportSide(a, b);
    const std::int64_t ta = canonicalT(*ddf_, f, side, a.I, a.K, NS);
    const std::int64_t tb = canonicalT(*ddf_, f, side, b.I, b.K, NS);
    chain_(static_cast<std::uint32_t>(ddf_->topology().faceEdge(f, side)), ta, tb, out);
  }

  static void emitPolygon(FaceResult& r, const std::vector<Vec3>& vs, const std::vector<int>& poly,
                          const std::array<int, 3>& cornerAt, int splitEdges, int lastSplit,
                          const AdaptiveLeaf& leaf) {
    const int count = static_cast<int>(poly.size());
    if (splitEdges == 0) {
      r.triangles.push_back({poly[0], poly[1], poly[2]});
    } else if (splitEdges == 1) {
      const int apex = poly[cornerAt[(lastSplit + 2) % 3]];
      const int end = lastSplit == 2 ? count : cornerAt[lastSplit + 1];
      for (int p = cornerAt[lastSplit]; p < end; ++p)
        r.triangles.push_back({poly[p], poly[(p + 1) % count], apex});
    } else {
      const int centroid = -static_cast<int>(r.centroids.size()) - 1;
      r.centroids.push_back(
          (vs[poly[cornerAt[0]]] + vs[poly[cornerAt[1]]] + vs[poly[cornerAt[2]]]) / 3.0);
      std::array<std::int64_t, 2> sum{0, 0};
      for (int corner : leaf.corner) {
        sum[0] += r.vertices[corner].I;
        sum[1] += r.vertices[corner].K;
      }
      r.centroidSums.push_back(sum);
      for (int p = 0; p < count; ++p)
        r.triangles.push_back({poly[p], poly[(p + 1) % count], centroid});
    }
  }

  const DisplacementField* ddf_;
  std::int64_t scale_;
  EdgeChain chain_;
};

/// @brief The leaves and sub-cell triangles of @p r as mesh triangles (no T-vertex removal).
void leafTriangles(FaceResult& r);

/// @brief Parameter position (i, k) in raster steps on face @p f of every corner of
/// r.triangles (after retriangulate(): mesh vertices, -(c+1) for centroid c, placed at the mean
/// of its leaf's corners). A vertex of the face's own subdivision has its lattice position; a
/// vertex another face put on a shared support edge is placed from its border key, which
/// @p slotKey gives per mesh vertex (borderKey()).
void cornerParams(const DisplacementField& ddf, std::int64_t scale, int f, const FaceResult& r,
                  const std::vector<std::uint64_t>& slotKey,
                  std::vector<std::array<std::array<float, 2>, 3>>& out);

}  // namespace ddfcam::ddf::detail
