// SPDX-License-Identifier: MIT
// ddfcam: cutter-location programs as CSV tables (one row per point) for robots, posts and
// spreadsheets; reads the common x,y,z[,i,j,k] variants too. Format: docs/tool_path_csv.md.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/cl_program_builder.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Options of the CSV writer.
struct CsvWriteParams {
  /// Digits after the decimal point of every real column, 0..17 (default 6: 1 nm in mm).
  int decimals = 6;
  /// Unit of the position and feed columns, named in the header (default mm).
  LengthUnit unit = LengthUnit::Millimetre;
};

/// @brief Largest number of data rows the reader accepts by default (50 million).
inline constexpr std::size_t kMaxCsvRows = 50'000'000;

/// @brief Options of the CSV reader.
struct CsvReadParams {
  /// Unit of the positions and feeds when the file does not name one (no ddfcam header), e.g.
  /// Metre for robot paths (default mm).
  LengthUnit unitIfUnstated = LengthUnit::Millimetre;
  /// Meaning of the positions when the file does not say (default tool reference point).
  planning::ClPointKind kindIfUnstated = planning::ClPointKind::ToolReference;
  /// More data rows than this are refused with an IoError (default kMaxCsvRows, 50 million).
  std::size_t maxRows = kMaxCsvRows;
};

/// @brief The header line (without line end): "path,point,P_x_U,P_y_U,P_z_U,axis_i,axis_j,
/// axis_k,normal_x,normal_y,normal_z,feed_U_per_min,move" with P = "contact" or "tool" and
/// U = unitSymbol(@p unit) ("mm", "in", "m").
std::string toolPathCsvHeader(planning::ClPointKind kind, LengthUnit unit = LengthUnit::Millimetre);

/// @brief The CSV text of @p program: the header, then one line per point, each ending in
/// "\n". Integers in decimal, reals in fixed notation with params.decimals digits and a '.'
/// whatever the locale (std::to_chars), positions and feeds converted to params.unit, move as
/// "cut", "link" or "rapid". A point without axis (or normal) has the three axis (normal)
/// fields empty. Header data other than the point kind (part and tool names, cutter, spindle,
/// comments, warnings) is not written.
/// @throws InvalidInput if params.decimals is outside 0..17 or a value is not finite (naming
/// the point).
std::string encodeToolPathCsv(const planning::ClProgram& program,
                              const CsvWriteParams& params = {});

/// @brief Writes encodeToolPathCsv() to @p file atomically (temporary file + rename).
/// @throws InvalidInput as encodeToolPathCsv(). @throws IoError if the file cannot be written.
void writeToolPathCsv(const planning::ClProgram& program, const std::filesystem::path& file,
                      const CsvWriteParams& params = {});

/// @brief File name @p base would get for a program named @p name in writeToolPathCsvFiles():
/// "<stem>_<sanitised name><extension>" next to @p base (extension ".csv" if @p base has none);
/// sanitised: every character other than ASCII letters, digits, '-' and '_' becomes '_', runs
/// of '_' are merged, leading and trailing '_' dropped; an empty result is "program".
std::filesystem::path toolPathCsvFileFor(const std::filesystem::path& base,
                                         const std::string& name);

/// @brief Writes each of @p programs to its own file (toolPathCsvFileFor(base, name); names
/// that sanitise alike get "_2", "_3", ... appended), or to @p base itself when there is
/// exactly one program.
/// @return the written files, in the order of @p programs.
/// @throws InvalidInput if @p programs is empty, as encodeToolPathCsv(); IoError as
/// writeToolPathCsv().
std::vector<std::filesystem::path> writeToolPathCsvFiles(
    const std::vector<planning::NamedProgram>& programs, const std::filesystem::path& base,
    const CsvWriteParams& params = {});

/// @brief Parses a ddfcam tool-path CSV (units and point kind from its header) or a common
/// variant: columns x,y,z / x,y,z,i,j,k / path,x,y,z[,i,j,k] with or without a header line
/// (names such as x y z i j k nx ny nz path path_index point feed move, any case), fields
/// separated by commas, semicolons, tabs or blanks (detected from the first data line), '#'
/// lines kept as comments, blank lines and "\r\n" line ends accepted. A path column gives
/// ClPoint::path (renumbered to 0-based consecutive indices in order of first appearance),
/// otherwise all points are path 0; point indices count within each path. Axes are normalised
/// to unit length. Every ClPoint::sourceLine is set; sourceUnit is the unit of the file.
/// @param sourceName file name used in messages and as the program's partName (its stem).
/// @throws IoError "<sourceName>: line N: <what>" for a wrong field count, a field that is not a
/// number, a zero, partial or non-finite axis or normal, an unknown move word, a negative path
/// index, a negative feed, a position beyond +-1e12 mm or a feed beyond 1e12 mm/min after the
/// unit conversion; or "<sourceName>: ..." for text with no data row recognised as such, binary
/// content, or more than params.maxRows rows.
planning::ClProgram decodeToolPathCsv(std::string_view text, const std::string& sourceName,
                                      const CsvReadParams& params = {});

/// @brief Reads @p file as decodeToolPathCsv().
/// @throws IoError if the file is missing, unreadable or larger than 1 GiB, or as
/// decodeToolPathCsv().
planning::ClProgram readToolPathCsv(const std::filesystem::path& file,
                                    const CsvReadParams& params = {});

}  // namespace ddfcam::io
