// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the path file of any readable format read and placed on the part.
#include "simulate_import.h"

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/error.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::cli {
namespace {

std::string pointsName(planning::ClPointKind kind) {
  return kind == planning::ClPointKind::Contact ? "contact" : "tip";
}

// CSVs whose cut rows all carry a normal (as 'plan' writes them) are placed at their contacts,
// where --lead, --tilt and resampling apply; other files by their own tool axes.
bool placedAtContacts(const io::PathFile& file) {
  return file.format == io::PathFormat::Csv &&
         std::all_of(file.program.points.begin(), file.program.points.end(),
                     [](const planning::ClPoint& p) {
                       return p.move != planning::MoveKind::Cut || p.normal;
                     });
}

// Refuses the options the route of @p file cannot honour.
void checkRouteOptions(const io::PathFile& file, bool atContacts, const SimulateOptions& o) {
  const std::string name = o.paths.filename().string();
  if (atContacts) {
    if (std::none_of(file.program.points.begin(), file.program.points.end(),
                     [](const planning::ClPoint& p) { return p.move == planning::MoveKind::Cut; }))
      throw InvalidInput("simulate: " + name + " has no cut rows");
    if (o.import.keepRapids)
      throw InvalidInput("simulate: --keep-rapids: " + name +
                         " is a CSV, of which only the cut rows are simulated");
    if (o.import.vectors == planning::PathVectorMeaning::ApproachDirection ||
        o.import.vectors == planning::PathVectorMeaning::SurfaceNormal)
      throw InvalidInput("simulate: --vectors " +
                         std::string(planning::pathVectorMeaningName(o.import.vectors)) + ": " +
                         name +
                         " gives normals, which place the tool; --vectors applies to files "
                         "placed by their vectors");
    return;
  }
  const std::string what = std::string(io::pathFormatName(file.format)) + " program " + name +
                           " is placed by its own tool axes";
  if (o.placement.leadDeg != 0.0 || o.placement.tiltDeg != 0.0)
    throw InvalidInput("simulate: --lead/--tilt apply to CSV paths with normals; the " + what);
  if (o.resample())
    throw InvalidInput("simulate: --sample-tolerance/--step apply to CSV paths with normals; the " +
                       what);
}

// The placement the workbench's import uses (gui/path_import.cpp), from the command line.
planning::PlaceProgramParams placeParams(const SimulateOptions& o, bool atContacts) {
  planning::PlaceProgramParams params;
  params.actualUnit = o.import.unit;
  params.transform = o.import.transform();
  params.includeRapids = o.import.keepRapids;
  params.name = o.paths.filename().string();
  params.vectorMeaning = o.import.vectors;
  params.pointMeaning = o.import.points;
  if (atContacts) {
    // The command's contract for CSVs with normals: their cut rows at --lead/--tilt (links
    // lift off the surface the rows' normals describe).
    params.includeLinks = false;
    params.contactAngles = o.placement;
  }
  return params;
}

// The placed passes resampled along the feed at the step of --step or --sample-tolerance.
CsvPath resampled(const planning::ToolPath& placed, const ddf::DisplacementField& goal,
                  const SimulateOptions& o) {
  const ddf::SurfaceLocator locator(goal);
  std::vector<std::vector<ddf::SurfaceLocation>> passes;
  for (std::size_t i = 0; i < placed.poses.size(); ++i) {
    if (passes.empty() || std::find(placed.passStarts.begin(), placed.passStarts.end(),
                                    static_cast<int>(i)) != placed.passStarts.end())
      passes.emplace_back();
    const auto location = locator.locate(placed.poses[i].contact);
    if (!location)
      throw InvalidInput("simulate: " + placed.name + ": the contact of pose " + std::to_string(i) +
                         " does not lie on the part");
    passes.back().push_back(*location);
  }
  planning::PathSamplingParams sampling;
  sampling.toleranceMm = o.sampleToleranceMm.value_or(o.toleranceMm);
  sampling.stepOverrideMm = o.stepMm;
  sampling.name = placed.name;
  planning::PlacedPath path =
      planning::placeAlongPathDetailed(goal, passes, o.tool, placed.tool, o.placement, sampling);
  path.path.feedMmPerMin = placed.feedMmPerMin;
  return {std::move(path.path), {}, std::move(path.passes), {}};
}

}  // namespace

void printPathWarnings(const std::filesystem::path& file,
                       const std::vector<planning::ClMessage>& messages) {
  const std::string name = file.string();
  for (const planning::ClMessage& m : messages) {
    if (m.line > 0)
      std::fprintf(stderr, "warning: %s: line %d: %s\n", name.c_str(), m.line, m.text.c_str());
    else
      std::fprintf(stderr, "warning: %s: %s\n", name.c_str(), m.text.c_str());
  }
}

CsvPath importSimulationPath(const ddf::DisplacementField& goal, const SimulateOptions& o) {
  const io::PathFile file = io::readPathFile(o.paths);
  const planning::ClProgram& program = file.program;
  printPathWarnings(o.paths, program.warnings);
  const bool atContacts = placedAtContacts(file);
  checkRouteOptions(file, atContacts, o);
  planning::ImportedPath placed =
      planning::placeProgram(program, o.tool, goal, placeParams(o, atContacts));
  printPathWarnings(o.paths, placed.warnings);
  CsvPath out = o.resample() ? resampled(placed.path, goal, o)
                             : CsvPath{std::move(placed.path), std::move(placed.normals), {}, {}};
  ImportFacts& f = out.facts;
  f.format = io::pathFormatName(file.format);
  f.unit = unitSymbol(o.import.unit.value_or(program.sourceUnit));
  f.placement = atContacts ? "contacts" : "program axes";
  f.vectors = planning::pathVectorMeaningName(placed.convention.vectors);
  f.points = pointsName(placed.convention.points);
  f.convention = placed.convention.reason;
  f.pointsRead = static_cast<int>(program.points.size());
  f.posesPlaced = static_cast<int>(out.path.poses.size());
  f.pointsOffPart = placed.pointsOffPart;
  f.maxContactDistanceMm = placed.maxAbsContactDistanceMm;
  f.maxOnPartContactDistanceMm = placed.maxOnPartContactDistanceMm;
  f.gougingPoses = placed.gougingPoses;
  f.maxGougeDepthMm = placed.maxGougeDepthMm;
  f.warnings = static_cast<int>(program.warnings.size() + placed.warnings.size());
  std::printf("  paths: %s in %s, %d points read, %d poses placed by %s\n", f.format.c_str(),
              f.unit.c_str(), f.pointsRead, f.posesPlaced, f.placement.c_str());
  std::printf("  paths: %s\n", f.convention.c_str());
  std::printf("  paths: %d of %d poses off the part, max |contact distance| %.4g mm",
              f.pointsOffPart, f.posesPlaced, f.maxContactDistanceMm);
  if (f.maxOnPartContactDistanceMm)
    std::printf(" (%.4g mm on the part)", *f.maxOnPartContactDistanceMm);
  if (f.gougingPoses)
    std::printf(", %d gouging (deepest %.4g mm)", *f.gougingPoses, f.maxGougeDepthMm.value_or(0.0));
  std::printf("\n");
  return out;
}

JsonReport importFactsJson(const ImportFacts& facts) {
  JsonReport json;
  json["format"] = facts.format;
  json["unit"] = facts.unit;
  json["placement"] = facts.placement;
  json["vectors"] = facts.vectors;
  json["points"] = facts.points;
  json["convention"] = facts.convention;
  json["points_read"] = facts.pointsRead;
  json["poses_placed"] = facts.posesPlaced;
  json["points_off_part"] = facts.pointsOffPart;
  json["points_on_part"] = facts.posesPlaced - facts.pointsOffPart;
  json["max_contact_distance_mm"] = facts.maxContactDistanceMm;
  json["max_contact_distance_on_part_mm"] = jsonOrNull(facts.maxOnPartContactDistanceMm);
  json["gouging_poses"] = jsonOrNull(facts.gougingPoses);
  json["max_gouge_depth_mm"] = jsonOrNull(facts.maxGougeDepthMm);
  json["warnings"] = facts.warnings;
  return json;
}

}  // namespace ddfcam::cli
