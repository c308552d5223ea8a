// SPDX-License-Identifier: MIT
// ddfcam: tangent line fields on a DDF (tool flow fields, principal directions).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <vector>

namespace ddfcam::planning {

/// @brief A tangent line field on a DDF surface: one unit direction per stored raster point
/// copy, laid out like DisplacementField::allHeights() (face after face, Raster order), in the
/// part frame. A line field has no sign: v and -v are the same line, and every consumer must
/// give the same result when any entry is negated. A zero vector means "undefined" (umbilic,
/// singular or outside the field's region).
using LineField = std::vector<ddf::Vec3>;

}  // namespace ddfcam::planning
