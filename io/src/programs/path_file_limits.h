// SPDX-License-Identifier: MIT
// ddfcam: the range of values a path reader accepts, checked after unit conversion.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <optional>
#include <string>

namespace ddfcam::io::detail {

/// Largest |coordinate| a path reader accepts, mm (1e12 mm = 1,000 km): beyond any machine, and
/// far enough inside the double range that differences, squared lengths and unit conversions of
/// accepted positions stay finite.
inline constexpr double kMaxCoordinateMm = 1e12;

/// Largest feed a path reader accepts, mm/min (1e12, about 17,000 km/s).
inline constexpr double kMaxFeedMmPerMin = 1e12;

/// @brief Why @p positionMm (mm, after unit conversion) cannot be a point of a program: a
/// coordinate not finite or beyond kMaxCoordinateMm. Nothing if it can.
std::optional<std::string> positionProblem(const ddf::Vec3& positionMm);

/// @brief Why @p feedMmPerMin (mm/min, after unit conversion) cannot be a feed: not finite,
/// negative or beyond kMaxFeedMmPerMin. Nothing if it can.
std::optional<std::string> feedProblem(double feedMmPerMin);

/// @brief The unit vector along @p v, computed without overflow or underflow (components are
/// scaled by the largest one first, so (0, -1e308, 1) gives (0, -1, 1e-308)).
/// @return nothing if a component is not finite or the length of @p v is <= @p minLength.
std::optional<ddf::Vec3> unitDirection(const ddf::Vec3& v, double minLength);

/// @brief The length of @p v if it is finite; +inf if it overflows (no intermediate overflow:
/// (1e200, 1e200, 0) gives 1.41e200), NaN if a component is not finite.
double safeLength(const ddf::Vec3& v);

}  // namespace ddfcam::io::detail
