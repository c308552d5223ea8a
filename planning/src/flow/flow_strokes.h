// SPDX-License-Identifier: MIT
// ddfcam: internal data term of user-drawn flow directions (strokes) on the raster points.
#pragma once

#include "field_frames.h"

#include <complex>
#include <cstdint>
#include <vector>

namespace ddfcam::planning::detail {

/// Per distinct raster point: the doubled angle of the nearest stroke segment's tangent
/// projected onto the point's tangent plane, or 0 where no segment applies or the projection
/// vanishes.
using StrokeTargets = std::vector<std::complex<double>>;

/// @brief Stroke targets of the points with @p active[p] != 0. With @p radiusMm > 0 only points
/// within that distance (mm) of a segment get a target (a spatial grid keeps this fast);
/// with radiusMm <= 0 every active point takes its nearest segment (brute force).
/// The nearest segment is chosen independently of the order of the points of a stroke and of
/// the order of the strokes: distances are computed on canonically ordered endpoints and ties
/// break on those endpoints.
/// @throws InvalidInput if there is no stroke with two distinct points or a point is not finite.
StrokeTargets strokeTargets(const SurfaceFrames& frames, const std::vector<std::uint8_t>& active,
                            const std::vector<std::vector<ddf::Vec3>>& strokes, double radiusMm);

/// @brief Mean length of the lattice edges of @p frames, mm (0 without edges).
double meanEdgeLength(const SurfaceFrames& frames);

}  // namespace ddfcam::planning::detail
