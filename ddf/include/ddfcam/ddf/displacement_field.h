// SPDX-License-Identifier: MIT
// ddfcam: the Discrete Displacement Field (dissertation ch. 3).
#pragma once

#include <ddfcam/ddf/raster.h>
#include <ddfcam/ddf/raster_topology.h>
#include <ddfcam/ddf/support_mesh.h>

#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief How the copies of a raster point on a shared edge or vertex are made to agree.
enum class SharedPolicy {
  Minimum,   ///< every copy takes the smallest value (depth-buffer semantics after a cut)
  Canonical  ///< every copy takes the value of the copy in the lowest-index face
};

/// @brief A Discrete Displacement Field: support mesh S, one displacement vector per support
/// vertex (interpolated barycentrically), and per support face a triangular raster of
/// resolution m of float heights. The represented point of raster point (i, j, k) of face f is
/// q = g + h v with g = (i p1 + j p2 + k p3)/(m-1) and v interpolated the same way. Heights are
/// in units of the local vector length (h = +-1 are the crust faces), positions in mm.
class DisplacementField {
 public:
  DisplacementField() = default;
  /// @brief Takes the support and per-vertex vectors; all heights start at @p initialHeight.
  /// @throws InvalidInput if the vector count differs from the vertex count or m < 2.
  DisplacementField(SupportMesh support, std::vector<Vec3> vectors, int m,
                    float initialHeight = 0.0f);

  const SupportMesh& support() const { return support_; }
  const RasterTopology& topology() const { return topology_; }
  const Raster& raster() const { return topology_.raster(); }
  /// @brief Raster resolution m (points per support edge).
  int resolution() const { return topology_.raster().m; }
  int faceCount() const { return static_cast<int>(faceVertices_.size()); }
  int vertexCount() const { return static_cast<int>(positions_.size()); }
  std::size_t pointsPerFace() const { return pointsPerFace_; }

  /// @brief Support vertex position, mm.
  const Vec3& position(int v) const { return positions_[v]; }
  /// @brief Displacement vector of support vertex @p v, mm per unit height.
  const Vec3& vector(int v) const { return vectors_[v]; }
  const std::vector<Vec3>& vectors() const { return vectors_; }
  /// @brief Replaces all vectors (e.g. after choosing lengths, sec. 4.4). Heights keep their
  /// values, so the represented surface changes with the vectors.
  /// @throws InvalidInput on a count mismatch.
  void setVectors(std::vector<Vec3> vectors);
  /// @brief Vertex indices (p1, p2, p3) of face @p f in raster order.
  const std::array<int, 3>& faceVertices(int f) const { return faceVertices_[f]; }

  /// @brief Heights of face @p f, pointsPerFace() values in Raster order.
  std::span<float> heights(int f) {
    return {heights_.data() + static_cast<std::size_t>(f) * pointsPerFace_, pointsPerFace_};
  }
  std::span<const float> heights(int f) const {
    return {heights_.data() + static_cast<std::size_t>(f) * pointsPerFace_, pointsPerFace_};
  }
  /// @brief All heights, face after face.
  std::vector<float>& allHeights() { return heights_; }
  const std::vector<float>& allHeights() const { return heights_; }
  /// @brief Height of raster point (i, k) of face f.
  float height(int f, int i, int k) const { return heights(f)[raster().index(i, k)]; }

  /// @brief Support point g at barycentric coordinates @p bary of face @p f, mm.
  Vec3 basePoint(int f, const Vec3& bary) const;
  /// @brief Interpolated displacement vector v at barycentric coordinates @p bary of face @p f.
  Vec3 vectorAt(int f, const Vec3& bary) const;
  /// @brief g + h v at barycentric coordinates @p bary, mm.
  Vec3 pointAt(int f, const Vec3& bary, double h) const;
  /// @brief Barycentric coordinates (i, j, k)/(m-1) of raster point (i, k).
  Vec3 rasterBary(int i, int k) const;
  /// @brief Represented surface point q of raster point (i, k) of face f, mm.
  Vec3 surfacePoint(int f, int i, int k) const;

  /// @brief Makes all copies of every shared raster point agree (see SharedPolicy).
  void synchronizeShared(SharedPolicy policy);
  /// @brief As above, limited to the edges and vertices of the listed faces.
  void synchronizeShared(SharedPolicy policy, std::span<const int> faces);

  /// @brief Bytes held by this field: support mesh, vectors, topology and heights.
  std::size_t memoryBytes() const;

 private:
  void syncEdge(int edge, SharedPolicy policy);
  void syncVertex(int vertex, SharedPolicy policy);

  SupportMesh support_;
  RasterTopology topology_;
  std::vector<Vec3> positions_;
  std::vector<Vec3> vectors_;
  std::vector<std::array<int, 3>> faceVertices_;
  std::size_t pointsPerFace_ = 0;
  std::vector<float> heights_;
};

}  // namespace ddfcam::ddf
