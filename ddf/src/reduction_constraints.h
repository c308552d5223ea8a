// SPDX-License-Identifier: MIT
// ddfcam (private): the unique-projection parts of the support reduction (sec. 6.2): the length
// of a new vertex's vector (sec. 4.4 rule) and non-adjacent crust conflicts through a spatial
// hash of crust boxes that follows the contractions.
#pragma once

#include "cut_kernel.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Crust height every face must keep after a contraction: 1 and a hair against
/// rounding.
inline constexpr double kReductionMinH0 = 1.0 + 1e-6;
/// @brief VectorLengthParams::safety of the initial length choice (h0 >= 1.25 everywhere).
inline constexpr double kInitialSafety = 0.8;
/// @brief A new vector gets this fraction of the longest admissible length when that still
/// keeps h0 >= 1 (it usually raises the limiting face's h0 to about 1.25).
inline constexpr double kNewVectorSafety = 0.8;

/// @brief A support face in a tentative configuration: its corners and which of them is the
/// new vertex (0..2).
struct NewFace {
  FaceCorners corners;
  int newCorner = 0;
};

/// @brief The longest length L <= @p maxLength of the new vertex's vector @p direction (unit)
/// for which every face of @p faces has crust heights min(h0+, h0-) >= kReductionMinH0 (the
/// rule of sec. 4.4 applied to the one vector that changes), then kNewVectorSafety L when that
/// is admissible too; the faces' newCorner vectors are overwritten with the result. std::nullopt
/// when no length in (0, maxLength] works.
std::optional<double> chooseNewVectorLength(std::span<NewFace> faces, const Vec3& direction,
                                            double maxLength);

/// @brief Uniform grid of the +-1 crust boxes of the support faces, kept in a hash table keyed
/// by cell (sec. 5.1, boxes only); faces are re-entered as contractions change them.
class CrustBoxHash {
 public:
  /// @brief An empty hash with cell edge @p cellMm (> 0).
  explicit CrustBoxHash(double cellMm = 1.0) : cell_(cellMm) {}
  /// @brief Enters or re-enters @p face with crust box @p box.
  void set(int face, const Eigen::AlignedBox3d& box);
  /// @brief Removes @p face (no-op when absent).
  void remove(int face);
  /// @brief Faces whose boxes may meet @p box, unsorted, unique (uses a stamp per face).
  void query(const Eigen::AlignedBox3d& box, std::vector<int>& out);
  /// @brief The box @p face was entered with.
  const Eigen::AlignedBox3d& box(int face) const { return boxes_[face]; }

 private:
  using Key = std::uint64_t;
  Eigen::Vector3i cellOf(const Vec3& p) const;
  static Key key(int x, int y, int z);

  double cell_;
  std::unordered_map<Key, std::vector<int>> cells_;
  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<char> present_;
  std::vector<unsigned> stamp_;
  unsigned now_ = 0;
};

/// @brief Whether the +-1 crusts of two faces that share no vertex intersect (crustsIntersect
/// on a two-face field).
bool crustsConflict(const FaceCorners& s, const FaceCorners& t);

}  // namespace ddfcam::ddf::detail
