// SPDX-License-Identifier: MIT
// ddfcam: range and histogram of a scalar field, for colour scales and the histogram plot.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief Extent of the finite values of a field.
struct FieldRange {
  double min = 0.0;              ///< smallest finite value
  double max = 0.0;              ///< largest finite value
  std::size_t finiteCount = 0;   ///< finite values
  std::size_t invalidCount = 0;  ///< NaN or infinite values (ignored)
};

/// @brief Range of the finite values of @p values.
/// @return std::nullopt if there is no finite value.
std::optional<FieldRange> fieldRange(std::span<const float> values);

/// @brief Counts of values in equal bins over [lo, hi].
struct Histogram {
  double lo = 0.0;                  ///< lower edge of bin 0
  double hi = 1.0;                  ///< upper edge of the last bin
  std::vector<std::size_t> counts;  ///< #bins counts; bin b is [lo + b w, lo + (b+1) w), the
                                    ///< last bin also holds hi (w = (hi - lo) / bins)
  std::size_t below = 0;            ///< finite values < lo
  std::size_t above = 0;            ///< finite values > hi
  std::size_t invalid = 0;          ///< NaN or infinite values
  /// @brief Bin width w.
  double binWidth() const { return counts.empty() ? 0.0 : (hi - lo) / counts.size(); }
  /// @brief Centre of bin @p b.
  double binCentre(int b) const { return lo + (b + 0.5) * binWidth(); }
};

/// @brief Histogram of @p values with @p bins equal bins over [lo, hi].
/// @throws InvalidInput if bins < 1, lo, hi or hi - lo is not finite, or lo >= hi.
Histogram histogram(std::span<const float> values, int bins, double lo, double hi);

}  // namespace ddfcam::planning
