// SPDX-License-Identifier: MIT
// ddfcam: reading VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu) surfaces without VTK.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/mould/mould_study.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Largest .vtp/.vtu file read, bytes (2 GiB); larger files are refused.
inline constexpr std::size_t kMaxVtkXmlFileBytes = std::size_t{2} << 30;
/// @brief Largest number of points or cells of one piece (50 million).
inline constexpr std::size_t kMaxVtkXmlItems = 50'000'000;

/// @brief A triangulated surface read from a VTK XML file, with its scalar fields.
struct VtkXmlMesh {
  ddf::TriangleMesh mesh;  ///< #V points (all points of the file, pieces appended), #T triangles
  /// Scalar fields: PointData arrays (#V values) and CellData arrays mapped to the output
  /// triangles (#T values, each triangle takes its cell's value). 3-component arrays are kept
  /// as their magnitude named "|name|"; unit is empty.
  std::vector<planning::MeshField> fields;
  int ignoredLineCells = 0;           ///< line and poly-line cells (and PolyData Lines) skipped
  int ignoredVertexCells = 0;         ///< vertex and poly-vertex cells (and PolyData Verts) skipped
  int ignoredOtherCells = 0;          ///< cells of unsupported types skipped (named in warnings)
  std::vector<std::string> warnings;  ///< e.g. skipped arrays with 2 or >3 components
};

/// @brief Decodes the text of a .vtp or .vtu file (already in memory).
///
/// Supported: DataArray format ascii, binary (base64, header_type UInt32/UInt64, optionally
/// compressor="vtkZLibDataCompressor") and appended (raw or base64 AppendedData);
/// types Float32/64, Int8..Int64, UInt8..UInt64; byte_order LittleEndian and BigEndian.
/// PolyData: Polys (fans) and Strips. UnstructuredGrid cells: triangle 5, triangle strip 6,
/// polygon 7 (fan), pixel 8, quad 9 (two triangles), quadratic triangle 22, quadratic quad 23
/// and biquadratic quad 28 (corner nodes only); tetra 10, voxel 11, hexahedron 12, wedge 13,
/// pyramid 14 contribute their boundary faces (faces used by one cell only), oriented outwards.
/// Lines and vertices are counted, not read. Points are in the file's frame and units.
/// @param text whole file contents.
/// @param source name used in error messages (usually the file name).
/// @return the triangles of all pieces; #T >= 1.
/// @throws IoError "<source>: <what>" naming the offending element or array, for malformed,
/// unsupported (e.g. other dataset types) or oversized input, and when no triangle results.
VtkXmlMesh decodeVtkXmlMesh(std::string_view text, const std::string& source);

/// @brief Reads a .vtp or .vtu file (see decodeVtkXmlMesh).
/// @throws IoError if the file is missing, larger than kMaxVtkXmlFileBytes or malformed; the
/// message names the file.
VtkXmlMesh readVtkXmlMesh(const std::filesystem::path& path);

}  // namespace ddfcam::io
