// SPDX-License-Identifier: MIT
// ddfcam (private): scanning the raster rows of one (support face, tool triangle) pair.
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/raster.h>

#include "cut_kernel.h"

namespace ddfcam::ddf::detail {

/// @brief Applies the kernel of @p mode to every raster point of face @p s whose stubble hits
/// tool triangle @p q (with @p forms its coefficients). With interval restriction, rows and
/// row intervals come from the V-projected corners of q, widened and grown until the exact
/// predicate fails, so the result equals the unrestricted scan; when a corner does not project
/// uniquely, the exact root intervals of sec. 5.2 are used on every row.
void scanPair(float* heights, const Raster& raster, const FaceCorners& s,
              const std::array<Vec3, 3>& q, const PairForms& forms, KernelMode mode,
              const DepthBufferParams& params, KernelCounts& counts);

}  // namespace ddfcam::ddf::detail
