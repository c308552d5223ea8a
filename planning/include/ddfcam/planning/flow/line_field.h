// SPDX-License-Identifier: MIT
// ddfcam: tangent line fields on a DDF (tool flow fields, principal directions).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>

#include <vector>

namespace ddfcam::planning {

/// @brief A tangent line field on a DDF surface: one unit direction per stored raster point
/// copy, laid out like DisplacementField::allHeights() (face after face, Raster order), in the
/// part frame. A line field has no sign: v and -v are the same line, and every consumer must
/// give the same result when any entry is negated. A zero vector means "undefined" (umbilic,
/// singular or outside the field's region).
using LineField = std::vector<ddf::Vec3>;

/// @brief @p field turned by 90 degrees about the surface normal at every raster point (the
/// normal of the raster facet there, as surfaceNormal()): the transverse direction along which
/// families of paths are seeded (figs. 8.11/8.13). Sign-free like its input; zero where
/// @p field is zero.
/// @throws InvalidInput if the field is not sized like ddf.allHeights().
LineField transverseField(const ddf::DisplacementField& ddf, const LineField& field);

}  // namespace ddfcam::planning
