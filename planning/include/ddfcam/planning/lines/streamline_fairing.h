// SPDX-License-Identifier: MIT
// ddfcam: Ceres fairing of streamlines on the DDF surface within a deviation bound (sec. 8.3).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/progress.h>

namespace ddfcam::planning {

/// @brief Options of fairStreamline().
struct FairingParams {
  /// Largest distance of a faired point from the raw polyline, mm (> 0) (default 0.05).
  double deviationMm = 0.05;
  /// Weight of the bending energy L sum_i (d_i . b_i)^2 / h^3, the squared geodesic turning of
  /// the line (d_i = x_{i-1} - 2 x_i + x_{i+1}, b_i the in-surface normal of the line, h the
  /// mean spacing, L the length); dimensionless and independent of mm and of the point count
  /// (it tends to L times the integral of the squared geodesic curvature) (>= 0) (default 1).
  double bendingWeight = 1.0;
  /// Weight of the same sum over the tangential component d_i . t_i, which is the change of
  /// spacing from segment to segment: it evens the spacing (>= 0) (default 0.1).
  double spacingWeight = 0.1;
  /// Weight of the mean squared lateral offset from the raw point in units of deviationMm
  /// (dimensionless, independent of the point count). With the bending term it makes the
  /// fairing a low-pass filter of cut-off wavelength about 2 pi (bendingWeight /
  /// closenessWeight)^(1/4) sqrt(L deviationMm) (5 mm for L = 40 mm and the defaults): shorter
  /// wiggles go, longer shapes stay, so a line of curvature that is not a geodesic (a torus
  /// parallel) is not pulled across the whole deviation bound towards a geodesic (>= 0)
  /// (default 10).
  double closenessWeight = 10.0;
  /// Largest tangential move of a point along the line, in units of the mean spacing h
  /// (in [0, 0.5]) (default 0.5).
  double maxSlide = 0.5;
  /// Keep the first and the last point of an open line where they are (default true).
  /// Closed loops (first point == last point) have no ends and stay closed.
  bool fixEnds = true;
  /// Largest number of Ceres (Levenberg-Marquardt) iterations (>= 1) (default 50).
  int iterations = 50;
  /// Progress in [0, 1] per Ceres iteration; returning false cancels (default: none).
  ProgressCallback progress = nullptr;
};

/// @brief The line @p raw faired: each point moves by a 2D offset (lateral within
/// [-deviationMm, deviationMm], tangential within maxSlide spacings) in the tangent plane of
/// the DDF surface at its raw point, in the frame (t, b) of the raw line (t from the chord over
/// four segments, b = n x t), and is put back onto the DDF surface by a Gauss-Newton
/// closest-point search in the barycentric domain of its raw face that walks across support
/// edges; Ceres minimises the bending, spacing and closeness energies (see FairingParams) over
/// the offsets. Every result point is a point of the DDF surface (g + h v with h the raster
/// interpolation at its barycentric coordinates); a point that ends farther than deviationMm
/// from the raw polyline (measured to the raw segments near its index) is pulled back towards
/// its raw point until it is within. Stops, seed index and point count are kept; lengthMm is
/// recomputed. Lines with fewer than 3 distinct points are returned unchanged.
/// @param raw points on the surface of @p ddf (face, bary used; h and point recomputed).
/// @throws InvalidInput if a point's face is out of range or its barycentric coordinates are
/// not finite (naming the point), or a parameter is out of its range.
/// @throws Cancelled if params.progress asks to stop.
Streamline fairStreamline(const ddf::DisplacementField& ddf, const Streamline& raw,
                          const FairingParams& params = {});

}  // namespace ddfcam::planning
