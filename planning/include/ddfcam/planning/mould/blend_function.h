// SPDX-License-Identifier: MIT
// ddfcam: blending functions d(u, v) for the blended surface f = s + d h v (dissertation ch. 9).
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <span>
#include <vector>

namespace ddfcam::planning {

/// @brief Shape of the blending function.
enum class BlendKind {
  Constant,  ///< d = value everywhere (fig. 9.5)
  Radial,    ///< value at a picked centre, falling smoothly to 0 at radiusMm (Euclidean)
  Region,    ///< value inside painted faces, 0 outside, smooth edge of edgeWidthMm (geodesic)
  Boundary   ///< 0 on the support's boundary, value from widthMm of geodesic distance inward
};

/// @brief Parameters of blendWeights(). Every fall-off uses the C1 smoothstep S(x) = 3x^2 - 2x^3
/// on [0, 1] (slope at most 1.5 / width).
struct BlendParams {
  BlendKind kind = BlendKind::Constant;  ///< Default Constant.
  double value = 1.0;                    ///< d at full strength (any sign). Default 1.
  /// Radial: centre, mm, part frame; distances are Euclidean from the support points g.
  /// Default origin.
  ddf::Vec3 centreMm = ddf::Vec3::Zero();
  /// Radial: d = value (1 - S(dist / radiusMm)), 0 from radiusMm on; > 0. Default 20.
  double radiusMm = 20.0;
  /// Region: painted support faces (any order, duplicates allowed). Default none (d = 0).
  std::vector<int> faces;
  /// Region: inside the painted faces d = value S(dist / edgeWidthMm), dist = geodesic distance
  /// along the support to the border with unpainted faces (the support boundary is no border);
  /// 0 on unpainted faces. > 0. Default 5.
  double edgeWidthMm = 5.0;
  /// Boundary: d = value S(dist / widthMm), dist = geodesic distance to the support boundary
  /// (0 on it); a closed support has no boundary and gets value everywhere. > 0. Default 10.
  double widthMm = 10.0;
};

/// @brief Blending weights d per raster point copy (layout of ddf.allHeights()), so that
/// s + d h v is the blended surface of ch. 9 (e.g. ddf::morphPositions with d as lambdas).
/// Copies of one shared raster point get the same weight. Geodesic distances are shortest paths
/// along the raster lattice of the support (Dijkstra over the lattice edges between support
/// points g, exact at the sources). They never underestimate the true geodesic distance, so every
/// point farther than the width from the sources gets the full value; on a lattice of (near)
/// equilateral triangles they overestimate it by at most 2/sqrt(3) (~15 %), on a grid split along
/// one diagonal they are exact along the axes and the diagonal.
/// @throws InvalidInput for a non-finite value, a non-positive width or radius, or a face index
/// out of range (the message names it).
std::vector<float> blendWeights(const ddf::DisplacementField& ddf, const BlendParams& params);

/// @brief Faces of @p ddf whose support triangle comes within @p radiusMm of @p centreMm
/// (exact point-triangle distance), ascending: the footprint of a paint brush for
/// BlendParams::faces.
/// @throws InvalidInput if radiusMm < 0 or not finite.
std::vector<int> facesWithinRadius(const ddf::DisplacementField& ddf, const ddf::Vec3& centreMm,
                                   double radiusMm);

/// @brief Geodesic distance along the support's raster lattice from the @p sources (distance 0)
/// to every raster point, mm, indexed by PointId; +infinity where unreachable (or everywhere
/// without sources). Edge weights are the Euclidean lengths between support points g.
/// @throws InvalidInput if a source id is out of range.
std::vector<double> latticeDistances(const ddf::DisplacementField& ddf,
                                     std::span<const ddf::PointId> sources);

}  // namespace ddfcam::planning
