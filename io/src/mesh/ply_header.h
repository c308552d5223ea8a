// SPDX-License-Identifier: MIT
// ddfcam: the PLY header (elements, properties, encoding) as parsed from a file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

enum class PlyEncoding { Ascii, BinaryLittle, BinaryBig };

/// @brief One PLY scalar type.
struct ScalarType {
  int bytes = 0;
  bool isFloat = false;
  bool isSigned = false;
};

struct PlyProperty {
  std::string name;
  ScalarType type;                      ///< value type (item type for lists)
  std::optional<ScalarType> countType;  ///< set for list properties
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;  ///< byte offset of the first body byte
  int bodyFirstLine = 0;       ///< line number of the first body line (ASCII)
};

/// @brief Parses the header of a PLY file.
/// @throws IoError naming the file and line for anything malformed.
PlyHeader readPlyHeader(std::string_view bytes, const std::string& name);

}  // namespace ddfcam::io::detail
