// SPDX-License-Identifier: MIT
// ddfcam-cli: helpers shared by the compare and compensate commands (number lists, surfaces,
// text output).
#pragma once

#include <ddfcam/length_unit.h>
#include <ddfcam/planning/mould/mould_study.h>

#include "arguments.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief What the options shared by compare and compensate apply to, for their descriptions.
struct MouldOptionTexts {
  std::string surfaces;  ///< the files --units applies to, e.g. "MOULD and FORMED"
  std::string written;   ///< e.g. "the outputs are in mm"
  std::string ddf;       ///< the DDF of --resolution, e.g. "the mould DDF"
  std::string reach;     ///< description of --reach
  std::string json;      ///< what --json writes
};

/// @brief Default --resolution of the DDF on the mould or target.
inline constexpr int kMouldResolution = 4;

/// @brief Adds the options compare and compensate share: --units, --resolution (2..64,
/// default kMouldResolution), --reach and --json.
void addMouldOptions(Arguments& args, const MouldOptionTexts& texts);

/// @brief @p count finite numbers separated by commas, e.g. "-0.2,0.5" for --band.
/// @throws UsageError naming @p option if the text is not such a list.
std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& option);

/// @brief Reads a surface file (io::readSurfaceFile: STL/OBJ/PLY/OFF/VTP/VTU) in @p unit (mm
/// when not given), scaled to mm, and prints its size on stderr, labelled @p role ("mould",
/// "formed"); without a unit it warns when the size suggests another one (warnIfOtherUnit).
/// @throws IoError as readSurfaceFile.
planning::LoadedSurface loadSurface(const std::filesystem::path& path, const std::string& role,
                                    const std::optional<ddfcam::LengthUnit>& unit);

/// @brief Writes @p text to @p file (replacing it).
/// @throws IoError naming @p command and the file if it cannot be written.
void writeTextFile(const std::string& text, const std::filesystem::path& file,
                   const std::string& command);

/// @brief Seconds elapsed since @p start.
double secondsSince(std::chrono::steady_clock::time_point start);

}  // namespace ddfcam::cli
