// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the path file of any readable format read and placed on the part.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/placement/cl_program.h>

#include "json_output.h"
#include "simulate_inputs.h"

#include <filesystem>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Prints @p messages to stderr, one a line: "warning: FILE: line N: what" ("warning:
/// FILE: what" for line 0).
void printPathWarnings(const std::filesystem::path& file,
                       const std::vector<planning::ClMessage>& messages);

/// @brief Reads o.paths with io::readPathFile() (any readable format, detected by extension and
/// content) and places it on @p goal with planning::placeProgram(), as the workbench's import
/// does: o.import's unit override and transform, the vectors read as o.import.vectors and the
/// points as o.import.points (both detected from @p goal by default), link moves kept, rapid
/// moves with keepRapids. CSVs whose cut rows all carry a normal (as 'plan' writes) are placed
/// at their contacts, their cut rows only, with o.placement's lead and tilt
/// (planning::PlaceProgramParams::contactAngles) and, with o.resample(), resampled along the
/// feed; --vectors approach or normal is refused there (their normals place the tool).
/// Prints the warnings of the reader and the placement to stderr as
/// "warning: FILE: line N: what".
/// @throws IoError as readPathFile(); InvalidInput for options the route cannot honour
/// (--lead, --tilt, --sample-tolerance, --step with a program placed by its axes;
/// --keep-rapids with, or no cut row in, a CSV placed at its contacts), and as placeProgram()
/// or the resampling.
CsvPath importSimulationPath(const ddf::DisplacementField& goal, const SimulateOptions& o);

/// @brief The "import" object of the report: format, unit, placement, vectors, points,
/// convention (what was used and why), points_read, poses_placed, points_off_part,
/// points_on_part, max_contact_distance_mm (largest |distance| over all poses),
/// max_contact_distance_on_part_mm (over the poses on the part; null if none),
/// gouging_poses and max_gouge_depth_mm (null where the route does not measure them),
/// warnings.
JsonReport importFactsJson(const ImportFacts& facts);

}  // namespace ddfcam::cli
