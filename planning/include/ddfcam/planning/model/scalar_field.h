// SPDX-License-Identifier: MIT
// ddfcam: a scalar value per raster point of a DDF (fields, error maps, deviations).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief A scalar per raster point of the part, laid out like the heights
/// (DisplacementField::allHeights(): face after face, Raster order; F * pointsPerFace values).
/// Copies of a shared raster point may differ (each face keeps its own); NaN marks "no value".
struct ScalarField {
  std::string name;           ///< e.g. "height", "material removed"
  std::string unit;           ///< e.g. "mm", "1/mm"; empty for dimensionless
  bool isSigned = false;      ///< values of both signs are meaningful (use a diverging map)
  std::vector<float> values;  ///< F * pointsPerFace values
  /// Digest of the part heights the values were computed from (planning::markComputedFrom);
  /// when the part's heights differ the field is stale (planning::isStale). Empty for a
  /// field that does not depend on the heights or whose origin is unknown (never stale).
  std::optional<std::uint64_t> heightsDigest;

  bool operator==(const ScalarField&) const = default;
};

}  // namespace ddfcam::planning
