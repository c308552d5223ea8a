// SPDX-License-Identifier: MIT
// ddfcam: the optional metadata section of a version-2 .ddf file (layout in ddf_file.h).
#pragma once

#include <ddfcam/io/mesh/ddf_file.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ddfcam::io::detail {

/// @brief The code of @p unit in .ddf and .ddfproj files: 0 mm, 1 cm, 2 m, 3 in.
std::uint32_t lengthUnitCode(ddfcam::LengthUnit unit);

/// @brief The unit of a stored @p code; std::nullopt for an unknown code.
std::optional<ddfcam::LengthUnit> lengthUnitOfCode(std::uint32_t code);

/// @brief Checks @p metadata against a field of @p faceCount support faces.
/// @throws InvalidInput if cadFaceOfSupportFace is neither empty nor @p faceCount long, or
/// holds an entry outside [-1, cadFaceNames.size()).
void checkDdfMetadata(const DdfMetadata& metadata, int faceCount);

/// @brief Appends the section (u32 length, then the members) for @p metadata to @p out.
void putDdfMetadata(std::string& out, const DdfMetadata& metadata);

/// @brief Parses the members of a section (the bytes after its u32 length) of a field with
/// @p faceCount support faces; bytes after the known members are ignored.
/// @return the metadata with stored = true.
/// @throws IoError "<sourceName>: metadata section: ..." if it is truncated or inconsistent.
DdfMetadata readDdfMetadata(std::string_view section, int faceCount, const std::string& sourceName);

}  // namespace ddfcam::io::detail
