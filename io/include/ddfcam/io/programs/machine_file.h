// SPDX-License-Identifier: MIT
// ddfcam: a 5-axis machine described in a JSON file: rotary axes, their directions, pivot and
// table offsets, limits, the preferred solution and how the control takes positions.
#pragma once

#include <ddfcam/io/programs/gcode_writer.h>
#include <ddfcam/planning/placement/machine_kinematics.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io {

/// @brief A table-table 5-axis machine as a post-processor needs it.
struct MachineSetup {
  std::string name;                      ///< shown in the G-code header and the GUI
  std::string description;               ///< free text: model, source of the figures
  planning::TableKinematics kinematics;  ///< axes, directions, pivot, offsets, limits, solution
  /// The control does tool centre point control: X Y Z are the tool tip in the part frame
  /// (default false: machine X Y Z from the kinematics).
  bool tcpPositions = false;
  std::string tcpOnBlock;   ///< block switching TCP on, "{tool}" = tool number; may be empty
  std::string tcpOffBlock;  ///< block switching TCP off; may be empty

  bool operator==(const MachineSetup&) const = default;
};

/// @brief Parses a machine file. JSON object, every key but "name" optional (defaults of
/// planning::TableKinematics and MachineSetup):
///
///     {
///       "name": "Haas UMC-750",
///       "description": "...",
///       "rotary_axes": "BC",                 // "AC" or "BC"
///       "tilt_direction": -1,                // +1 right-handed about +X|+Y, -1 the other way
///       "rotary_direction": -1,              // +1 right-handed about the table normal, -1
///       "pivot_mm": [0, 0, 0],               // a point of the tilt axis, machine frame
///       "rotary_offset_mm": [0, 0, 0],       // C axis from the pivot at tilt 0
///       "tilt_limits_deg": [-35, 120],       // programmed A|B
///       "rotary_limits_deg": null,           // [min, max] or null for an endless table
///       "solution": "nearest",               // "nearest", "positive-tilt", "negative-tilt"
///       "positions": "tool-tip",             // "tool-tip" (TCP) or "machine"
///       "tcp_on": "G234 H{tool}", "tcp_off": "G49"
///     }
///
/// @param sourceName file name used in messages.
/// @throws IoError "<sourceName>: <what>" for malformed JSON, an unknown key (named), a value
/// of the wrong type or out of range, or kinematics planning::validateKinematics() refuses.
MachineSetup parseMachineFile(std::string_view text, const std::string& sourceName);

/// @brief The JSON text of @p machine, every key written; parseMachineFile() reads it back
/// to an equal MachineSetup.
/// @throws InvalidInput if the kinematics are invalid.
std::string formatMachineFile(const MachineSetup& machine);

/// @brief Reads the machine file @p path (see parseMachineFile).
/// @throws IoError if it is missing, unreadable, larger than 1 MiB, or as parseMachineFile.
MachineSetup readMachineFile(const std::filesystem::path& path);

/// @brief Sets @p params for @p machine: FiveAxis, its kinematics, TCP positions and blocks,
/// and its name in the header.
void applyMachine(const MachineSetup& machine, GCodeWriteParams& params);

}  // namespace ddfcam::io
