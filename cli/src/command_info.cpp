// SPDX-License-Identifier: MIT
// ddfcam-cli info: sizes, height range, bounds and file facts of a .ddf file.
#include <ddfcam/ddf/validation.h>
#include <ddfcam/io/ddf_file.h>

#include "arguments.h"
#include "commands.h"
#include "field_summary.h"

#include <array>
#include <cstdio>
#include <filesystem>

namespace ddfcam::cli {
namespace {

constexpr const char* kHelp =
    "usage: ddfcam-cli info IN.ddf [--json]\n\n"
    "Prints the support size (vertices, faces), raster resolution m and raster point counts,\n"
    "memory, height range (in vector lengths), support and surface bounding boxes (mm), and\n"
    "the check of the three DDF constraints (chapter 3).\n\n"
    "options:\n"
    "  --json      print one JSON object instead of text\n"
    "  -h, --help  show this help\n";

std::string validationJson(const ddf::ValidationReport& r) {
  return "{\"ok\": " + std::string(r.ok() ? "true" : "false") +
         ", \"constraint1\": " + std::to_string(r.count(1)) +
         ", \"constraint2\": " + std::to_string(r.count(2)) +
         ", \"constraint3\": " + std::to_string(r.count(3)) +
         ", \"suppressed\": " + std::to_string(r.suppressedIssues) +
         ", \"minCrustHeight\": " + jsonNumber(r.minCrustHeight) + "}";
}

std::string validationText(const ddf::ValidationReport& r) {
  char text[256];
  std::snprintf(text, sizeof text,
                "  validation: %s (constraint 1: %d, 2: %d, 3: %d issues%s), min crust height "
                "%.4g\n",
                r.ok() ? "ok" : "FAILED", r.count(1), r.count(2), r.count(3),
                r.suppressedIssues > 0 ? ", more not listed" : "", r.minCrustHeight);
  std::string out = text;
  if (!r.issues.empty()) out += "    first issue: " + r.issues.front().message + "\n";
  return out;
}

int runInfo(std::span<const std::string> words) {
  static const std::array<OptionSpec, 1> kSpecs = {OptionSpec{"json", '\0', false}};
  const Arguments args(words, kSpecs, "info");
  args.expectPositionals(1, "an input .ddf file");
  const std::filesystem::path input = args.positionals()[0];
  const ddf::DisplacementField field = io::readDdf(input);
  const FieldSummary summary = summarize(field);
  const ddf::ValidationReport validation = ddf::validate(field);
  const auto fileBytes = std::filesystem::file_size(input);
  if (args.has("json")) {
    std::printf(
        "{\n  \"file\": %s,\n  \"fileBytes\": %ju,\n  \"formatVersion\": %u,\n%s,\n"
        "  \"validation\": %s\n}\n",
        jsonString(input.string()).c_str(), static_cast<std::uintmax_t>(fileBytes),
        io::kDdfFormatVersion, summaryJsonMembers(summary).c_str(),
        validationJson(validation).c_str());
  } else {
    std::printf("%s: .ddf format version %u, %ju bytes\n%s%s", input.string().c_str(),
                io::kDdfFormatVersion, static_cast<std::uintmax_t>(fileBytes),
                summaryText(summary).c_str(), validationText(validation).c_str());
  }
  return 0;
}

}  // namespace

const Command kInfoCommand{"info", "print the key numbers of a .ddf file", kHelp, &runInfo};

}  // namespace ddfcam::cli
