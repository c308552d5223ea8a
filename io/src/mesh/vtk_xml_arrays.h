// SPDX-License-Identifier: MIT
// ddfcam: decoding VTK XML DataArray elements (ascii, base64 binary, appended; zlib).
#pragma once

#include "vtk_xml_document.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief File-wide settings for decoding data arrays.
struct VtkArrayContext {
  std::string_view text;  ///< whole file
  const XmlDocument* doc = nullptr;
  bool bigEndian = false;       ///< VTKFile byte_order
  int headerBytes = 4;          ///< VTKFile header_type: 4 (UInt32) or 8 (UInt64)
  bool compressed = false;      ///< VTKFile compressor="vtkZLibDataCompressor"
  bool appendedBase64 = false;  ///< AppendedData encoding="base64"
  std::string source;           ///< file name for messages
};

/// @brief Name and number of components of a DataArray element.
struct VtkArrayInfo {
  std::string name;    ///< Name attribute (may be empty)
  int components = 1;  ///< NumberOfComponents, >= 1
};

/// @brief Name and components of DataArray @p element.
/// @throws IoError for a bad NumberOfComponents.
VtkArrayInfo vtkArrayInfo(const VtkArrayContext& ctx, int element);

/// @brief Values of DataArray @p element converted to double, exactly @p tuples x components.
/// @param what names the array in messages, e.g. "Piece 0 Points".
/// @throws IoError "<source>: <what>: ..." if the array is malformed, of another size, of an
/// unknown type or format.
std::vector<double> decodeVtkArray(const VtkArrayContext& ctx, int element, std::size_t tuples,
                                   const std::string& what);

}  // namespace ddfcam::io::detail
