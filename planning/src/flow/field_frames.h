// SPDX-License-Identifier: MIT
// ddfcam: internal tangent frames and raster triangles of a DDF surface for line fields.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

namespace ddfcam::planning::detail {

/// One triangle of the raster lattice of a support face: its face, its three stored copies
/// (local raster indices in that face) and their point ids, counter-clockwise like the face.
struct RasterTriangle {
  int face = 0;
  std::array<std::uint32_t, 3> local{};
  std::array<ddf::PointId, 3> point{};
};

/// The represented surface as a triangle mesh over the distinct raster points, with a tangent
/// frame (axis1, axis2, normal; right-handed, normal on the orientation side of the support) at
/// every point. Lines are handled as doubled angles in these frames.
struct SurfaceFrames {
  std::vector<ddf::Vec3> position;  ///< per PointId, mm (the first stored copy)
  std::vector<ddf::Vec3> normal;    ///< per PointId: area-weighted raster triangle normal
  std::vector<ddf::Vec3> axis1;     ///< per PointId: unit tangent, orthogonal to normal
  std::vector<ddf::Vec3> axis2;     ///< per PointId: normal x axis1
  std::vector<double> area;         ///< per PointId: a third of the incident triangles' area, mm^2
  std::vector<ddf::PointId> idOfCopy;              ///< per stored copy (allHeights() layout)
  std::vector<RasterTriangle> triangles;           ///< all raster triangles, face after face
  std::vector<std::array<ddf::PointId, 2>> edges;  ///< distinct lattice edges (p < q)
};

/// @brief Builds the frames of @p ddf (positions q = g + h v of the raster points).
SurfaceFrames buildSurfaceFrames(const ddf::DisplacementField& ddf);

/// @brief Angle of the projection of @p d onto the tangent plane of point @p p, measured from
/// axis1 towards axis2, in (-pi, pi]; a zero projection gives 0.
double tangentAngle(const SurfaceFrames& frames, ddf::PointId p, const ddf::Vec3& d);

/// @brief Discrete Levi-Civita transport angle from point @p p to point @p q along their edge:
/// the edge direction p->q seen in p's frame maps onto the same direction seen in q's frame.
/// A tangent direction at angle a in p's frame arrives at angle a + result in q's frame.
double transportAngle(const SurfaceFrames& frames, ddf::PointId p, ddf::PointId q);

/// @brief Wraps an angle to (-pi, pi].
double wrapAngle(double a);

/// @brief The doubled-angle (sign-free) representation e^{2 i a} of line @p d at point @p p,
/// or 0 when the projection of @p d onto the tangent plane is shorter than @p minLength.
std::complex<double> doubledAngle(const SurfaceFrames& frames, ddf::PointId p, const ddf::Vec3& d,
                                  double minLength = 1e-9);

/// @brief The unit line of doubled-angle vector @p z at point @p p (zero for z = 0).
ddf::Vec3 lineOf(const SurfaceFrames& frames, ddf::PointId p, std::complex<double> z);

}  // namespace ddfcam::planning::detail
