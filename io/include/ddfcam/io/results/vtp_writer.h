// SPDX-License-Identifier: MIT
// ddfcam: writing a triangle mesh with per-point data as a VTK XML PolyData (.vtp) file.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <filesystem>
#include <string>
#include <vector>

namespace ddfcam::io {

/// @brief A named scalar per mesh vertex, written as a Float32 DataArray.
struct VtpScalarArray {
  std::string name;           ///< array name shown by VTK readers, e.g. "k_max"; non-empty
  std::vector<float> values;  ///< #V values, one per mesh vertex; NaN allowed ("nan")
};

/// @brief A named 3-vector per mesh vertex, written as a 3-component Float32 DataArray.
struct VtpVectorArray {
  std::string name;                     ///< array name, e.g. "dir_max"; non-empty
  std::vector<Eigen::Vector3d> values;  ///< #V vectors, part frame (rounded to float on output)
};

/// @brief Per-point data of a .vtp file. The first scalar and the first vector array are marked
/// as the active ones (PointData Scalars= / Vectors=), which viewers colour and glyph by.
struct VtpPointData {
  std::vector<VtpScalarArray> scalars;  ///< scalar arrays, written in this order (default none)
  std::vector<VtpVectorArray> vectors;  ///< vector arrays, written after the scalars (default none)
};

/// @brief The text of a VTK XML PolyData file (type "PolyData", version "0.1", ASCII): one
/// Piece with the mesh vertices as Float64 Points, the triangles as Polys (Int64 connectivity
/// and offsets) and @p data as Float32 PointData. Every number is written in its shortest form
/// that reads back to the identical double (points) or float (arrays, vector components rounded
/// to float first); non-finite values are written "nan", "inf", "-inf" (VTK 9.1's reader loads
/// such files, but its colour ranges then include the non-finite values).
/// @param mesh #V vertices (mm, part frame) and #T triangles.
/// @throws InvalidInput naming the array if an array has an empty, duplicate or XML-unsafe
/// name ('<', '>', '&', '"') or not #V values, or naming the triangle if a vertex index is out
/// of range.
std::string formatVtp(const ddf::TriangleMesh& mesh, const VtpPointData& data);

/// @brief Writes formatVtp(@p mesh, @p data) to @p path atomically (temporary file + rename),
/// so an existing file is either kept or fully replaced.
/// @throws InvalidInput as formatVtp (nothing is written); IoError naming @p path if the file
/// cannot be written.
void writeVtp(const ddf::TriangleMesh& mesh, const VtpPointData& data,
              const std::filesystem::path& path);

}  // namespace ddfcam::io
