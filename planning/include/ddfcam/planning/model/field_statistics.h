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

/// @brief Options of robustFieldRange().
struct RobustRangeParams {
  /// Fraction of the finite values allowed below the range (default 0.01).
  double lowerFraction = 0.01;
  /// Fraction of the finite values allowed above the range (default 0.01).
  double upperFraction = 0.01;
  /// The quantile range replaces the full range only when the full range is more than this
  /// many times wider, i.e. when a few outliers would wash out the colours (default 2).
  double outlierSpanRatio = 2.0;
};

/// @brief Range for an automatic colour scale: the full range of the finite values, unless a
/// few outliers make it more than params.outlierSpanRatio times wider than the range between
/// the lowerFraction and (1 - upperFraction) quantiles, which is then returned (e.g. curvature
/// spikes at the sharp edges of a scanned part). A degenerate quantile range (most values
/// equal) keeps the full range. finiteCount and invalidCount count all values.
/// @return std::nullopt if there is no finite value.
/// @throws InvalidInput if a fraction is outside [0, 0.5) or the ratio is below 1.
std::optional<FieldRange> robustFieldRange(std::span<const float> values,
                                           const RobustRangeParams& params = {});

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
