// SPDX-License-Identifier: MIT
// ddfcam-cli: the subcommands; each takes the words after its name and returns the exit code.
#pragma once

#include <span>
#include <string>

namespace ddfcam::cli {

/// @brief A subcommand: name, one-line summary, help text and entry point.
struct Command {
  const char* name;
  const char* summary;
  /// The --help text, generated from the command's option table.
  std::string (*help)();
  /// Runs the command; throws ddfcam::Error (UsageError for bad arguments) on failure.
  int (*run)(std::span<const std::string> args);
};

extern const Command kConvertCommand;
extern const Command kExtractCommand;
extern const Command kInfoCommand;
extern const Command kDemoCommand;
extern const Command kCurvatureCommand;   // section C
extern const Command kPlanCommand;        // section L
extern const Command kSimulateCommand;    // section BV
extern const Command kRunCommand;         // section JB
extern const Command kPathsCommand;       // section CP
extern const Command kCompareCommand;     // section PRJ
extern const Command kCompensateCommand;  // section PRJ

}  // namespace ddfcam::cli
