// SPDX-License-Identifier: MIT
// ddfcam: APT/CLDATA source output (PARTNO ... GOTO ... FINI) for NC post-processors.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>
#include <ddfcam/planning/tools/tool.h>

#include <filesystem>
#include <string>

namespace ddfcam::io {

/// @brief Options of the APT writer.
struct AptWriteParams {
  int coordinateDecimals = 4;  ///< digits after the point of lengths and feeds, 4..6 (default 4)
  int vectorDecimals = 7;      ///< digits after the point of tool-axis components, 6..9 (default 7)
  /// Unit of the file: Millimetre (UNITS/MM, feeds MMPM) or Inch (UNITS/INCHES, feeds IPM).
  /// Metre is refused. Default Millimetre.
  LengthUnit unit = LengthUnit::Millimetre;
  /// NX dialect: FEDRAT/MMPM,f (unit first) instead of FEDRAT/f,MMPM. Default false.
  bool feedUnitFirst = false;
  /// Longest record line; longer records are broken after a comma with a trailing '$',
  /// 32..200 (default 72, the card width of APT source).
  int maxColumns = 72;
};

/// @brief The APT source text of @p program, lines ending in "\n": PARTNO (no slash; an empty
/// name gives DDFCAM; '$' and control characters become '_'), UNITS, program.comments as "$$"
/// lines (split at line ends and at the column limit), CUTTER (if program.cutter), LOADTL,
/// SPINDL/rpm,CLW|CCLW (if spindleRpm > 0), COOLNT/ON (if program.coolant), MULTAX/ON (if
/// program.multiAxis()), then per point CUTTER and LOADTL where a tool change starts
/// (ClProgram::toolChanges), RAPID (rapid moves), FEDRAT (when the feed of a non-rapid
/// move changes) and GOTO/x,y,z[,i,j,k]; then COOLNT/OFF, SPINDL/OFF, END, FINI. A point without an
/// axis in a multi-axis program is written with 3 values (APT keeps the previous axis). A
/// feed or link point whose GOTO would repeat the previous one as written (the first cut point
/// of a linked pass repeats the end of its approach) is left out: no zero-length moves.
/// Positions and feeds are converted from mm to params.unit.
/// @throws InvalidInput for a Contact program (APT needs tool reference points), decimals or
/// columns out of range, a Metre unit, non-finite positions, feeds or cutter values or ones
/// of 1e9 file units or more, or a non-unit or non-finite axis (|1 - |a|| > 1e-6).
std::string encodeApt(const planning::ClProgram& program, const AptWriteParams& params = {});

/// @brief Writes encodeApt(program, params) to @p path atomically (temporary file + rename).
/// @throws InvalidInput as encodeApt(); IoError if the file cannot be written.
void writeApt(const planning::ClProgram& program, const std::filesystem::path& path,
              const AptWriteParams& params = {});

}  // namespace ddfcam::io
