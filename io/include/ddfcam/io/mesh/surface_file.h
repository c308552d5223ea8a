// SPDX-License-Identifier: MIT
// ddfcam: loading a mould or formed surface from any supported mesh file (STL/OBJ/PLY/OFF/VTK XML).
#pragma once

#include <ddfcam/planning/mould/mould_study.h>

#include <filesystem>
#include <string>
#include <vector>

namespace ddfcam::io {

/// @brief Lower-case extensions readSurfaceFile accepts, with the dot:
/// ".stl", ".obj", ".ply", ".off", ".vtp", ".vtu".
const std::vector<std::string>& surfaceFileExtensions();

/// @brief A file-dialog filter for surfaces, e.g.
/// "Surfaces (*.stl *.obj *.ply *.off *.vtp *.vtu)".
std::string surfaceFileDialogFilter();

/// @brief Whether readSurfaceFile accepts @p path by its extension (case-insensitive).
bool isSurfaceFile(const std::filesystem::path& path);

/// @brief Reads a surface: .stl/.obj/.ply/.off through readMesh (no fields), .vtp/.vtu through
/// readVtkXmlMesh (with its point and cell scalar fields).
/// @return name = file name, sourcePath = @p path as given, mesh in the file's frame (mm),
/// fields as read.
/// @throws IoError for a missing, unknown or malformed file (the message names the file).
planning::LoadedSurface readSurfaceFile(const std::filesystem::path& path);

}  // namespace ddfcam::io
