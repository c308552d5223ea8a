// SPDX-License-Identifier: MIT
// ddfcam-cli: the warnings of one command run, for the summary, the JSON report and --strict.
#pragma once

#include "arguments.h"
#include "json_output.h"

#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief Exit code of a run that completed and wrote its outputs but had warnings, with
/// --strict (0 without it; 1 is an error, 2 a usage error).
inline constexpr int kStrictWarningExitCode = 3;

/// @brief Warnings of one run: printed to stderr as "warning: TEXT" when added, counted for
/// --strict and listed in the JSON report.
class RunWarnings {
 public:
  /// @brief Prints "warning: @p text" to stderr and keeps it.
  void add(const std::string& text);
  /// @brief Counts @p count warnings printed elsewhere (e.g. a reader's line warnings).
  void addPrinted(int count) { printed_ += count; }
  /// @brief All warnings of the run.
  int count() const { return printed_ + static_cast<int>(texts_.size()); }
  /// @brief Sets "run_warnings": count and "warning_texts": [...] (the added ones) in the
  /// object @p json.
  void write(JsonReport& json) const;
  /// @brief 0, or with @p strict and warnings kStrictWarningExitCode after printing
  /// "COMMAND: N warnings with --strict" to stderr.
  int exitCode(bool strict, const std::string& command) const;

 private:
  std::vector<std::string> texts_;
  int printed_ = 0;
};

/// @brief Adds --min-coverage P (a percentage in [0, 100]) with @p description.
CLI::Option* addMinCoverageOption(Arguments& args, const std::string& description);

/// @brief The --min-coverage of addMinCoverageOption(), or @p fallback if absent.
double minCoverageOption(const Arguments& args, double fallback);

}  // namespace ddfcam::cli
