// SPDX-License-Identifier: MIT
// ddfcam-cli: the warnings of one command run, for the summary, the JSON report and --strict.
#include "run_warnings.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace ddfcam::cli {

void RunWarnings::add(const std::string& text) {
  std::fprintf(stderr, "warning: %s\n", text.c_str());
  texts_.push_back(text);
}

void RunWarnings::write(JsonWriter& json) const {
  json.key("run_warnings").value(count());
  json.key("warning_texts").beginArray();
  for (const std::string& text : texts_) json.value(text);
  json.endArray();
}

int RunWarnings::exitCode(bool strict, const std::string& command) const {
  if (!strict || count() == 0) return 0;
  std::fprintf(stderr, "ddfcam-cli %s: %d warning%s with --strict (exit code %d)\n",
               command.c_str(), count(), count() == 1 ? "" : "s", kStrictWarningExitCode);
  return kStrictWarningExitCode;
}

double minCoverageOption(const Arguments& args, double fallback) {
  const std::optional<std::string> text = args.value("min-coverage");
  if (!text) return fallback;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || !std::isfinite(value) ||
      value < 0.0 || value > 100.0)
    throw UsageError("--min-coverage " + *text + ": expected a percentage in [0, 100]");
  return value;
}

}  // namespace ddfcam::cli
