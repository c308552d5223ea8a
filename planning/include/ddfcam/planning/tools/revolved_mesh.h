// SPDX-License-Identifier: MIT
// ddfcam: closed triangle meshes of solids of revolution from a 2D profile polyline.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <span>

namespace ddfcam::planning {

/// @brief A point of a 2D profile in the half plane of a solid of revolution: @p axial is the
/// coordinate along the rotation axis, @p radial the distance from it (>= 0), both in mm.
struct ProfilePoint {
  double axial = 0.0;   ///< along the axis, mm (default 0)
  double radial = 0.0;  ///< distance from the axis, mm, >= 0 (default 0)

  bool operator==(const ProfilePoint&) const = default;
};

/// @brief The tool-frame axis a profile is revolved about.
/// - X: point (a, r) at angle t maps to (a, r cos t, r sin t) (wheels; t = 270 deg is -z);
/// - Z: point (a, r) at angle t maps to (r cos t, r sin t, a) (cutters, balls).
enum class RevolveAxis { X, Z };

/// @brief Revolves @p profile about @p axis into a closed, outward-oriented, watertight
/// triangle mesh (every edge is shared by exactly two triangles, in opposite directions).
///
/// The profile is an open polyline whose first and last points lie on the axis (radial 0;
/// they become the two poles, closing the solid) and whose other points have radial > 0. It
/// may run in either direction and must not cross itself; the orientation of the triangles is
/// chosen from the sign of the area it encloses with the axis. Each interior point becomes a
/// ring of @p segments vertices at angles t_j = 2 pi j / segments (exactly on the surface of
/// revolution); between two rings lie 2 @p segments triangles, between a pole and a ring
/// @p segments triangles (so a 4-point profile gives 4 @p segments triangles, as
/// makeCylinderTool).
/// @throws InvalidInput if the profile has fewer than 3 points, does not start and end on the
/// axis, has an interior point with radial <= 0 or a non-finite coordinate, two equal
/// consecutive points, a zero enclosed area, or if @p segments < 3.
ddf::TriangleMesh revolveProfile(std::span<const ProfilePoint> profile, RevolveAxis axis,
                                 int segments);

/// @brief Appends the vertices and triangles of @p part to @p mesh (indices shifted), e.g. to
/// collect several closed components into one mesh.
void appendMesh(ddf::TriangleMesh& mesh, const ddf::TriangleMesh& part);

}  // namespace ddfcam::planning
