// SPDX-License-Identifier: MIT
// ddfcam-cli plan: the streamline stages of the plan command (seeding, smoothing, fairing).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/evenly_spaced_streamlines.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/streamline.h>

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
/// @throws InvalidInput, Cancelled from the planning functions.
std::vector<planning::Streamline> planLines(const ddf::DisplacementField& part,
                                            const planning::LineField& field, Seeding seeding,
                                            planning::StreamlineMethod method, double spacingMm,
                                            double maxLengthMm, const ProgressCallback& progress);

/// @brief Moving average of half window @p halfWindow (smoothMovingAverage) with each point put
/// back onto the surface (locateOnFace on the faces of its window, nearest wins).
std::vector<planning::Streamline> smoothOnSurface(const ddf::DisplacementField& part,
                                                  const std::vector<planning::Streamline>& lines,
                                                  int halfWindow);

}  // namespace ddfcam::cli
