// SPDX-License-Identifier: MIT
// ddfcam: the tool library text file (one planning::Tool per line), read and written.
#pragma once

#include <ddfcam/planning/tools/tool.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Parses tool library text. The format (UTF-8, line based, locale independent):
///
///     # comment to the end of the line (outside quotes); blank lines are ignored
///     tool "ball D6" kind=ball_end radius_mm=3 width_mm=20 shank_radius_mm=3
///
/// One tool per line: the word `tool`, the name in double quotes (escapes \" \\ and \n), then
/// `key=value` pairs separated by blanks, in any order, each key at most once. `kind` is
/// required; every other key takes the default of planning::Tool when left out. Keys and
/// values (planning::Tool field):
/// | key | field | value |
/// |---|---|---|
/// | kind | kind | cylinder_roll, sphere, belt_contact_wheel, ball_end, flat_end, torus_cutter |
/// | radius_mm | radiusMm | decimal number (C locale: '.' decimal point, optional exponent) |
/// | width_mm | widthMm | number |
/// | edge_radius_mm | edgeRadiusMm | number |
/// | crown_radius_mm | crownRadiusMm | number |
/// | shank_radius_mm | shankRadiusMm | number |
/// | shank_length_mm | shankLengthMm | number |
/// | holder_radius_mm | holderRadiusMm | number |
/// | holder_length_mm | holderLengthMm | number |
/// | chord_tolerance_mm | chordToleranceMm | number |
/// | segments | segments | integer (0 = from the chord tolerance) |
/// Numbers must be finite. Every tool must pass planning::validateTool().
/// @param text whole file content. @param sourceName file name used in messages.
/// @return the tools in file order.
/// @throws IoError "<sourceName>:<line>:<column>: <what>" (column 1-based, in bytes) for a
/// syntax error, an unknown key or kind (named), a repeated or missing key, a bad number, or a
/// tool that fails validateTool (its message follows).
std::vector<planning::Tool> parseToolLibrary(std::string_view text, const std::string& sourceName);

/// @brief The text of @p tools in the format of parseToolLibrary: a comment header, then one
/// line per tool with every key; numbers in their shortest form that reads back to the same
/// double, so parseToolLibrary(formatToolLibrary(t)) == t exactly.
/// @throws InvalidInput if a tool fails planning::validateTool (nothing is formatted).
std::string formatToolLibrary(const std::vector<planning::Tool>& tools);

/// @brief Reads the tool library file @p path (see parseToolLibrary).
/// @throws IoError if the file is missing or unreadable, or as parseToolLibrary.
std::vector<planning::Tool> readToolLibrary(const std::filesystem::path& path);

/// @brief Writes @p tools to @p path atomically (see formatToolLibrary).
/// @throws InvalidInput as formatToolLibrary (the file is not touched).
/// @throws IoError if the file cannot be written.
void writeToolLibrary(const std::filesystem::path& path, const std::vector<planning::Tool>& tools);

}  // namespace ddfcam::io
