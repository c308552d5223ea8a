// SPDX-License-Identifier: MIT
// ddfcam: a scalar value per raster point of a DDF (fields, error maps, deviations).
#pragma once

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

  bool operator==(const ScalarField&) const = default;
};

}  // namespace ddfcam::planning
