// SPDX-License-Identifier: MIT
// ddfcam: canonical copies of shared raster points (private to ddfcam_ddf).
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <algorithm>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Owner of every raster point: the lowest-index face among its copies (the rule of
/// SharedPolicy::Canonical). Every position of a shared point is computed from its owner's copy
/// with the owner's formula, so all faces see bitwise identical shared points even when the
/// copies' heights disagree.
class PointOwners {
 public:
  explicit PointOwners(const DisplacementField& ddf);

  /// @brief Owner face of point @p id, of which face @p f holds a copy.
  int owner(PointId id, int f) const {
    if (id < vertexCount_) return vertexOwner_[id];
    if (id < boundaryCount_) {
      const auto& sides = topology_->edgeFaces(static_cast<int>((id - vertexCount_) / perEdge_));
      return sides[1] < 0 ? sides[0] : std::min(sides[0], sides[1]);
    }
    return f;
  }
  /// @brief Ids below this value lie on support vertices or edges (shared candidates).
  PointId boundaryIdCount() const { return boundaryCount_; }

 private:
  const RasterTopology* topology_ = nullptr;
  std::vector<int> vertexOwner_;
  PointId vertexCount_ = 0;
  PointId boundaryCount_ = 0;
  PointId perEdge_ = 1;
};

/// @brief Canonical surface points q of all support-vertex and support-edge raster points, mm,
/// indexed by PointId (< owners.boundaryIdCount()); support vertices without a face keep their
/// support position.
std::vector<Vec3> canonicalBoundaryPoints(const DisplacementField& ddf, const PointOwners& owners);

/// @brief Surface points q of all raster points of face @p f in Raster order, mm, taking shared
/// points from @p boundary (see canonicalBoundaryPoints). @p out is resized to pointsPerFace().
void faceSurfacePoints(const DisplacementField& ddf, const std::vector<Vec3>& boundary, int f,
                       std::vector<Vec3>& out);

}  // namespace ddfcam::ddf::detail
