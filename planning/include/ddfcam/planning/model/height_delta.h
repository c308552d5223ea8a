// SPDX-License-Identifier: MIT
// ddfcam: the compact difference between two height states, for bounded-memory undo.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <cstddef>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief The faces whose heights differ between two states of one DDF, with both versions of
/// those faces only. A grinding pass touches a small part of a large field, so an undo step
/// costs memory in proportion to what changed, not to the field.
class HeightDelta {
 public:
  /// @brief An empty delta made for no field: apply() and revert() leave any field unchanged.
  HeightDelta() = default;
  /// @brief Difference from @p before to @p after (both laid out like allHeights(), faces of
  /// @p pointsPerFace values). Faces are compared bitwise (NaN payloads included).
  /// @throws InvalidInput if the sizes differ or are not a multiple of pointsPerFace.
  static HeightDelta between(std::span<const float> before, std::span<const float> after,
                             std::size_t pointsPerFace);

  /// @brief Sets the changed faces of @p ddf to their "after" heights.
  /// @throws InvalidInput if @p ddf does not have the layout the delta was made for.
  void apply(ddf::DisplacementField& ddf) const;
  /// @brief Sets the changed faces of @p ddf to their "before" heights.
  /// @throws InvalidInput as apply().
  void revert(ddf::DisplacementField& ddf) const;

  /// @brief Number of faces that differ.
  std::size_t changedFaces() const { return faces_.size(); }
  /// @brief True if the two states were identical.
  bool empty() const { return faces_.empty(); }
  /// @brief Bytes held (face list and both height copies).
  std::size_t memoryBytes() const;

 private:
  void write(ddf::DisplacementField& ddf, const std::vector<float>& source) const;

  std::size_t pointsPerFace_ = 0;
  std::size_t totalValues_ = 0;
  std::vector<int> faces_;     // ascending
  std::vector<float> before_;  // faces_.size() * pointsPerFace_
  std::vector<float> after_;
};

}  // namespace ddfcam::planning
