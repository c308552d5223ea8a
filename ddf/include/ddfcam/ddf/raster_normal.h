// SPDX-License-Identifier: MIT
// ddfcam: the unit normal of a DDF's represented raster surface at a raster point.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

namespace ddfcam::ddf {

/// @brief Unit normal of the raster surface of @p ddf at raster point (i, k) of face @p f, on
/// the side of the vector there: the area-weighted normal of the raster triangles of the face
/// around the point (6 inside the face, fewer on its border), built from the represented
/// surface points q = g + h v. Where no raster triangle has area (the corner of an m = 2
/// raster, or collapsed heights) the unit vector direction is returned. This is the normal
/// along which a stock allowance raises the surface and along which the crust's reach is
/// measured.
/// @return unit vector, part frame.
Vec3 rasterNormal(const DisplacementField& ddf, int f, int i, int k);

}  // namespace ddfcam::ddf
