// SPDX-License-Identifier: MIT
// ddfcam: displacement "stubbles" along the vectors of raster points, as drawn in the figures.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <vector>

namespace ddfcam::ddf {

/// @brief Which part of the line g + h v a stubble covers.
enum class StubbleRange {
  BaseToSurface,  ///< from the support point g (h = 0) to the surface point q (h = height)
  FullCrust       ///< the whole crust, h = -1 .. +1
};

/// @brief Parameters of stubbleLines().
struct StubbleLinesParams {
  /// Lattice stride: a raster point is drawn when its coordinates i and k in its owner face
  /// (the lowest-index face holding a copy) are multiples of stride. Values < 1 act as 1.
  /// Default 4.
  int stride = 4;
  /// Extent of each stubble. Default BaseToSurface.
  StubbleRange range = StubbleRange::BaseToSurface;
};

/// @brief Line segments from g + h_lo v to g + h_hi v, one per drawn raster point, mm, part
/// frame; all three arrays have one entry per segment, ordered by owner face then raster index.
struct StubbleLines {
  std::vector<Vec3> from;      ///< g + h_lo v
  std::vector<Vec3> to;        ///< g + h_hi v
  std::vector<PointId> point;  ///< raster point of the segment
};

/// @brief Stubbles of every stride-th raster point (each distinct point at most once, computed
/// from its owner copy), for views that show the displacement vectors like the dissertation's
/// figures.
/// @throws nothing beyond std::bad_alloc.
StubbleLines stubbleLines(const DisplacementField& ddf, const StubbleLinesParams& params = {});

}  // namespace ddfcam::ddf
