// SPDX-License-Identifier: MIT
// ddfcam: private building blocks of the deformation sequence (point/mesh distance, stages).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Bounding-volume hierarchy over the triangles of a mesh for exact point distances.
class TriangleBvh {
 public:
  /// @brief Builds the tree over @p mesh (kept by reference: it must outlive the tree).
  explicit TriangleBvh(const TriangleMesh& mesh);
  /// @brief Euclidean distance from @p p to the nearest triangle, mm; +inf for an empty mesh.
  double distance(const Vec3& p) const;

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int first = 0;  // leaf: first triangle in order_; inner: left child index
    int count = 0;  // leaf: triangle count; inner: 0
    int right = 0;  // inner: right child index
  };
  int build(int first, int count, int depth);
  double triangleDistanceSq(int t, const Vec3& p) const;
  const TriangleMesh& mesh_;
  std::vector<int> order_;
  std::vector<Vec3> centroids_;
  std::vector<Node> nodes_;
};

/// @brief Largest distance from a support vertex of @p ddf to the mesh of @p bvh, mm (parallel).
double largestVertexDistance(const DisplacementField& ddf, const TriangleBvh& bvh);

/// @brief Per face, the smallest h0 / |h| over its finite heights on either side (+inf when
/// all heights are zero or NaN; 0 where constraint 1 fails and some height is non-zero).
std::vector<double> crustRatios(const DisplacementField& ddf);

/// @brief Per support vertex, the move t h v of its corner raster point (first finite copy);
/// vertices without a finite height take the mean move of neighbours that have one (a few
/// sweeps), else zero.
std::vector<Vec3> vertexMoves(const DisplacementField& ddf, double t);

/// @brief Faces whose normal turns by 90 degrees or more when the vertices move to
/// @p positions (a fold of the support), ascending.
std::vector<int> flippedFaces(const DisplacementField& ddf, const std::vector<Vec3>& positions);

}  // namespace ddfcam::ddf::detail
