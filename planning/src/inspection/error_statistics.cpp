// SPDX-License-Identifier: MIT
// ddfcam: tolerance classes, area-weighted statistics and histograms of error maps.
#include "error_region.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace detail {

void checkFieldSize(const ddf::DisplacementField& ddf, std::size_t size, const std::string& what) {
  if (size != ddf.allHeights().size()) {
    throw InvalidInput(what + ": " + std::to_string(size) + " values, expected " +
                       std::to_string(ddf.allHeights().size()));
  }
}

std::vector<int> regionFaces(const ddf::DisplacementField& ddf, std::span<const int> faces,
                             const std::string& what) {
  std::vector<int> out(faces.begin(), faces.end());
  if (out.empty()) {
    out.resize(ddf.faceCount());
    for (int f = 0; f < ddf.faceCount(); ++f) out[f] = f;
  }
  for (int f : out)
    if (f < 0 || f >= ddf.faceCount()) {
      throw InvalidInput(what + ": region face " + std::to_string(f) + " out of range [0, " +
                         std::to_string(ddf.faceCount()) + ")");
    }
  return out;
}

std::vector<WeightedValue> weightedRegionValues(const ddf::DisplacementField& ddf,
                                                std::span<const float> values,
                                                std::span<const int> faces,
                                                const std::string& what) {
  checkFieldSize(ddf, values.size(), what + ": field");
  const std::vector<int> region = regionFaces(ddf, faces, what);
  const std::vector<double> areas = rasterPointAreas(ddf);
  std::vector<WeightedValue> out;
  for (int f : region) {
    const std::size_t base = static_cast<std::size_t>(f) * ddf.pointsPerFace();
    for (std::size_t l = base; l < base + ddf.pointsPerFace(); ++l)
      if (std::isfinite(values[l]) && areas[l] > 0.0) out.push_back({values[l], areas[l], l});
  }
  return out;
}

double weightedQuantile(std::vector<WeightedValue> samples, double quantile) {
  std::sort(samples.begin(), samples.end(),
            [](const WeightedValue& a, const WeightedValue& b) { return a.value < b.value; });
  if (quantile >= 1.0) return samples.back().value;
  double total = 0.0;
  for (const WeightedValue& s : samples) total += s.weight;
  double cumulative = 0.0;
  for (const WeightedValue& s : samples) {
    cumulative += s.weight;
    if (cumulative >= quantile * total) return s.value;
  }
  return samples.back().value;
}

}  // namespace detail

void validateToleranceBand(const ToleranceBand& band) {
  if (!std::isfinite(band.lowerMm) || band.lowerMm > 0.0) {
    throw InvalidInput("tolerance band: lower bound " + std::to_string(band.lowerMm) +
                       " mm must be finite and <= 0");
  }
  if (!std::isfinite(band.upperMm) || band.upperMm < 0.0) {
    throw InvalidInput("tolerance band: upper bound " + std::to_string(band.upperMm) +
                       " mm must be finite and >= 0");
  }
}

ToleranceClass classify(double deviationMm, const ToleranceBand& band) {
  if (deviationMm > band.upperMm) return ToleranceClass::MaterialLeft;
  if (deviationMm < band.lowerMm) return ToleranceClass::Overcut;
  return ToleranceClass::InTolerance;
}

namespace {

// Distinct raster points (PointId) among the samples' copies.
std::size_t distinctPoints(const ddf::DisplacementField& ddf,
                           const std::vector<detail::WeightedValue>& samples) {
  std::vector<char> seen(ddf.topology().pointCount(), 0);
  std::size_t count = 0;
  for (const detail::WeightedValue& s : samples) {
    const int f = static_cast<int>(s.index / ddf.pointsPerFace());
    const ddf::RasterCoord c =
        ddf.topology().coord({f, static_cast<std::uint32_t>(s.index % ddf.pointsPerFace())});
    char& mark = seen[ddf.topology().id(f, c.i, c.k)];
    if (!mark) ++count;
    mark = 1;
  }
  return count;
}

// Area-weighted sigma about the mean in a second pass: sum(w x^2)/A - mean^2 cancels badly when
// the mean is large against the spread.
double weightedSigma(const std::vector<detail::WeightedValue>& samples, double mean, double area) {
  double spread = 0.0;
  for (const detail::WeightedValue& s : samples)
    spread += s.weight * (s.value - mean) * (s.value - mean);
  return std::sqrt(spread / area);
}

}  // namespace

