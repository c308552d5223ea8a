// SPDX-License-Identifier: MIT
// ddfcam: internal: a face's height raster extended by a band of ghost heights across its edges.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <vector>

namespace ddfcam::planning::detail {

/// @brief Heights of one support face on its raster lattice extended by a band of b steps
/// beyond every edge: lattice (j, k) with j, k >= -b and i = n - j - k >= -b, in units of the
/// vector of the face's own (affinely extended) parametrization g + h v.
struct ExtendedRaster {
  int n = 0;  ///< raster steps m - 1
  int b = 0;  ///< band width, raster steps
  int w = 0;  ///< row stride n + 2 b + 1
  std::vector<double> h;

  double at(int j, int k) const { return h[static_cast<std::size_t>(j + b) * w + (k + b)]; }
  double& at(int j, int k) { return h[static_cast<std::size_t>(j + b) * w + (k + b)]; }
};

/// @brief Fills @p out for face @p face with band width @p band: the face's own heights
/// inside; outside, the height t at which the face's extended stubble line g + t v meets the
/// surface of a neighbouring face (that face's heights interpolated by a polynomial of degree
/// min(6, m - 1) over a raster sub-triangle, solved by Newton's method), so that ghost heights
/// are accurate to O(spacing^7) and fourth-order stencils keep their order across seams. Where
/// no neighbour is met (open boundary) the face's own boundary cubic is extrapolated. Requires
/// m >= 4 and 1 <= band <= m - 1.
void fillExtendedRaster(const ddf::DisplacementField& ddf, int face, int band, ExtendedRaster& out);

}  // namespace ddfcam::planning::detail
