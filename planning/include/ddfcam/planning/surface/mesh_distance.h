// SPDX-License-Identifier: MIT
// ddfcam: exact signed point-to-mesh distance (BVH, angle-weighted pseudo-normals).
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief The point of a mesh nearest to a query point.
struct MeshClosestPoint {
  double distance = 0.0;        ///< |p - point|, mm
  double signedDistance = 0.0;  ///< distance, negative behind the mesh (see MeshDistance), mm
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< nearest mesh point, mm, mesh frame
  int triangle = -1;  ///< index of a triangle containing the nearest point
};

/// @brief Exact point-to-mesh distance queries over a triangle mesh built once.
///
/// An axis-aligned bounding-volume hierarchy over the triangles prunes the search; each
/// candidate triangle gives its exact closest point (Ericson, Real-Time Collision Detection
/// 5.1.5), so the result equals a brute-force minimum over all triangles. The sign follows
/// Baerentzen & Aanaes (2005): sign((p - c) . n) with n the angle-weighted pseudo-normal of the
/// feature holding the closest point c (the face normal inside a triangle, the sum of the
/// adjacent face normals on an edge, the angle-weighted vertex normal at a vertex). On a closed
/// manifold mesh oriented outwards this is + outside and - inside for every point; on an open
/// surface it is + on the side its counter-clockwise normals point to, and it stays consistent
/// across edges and vertices. The mesh is copied; queries are const and thread-safe.
class MeshDistance {
 public:
  /// @brief Builds the hierarchy and pseudo-normals of @p mesh (O(T log T)).
  /// @throws InvalidInput if @p mesh has no triangles or a triangle uses a vertex index out of
  /// range.
  explicit MeshDistance(const ddf::TriangleMesh& mesh);

  /// @brief Nearest point of the mesh to @p p (mm, mesh frame).
  /// @param maxDistanceMm only points within this distance are considered (default: any).
  /// @return std::nullopt if no triangle lies within @p maxDistanceMm of @p p, or @p p is not
  /// finite.
  std::optional<MeshClosestPoint> closestPoint(
      const Eigen::Vector3d& p,
      double maxDistanceMm = std::numeric_limits<double>::infinity()) const;

  /// @brief Number of triangles of the mesh.
  int triangleCount() const { return static_cast<int>(triangles_.size()); }

 private:
  struct Node {
    Eigen::Vector3d lo, hi;   // bounds of the node's triangles
    std::uint32_t first = 0;  // leaf: first index into order_; inner: left child
    std::uint32_t count = 0;  // leaf: number of triangles; inner: 0
    std::uint32_t right = 0;  // inner: right child
  };
  // Per triangle: the pseudo-normals of its three vertices, three edges (a->b, b->c, c->a)
  // and its face, in that order.
  using FeatureNormals = std::array<Eigen::Vector3d, 7>;

  std::uint32_t build(std::uint32_t begin, std::uint32_t end,
                      const std::vector<Eigen::Vector3d>& centroids);
  void computeNormals();

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<FeatureNormals> normals_;
  std::vector<std::uint32_t> order_;  // triangle indices, leaves' ranges contiguous
  std::vector<Node> nodes_;           // nodes_[0] is the root
};

}  // namespace ddfcam::planning
