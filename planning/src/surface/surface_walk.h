// SPDX-License-Identifier: MIT
// ddfcam: short walks on a DDF surface across support seams (private to planning).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace ddfcam::planning::detail {

/// @brief The surface location near @p q found by walking the support faces from @p face: q is
/// V-projected onto the face; while its foot lies outside, the walk moves to the neighbour
/// across the edge with the most negative barycentric coordinate.
/// @return std::nullopt at an open support edge, at a face outside @p faceMask (non-empty mask,
/// zero entry), when no V-projection exists or the walk does not settle within a few faces.
std::optional<ddf::SurfaceLocation> locateNear(const ddf::DisplacementField& ddf, int face,
                                               const ddf::Vec3& q,
                                               const std::vector<std::uint8_t>& faceMask);

/// @brief Walks from @p start along the surface, starting in the tangent direction @p dir
/// (projected onto the tangent plane and carried along by re-projection at every sub-step),
/// until the straight distance from start.point is @p distanceMm (within ~1e-3 of it).
/// @param subSteps sub-steps of the walk (>= 1); each is re-located with locateNear().
/// @return std::nullopt if the walk leaves the surface or the allowed faces (see locateNear).
std::optional<ddf::SurfaceLocation> walkOnSurface(const ddf::DisplacementField& ddf,
                                                  const ddf::SurfaceLocation& start,
                                                  const ddf::Vec3& dir, double distanceMm,
                                                  int subSteps,
                                                  const std::vector<std::uint8_t>& faceMask);

}  // namespace ddfcam::planning::detail
