// SPDX-License-Identifier: MIT
// ddfcam: evenly spaced streamlines covering a region (Jobard-Lefer, sec. 8.3 / fig. 8.4d).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief Options of evenlySpacedStreamlines().
struct EvenSpacingParams {
  /// Reference separation d_sep between neighbouring lines, mm, > 0 (default 1). With
  /// separationAt set it is only the cell size of the search grid and the default step; set it
  /// to about the smallest spacing separationAt returns.
  double separationMm = 1.0;
  /// d_test / d_sep: a line stops where it comes closer than d_test to another line (or to a
  /// part of itself more than pi d_test of arc away), in (0, 1] (default 0.5, Jobard-Lefer).
  double testRatio = 0.5;
  /// Spacing that varies over the surface: d_sep at a location, mm, > 0 (e.g. from the
  /// curvature: interpolateOnFace(ddf, curvature.kMax, loc.face, loc.bary)). A seed at d_sep
  /// of its origin point is valid when no line is closer than 0.99 d_sep(seed); a line stops
  /// closer than testRatio d_sep(point). Empty: separationMm everywhere (default).
  std::function<double(const ddf::SurfaceLocation&)> separationAt;
  /// Support faces the lines may cover, one entry per face (non-zero: allowed), e.g. the
  /// faces of one region. Empty: every face (default).
  std::vector<std::uint8_t> faceMask;
  /// Seed of the first line. Default: the allowed raster point with a defined field nearest to
  /// the centroid of the allowed raster points.
  std::optional<ddf::SurfaceLocation> firstSeed;
  /// Tracing of each line (traceStreamline). stepMm 0 picks 0.1 separationMm (Jobard-Lefer);
  /// its faceMask, existingPaths, nearPathDistanceMm and progress are ignored (replaced by the
  /// fields above), and maxLengthMm is capped at 4 area / d_test + pi x (diagonal of the
  /// region's bounding box), the most a line kept d_test from itself can use (default:
  /// StreamlineParams defaults).
  StreamlineParams trace;
  /// Lines shorter than this many d_sep (at their seed) are dropped and their seed remembered
  /// (not tried again). Every seed lies about d_sep from all lines, so a dropped line leaves a
  /// pocket uncovered (up to ~1.5 d_sep at corners of the region); 0 keeps every line and so
  /// covers every sampled point with a defined field; ~1 avoids tiny tool paths (default 0).
  double minLengthRatio = 0.0;
  /// Largest number of lines (default 10,000).
  int maxLines = 10000;
  /// Fill gaps after the propagation: every raster point of the allowed faces (subsampled to
  /// about one trace step) with a defined field that is farther than d_sep from all lines (and
  /// d_test from seeds whose lines were dropped) seeds a new line
  /// (default true).
  bool fillGaps = true;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief Evenly spaced streamlines of @p field covering the allowed faces of @p ddf (Jobard
/// and Lefer 1997 on the surface):
/// 1. The first line is traced from the first seed.
/// 2. Accepted lines are taken in FIFO order; from their points every 0.25 d_sep of arc a
///    candidate seed is placed on either side by walking on the surface perpendicular to the
///    line (in the tangent plane) until the straight distance is d_sep(point); a candidate is
///    valid if no line is closer than 0.99 d_sep(candidate) (the 1 % absorbs polyline chords).
/// 3. A valid candidate's line is traced in both directions (traceStreamline with the face
///    mask) and cut where it first comes closer than d_test = testRatio d_sep to a line
///    accepted before (or to itself, more than pi d_test of arc away); kept if at least
///    minLengthRatio d_sep long.
/// 4. With fillGaps, raster points still farther than d_sep from every line seed lines too
///    (step 3), so separate pieces of the region and pockets behind singularities get covered.
/// Distances are straight 3D distances between points and polyline segments; segments whose
/// surface normal faces away (more than 90 degrees) from the query point's are ignored, so
/// lines on the two sides of a wall thinner than d_sep do not interfere. The result does not
/// change when any entry of @p field is negated.
/// @param field line field laid out like ddf.allHeights() (zero entries: undefined).
/// @return the lines in the order they were accepted; points on the surface, mm, part frame.
/// @throws InvalidInput if the field or mask size is wrong, separationMm <= 0, testRatio is
/// outside (0, 1], minLengthRatio < 0, maxLines < 0, the first seed's face is out of range or
/// separationAt returns a value that is not finite or not > 0.
/// @throws Cancelled if params.progress asks to stop.
std::vector<Streamline> evenlySpacedStreamlines(const ddf::DisplacementField& ddf,
                                                const LineField& field,
                                                const EvenSpacingParams& params = {});

}  // namespace ddfcam::planning
