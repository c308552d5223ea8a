// SPDX-License-Identifier: MIT
// ddfcam: indexing of the triangular height raster on one support triangle (dissertation ch. 3).
#pragma once

#include <cstddef>

namespace ddfcam::ddf {

/// @brief The raster of resolution m on a support triangle (p1, p2, p3): points g_ijk =
/// (i p1 + j p2 + k p3)/n with n = m - 1 and i + j + k = n. Stored row by row: row k (constant
/// barycentric mu3 = k/n) holds n - k + 1 points ordered by i = 0..n-k (j = n - k - i), so a
/// step along a row is (mu1, mu2) += (1/n, -1/n) as in sec. 5.2.
struct Raster {
  int m = 2;  ///< resolution: points per support edge, >= 2

  /// @brief n = m - 1, the number of raster steps along an edge.
  constexpr int steps() const { return m - 1; }
  /// @brief Number of raster points on one support triangle, m (m + 1) / 2.
  constexpr std::size_t pointCount() const { return static_cast<std::size_t>(m) * (m + 1) / 2; }
  /// @brief Offset of the first point of row k.
  constexpr std::size_t rowOffset(int k) const {
    const std::size_t n = steps();
    return static_cast<std::size_t>(k) * (n + 1) - static_cast<std::size_t>(k) * (k - 1) / 2;
  }
  /// @brief Number of points in row k.
  constexpr int rowLength(int k) const { return steps() - k + 1; }
  /// @brief Linear index of point (i, j = n - i - k, k).
  constexpr std::size_t index(int i, int k) const { return rowOffset(k) + i; }
};

/// @brief Integer barycentric raster coordinates of one raster point, i + j + k = n.
struct RasterCoord {
  int i = 0;
  int j = 0;
  int k = 0;
  friend constexpr bool operator==(const RasterCoord&, const RasterCoord&) = default;
};

}  // namespace ddfcam::ddf
