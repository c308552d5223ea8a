// SPDX-License-Identifier: MIT
// ddfcam-cli run: a job's part, segmentation and region entries turned into library calls
// (the planning pipeline the workbench panels call too).
#pragma once

#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/model/project.h>

#include "job_runner.h"
#include "job_spec.h"

#include <string>

namespace ddfcam::cli {

/// @brief The project of the part: the demo session (planning::demoProject(): part, "stock"
/// state, design mesh) or io::openProject() of the file, without paths, with the job's tools.
/// @throws IoError naming the part file; InvalidInput for a project without a part.
planning::Project loadJobProject(const JobSpec& spec);

/// @brief The regions of the Segmentation panel (or one region "whole part").
/// @throws InvalidInput, Cancelled from the segmentation.
std::vector<planning::Region> segmentJobPart(const ddf::DisplacementField& part,
                                             const planning::CurvatureField& curvature,
                                             const SegmentationSpec& spec);

/// @brief The region indices @p job selects in @p regions (all, one index, or by name).
/// @throws InvalidInput naming an index out of range or an unknown region name.
std::vector<int> selectRegions(const std::vector<planning::Region>& regions, const RegionJob& job,
                               const std::string& what);

/// @brief Plans region @p region of @p project with the planning pipeline
/// (planning/pipeline/region_planning.h: the region's fields, spacing, lines, linking and
/// placement, as the Streamlines panel does) or with planning::refineSpacing
/// (LineMethod::Refined, as the Spacing refinement panel does), and appends the path (and for
/// Refined the "refinement error" field) to the project.
/// @throws InvalidInput when no line can be traced; Error from the planning functions.
RegionPathInfo planRegion(planning::Project& project, const planning::CurvatureField& curvature,
                          int region, const RegionJob& job,
                          const planning::StreamlinePathParams& placement);

/// @brief The Simulation panel's "Raise by stock allowance" and "Simulate path" for every path
/// in order: states "design", "stock +A mm" and "after <path>", the part at the last heights.
/// @throws InvalidInput, Error from the simulation.
std::vector<planning::GrindingReport> simulateJob(planning::Project& project,
                                                  const SimulationSpec& spec);

/// @brief The Error map panel's deviation against the "design" state (else the first state):
/// adds field "deviation" and returns the statistics over the whole part.
/// @throws InvalidInput if the project has no state to compare with.
planning::ErrorStatistics errorMapJob(planning::Project& project, const ErrorMapSpec& spec);

}  // namespace ddfcam::cli
