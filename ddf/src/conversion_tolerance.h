// SPDX-License-Identifier: MIT
// ddfcam: the tolerance tries of a mesh conversion with a reduced support.
#pragma once

#include <ddfcam/ddf/mesh_conversion.h>

#include <functional>

namespace ddfcam::ddf::detail {

/// @brief One conversion of the input with @p params (the resolution and edge bound of one try).
using SingleConversion = std::function<ConversionResult(const ConversionParams& params)>;

/// @brief Median edge length of the input triangles, mm (0 without a finite positive edge):
/// the input's own sampling of its surface, the first target raster spacing of a reduced
/// support for a tolerance.
double medianEdgeMm(const TriangleMesh& mesh);

/// @brief A reduced support for params.toleranceMm (> 0): tries reductions with support edges
/// bounded by (m - 1) x @p spacingMm at m = params.resolution, each raising m on its support
/// until the tolerance holds or stops paying, and then shortening the edge bound; returns the
/// best try, its accuracy.note saying why when the tolerance is not met (and logged as a
/// warning). @p once runs one try; its result must have raised m already.
/// @throws Cancelled through params.progress (via @p once).
ConversionResult convertReducedForTolerance(const ConversionParams& params, double spacingMm,
                                            const SingleConversion& once);

}  // namespace ddfcam::ddf::detail
