// SPDX-License-Identifier: MIT
// ddfcam: warps of a DDF by its vectors and its support, and meshes of morph positions (ch. 9).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <span>

namespace ddfcam::ddf {

/// @brief Multiplies every displacement vector of @p ddf by @p factor, heights unchanged
/// (dissertation fig. 9.2 b/c): the details (engravings) get @p factor times their depth along
/// the vectors, every represented point q = g + h v moves to g + factor h v.
///
/// A negative factor reverses the vectors and so mirrors the details through the support
/// (fig. 9.2 c). The vectors then point to the back side of the support: this breaks
/// constraint 1 of the DDF (vectors on the front side, sec. 3) — crusts, pseudo-normal repair
/// and the depth buffer assume it, so use such a field for display and export only, or scale it
/// back before cutting.
/// @throws InvalidInput if @p factor is 0 or not finite (a zero field represents nothing).
void scaleVectors(DisplacementField& ddf, double factor);

/// @brief Frame and radius of the cylinder warp (fig. 9.2 d).
///
/// Bend frame: origin o, unit bend direction x (the arc-length direction), unit axis direction
/// y (orthonormalised against x), normal z = x cross y. A point with bend-frame coordinates
/// (x, y, z) goes to o + (R + z) sin(x/R) x_hat + y y_hat + ((R + z) cos(x/R) - R) z_hat, i.e.
/// the plane z = 0 is wrapped onto the cylinder of radius |R| whose axis is parallel to y
/// through o - R z_hat; arc length along x is preserved and heights above the plane become
/// radial offsets. R > 0 bends the front side (+z) outward (convex), R < 0 inward (concave).
struct CylinderWarpParams {
  double radiusMm = 100.0;             ///< signed cylinder radius R, mm, nonzero. Default 100.
  Vec3 originMm = Vec3::Zero();        ///< o: the point that stays fixed, mm. Default 0.
  Vec3 bendDirection = Vec3::UnitX();  ///< x_hat, part frame. Default +x.
  Vec3 axisDirection = Vec3::UnitY();  ///< y_hat, part frame. Default +y.
};

/// @brief Moves the support vertices of @p ddf onto the cylinder of @p params (fig. 9.2 d) and
/// rotates every vector with the local frame (rotation by x/R about the axis direction), so the
/// details keep their depth along the cylinder's normal; heights unchanged. Intended for a
/// (near) planar support in the bend frame's z = 0 plane; vertices off that plane keep their z
/// as a radial offset. Raster points between vertices lie on the chords (sagitta up to
/// L^2 / (8 |R|) for a support edge of length L along x).
/// @throws InvalidInput if R is 0 or not finite, the directions are zero or parallel, a vertex
/// has R + z <= 0 (it would cross the axis) or the support spans more than 2 pi |R| along x (it
/// would overlap itself).
void mapSupportOntoCylinder(DisplacementField& ddf, const CylinderWarpParams& params);

/// @brief Like morphMesh(), with the raster point of every vertex (to colour per-point fields).
/// Vertices are the distinct raster points that have a finite position; a shared point takes the
/// position of its copy in the lowest-index face (as extractRasterMesh()).
/// @param layout the DDF whose support, connectivity and resolution define the lattice.
/// @param positions one position per raster point copy (layout.allHeights() order), mm; NaN
/// coordinates mark points to leave out.
/// @throws InvalidInput if positions.size() != layout.allHeights().size().
RasterMesh morphRasterMesh(const DisplacementField& layout, std::span<const Vec3> positions);

/// @brief The raster-lattice triangulation (as extractRasterMesh()) of arbitrary per-copy
/// positions, e.g. ddf::morphPositions() of a deformation sequence or blended points s + d h v:
/// (m-1)^2 triangles per support face, oriented like the face, shared points welded; triangles
/// with a NaN corner are dropped and points with a NaN position get no vertex. With the positions
/// layout.surfacePoint(f, i, k) it reproduces extractRasterMesh(layout).mesh exactly. Used to
/// display and export any intermediate surface.
/// @throws InvalidInput if positions.size() != layout.allHeights().size().
TriangleMesh morphMesh(const DisplacementField& layout, std::span<const Vec3> positions);

/// @brief The represented surface points q = g + h v of @p heights over @p layout's support and
/// vectors, one per raster point copy (allHeights() order), mm — the positions morphMesh()
/// takes for a height field such as morphHeights() of shared_support_shapes.h. NaN heights give
/// NaN points.
/// @throws InvalidInput if heights.size() != layout.allHeights().size().
std::vector<Vec3> heightPositions(const DisplacementField& layout, std::span<const float> heights);

}  // namespace ddfcam::ddf
