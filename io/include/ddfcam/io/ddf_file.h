// SPDX-License-Identifier: MIT
// ddfcam: the .ddf binary file format of a Discrete Displacement Field.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io {

/// @brief Format version this build writes and the newest it reads.
inline constexpr std::uint32_t kDdfFormatVersion = 1;

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
/// @return the file content.
std::string encodeDdf(const ddf::DisplacementField& field);

/// @brief Writes @p field to @p path in the .ddf format, atomically (temporary file + rename).
/// @throws IoError if the file cannot be written; the target is then left unchanged.
void writeDdf(const ddf::DisplacementField& field, const std::filesystem::path& path);

/// @brief Rebuilds a field from .ddf content; the exact inverse of encodeDdf (positions,
/// vectors, face vertex order and heights are bit-identical).
/// @param bytes whole file content; @param sourceName file name used in messages.
/// @throws IoError if the content is empty, truncated, has trailing bytes, a wrong magic, a
/// newer or invalid version, a foreign byte order, a checksum mismatch, or describes an invalid
/// field (index out of range, non-finite position, non-manifold support); the message names
/// @p sourceName and what is wrong.
ddf::DisplacementField decodeDdf(std::string_view bytes, const std::string& sourceName);

/// @brief Reads a .ddf file written by writeDdf.
/// @throws IoError if the file is missing or unreadable, or as decodeDdf.
ddf::DisplacementField readDdf(const std::filesystem::path& path);

}  // namespace ddfcam::io
