// SPDX-License-Identifier: MIT
// ddfcam: RS274NGC G-code output of a cutter-location program, 3-axis or 5-axis table-table.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/placement/machine_kinematics.h>
#include <ddfcam/planning/tools/tool.h>

#include <filesystem>
#include <string>

namespace ddfcam::io {

/// @brief Options of encodeGCode() / writeGCode().
struct GCodeWriteParams {
  /// @brief Machine the program is for.
  enum class Mode {
    ThreeAxis,  ///< X Y Z only; the tool axis must be +Z on every point
    FiveAxis    ///< X Y Z plus A|B and C of a table-table machine (kinematics)
  };
  Mode mode = Mode::ThreeAxis;           ///< (default ThreeAxis)
  planning::TableKinematics kinematics;  ///< FiveAxis machine (default: A/C, pivot at origin)
  /// Rotary positions the inverse kinematics start from (the first point's solution is the
  /// one nearest to it). Default A|B = 0, C = 0.
  planning::MachinePose startPose;
  LengthUnit unit = LengthUnit::Millimetre;  ///< G21 mm or G20 inch; Metre is refused (mm)
  int decimals = 4;          ///< digits after the point of X Y Z and F, 1..8 (default 4)
  int angleDecimals = 4;     ///< digits after the point of A B C (degrees), 1..8 (default 4)
  bool lineNumbers = false;  ///< write N words (N10, N20, ...) (default false)
  int lineNumberStep = 10;   ///< increment of N words, 1..1000 (default 10)
  /// Height of the safe plane above the highest machine Z of the program, mm: the program
  /// starts with a rapid to it, over the first point, and ends with a retract to it
  /// (default 10).
  double rapidClearanceMm = 10.0;
  int toolNumber = -1;  ///< T word, >= 1; -1 = ClProgram::toolNumber (or 1 if that is 0)
  /// Spindle speed, rpm, > 0; 0 = ClProgram::spindleRpm, or 6000 if that is 0 (default 0).
  double spindleRpm = 0.0;
  /// Feed for cut and link points whose ClPoint::feedMmPerMin is 0, mm/min, > 0
  /// (default 1000).
  double defaultFeedMmPerMin = 1000.0;
  /// Write the tool length offset G43 H<tool> after the tool change (default true).
  bool toolLengthOffset = true;
  /// Inverse-time feed (G93): every G1 carries F = 1 / (minutes for the move), the minutes
  /// being the tip's straight distance over the part divided by the point's feed, so the tip
  /// keeps the programmed feed over the part while the tables turn (pure rotations: degrees
  /// divided by the feed). Default false: G94, F in mm/min (inch/min).
  bool inverseTimeFeed = false;
  /// FiveAxis: write X Y Z as the tool tip in the part frame, for a control that does the
  /// kinematics itself (tool centre point control: Haas G234, LinuxCNC G43.4, Fanuc G43.4);
  /// false: machine X Y Z from the kinematics (default false).
  bool tcpPositions = false;
  /// Block that switches the control's TCP on after each tool change, "{tool}" standing for
  /// the tool number (e.g. "G234 H{tool}"); it replaces G43 H. Empty: none (default).
  std::string tcpOnBlock;
  /// Block that switches TCP off before a tool change and at the end (e.g. "G49"); empty: none
  /// (default).
  std::string tcpOffBlock;
  /// Machine named in the header comment (a machine file's name); empty: none (default).
  std::string machineName;
};

/// @brief The program as RS274NGC text (LinuxCNC dialect, one block per line, "\n" endings).
/// Start: comments (part, tool, machine), G17 G21|G20 G40 G49 G80 G90 G94|G93, T M6 (G43 H), S
/// M3|M4, M8 when ClProgram::coolant; a G0 to the safe plane and over the first point. Then one
/// line per ClPoint: G0 X Y Z [A|B C] for rapid moves (no F), G1 ... F for cut and link moves (F in
/// mm/min, or inch/min with G20, written when it changes; with inverseTimeFeed on every G1);
/// every motion line carries its G word.
/// At each ClProgram::toolChanges entry: retract to the safe plane, T M6 (G43 H) of that tool,
/// G0 over its first point. A point without an axis keeps the axis in force (the last one
/// given), +Z before any.
/// End: G0 retract to the safe plane, M5 M9, M30.
/// Positions: the tool tip (planning::Tool frame origin). For ClPointKind::Contact programs
/// the tip is computed from the contact point c, the unit normal n (required) and the tool
/// axis a: tip = c + r n + (R - r) h - r a with h the normalised part of n normal to a (0 if
/// n is along a): r = R for BallEnd, r = 0 for FlatEnd, r = edgeRadiusMm for TorusCutter.
/// ThreeAxis: X Y Z are the tip in the part (work) frame. FiveAxis: machine positions from
/// planning::inverseKinematics() of the tip and axis (points without an axis use +Z).
/// @param tool a cutter (BallEnd, FlatEnd or TorusCutter).
/// @throws InvalidInput for a tool that is not a cutter or invalid, invalid params, a
/// non-finite value, a missing or non-unit normal of a contact point or one pointing away from
/// the tool side (n . a < 0), a tilted axis in ThreeAxis mode, or an axis the machine cannot
/// reach; messages name the point (index, path, source line).
std::string encodeGCode(const planning::ClProgram& program, const planning::Tool& tool,
                        const GCodeWriteParams& params = {});

/// @brief Writes encodeGCode() to @p path atomically (temporary file + rename).
/// @throws InvalidInput as encodeGCode(); IoError if the file cannot be written.
void writeGCode(const std::filesystem::path& path, const planning::ClProgram& program,
                const planning::Tool& tool, const GCodeWriteParams& params = {});

}  // namespace ddfcam::io
