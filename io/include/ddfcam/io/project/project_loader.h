// SPDX-License-Identifier: MIT
// ddfcam: opening any file the workbench accepts (project, .ddf, mesh) as a Project.
#pragma once

#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/planning/model/project.h>

#include <filesystem>

namespace ddfcam::io {

/// @brief True if @p path has the project file suffix ".ddfproj" (any case).
bool isProjectFile(const std::filesystem::path& path);

/// @brief True if @p path has a suffix openProject() accepts: .ddfproj, .ddf, .stl, .obj,
/// .ply, .off, .step, .stp, .iges, .igs (any case).
bool canOpenAsProject(const std::filesystem::path& path);

/// @brief Opens @p path as a project: a .ddfproj file as saved; a .ddf or mesh file as a new
/// project on that part (partName = file name, sourcePath = @p path, one simulation state
/// "stock" with the initial heights; sourceUnit = the unit the file was read in). A mesh file
/// (scaled to mm) or a CAD model's tessellation is kept as the design mesh, the surface the part
/// is compared with, as is the design mesh a .ddf file stores; a CAD model (or a .ddf file
/// converted from one) also sets cadFaceOfSupportFace and cadFaceNames.
/// @param params conversion parameters and progress for part files (ignored for projects).
/// @param report if not null, receives what loading the part did (converted = false for a
/// project or a .ddf file): a mesh's repairs and whether it became a valid DDF.
/// @throws IoError naming the file (nested cause); Cancelled through params.progress.
planning::Project openProject(const std::filesystem::path& path, const LoadPartParams& params = {},
                              LoadPartReport* report = nullptr);

}  // namespace ddfcam::io
