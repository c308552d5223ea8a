// SPDX-License-Identifier: MIT
// ddfcam: private helpers of the error maps: iterating the raster point copies of a face region.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief Throws InvalidInput (prefixed by @p what) unless @p values is sized like the heights.
void checkFieldSize(const ddf::DisplacementField& ddf, std::size_t size, const std::string& what);

/// @brief The faces of a region: @p faces checked against the face range, or all faces if empty.
/// @throws InvalidInput naming the first face out of range.
std::vector<int> regionFaces(const ddf::DisplacementField& ddf, std::span<const int> faces,
                             const std::string& what);

/// @brief A finite value of a region with its area weight (mm^2) and its copy's flat index.
struct WeightedValue {
  double value = 0.0;
  double weight = 0.0;
  std::size_t index = 0;
};

/// @brief The copies of the region's faces with a finite value and a positive area weight.
std::vector<WeightedValue> weightedRegionValues(const ddf::DisplacementField& ddf,
                                                std::span<const float> values,
                                                std::span<const int> faces,
                                                const std::string& what);

/// @brief The value at which the cumulative weight of @p samples (sorted here) first reaches
/// @p quantile of the total weight; quantile 1 gives the maximum. @p samples must not be empty.
double weightedQuantile(std::vector<WeightedValue> samples, double quantile);

}  // namespace ddfcam::planning::detail
