// SPDX-License-Identifier: MIT
// ddfcam: a cutter-location program, the tool path as exchanged with CAM systems, posts and robots.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/length_unit.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::planning {

/// @brief Which point of the tool a program's positions give.
enum class ClPointKind {
  Contact,       ///< the point meant to touch the design surface
  ToolReference  ///< origin of the tool frame (ToolKind): cutters' tip on the axis
                 ///< (APT's CL point), wheels' centre, a bare ball's centre
};

/// @brief One point of a program: the end point of a straight move from the previous point.
/// Part (program) frame, millimetres.
struct ClPoint {
  int path = 0;                              ///< 0-based pass / move index the point belongs to
  int point = 0;                             ///< 0-based index of the point within its path
  ddf::Vec3 positionMm = ddf::Vec3::Zero();  ///< contact or reference point (ClProgram::pointKind)
  /// Unit tool axis if the file gives one: the spindle (rotation) axis, for cutters from the
  /// tip towards the holder (APT's i,j,k); wheels' rotation axis. Empty: no axis given here,
  /// so the axis in force applies (the last one given before this point, as APT's 3-value
  /// GOTO keeps it); before any, 3-axis (+z) or the placement's default. Readers fill in the
  /// axis in force, so a point read from a file has one once any point before it had one.
  std::optional<ddf::Vec3> axis;
  std::optional<ddf::Vec3> normal;  ///< unit surface normal at the contact, tool side, if given
  double feedMmPerMin = 0.0;        ///< feed, mm/min; 0 for rapid moves or when the file gives none
  MoveKind move = MoveKind::Cut;    ///< cut, link or rapid
  int sourceLine = 0;  ///< 1-based line of the file the point was read from; 0 if not read

  bool operator==(const ClPoint&) const = default;
};

/// @brief APT's 7-parameter cutter description CUTTER/d,r,e,f,alpha,beta,h (lengths in mm,
/// angles in degrees): d diameter, r corner radius, e and f the corner centre's radial and axial
/// offsets, alpha the bottom angle, beta the side taper, h the height.
struct ClCutter {
  double diameterMm = 0.0;      ///< d, mm
  double cornerRadiusMm = 0.0;  ///< r, mm
  double eMm = 0.0;             ///< e: radial distance of the corner centre from the axis, mm
  double fMm = 0.0;             ///< f: axial height of the corner centre above the tip, mm
  double alphaDeg = 0.0;        ///< alpha: bottom angle, degrees
  double betaDeg = 0.0;         ///< beta: side taper angle, degrees
  double heightMm = 0.0;        ///< h: cutting height, mm

  bool operator==(const ClCutter&) const = default;
};

/// @brief A tool change within a program (APT LOADTL/CUTTER/TLDATA after motion, G-code T M6):
/// from points[firstPoint] on, this tool cuts.
struct ClToolChange {
  std::size_t firstPoint = 0;      ///< index into ClProgram::points of the first point it cuts
  int toolNumber = 1;              ///< LOADTL / T number, >= 0
  std::string toolName;            ///< tool name or description; may be empty
  std::optional<ClCutter> cutter;  ///< its CUTTER record, if known
  int sourceLine = 0;              ///< 1-based line of the record that changed it; 0 if none

  bool operator==(const ClToolChange&) const = default;
};

/// @brief A diagnostic tied to a line of the file it was read from.
struct ClMessage {
  int line = 0;      ///< 1-based source line; 0 if none
  std::string text;  ///< what was noticed, e.g. "unknown record 'PAINT' kept as a comment"

  bool operator==(const ClMessage&) const = default;
};

/// @brief A whole program: header data and points in machining order. Positions in mm in the
/// program frame; the unit of the file is kept in sourceUnit for display and re-export.
struct ClProgram {
  std::string partName;  ///< PARTNO, job or file name; may be empty
  /// Unit of the file read (or to write); programs hold millimetres, readers convert and
  /// writers convert back, feeds are in the unit per minute.
  LengthUnit sourceUnit = LengthUnit::Millimetre;
  ClPointKind pointKind = ClPointKind::ToolReference;  ///< meaning of ClPoint::positionMm
  int toolNumber = 1;                                  ///< LOADTL / T number, >= 0 (default 1)
  std::string toolName;                                ///< tool name or description; may be empty
  std::optional<ClCutter> cutter;                      ///< CUTTER record, if known
  double spindleRpm = 0.0;                             ///< spindle speed, rpm; 0 if not given
  bool spindleClockwise = true;                        ///< spindle direction (default CLW)
  bool coolant = false;                                ///< coolant on during the cut
  std::vector<ClPoint> points;                         ///< points in machining order
  /// Tools after the first, in order of increasing firstPoint (> 0); toolNumber, toolName and
  /// cutter above describe the tool of the first point. Empty: one tool throughout.
  std::vector<ClToolChange> toolChanges;
  std::vector<std::string> comments;  ///< comments and records kept as comments, in file order
  std::vector<ClMessage> warnings;    ///< what a reader noticed but could read past

  /// True when some point carries a tool axis (a 5-axis program).
  bool multiAxis() const;
  /// Number of paths: 1 + the largest ClPoint::path, 0 when there are no points.
  int pathCount() const;

  bool operator==(const ClProgram&) const = default;
};

/// @brief @p program cut at its tool changes: one program per tool segment, in order, each
/// with that tool's number, name and cutter in its header fields and no tool changes; path
/// indices renumbered from 0 within each. Segments without points are left out.
std::vector<ClProgram> splitByTool(const ClProgram& program);

}  // namespace ddfcam::planning
