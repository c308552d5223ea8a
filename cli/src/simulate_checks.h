// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: what tells a result from a silent wrong answer: the coverage of the part
// by the path, and the warnings of the run (for the summary, the report and --strict).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include "run_warnings.h"
#include "simulate_inputs.h"

namespace ddfcam::cli {

/// @brief The share of @p goal (the desired surface) that the tool of @p o comes within
/// planning::PathCoverageParams::reachMm (0.1 mm) of along @p path (planning::pathCoverage),
/// with console progress.
planning::Coverage simulationCoverage(const ddf::DisplacementField& goal, const SimulateOptions& o,
                                      const planning::ToolPath& path);

/// @brief What a simulate run found that its statistics do not show.
struct SimulateFindings {
  const ImportFacts& import;                 ///< the path file's warnings (already printed)
  const planning::Coverage& coverage;        ///< share of the part the tool touched
  const planning::CrustClamping& clamping;   ///< points left at the crust bottom
  const planning::ErrorStatistics& stats;    ///< the deviation statistics
  const planning::GrindingReport& grinding;  ///< V-convexity and collisions (rigid cuts)
};

/// @brief Adds every warning of the run to @p warnings: the path file's (counted), a coverage
/// below o.minCoveragePercent, clamping at the crust bottom, V-convexity, collisions.
void collectSimulateWarnings(const SimulateOptions& o, const SimulateFindings& found,
                             RunWarnings& warnings);

}  // namespace ddfcam::cli
