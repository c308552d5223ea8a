// SPDX-License-Identifier: MIT
// ddfcam: identity and neighbourhood of raster points across support edges and vertices.
#pragma once

#include <ddfcam/ddf/raster.h>
#include <ddfcam/ddf/support_mesh.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace ddfcam::ddf {

/// @brief Identifier of a raster point of the whole DDF. Points on a shared support edge or
/// vertex exist once per incident face in the height arrays but have one PointId.
using PointId = std::uint32_t;

/// @brief One stored copy of a raster point: support face and linear index in its raster.
struct PointCopy {
  int face = 0;
  std::uint32_t local = 0;
};

/// @brief Global numbering of the raster points of a DDF and their lattice neighbourhoods.
///
/// Ids: [0, V) support vertices; then (m - 2) interior points per support edge, counted from the
/// edge's lower-index vertex; then the (m - 2)(m - 3)/2 interior points of every face. Local
/// vertex order of face f is p1 = from(h0), p2 = to(h0), p3 = to(next(h0)) with h0 the face's
/// first halfedge; local edge 0 is p1->p2 (row k = 0), 1 is p2->p3 (i = 0), 2 is p3->p1 (j = 0).
class RasterTopology {
 public:
  RasterTopology() = default;
  /// @brief Builds the numbering for @p mesh at raster resolution @p m (>= 2).
  RasterTopology(const SupportMesh& mesh, int m);

  const Raster& raster() const { return raster_; }
  /// @brief Number of distinct raster points.
  std::size_t pointCount() const { return pointCount_; }
  /// @brief Vertex indices (p1, p2, p3) of face @p f in local order.
  const std::array<int, 3>& faceVertices(int f) const { return faceVertices_[f]; }
  /// @brief Mesh edge index of local edge @p e of face @p f.
  int faceEdge(int f, int e) const { return faceEdges_[f][e]; }
  /// @brief Global id of the point (i, k) of face @p f.
  PointId id(int f, int i, int k) const;
  /// @brief Id of the point t steps (1..m-2) from the lower-index vertex of mesh edge @p edge.
  PointId edgePointId(int edge, int t) const {
    const std::size_t perEdge = static_cast<std::size_t>(raster_.steps()) - 1;
    return static_cast<PointId>(vertexCount_ + static_cast<std::size_t>(edge) * perEdge + (t - 1));
  }
  /// @brief Local raster index in @p face of the point t steps (0..m-1) from the lower-index
  /// vertex of the face's local edge @p localEdge.
  std::uint32_t edgeCopyLocal(int face, int localEdge, int t) const;
  /// @brief Local edge (0..2) of @p face that is mesh edge @p edge, or -1.
  int localEdgeOf(int face, int edge) const;
  /// @brief Calls @p fn(PointCopy) for every stored copy of @p p.
  template <class Fn>
  void forEachCopy(PointId p, Fn&& fn) const;
  /// @brief Appends the distinct lattice neighbours of @p p, across edges and vertices, to
  /// @p out (cleared first). Interior points have 6; points on seams and vertices get the union
  /// over all incident faces.
  void neighbors(PointId p, std::vector<PointId>& out) const;
  /// @brief Raster coordinates of copy @p c.
  RasterCoord coord(const PointCopy& c) const;
  /// @brief Mesh edge e with the faces on its two sides (-1 on a boundary).
  const std::array<int, 2>& edgeFaces(int e) const { return edgeFaces_[e]; }
  /// @brief Bytes held by the numbering tables (container storage and allocation overhead).
  std::size_t memoryBytes() const;
  /// @brief Faces incident to vertex v.
  const std::vector<int>& vertexFaces(int v) const { return vertexFaces_[v]; }

 private:
  void forEachCopyImpl(PointId p, const std::function<void(PointCopy)>& fn) const;

  Raster raster_;
  std::size_t vertexCount_ = 0;
  std::size_t edgeCount_ = 0;
  std::size_t pointCount_ = 0;
  std::vector<std::array<int, 3>> faceVertices_;
  std::vector<std::array<int, 3>> faceEdges_;
  std::vector<std::array<int, 2>> edgeFaces_;
  std::vector<std::array<int, 2>> edgeVertices_;  // (lower, higher) vertex index
  std::vector<std::vector<int>> vertexFaces_;
};

template <class Fn>
void RasterTopology::forEachCopy(PointId p, Fn&& fn) const {
  forEachCopyImpl(p, [&](PointCopy c) { fn(c); });
}

}  // namespace ddfcam::ddf
