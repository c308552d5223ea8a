// SPDX-License-Identifier: MIT
// ddfcam: range and histogram of a scalar field, for colour scales and the histogram plot.
#include <ddfcam/error.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ddfcam::planning {

std::optional<FieldRange> fieldRange(std::span<const float> values) {
  FieldRange range;
  range.min = std::numeric_limits<double>::infinity();
  range.max = -std::numeric_limits<double>::infinity();
  for (const float x : values) {
    if (!std::isfinite(x)) {
      ++range.invalidCount;
      continue;
    }
    range.min = std::min(range.min, static_cast<double>(x));
    range.max = std::max(range.max, static_cast<double>(x));
    ++range.finiteCount;
  }
  if (range.finiteCount == 0) return std::nullopt;
  return range;
}

std::optional<FieldRange> robustFieldRange(std::span<const float> values,
                                           const RobustRangeParams& params) {
  if (!(params.lowerFraction >= 0.0 && params.lowerFraction < 0.5 && params.upperFraction >= 0.0 &&
        params.upperFraction < 0.5 && params.outlierSpanRatio >= 1.0)) {
    throw InvalidInput("robustFieldRange: fractions must lie in [0, 0.5) and the ratio be >= 1");
  }
  std::optional<FieldRange> full = fieldRange(values);
  if (!full) return full;
  std::vector<float> finite;
  finite.reserve(full->finiteCount);
  for (const float x : values)
    if (std::isfinite(x)) finite.push_back(x);
  const auto last = static_cast<double>(finite.size() - 1);
  auto quantile = [&](double q) {
    const auto at = finite.begin() + static_cast<std::ptrdiff_t>(std::floor(q * last));
    std::nth_element(finite.begin(), at, finite.end());
    return static_cast<double>(*at);
  };
  const double lo = quantile(params.lowerFraction);
  const double hi = quantile(1.0 - params.upperFraction);
  // A degenerate quantile range (most values equal) says nothing about outliers.
  if (hi > lo && full->max - full->min > params.outlierSpanRatio * (hi - lo))
    full->min = lo, full->max = hi;
  return full;
}

Histogram histogram(std::span<const float> values, int bins, double lo, double hi) {
  if (bins < 1 || !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi) ||
      !std::isfinite(hi - lo)) {
    std::ostringstream msg;
    msg << "histogram: need bins >= 1 and finite lo < hi, got bins " << bins << ", lo " << lo
        << ", hi " << hi;
    throw InvalidInput(msg.str());
  }
  Histogram out;
  out.lo = lo;
  out.hi = hi;
  out.counts.assign(static_cast<std::size_t>(bins), 0);
  const double w = out.binWidth();
  for (const float f : values) {
    const double x = f;
    if (!std::isfinite(x)) {
      ++out.invalid;
    } else if (x < lo) {
      ++out.below;
    } else if (x > hi) {
      ++out.above;
    } else {
      // The quotient may round across a bin edge; the edges lo + b w as documented decide.
      int b = std::clamp(static_cast<int>((x - lo) / w), 0, bins - 1);
      while (b > 0 && x < lo + b * w) --b;
      while (b < bins - 1 && x >= lo + (b + 1) * w) ++b;
      ++out.counts[b];
    }
  }
  return out;
}

}  // namespace ddfcam::planning
