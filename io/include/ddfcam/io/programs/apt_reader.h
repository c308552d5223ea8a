// SPDX-License-Identifier: MIT
// ddfcam: APT/CLDATA source input as real CAM systems write it (NX CLSF, Pro/CLfile, ...).
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace ddfcam::io {

/// @brief Options of the APT reader.
struct AptReadParams {
  /// Largest distance between a CIRCLE arc and the chords that replace it, mm, > 0
  /// (default 0.005).
  double chordToleranceMm = 0.005;
};

/// @brief Reads APT/CLDATA source text into a program (positions and feeds in mm, tool
/// reference points = APT CL points, pointKind ToolReference). Accepts "$$" comments (whole
/// line and trailing), "$" continuation, blanks around '/' and after commas, any letter case;
/// GOTO with 3 or 6 values (6 values: a multi-axis point, whether or not MULTAX/ON came);
/// FROM (a rapid start point); RAPID (the next motion only); FEDRAT in both orders (MMPM, IPM;
/// MMPR/IPR give a warning); UNITS/MM, UNIT/MM, UNITS/INCHES (without a UNITS record the unit
/// of the first FEDRAT's IPM/MMPM, else mm); CIRCLE/xc,yc,zc,i,j,k,r[,...] followed by the
/// end-point GOTO, interpolated at params.chordToleranceMm (clockwise seen from the tip of the
/// axis vector, as NX writes it; a GOTO on the start point makes a full circle);
/// PARTNO (with or without '/'), LOADTL, CUTTER, TLDATA, SPINDL, COOLNT, MSYS (a warning if
/// not identity; not applied), END, FINI. Unknown major words are kept in comments with one
/// warning per distinct word. A new path starts at the first cut move after a rapid.
/// @param sourceName file name used in messages.
/// @throws IoError "<name>: line N: <what>" for truncated records, non-numbers, wrong value
/// counts, zero axis vectors, a CIRCLE not followed by a GOTO or with an inconsistent radius,
/// binary input, or more than 50 M points; positions beyond +-1e12 mm or feeds beyond 1e12
/// mm/min after the unit conversion, negative feeds, a CIRCLE of radius > 1e6 mm, an arc needing
/// more than 1e6 chords or arcs adding more than 1e6 points to one program (use a coarser
/// chord tolerance); InvalidInput for a bad chord tolerance.
planning::ClProgram decodeApt(std::string_view text, const std::string& sourceName,
                              const AptReadParams& params = {});

/// @brief decodeApt() of the file at @p path (files over 1 GiB are refused).
/// @throws IoError as decodeApt(), and if the file is missing, unreadable or too large.
planning::ClProgram readApt(const std::filesystem::path& path, const AptReadParams& params = {});

}  // namespace ddfcam::io
