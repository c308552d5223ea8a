// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the path file of any readable format read and placed on the part.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/io/programs/cl_program.h>
#include <ddfcam/io/programs/path_file.h>

#include "json_writer.h"
#include "simulate_inputs.h"

#include <filesystem>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Prints @p messages to stderr, one a line: "warning: FILE: line N: what" ("warning:
/// FILE: what" for line 0).
void printPathWarnings(const std::filesystem::path& file,
                       const std::vector<io::ClMessage>& messages);

/// @brief Format of a path file that io::readPathFile() accepted (detectPathFormat() on its
/// extension and first 4 KiB; Csv if detection fails).
io::PathFormat pathFormatOf(const std::filesystem::path& file);

/// @brief @p program with the options' unit override and transform applied: positions and
/// feeds scaled by millimetresPer(unit) / millimetresPer(program.sourceUnit), then positions
/// mapped by o.transform(), axes and normals rotated; sourceUnit set to the override.
io::ClProgram mappedProgram(io::ClProgram program, const ImportOptions& o);

/// @brief Reads o.paths with io::readPathFile() (any readable format, detected by extension and
/// content) and places it on @p goal:
/// - CSV whose cut rows all carry a normal (as 'plan' writes): mappedProgram(), then
///   pathFromCsv() (the tool at each cut row's contact with the row's normal and o.placement;
///   the file's axis only orients wheels), as before;
/// - APT/CLDATA, ROS toolpath YAML, FANUC .ls and CSV tables without normals:
///   io::placeProgram() with o.import (the vectors read as o.import.vectors, the points as
///   o.import.points, both detected from @p goal by default; link moves kept, rapid moves
///   with keepRapids).
/// --points contact|tip also sets the point kind of a CSV with normals; --vectors approach or
/// normal is refused there (its normals place the tool).
/// Prints the warnings of the reader and the placement to stderr as
/// "warning: FILE: line N: what".
/// @throws IoError as readPathFile(); InvalidInput for options the route cannot honour
/// (--lead, --tilt, --sample-tolerance, --step with a program placed by its axes;
/// --keep-rapids with a CSV), and as pathFromCsv() / placeProgram().
CsvPath importSimulationPath(const ddf::DisplacementField& goal, const SimulateOptions& o);

/// @brief Writes the "import" object of the report: format, unit, placement, vectors, points,
/// convention (what was used and why), points_read, poses_placed, points_off_part,
/// points_on_part, max_contact_distance_mm (largest |distance| over all poses),
/// max_contact_distance_on_part_mm (over the poses on the part; null if none),
/// gouging_poses and max_gouge_depth_mm (null where the route does not measure them),
/// warnings.
void writeImportFacts(JsonWriter& json, const ImportFacts& facts);

}  // namespace ddfcam::cli
