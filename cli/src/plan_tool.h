// SPDX-License-Identifier: MIT
// ddfcam-cli plan: the tool, its placement and the sampling along the lines, and the linked
// program of the placed lines.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/placement/path_linking.h>
#include <ddfcam/planning/placement/path_sampling.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/tools/tool.h>

#include "arguments.h"

#include <optional>
#include <vector>

namespace ddfcam::cli {

/// @brief The options --tool, --radius, --corner-radius, --lead, --tilt, --tolerance, --step.
struct PlanTool {
  planning::Tool tool;                  ///< shape and size (validated)
  planning::PlacementParams placement;  ///< lead and tilt, deg
  /// Set by --tolerance or --step: lines resampled along the feed (placeAlongPath).
  std::optional<planning::PathSamplingParams> sampling;
};

/// @brief Reads the tool options from @p args (see the plan help; --tool accepts roll,
/// ball, ball_end, flat_end, torus, belt_wheel and every toolKindName() key).
/// @throws UsageError naming the option for an unknown kind, a bad number or a tool that
/// validateTool() refuses.
PlanTool parsePlanTool(const Arguments& args);

/// @brief Adds the options parsePlanTool() reads: --tool, --radius, --corner-radius, --lead,
/// --tilt, --tolerance, --step.
void addPlanToolOptions(Arguments& args);

/// @brief Placed, linked lines ready for the CSV.
struct PlacedProgram {
  planning::ToolPath path;         ///< one pass per kept line, poses in the tool kind's frame
  std::vector<ddf::Vec3> normals;  ///< #poses unit surface normals (tool side)
  planning::LinkedPaths linked;    ///< the passes of path ordered and linked
  std::vector<planning::PassSampling> passes;  ///< per pass sampling; empty without sampling
};

/// @brief Places @p tool along @p lines (toolPathFromStreamlinesDetailed) and links the passes
/// by their contacts and normals. The poses keep the tool frames of planning/tool.h (the
/// program builder takes each kind's spindle axis from them).
/// @throws InvalidInput as toolPathFromStreamlines() and linkPaths().
PlacedProgram placeAndLink(const ddf::DisplacementField& part,
                           const std::vector<planning::Streamline>& lines, const PlanTool& tool,
                           double feedMmPerMin, const planning::LinkingParams& linking);

}  // namespace ddfcam::cli
