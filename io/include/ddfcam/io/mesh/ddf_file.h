// SPDX-License-Identifier: MIT
// ddfcam: the .ddf binary file format of a Discrete Displacement Field.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/length_unit.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Newest format version this build writes and reads. A field without metadata is
/// written as version 1 (so older builds read it); with metadata as version 2.
inline constexpr std::uint32_t kDdfFormatVersion = 2;

/// @brief Where a field came from, stored in the optional metadata section of a version-2
/// .ddf file. The field itself is always in mm.
struct DdfMetadata {
  /// Unit the source file of the part was read in. Default mm.
  ddfcam::LengthUnit sourceUnit = ddfcam::LengthUnit::Millimetre;
  /// Empty, or per support face the CAD face it came from (-1: none), an index into
  /// cadFaceNames. Default empty.
  std::vector<int> cadFaceOfSupportFace;
  /// Display names of the CAD faces, e.g. "face 12 (B-spline)". Default empty.
  std::vector<std::string> cadFaceNames;
  /// The triangles the field was converted from (mm, part frame), or none: kept so that the
  /// curvature of a reduced support comes from them (planning::computeDesignCurvature) and the
  /// part can be compared with what was delivered. Default none.
  std::optional<ddf::TriangleMesh> designMesh;
  /// Set by decodeDdf/readDdf: whether the file held a metadata section (version 2); when
  /// false the other members keep their defaults. Ignored when writing.
  bool stored = false;
};

/// @brief Serialises @p field in the .ddf format (format version kDdfFormatVersion).
///
/// Layout, every field little-endian and written byte by byte (host order does not matter):
/// | offset | size | field |
/// |---|---|---|
/// | 0 | 8 | magic "DDFCAM\x1a\n" |
/// | 8 | 4 | u32 format version |
/// | 12 | 4 | u32 byte-order marker 0x01020304 (bytes 04 03 02 01) |
/// | 16 | 8 | u64 support vertex count V |
/// | 24 | 8 | u64 support face count F |
/// | 32 | 4 | u32 raster resolution m |
/// | 36 | 4 | u32 reserved, 0 |
/// | 40 | 24 V | vertex positions, f64 x y z, mm |
/// | | 24 V | displacement vectors, f64 x y z, mm per unit height |
/// | | 12 F | faces, u32 p1 p2 p3 in the field's local order faceVertices(f) |
/// | | 4 F m(m+1)/2 | heights, f32, face after face in Raster order |
/// | end-4 | 4 | u32 CRC-32 (IEEE, zlib) of every byte before it |
///
/// Version 2 (written when metadata is given) has the same layout with the metadata section
/// between the heights and the checksum: u32 byte count L, then L bytes: u32 source unit (0 mm,
/// 1 cm, 2 m, 3 in), u32 N CAD face names, each a u32 byte count and UTF-8 bytes, u64 K (0 or
/// F) and K i32 CAD faces of the support faces (-1 or < N), then the design mesh: u64 vertex
/// count W, 24 W f64 x y z (mm), u64 triangle count T, 12 T u32 vertex indices (W = T = 0: none;
/// sections written before this member end after the CAD faces). A reader ignores bytes of the
/// section after the members it knows, so later members extend it without a version bump.
/// @return the file content (version 1).
std::string encodeDdf(const ddf::DisplacementField& field);

/// @brief Serialises @p field with @p metadata (format version 2, see above).
/// @throws InvalidInput if cadFaceOfSupportFace is neither empty nor one entry per face, or
/// holds an entry outside [-1, cadFaceNames.size()).
std::string encodeDdf(const ddf::DisplacementField& field, const DdfMetadata& metadata);

/// @brief Writes @p field to @p path in the .ddf format, atomically (temporary file + rename).
/// @throws IoError if the file cannot be written; the target is then left unchanged.
void writeDdf(const ddf::DisplacementField& field, const std::filesystem::path& path);

/// @brief Writes @p field with @p metadata (format version 2), as writeDdf above.
/// @throws InvalidInput as encodeDdf with metadata (the target is not touched); IoError as
/// writeDdf.
void writeDdf(const ddf::DisplacementField& field, const std::filesystem::path& path,
              const DdfMetadata& metadata);

/// @brief Rebuilds a field from .ddf content (version 1 or 2); the exact inverse of encodeDdf
/// (positions, vectors, face vertex order and heights are bit-identical).
/// @param bytes whole file content; @param sourceName file name used in messages.
/// @param metadata if not null, receives the metadata section (defaults, stored = false, for
/// a version-1 file).
/// @throws IoError if the content is empty, truncated, has trailing bytes, a wrong magic, a
/// newer or invalid version, a foreign byte order, a checksum mismatch, or describes an invalid
/// field (index out of range, non-finite position, non-manifold support); the message names
/// @p sourceName and what is wrong (also a malformed metadata section).
ddf::DisplacementField decodeDdf(std::string_view bytes, const std::string& sourceName,
                                 DdfMetadata* metadata = nullptr);

/// @brief Reads a .ddf file written by writeDdf.
/// @param metadata if not null, receives the metadata as decodeDdf.
/// @throws IoError if the file is missing or unreadable, or as decodeDdf.
ddf::DisplacementField readDdf(const std::filesystem::path& path, DdfMetadata* metadata = nullptr);

}  // namespace ddfcam::io