ErrorStatistics errorStatistics(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                                const ToleranceBand& band, std::span<const int> faces) {
  validateToleranceBand(band);
  const auto samples =
      detail::weightedRegionValues(ddf, deviation.values, faces, "errorStatistics");
  if (samples.empty())
    throw InvalidInput("errorStatistics: no finite deviation with positive area in the region");
  ErrorStatistics stats;
  stats.maxMm = -std::numeric_limits<double>::infinity();
  stats.minMm = std::numeric_limits<double>::infinity();
  double sum = 0.0, sumSquares = 0.0, inside = 0.0, left = 0.0, over = 0.0;
  for (const detail::WeightedValue& s : samples) {
    stats.maxMm = std::max(stats.maxMm, s.value);
    stats.minMm = std::min(stats.minMm, s.value);
    stats.areaMm2 += s.weight;
    sum += s.weight * s.value;
    sumSquares += s.weight * s.value * s.value;
    const ToleranceClass cls = classify(s.value, band);
    (cls == ToleranceClass::MaterialLeft ? left
     : cls == ToleranceClass::Overcut    ? over
                                         : inside) += s.weight;
  }
  stats.points = distinctPoints(ddf, samples);
  stats.meanMm = sum / stats.areaMm2;
  stats.rmsMm = std::sqrt(sumSquares / stats.areaMm2);
  stats.sigmaMm = weightedSigma(samples, stats.meanMm, stats.areaMm2);
  stats.inTolerancePercent = 100.0 * inside / stats.areaMm2;
  stats.materialLeftPercent = 100.0 * left / stats.areaMm2;
  stats.overcutPercent = 100.0 * over / stats.areaMm2;
  return stats;
}

CrustClamping crustClamping(const ScalarField& deviation, const ddf::DisplacementField& produced,
                            std::span<const int> faces) {
  std::vector<detail::WeightedValue> clamped =
      detail::weightedRegionValues(produced, deviation.values, faces, "crustClamping");
  const std::vector<float>& heights = produced.allHeights();
  std::erase_if(clamped, [&](const detail::WeightedValue& s) {
    return !(s.value < 0.0 && heights[s.index] <= -1.0f);
  });
  CrustClamping out;
  for (const detail::WeightedValue& s : clamped) out.areaMm2 += s.weight;
  out.points = distinctPoints(produced, clamped);
  return out;
}

AreaHistogram errorHistogram(const ScalarField& deviation, const ddf::DisplacementField& ddf,
                             int bins, double lowerMm, double upperMm, std::span<const int> faces) {
  if (bins < 1) throw InvalidInput("errorHistogram: " + std::to_string(bins) + " bins, need >= 1");
  if (!std::isfinite(lowerMm) || !std::isfinite(upperMm) || !std::isfinite(upperMm - lowerMm) ||
      lowerMm >= upperMm) {
    throw InvalidInput("errorHistogram: invalid range [" + std::to_string(lowerMm) + ", " +
                       std::to_string(upperMm) + "] mm");
  }
  AreaHistogram out{lowerMm, upperMm, std::vector<double>(bins, 0.0), 0.0, 0.0};
  const double width = (upperMm - lowerMm) / bins;
  for (const auto& s :
       detail::weightedRegionValues(ddf, deviation.values, faces, "errorHistogram")) {
    if (s.value < lowerMm) {
      out.belowMm2 += s.weight;
    } else if (s.value > upperMm) {
      out.aboveMm2 += s.weight;
    } else {
      const int b = std::min(bins - 1, static_cast<int>((s.value - lowerMm) / width));
      out.areaMm2[b] += s.weight;
    }
  }
  return out;
}

}  // namespace ddfcam::planning
