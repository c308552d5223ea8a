// SPDX-License-Identifier: MIT
// ddfcam: the range of values a path reader accepts, checked after unit conversion.
#include "path_file_limits.h"

#include <cmath>
#include <cstdio>

namespace ddfcam::io::detail {
namespace {

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

std::optional<std::string> positionProblem(const ddf::Vec3& positionMm) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const double c = positionMm[k];
    if (!std::isfinite(c)) {
      return std::string("position ") + kAxes[k] + " is not finite in mm (" + shortNumber(c) +
             " after unit conversion)";
    }
    if (std::abs(c) > kMaxCoordinateMm) {
      return std::string("position ") + kAxes[k] + " = " + shortNumber(c) +
             " mm is beyond +-1e12 mm; not a machine position";
    }
  }
  return std::nullopt;
}

std::optional<std::string> feedProblem(double feedMmPerMin) {
  if (!std::isfinite(feedMmPerMin)) {
    return "feed is not finite in mm/min (" + shortNumber(feedMmPerMin) + " after unit conversion)";
  }
  if (feedMmPerMin < 0.0) return "negative feed " + shortNumber(feedMmPerMin) + " mm/min";
  if (feedMmPerMin > kMaxFeedMmPerMin) {
    return "feed " + shortNumber(feedMmPerMin) + " mm/min is beyond 1e12 mm/min";
  }
  return std::nullopt;
}

double safeLength(const ddf::Vec3& v) {
  if (!v.allFinite()) return std::nan("");
  const double largest = v.cwiseAbs().maxCoeff();
  if (largest == 0.0) return 0.0;
  return largest * (v / largest).norm();
}

std::optional<ddf::Vec3> unitDirection(const ddf::Vec3& v, double minLength) {
  if (!v.allFinite()) return std::nullopt;
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return std::nullopt;
  const ddf::Vec3 scaled = v / largest;  // largest component +-1: the norm is in [1, sqrt 3]
  const double norm = scaled.norm();
  if (!(largest * norm > minLength)) return std::nullopt;
  const ddf::Vec3 unit = scaled / norm;
  if (!unit.allFinite()) return std::nullopt;
  return unit;
}

}  // namespace ddfcam::io::detail
