// SPDX-License-Identifier: MIT
// ddfcam: streamlines by the raster walk with error compensation and low-pass filter (sec. 8.3).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>

namespace ddfcam::planning {

/// @brief Options of traceStreamlineRasterWalk() beyond StreamlineParams.
struct RasterWalkParams {
  /// Carry the lateral error between the ideal line and the raster moves over to the next
  /// move (fig. 8.10); false gives the plain walk to the neighbour closest in direction to the
  /// field (default true).
  bool compensateError = true;
  /// Half width k of the moving-average low-pass filter: each point becomes the mean of the
  /// 2k + 1 points around it (the window shrinks at the ends, which stay); 0 switches the
  /// filter off (default 2).
  int filterHalfWindow = 2;
  /// Times the filter is applied (default 1).
  int filterPasses = 1;
};

/// @brief The streamline of line field @p field through @p seed by the dissertation's raster
/// walk (sec. 8.3, fig. 8.10): the line moves from raster point to raster point, to lattice
/// neighbours in any allowed face around the current point (across seams and vertices through
/// the raster topology). The walker follows an ideal line that advances along the
/// sign-aligned field (unit tangent w, mean of w at both ends of each move) and carries the
/// lateral offset e of that line from the current raster point (the error of fig. 8.10). Of
/// the neighbours that make progress (cos(move, w) >= 0.3), or make a sideways correction
/// (cos >= -0.2, at most two in a row), the one nearest the ideal line is taken, so the error
/// is compensated at the next move (a correction through the aim direction alone, p + w + e,
/// cannot leave a raster row that runs parallel to the field, as on the torus, where the only
/// correcting neighbour is sideways). |e| is capped at the step L (StreamlineParams::stepMm,
/// default the mean raster spacing). The seed itself is the first point; the walk starts at the
/// corner of the seed's raster triangle ahead of it nearest the field line, with the seed's offset
/// as the first error. Both halves are traced as in traceStreamline() (same sign rule, joining and
/// stop reasons: the line stops at a raster point on an open or masked edge where w leaves the
/// allowed faces; the other tests run on the raster points), then each half from the seed to its
/// end is low-pass filtered (RasterWalkParams) with every filtered point put back on the surface:
/// averaged in the barycentric coordinates where the whole window lies in one face, else averaged
/// in 3D and V-projected onto its face or a neighbour (walking across seams, never into a masked
/// face).
/// The seed and both end points stay where the walk put them. maxLengthMm and maxSteps (one
/// raster move per step) bound the raw walk; lengthMm is the length of the filtered line.
/// @param field line field laid out like ddf.allHeights() (zero entries: undefined).
/// @param seed a location on the surface (face, bary; h and point are recomputed).
/// @throws InvalidInput as traceStreamline(), or if a filter option is negative.
/// @throws Cancelled if params.progress asks to stop.
Streamline traceStreamlineRasterWalk(const ddf::DisplacementField& ddf, const LineField& field,
                                     const ddf::SurfaceLocation& seed,
                                     const StreamlineParams& params = {},
                                     const RasterWalkParams& walk = {});

}  // namespace ddfcam::planning
