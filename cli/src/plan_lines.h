// SPDX-License-Identifier: MIT
// ddfcam-cli plan: the streamline stages of the plan command (seeding, smoothing, fairing).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/evenly_spaced_streamlines.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/streamline.h>

#include <functional>
#include <vector>

namespace ddfcam::cli {

/// @brief How the lines of the plan command are placed.
enum class Seeding {
  Transverse,  ///< seeds every spacing along one transverse line through the centre
  Even         ///< evenlySpacedStreamlines (Jobard-Lefer), RK4 tracing
};

/// @brief The raster point with a defined field nearest to the centroid of all raster points,
/// as a surface location.
/// @throws InvalidInput if the field is zero everywhere.
ddf::SurfaceLocation centralSeed(const ddf::DisplacementField& part,
                                 const planning::LineField& field);

/// @brief Lines @p spacingMm apart: seeded along the transverse line through centralSeed()
/// and traced by @p method, or evenly spaced (RK4). Every line (the transverse one too) stops
/// after @p maxLengthMm. Lines with fewer than 2 points are dropped.
/// @param separationAt for Seeding::Even only: spacing that varies over the surface, mm
/// (EvenSpacingParams::separationAt; @p spacingMm should then be its smallest value); empty:
/// @p spacingMm everywhere.
/// @throws InvalidInput, Cancelled from the planning functions; InvalidInput if
/// @p separationAt is set with Seeding::Transverse.
std::vector<planning::Streamline> planLines(
    const ddf::DisplacementField& part, const planning::LineField& field, Seeding seeding,
    planning::StreamlineMethod method, double spacingMm, double maxLengthMm,
    const ProgressCallback& progress,
    const std::function<double(const ddf::SurfaceLocation&)>& separationAt = {});

}  // namespace ddfcam::cli
