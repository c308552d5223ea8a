// SPDX-License-Identifier: MIT
// ddfcam: a plain indexed triangle mesh, the exchange type for tools, extracted surfaces and I/O.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace ddfcam::ddf {

/// @brief Indexed triangle mesh in the part frame (mm). Triangles are counter-clockwise seen
/// from outside (for closed tools) or from the front side (for surfaces).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;      ///< #V points, mm
  std::vector<std::array<int, 3>> triangles;  ///< #T vertex index triples

  /// @brief Axis-aligned bounds (min, max); both zero for an empty mesh.
  std::array<Eigen::Vector3d, 2> bounds() const;
  /// @brief Signed enclosed volume, mm^3 (positive for a closed outward-oriented mesh).
  double signedVolume() const;
  /// @brief A copy with every vertex mapped by @p pose.
  TriangleMesh transformed(const Eigen::Isometry3d& pose) const;
};

}  // namespace ddfcam::ddf
