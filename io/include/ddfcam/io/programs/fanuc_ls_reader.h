// SPDX-License-Identifier: MIT
// ddfcam: reading FANUC teach-pendant programs in their ASCII form (.ls).
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io {

/// @brief Parses a FANUC TP program in ASCII (.ls) form: `/PROG name`, `/ATTR`, `/MN` with
/// numbered instructions ending in ';' (continuation lines start with ':'), `/POS` with
/// Cartesian positions `P[n]{ GP1: UF : u, UT : t, CONFIG : '...', X = .. mm, Y = .. mm,
/// Z = .. mm, W = .. deg, P = .. deg, R = .. deg };` and `/END`.
///
/// Points come in the order the /MN motion instructions use them (a P[n] may be visited
/// several times). `J P[n] ...` (joint motion) gives a MoveKind::Rapid point with feed 0 and
/// starts a new path when the current one already holds points reached by linear moves;
/// `L P[n] speed term` gives a Cut point with the speed converted to mm/min (mm/sec x 60,
/// cm/min x 10, inch/min x 25.4); deg/sec, sec, msec, % and speed registers give no linear
/// feed (0, with a warning). `C P[via] P[end]` and `A P[n]` (circular motion) are approximated
/// by straight Cut moves through their points, with a warning. Positions are the TCP in mm in
/// the user frame of the point (ClPointKind::ToolReference, sourceUnit Millimetre); the tool
/// axis is the tool frame's z axis R * (0,0,1) with FANUC's fixed-angle convention
/// R = Rz(R) * Ry(P) * Rx(W). The program's partName is the /PROG name and toolNumber the
/// first UTOOL_NUM. Comments (`!text`) are kept; other instructions (CALL, WAIT, I/O, motion
/// to position registers PR[n], ...) are kept as comments with a warning, as are motion options
/// (Offset, Tool_Offset, INC, ...) that would change the point; points in a user frame other
/// than 0 give a warning.
/// @param sourceName file name used in messages.
/// @throws IoError "<sourceName>: line N: <what>" when /PROG is missing, an instruction is
/// malformed or never ends with ';', a P[n] used by /MN has no /POS entry or only joint
/// angles, a /POS entry is malformed, duplicated or lacks one of X Y Z W P R, a coordinate is
/// beyond +-1e12 mm or a speed beyond 1e12 mm/min after conversion; and
/// "<sourceName>: ..." when there is no /MN section or no motion at all.
planning::ClProgram decodeFanucLs(std::string_view text, const std::string& sourceName);

/// @brief Reads a FANUC .ls file (see decodeFanucLs).
/// @throws IoError if the file is missing, unreadable, larger than 1 GiB, or as decodeFanucLs.
planning::ClProgram readFanucLs(const std::filesystem::path& file);

}  // namespace ddfcam::io
