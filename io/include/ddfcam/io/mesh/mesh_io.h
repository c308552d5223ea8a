// SPDX-License-Identifier: MIT
// ddfcam: reading and writing triangle meshes (STL, OBJ, PLY, OFF) as plain triangle soups.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <filesystem>
#include <optional>

namespace ddfcam::io {

/// @brief Mesh file formats, chosen by file extension (case-insensitive).
enum class MeshFormat {
  Stl,  ///< .stl, ASCII or binary (binary when written)
  Obj,  ///< .obj, Wavefront, vertices and faces only
  Ply,  ///< .ply, ASCII or binary little/big endian (binary little endian, doubles, when written)
  Off   ///< .off, Object File Format (ASCII)
};

/// @brief Format of @p path by its extension; std::nullopt for an unknown extension.
std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path);

/// @brief Reads a mesh file into an indexed triangle soup, in the file's frame and units.
///
/// Nothing is dropped for topological reasons: non-manifold edges, duplicate and degenerate
/// faces are kept as they are (conversion to a support mesh decides later). Polygons with more
/// than three corners are split into a fan from their first corner. STL carries no
/// connectivity, so bit-identical STL corners are welded into one vertex (see weldVertices);
/// other formats keep their vertex list unchanged, including unreferenced vertices.
/// @param path .stl, .obj, .ply or .off file.
/// @return #V vertices and #T triangles; #T >= 1.
/// @throws IoError if the file is missing, has an unknown extension, holds no triangles or is
/// malformed; the message names the file and, for text formats, the line.
ddf::TriangleMesh readMesh(const std::filesystem::path& path);

/// @brief Writes @p mesh in the format given by the extension of @p path, atomically
/// (temporary file + rename). OBJ, PLY and OFF store coordinates exactly (shortest round-trip
/// decimal, or binary doubles for PLY); binary STL stores 32-bit floats and per-face normals.
/// @throws InvalidInput if a triangle refers to a vertex out of range.
/// @throws IoError for an unknown extension or if the file cannot be written.
void writeMesh(const ddf::TriangleMesh& mesh, const std::filesystem::path& path);

/// @brief Merges vertices with bit-identical coordinates (+0 and -0 count as equal) and drops
/// vertices no triangle refers to. Vertices keep the order of their first use by the triangles.
/// @throws InvalidInput if a triangle refers to a vertex out of range.
ddf::TriangleMesh weldVertices(const ddf::TriangleMesh& mesh);

}  // namespace ddfcam::io
