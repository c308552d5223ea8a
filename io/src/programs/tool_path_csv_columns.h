// SPDX-License-Identifier: MIT
// ddfcam: columns of a tool-path CSV: which quantity a header name or a headerless field count
// stands for, and the units and point kind the header states.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief Quantity held by a CSV column.
enum class CsvColumn { Ignore, Path, Point, X, Y, Z, I, J, K, Nx, Ny, Nz, Feed, Move };

/// @brief Column layout of a CSV with the units and point kind it states.
struct CsvLayout {
  std::vector<CsvColumn> columns;             ///< one entry per field
  std::optional<LengthUnit> unit;             ///< unit of the position columns, if stated
  std::optional<LengthUnit> feedUnit;         ///< unit of the feed column, if stated
  std::optional<planning::ClPointKind> kind;  ///< point kind, if stated (ddfcam's own header)
  std::vector<std::string> ignoredColumns;    ///< header names not understood (kept as warnings)
};

/// @brief A layout, or why a header does not give one.
struct CsvLayoutResult {
  std::optional<CsvLayout> layout;  ///< set on success
  std::string error;                ///< why not, when layout is empty
};

/// @brief The layout of header fields @p names (any case, quotes and blanks around names
/// allowed, units as "_mm", "[mm]" or "(mm)" suffixes).
/// @return the layout, or an error text (column named twice, unknown unit, conflicting units,
/// missing x/y/z, incomplete axis or normal).
CsvLayoutResult layoutFromHeader(const std::vector<std::string_view>& names);

/// @brief The layout of a headerless file with @p fields fields per line: 3 x,y,z; 4
/// path,x,y,z; 6 x,y,z,i,j,k; 7 path,x,y,z,i,j,k; 13 ddfcam's own columns.
/// @return std::nullopt for any other count.
std::optional<CsvLayout> layoutFromFieldCount(std::size_t fields);

/// @brief Readable list of the headerless layouts for error messages.
std::string headerlessLayouts();

}  // namespace ddfcam::io::detail
