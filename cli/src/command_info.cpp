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
#include "part_facts.h"
#include "unit_options.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace ddfcam::cli {
namespace {

const std::string kHelp =
    std::string(
        "usage: ddfcam-cli info IN.(ddf|stl|obj|ply|off|step|stp|iges|igs) [options]\n\n"
        "Prints the support size (vertices, faces), raster resolution m, raster spacing\n"
        "(longest support edge / (m - 1)) and raster point counts, memory, height range (in\n"
        "vector lengths), how far the +-1 crust reaches above and below the surface (smallest\n"
        "and median, along the surface normal), support and surface bounding boxes (mm), the\n"
        "unit the part's source file was read in, its CAD faces (count and names, for CAD\n"
        "input), and the check of the three DDF constraints (chapter 3).\n"
        "A mesh or CAD file is converted first, with the options below (as 'convert'), and its\n"
        "conversion summary is printed too (not with --json).\n\n"
        "options:\n"
        "  --json                     print one JSON object instead of text\n") +
    kConversionOptionsHelp + "  -h, --help                 show this help\n";

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

/// The part of @p input with its facts: a .ddf file as stored, anything else converted.
struct InfoInput {
  ddf::DisplacementField field;
  PartFacts facts;
  std::string fileLine;  ///< "x.ddf: .ddf format version 2, 1234 bytes" (text)
  std::string fileJson;  ///< the matching JSON members (with a trailing ",\n")
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
    in.fileJson = "  \"file\": " + jsonString(input.string()) +
                  ",\n  \"fileBytes\": " + std::to_string(bytes) +
                  ",\n  \"formatVersion\": " + std::to_string(version) +
                  ",\n  \"designMeshTriangles\": " + std::to_string(design) + ",\n";
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
  in.fileJson = "  \"file\": " + jsonString(input.string()) + ",\n  \"converted\": true,\n";
  return in;
}

int runInfo(std::span<const std::string> words) {
  std::vector<OptionSpec> specs = conversionOptionSpecs();
  specs.push_back({"json", '\0', false});
  const Arguments args(words, specs, "info");
  args.expectPositionals(1, "an input .ddf, mesh or CAD file");
  const InfoInput in = readInput(args.positionals()[0], args);
  const FieldSummary summary = summarize(in.field);
  const ddf::ValidationReport validation = ddf::validate(in.field);
  if (args.has("json")) {
    std::printf("{\n%s%s,\n%s,\n  \"validation\": %s\n}\n", in.fileJson.c_str(),
                summaryJsonMembers(summary).c_str(), partFactsJsonMembers(in.facts).c_str(),
                validationJson(validation).c_str());
  } else {
    std::printf("%s%s%s%s", in.fileLine.c_str(), summaryText(summary).c_str(),
                partFactsText(in.facts).c_str(), validationText(validation).c_str());
  }
  return 0;
}

}  // namespace

const Command kInfoCommand{"info", "print the key numbers of a .ddf, mesh or CAD file",
                           kHelp.c_str(), &runInfo};

}  // namespace ddfcam::cli
