// SPDX-License-Identifier: MIT
// ddfcam: localization of support triangles by a spatial hash of their crusts (sec. 5.1).
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of the crust hash.
struct CrustHashParams {
  /// Grid cell edge = cellScale x the mean support-triangle extent per axis (the centre of the
  /// triangle extension space, sec. 5.1). Default 1.
  double cellScale = 1.0;
  /// Sub-volume size as a fraction of the cell size: a support triangle is split into
  /// sub-triangles and its +-1 crust into height slabs no larger than this, and each sub-volume
  /// box is entered into the cells it overlaps (fig. 5.2). Smaller = fewer false candidates,
  /// slower build. Default 0.5.
  double subVolumeFraction = 0.5;
};

/// @brief Hash parameters for a DDF whose vectors are long compared with its support edges (e.g.
/// vectors sized to reach a distant surface): cellScale = mean vector length / mean support edge
/// length, clamped to [1, 8], so that a cell holds a few crusts instead of a few sub-volumes of
/// one crust (cells of the default size make such hashes slow to build and to query).
CrustHashParams crustHashParamsFor(const DisplacementField& ddf);

/// @brief Spatial hash of the +-1 crusts of a DDF's support faces (dissertation sec. 5.1).
///
/// Occupied grid cells are kept in a hash table keyed by the cell's integer coordinates; each
/// holds the faces whose crust sub-volume boxes overlap it. Queries return a superset of the
/// faces whose crust a query object intersects.
class CrustHash {
 public:
  CrustHash() = default;
  /// @brief Builds the hash for @p ddf. The cell size is fixed at construction.
  explicit CrustHash(const DisplacementField& ddf, const CrustHashParams& params = {});

  /// @brief Re-enters @p faces after their vertices' vectors or positions changed.
  void updateFaces(const DisplacementField& ddf, std::span<const int> faces);
  /// @brief Re-enters every face (after setVectors on the whole field).
  void rebuild(const DisplacementField& ddf);

  /// @brief Faces whose crust may intersect triangle (a, b, c), mm; sorted, unique.
  void queryTriangle(const Vec3& a, const Vec3& b, const Vec3& c, std::vector<int>& out) const;
  /// @brief Faces whose crust may intersect @p box; sorted, unique.
  void queryBox(const Eigen::AlignedBox3d& box, std::vector<int>& out) const;
  /// @brief Faces sharing at least one cell with the crust of @p face (itself excluded).
  void queryCrust(int face, std::vector<int>& out) const;

  /// @brief Axis-aligned bounds of the +-1 crust of @p face.
  static Eigen::AlignedBox3d crustBox(const DisplacementField& ddf, int face);

  /// @brief Grid cell edge lengths per axis, mm.
  const Vec3& cellSize() const { return cellSize_; }
  /// @brief Number of occupied cells.
  std::size_t occupiedCells() const { return cells_.size(); }
  /// @brief Approximate bytes held.
  std::size_t memoryBytes() const;

 private:
  using CellKey = std::uint64_t;
  CellKey key(const Eigen::Vector3i& cell) const;
  Eigen::Vector3i cellOf(const Vec3& p) const;
  void insertFace(const DisplacementField& ddf, int face);
  std::vector<CellKey> faceKeys(const DisplacementField& ddf, int face) const;
  void removeFace(int face);
  void collectCells(const Eigen::AlignedBox3d& box, std::vector<CellKey>& keys) const;
  void gatherFaces(const std::vector<CellKey>& keys, std::vector<int>& out) const;

  CrustHashParams params_;
  Vec3 cellSize_ = Vec3::Ones();
  Vec3 invCell_ = Vec3::Ones();
  std::unordered_map<CellKey, std::vector<int>> cells_;
  std::vector<std::vector<CellKey>> faceCells_;
};

}  // namespace ddfcam::ddf
