// SPDX-License-Identifier: MIT
// ddfcam: tool paths as CSV tables (one row per point) for post-processors and spreadsheets.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/path_linking.h>
#include <ddfcam/planning/tool_path.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Which point of the tool the x y z columns give.
enum class CsvPointKind {
  Contact,       ///< PathPose::contact, the point meant to touch the design surface
  ToolReference  ///< origin of the tool frame (PathPose::pose translation): roll or ball centre
};

/// @brief One row of a tool-path CSV: one point of the program. Part frame, mm.
struct ToolPathCsvRow {
  int path = 0;                             ///< pass (ToolPath) or move (LinkedPaths), 0-based
  int point = 0;                            ///< point within the pass or move, 0-based
  ddf::Vec3 position = ddf::Vec3::Zero();   ///< contact or tool reference point, mm
  ddf::Vec3 toolAxis = ddf::Vec3::UnitX();  ///< tool frame +x in the part frame (roll axis), unit
  ddf::Vec3 normal = ddf::Vec3::UnitZ();    ///< surface normal at the contact, tool side, unit
  double feedMmPerMin = 0.0;                ///< feed, mm/min; 0 on Rapid rows (machine rapid)
  planning::MoveKind move = planning::MoveKind::Cut;  ///< cut, link or rapid
};

/// @brief A whole table: its rows and which point they give.
struct ToolPathCsv {
  CsvPointKind pointKind = CsvPointKind::Contact;  ///< meaning of the x y z columns
  std::vector<ToolPathCsvRow> rows;                ///< rows in machining order
};

/// @brief Options of the CSV writer.
struct ToolPathCsvParams {
  /// Digits after the decimal point of every real column, 0..17 (default 6: 1 nm in mm).
  int decimals = 6;
};

/// @brief Rows of @p path: one per pose, pass by pass (ToolPath::passStarts; a path without
/// passStarts is one pass), all Cut at the path's feed. The tool axis is pose.linear() * +x.
/// @param normals #poses unit normals (tool side) or empty: then each normal is the direction
/// from the contact to the tool reference point, which is the normal for poses made by
/// rollPoseAtContact or toolPathFromStreamlines (the tool sits R - depth > 0 above the contact).
/// @param kind contact or tool reference point in the x y z columns.
/// @throws InvalidInput if @p normals has another size, or a derived normal is undefined
/// (reference point on the contact).
ToolPathCsv toolPathCsvRows(const planning::ToolPath& path, CsvPointKind kind,
                            const std::vector<ddf::Vec3>& normals = {});

/// @brief Rows of a linked program: one block per move of @p linked, in order (path column =
/// move index). A Cut move takes the poses of pass move.path of @p path (in reverse order if
/// move.reversed); its points must be that pass's contacts. Link and Rapid rows use the move's
/// points as contact-level points and carry the tool axis, normal and reference-point offset of
/// the last pose of the preceding Cut (the tool keeps that orientation while it travels); their
/// feed is the path's feed for Link and 0 for Rapid.
/// @param path poses, one pass per input path of linkPaths (same indices).
/// @param normals #poses unit normals (tool side) of @p path, or empty: then derived as in
/// toolPathCsvRows() (needed for cutters, whose tip may be the contact).
/// @throws InvalidInput if a Cut refers to a missing pass, its points do not match the pass's
/// contacts (count or value), the first move is not a Cut, or @p normals has another size.
ToolPathCsv linkedToolPathCsvRows(const planning::LinkedPaths& linked,
                                  const planning::ToolPath& path, CsvPointKind kind,
                                  const std::vector<ddf::Vec3>& normals = {});

/// @brief The header line (without line end) for @p kind:
/// "path,point,P_x_mm,P_y_mm,P_z_mm,axis_i,axis_j,axis_k,normal_x,normal_y,normal_z,
/// feed_mm_per_min,move" with P = "contact" or "tool".
std::string toolPathCsvHeader(CsvPointKind kind);

/// @brief The CSV text: the header, then one line per row, each ending in "\n". Integers in
/// decimal, reals in fixed notation with params.decimals digits and a '.' whatever the locale
/// (std::to_chars), "nan"/"inf" for non-finite values, move as "cut", "link" or "rapid".
/// @throws InvalidInput if params.decimals is outside 0..17.
std::string encodeToolPathCsv(const ToolPathCsv& table, const ToolPathCsvParams& params = {});

/// @brief Parses text written by encodeToolPathCsv (either header; "\r\n" line ends accepted;
/// blank last line allowed). Values are read back to the written precision.
/// @param sourceName file name used in messages.
/// @throws IoError "<sourceName>: line N: ..." naming the line and the column that does not
/// parse (unknown header, wrong field count, bad number, unknown move type).
ToolPathCsv decodeToolPathCsv(std::string_view text, const std::string& sourceName);

/// @brief Writes encodeToolPathCsv() to @p file atomically (temporary file + rename).
/// @throws InvalidInput as encodeToolPathCsv. @throws IoError if the file cannot be written.
void writeToolPathCsv(const ToolPathCsv& table, const std::filesystem::path& file,
                      const ToolPathCsvParams& params = {});

/// @brief Reads a CSV written by writeToolPathCsv.
/// @throws IoError if the file is missing or unreadable, or as decodeToolPathCsv.
ToolPathCsv readToolPathCsv(const std::filesystem::path& file);

}  // namespace ddfcam::io
