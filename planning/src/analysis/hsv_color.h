// SPDX-License-Identifier: MIT
// ddfcam: HSV to RGB for region display colours (private).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace ddfcam::planning::detail {

/// @brief RGB in [0, 1] of hue @p hue01 (turns, wrapped into [0, 1)), saturation @p s and
/// value @p v, both in [0, 1].
inline std::array<float, 3> hsvColor(double hue01, double s, double v) {
  const double hue = std::fmod(hue01, 1.0) * 6.0;
  const double c = s * v;
  const double x = c * (1.0 - std::abs(std::fmod(hue, 2.0) - 1.0));
  const double r[6] = {c, x, 0, 0, x, c}, g[6] = {x, c, c, x, 0, 0}, b[6] = {0, 0, x, c, c, x};
  const int sector = std::min(5, static_cast<int>(hue));
  const double m = v - c;
  return {static_cast<float>(r[sector] + m), static_cast<float>(g[sector] + m),
          static_cast<float>(b[sector] + m)};
}

}  // namespace ddfcam::planning::detail
