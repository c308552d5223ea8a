// SPDX-License-Identifier: MIT
// ddfcam-cli: the warnings of one command run, for the summary, the JSON report and --strict.
#include "run_warnings.h"

#include <cstdio>

namespace ddfcam::cli {

void RunWarnings::add(const std::string& text) {
  std::fprintf(stderr, "warning: %s\n", text.c_str());
  texts_.push_back(text);
}

void RunWarnings::write(JsonReport& json) const {
  json["run_warnings"] = count();
  json["warning_texts"] = texts_;
}

int RunWarnings::exitCode(bool strict, const std::string& command) const {
  if (!strict || count() == 0) return 0;
  std::fprintf(stderr, "ddfcam-cli %s: %d warning%s with --strict (exit code %d)\n",
               command.c_str(), count(), count() == 1 ? "" : "s", kStrictWarningExitCode);
  return kStrictWarningExitCode;
}

CLI::Option* addMinCoverageOption(Arguments& args, const std::string& description) {
  return args.option("--min-coverage", "P", description)->check(numberIn(0.0, 100.0));
}

double minCoverageOption(const Arguments& args, double fallback) {
  return args.number("min-coverage").value_or(fallback);
}

}  // namespace ddfcam::cli
