// SPDX-License-Identifier: MIT
// ddfcam: per-format mesh readers and writers behind readMesh / writeMesh.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

// Readers take the whole file content and the file name for messages; they throw IoError.
ddf::TriangleMesh readStl(std::string_view bytes, const std::string& name);
ddf::TriangleMesh readObj(std::string_view bytes, const std::string& name);
ddf::TriangleMesh readPly(std::string_view bytes, const std::string& name);
ddf::TriangleMesh readOff(std::string_view bytes, const std::string& name);

// Writers return the file content; indices are validated by the caller.
std::string writeStl(const ddf::TriangleMesh& mesh);
std::string writeObj(const ddf::TriangleMesh& mesh);
std::string writePly(const ddf::TriangleMesh& mesh);
std::string writeOff(const ddf::TriangleMesh& mesh);

/// @brief Appends the fan triangulation (c0, c_i, c_i+1) of a polygon to @p mesh.
void appendFan(ddf::TriangleMesh& mesh, const int* corners, int count);

}  // namespace ddfcam::io::detail
