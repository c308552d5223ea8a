// SPDX-License-Identifier: MIT
// ddfcam: scalar fields every part has (height, material removed), laid out like the heights.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/project.h>
#include <ddfcam/progress.h>

#include <span>

namespace ddfcam::planning {

/// @brief Height h of every raster point in units of its vector length (name "height (h)",
/// dimensionless, signed: h = +-1 are the crust faces).
ScalarField heightField(const ddf::DisplacementField& ddf);

/// @brief Signed distance of every raster point's surface point from its support point along
/// the stubble, h |v|, mm (name "height above support", unit "mm", signed).
ScalarField heightMmField(const ddf::DisplacementField& ddf);

/// @brief Material removed at every raster point since @p referenceHeights (e.g. the "stock"
/// state): (h_ref - h) |v|, mm, >= 0 where material was only removed (name "material
/// removed", unit "mm", not signed).
/// @param referenceHeights heights laid out like ddf.allHeights().
/// @throws InvalidInput if referenceHeights has the wrong size.
ScalarField materialRemovedField(const ddf::DisplacementField& ddf,
                                 std::span<const float> referenceHeights);

/// @brief Signed distance (mm) of every raster point's surface point from @p reference (e.g.
/// the mesh the part was converted from, or a design surface): positive on the side the
/// reference's triangle normals point to (outside, stock left), negative inside (gouge).
/// Exact point-to-triangle distances through a bounding-volume hierarchy over @p reference;
/// the sign is taken from the nearest triangle's (angle-weighted pseudo-) normal. Name
/// "deviation from mesh", unit "mm", signed, NaN where a height is not finite. Parallel over
/// faces (see MeshDistance, which answers single queries).
/// @param progress fraction of faces done, and cancellation (at least every ~0.1 s).
/// @throws InvalidInput if @p reference has no triangles; Cancelled through @p progress.
ScalarField deviationField(const ddf::DisplacementField& ddf, const ddf::TriangleMesh& reference,
                           const ProgressCallback& progress = {});

}  // namespace ddfcam::planning
