// SPDX-License-Identifier: MIT
// ddfcam-cli info: sizes, raster spacing, crust reach, source unit, CAD faces, height range,
// bounds and the constraint check of a .ddf file, or of a mesh or CAD file as converted.
#include <ddfcam/ddf/validation.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/part_loader.h>

#include "arguments.h"
#include "commands.h"
#include "conversion_options.h"
#include "field_summary.h"
#include "json_output.h"
#include "part_facts.h"
#include "unit_options.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Prints the support size (vertices, faces), raster resolution m, raster spacing\n"
    "(longest support edge / (m - 1)) and raster point counts, memory, height range (in\n"
    "vector lengths), how far the +-1 crust reaches above and below the surface (smallest\n"
    "and median, along the surface normal), support and surface bounding boxes (mm), the\n"
    "unit the part's source file was read in, its CAD faces (count and names, for CAD\n"
    "input), and the check of the three DDF constraints (chapter 3).\n"
    "A mesh or CAD file is converted first, with the options below (as 'convert'), and its\n"
    "conversion summary is printed too (not with --json).";

Arguments options() {
  Arguments args("info", "info IN.(ddf|stl|obj|ply|off|step|stp|iges|igs) [options]", kDescription);
  args.positional("IN", "input .ddf, mesh or CAD file");
  args.flag("--json", "print one JSON object instead of text");
  addConversionOptions(args);
  return args;
}

std::string help() {
  return options().help();
}

JsonReport validationJson(const ddf::ValidationReport& r) {
  JsonReport json;
  json["ok"] = r.ok();
  json["constraint1"] = r.count(1);
  json["constraint2"] = r.count(2);
  json["constraint3"] = r.count(3);
  json["suppressed"] = r.suppressedIssues;
  json["minCrustHeight"] = r.minCrustHeight;
  return json;
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

/// The part of @p input with its facts: a .ddf file as stored, anything else converted.
struct InfoInput {
  ddf::DisplacementField field;
  PartFacts facts;
  std::string fileLine;  ///< "x.ddf: .ddf format version 2, 1234 bytes" (text)
  JsonReport fileJson;   ///< the matching JSON members, the first of the report
};

InfoInput readInput(const std::filesystem::path& input, const Arguments& args) {
  if (input.extension() == ".ddf") {
    io::DdfMetadata metadata;
    ddf::DisplacementField field = io::readDdf(input, &metadata);
    InfoInput in{std::move(field), {}, {}, {}};
    in.facts = partFacts(in.field);
    if (metadata.stored) in.facts.sourceUnit = metadata.sourceUnit;
    in.facts.cadFaceOfSupportFace = std::move(metadata.cadFaceOfSupportFace);
    in.facts.cadFaceNames = std::move(metadata.cadFaceNames);
    const unsigned version = metadata.stored ? 2u : 1u;
    const auto bytes = static_cast<std::uintmax_t>(std::filesystem::file_size(input));
    const std::size_t design = metadata.designMesh ? metadata.designMesh->triangles.size() : 0;
    in.fileLine = input.string() + ": .ddf format version " + std::to_string(version) + ", " +
                  std::to_string(bytes) + " bytes" +
                  (design ? ", design mesh of " + std::to_string(design) + " triangles" : "") +
                  "\n";
    in.fileJson = {{"file", input.string()},
                   {"fileBytes", bytes},
                   {"formatVersion", version},
                   {"designMeshTriangles", design}};
    return in;
  }
  io::LoadPartReport report;
  ddf::DisplacementField field =
      loadPartInUnit(input, conversionParams(args), "converting", &report);
  if (!args.has("json") && report.converted) {
    printConversion(input, report);
    printVerdict(input, report);
  }
  InfoInput in{std::move(field), {}, {}, {}};
  in.facts = partFacts(in.field);
  in.facts.sourceUnit = report.unit;
  in.facts.unitFromFile = report.unitFromFile;
  in.facts.cadFaceOfSupportFace = std::move(report.cadFaceOfSupportFace);
  in.facts.cadFaceNames = std::move(report.cadFaceNames);
  in.fileLine = input.string() + ": converted, not stored\n";
  in.fileJson = {{"file", input.string()}, {"converted", true}};
  return in;
}

int runInfo(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input .ddf, mesh or CAD file");
  const InfoInput in = readInput(args.positionals()[0], args);
  const FieldSummary summary = summarize(in.field);
  const ddf::ValidationReport validation = ddf::validate(in.field);
  if (args.has("json")) {
    JsonReport json = in.fileJson;
    writeSummary(json, summary);
    writePartFacts(json, in.facts);
    json["validation"] = validationJson(validation);
    std::printf("%s", jsonText(json).c_str());
  } else {
    std::printf("%s%s%s%s", in.fileLine.c_str(), summaryText(summary).c_str(),
                partFactsText(in.facts).c_str(), validationText(validation).c_str());
  }
  return 0;
}

}  // namespace

const Command kInfoCommand{"info", "print the key numbers of a .ddf, mesh or CAD file", &help,
                           &runInfo};

}  // namespace ddfcam::cli
