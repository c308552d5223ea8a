// SPDX-License-Identifier: MIT
// ddfcam-cli: the --units option of the commands that read a part or a surface, and the
// warning when a file's size suggests another unit.
#pragma once

#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/model/project.h>

#include "arguments.h"

#include <filesystem>
#include <optional>

namespace ddfcam::cli {

/// @brief Adds --units U to @p args: "unit of <@p of>: mm, cm, m or in (default: <@p
/// byDefault>)", checked against lengthUnitChoices().
CLI::Option* addUnitsOption(Arguments& args, const std::string& of, const std::string& byDefault);

/// @brief The unit given with --units (see addUnitsOption), or std::nullopt if absent.
std::optional<ddfcam::LengthUnit> unitOption(const Arguments& args);

/// @brief Prints "warning: <file> is <d> units across; if it is not in mm, pass --units (as m
/// it would be ... mm)" on stderr when no unit was given and sizeSuggestsOtherUnit(@p
/// fileDiagonal) holds; nothing otherwise.
/// @param remedy what the user changes to state the unit (e.g. the job file's key instead of
/// the command's option).
/// @return whether it warned.
bool warnIfOtherUnit(const std::filesystem::path& file, double fileDiagonal,
                     const std::optional<ddfcam::LengthUnit>& given,
                     const std::string& remedy = "pass --units");

/// @brief io::loadPart of @p path in params.unit (set it from unitOption), with a console
/// progress line labelled @p label; warns as warnIfOtherUnit for a converted mesh file.
/// @param report if not null, receives the load report.
/// @param inputMesh if not null, receives the triangles the part was converted from (mm; for a
/// .ddf file the design mesh it stores, if any).
/// @throws as io::loadPart.
ddf::DisplacementField loadPartInUnit(const std::filesystem::path& path, io::LoadPartParams params,
                                      const char* label, io::LoadPartReport* report = nullptr,
                                      ddf::TriangleMesh* inputMesh = nullptr);

/// @brief io::openProject of a part file (.ddf, mesh or CAD) in params.unit, with the progress
/// line and the size warning of loadPartInUnit(): the part with its design mesh and CAD faces,
/// from which planning::partCurvatureParams() takes the curvature as the workbench shows it.
/// @throws as io::openProject; InvalidInput if the file holds no part.
planning::Project openPartInUnit(const std::filesystem::path& path, io::LoadPartParams params,
                                 const char* label);

}  // namespace ddfcam::cli
