// SPDX-License-Identifier: MIT
// ddfcam-cli: --units and the size warning.
#include "unit_options.h"

#include "console.h"

#include <ddfcam/error.h>
#include <ddfcam/io/project/project_loader.h>

#include <cstdio>
#include <string>

namespace ddfcam::cli {

CLI::Option* addUnitsOption(Arguments& args, const std::string& of, const std::string& byDefault) {
  const std::string choices(lengthUnitChoices());
  const CLI::Validator known(
      [choices](std::string& text) -> std::string {
        return parseLengthUnit(text) ? std::string()
                                     : "expects " + choices + ", got '" + text + "'";
      },
      "UNIT");
  return args
      .option("--units", "U", "unit of " + of + ": " + choices + "\n(default: " + byDefault + ")")
      ->check(known);
}

std::optional<ddfcam::LengthUnit> unitOption(const Arguments& args) {
  const std::optional<std::string> text = args.value("units");
  if (!text) return std::nullopt;
  return parseLengthUnit(*text);
}

bool warnIfOtherUnit(const std::filesystem::path& file, double fileDiagonal,
                     const std::optional<ddfcam::LengthUnit>& given, const std::string& remedy) {
  if (given || !sizeSuggestsOtherUnit(fileDiagonal)) return false;
  char hint[160];
  if (const std::optional<ddfcam::LengthUnit> likely = likelyUnit(fileDiagonal)) {
    std::snprintf(hint, sizeof hint, "as %s it would be %.4g mm",
                  std::string(unitSymbol(*likely)).c_str(), fileDiagonal * millimetresPer(*likely));
  } else {
    std::snprintf(hint, sizeof hint, "as mm it is %.4g m across", fileDiagonal / 1000.0);
  }
  endProgressLine();
  std::fflush(stdout);
  std::fprintf(stderr, "warning: %s is %.4g units across; if it is not in mm, %s (%s)\n",
               file.string().c_str(), fileDiagonal, remedy.c_str(), hint);
  return true;
}

ddf::DisplacementField loadPartInUnit(const std::filesystem::path& path, io::LoadPartParams params,
                                      const char* label, io::LoadPartReport* report,
                                      ddf::TriangleMesh* inputMesh) {
  params.progress = consoleProgress(label);
  io::LoadPartReport local;
  io::LoadPartReport& r = report ? *report : local;
  io::LoadedPart part = io::loadPartWithInput(path, params, &r);
  endProgressLine();
  // A CAD file states its unit, so its size needs no second opinion.
  if (r.converted && !r.unitFromFile) warnIfOtherUnit(path, r.fileDiagonal, params.unit);
  if (inputMesh) *inputMesh = std::move(part.inputMesh);
  return std::move(part.ddf);
}

planning::Project openPartInUnit(const std::filesystem::path& path, io::LoadPartParams params,
                                 const char* label) {
  params.progress = consoleProgress(label);
  io::LoadPartReport report;
  planning::Project project = io::openProject(path, params, &report);
  endProgressLine();
  if (!project.part) throw InvalidInput(path.string() + " holds no part");
  if (report.converted && !report.unitFromFile)
    warnIfOtherUnit(path, report.fileDiagonal, params.unit);
  return project;
}

}  // namespace ddfcam::cli
