// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the path file of any readable format read and placed on the part.
#include "simulate_import.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/io/programs/imported_path.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace ddfcam::cli {
namespace {

// Same limit as io::PlaceProgramParams::contactSearchMm's default.
constexpr double kOffPartMm = 2.0;

// Distance of the poses' contacts to the part's raster mesh; off the part beyond kOffPartMm.
void contactFacts(const ddf::DisplacementField& goal, const planning::ToolPath& path,
                  ImportFacts& facts, std::vector<io::ClMessage>& warnings) {
  const planning::MeshDistance mesh(ddf::extractRasterMesh(goal).mesh);
  int firstOff = -1;
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const auto near = mesh.closestPoint(path.poses[i].contact);
    const double distance = near ? near->distance : std::numeric_limits<double>::infinity();
    facts.maxContactDistanceMm = std::max(facts.maxContactDistanceMm, distance);
    if (distance > kOffPartMm) {
      if (facts.pointsOffPart++ == 0) firstOff = static_cast<int>(i);
    } else {
      facts.maxOnPartContactDistanceMm =
          std::max(facts.maxOnPartContactDistanceMm.value_or(0.0), distance);
    }
  }
  if (facts.pointsOffPart > 0)
    warnings.push_back({0, std::to_string(facts.pointsOffPart) +
                               " poses have their contact farther than 2 mm from the part "
                               "(first: pose " +
                               std::to_string(firstOff) + ")"});
}

std::string pointsName(io::ClPointKind kind) {
  return kind == io::ClPointKind::Contact ? "contact" : "tip";
}

CsvPath fromCsv(io::ClProgram program, const ddf::DisplacementField& goal, const SimulateOptions& o,
                std::vector<io::ClMessage>& warnings) {
  if (o.import.keepRapids)
    throw InvalidInput("simulate: --keep-rapids: " + o.paths.filename().string() +
                       " is a CSV, of which only the cut rows are simulated");
  if (o.import.vectors == io::PathVectorMeaning::ApproachDirection ||
      o.import.vectors == io::PathVectorMeaning::SurfaceNormal)
    throw InvalidInput("simulate: --vectors " +
                       std::string(io::pathVectorMeaningName(o.import.vectors)) + ": " +
                       o.paths.filename().string() +
                       " gives normals, which place the tool; --vectors applies to files placed "
                       "by their vectors");
  if (o.import.points == io::PathPointMeaning::Contact)
    program.pointKind = io::ClPointKind::Contact;
  else if (o.import.points == io::PathPointMeaning::ToolReference)
    program.pointKind = io::ClPointKind::ToolReference;
  CsvPath out = pathFromCsv(mappedProgram(program, o.import), goal, o, o.paths.filename().string());
  out.facts.placement = "contacts";
  out.facts.vectors = "file normals";
  out.facts.points = pointsName(program.pointKind);
  out.facts.convention = "the file's normals place the tool; points: " + out.facts.points +
                         (o.import.points == io::PathPointMeaning::Contact ||
                                  o.import.points == io::PathPointMeaning::ToolReference
                              ? " (as chosen)"
                              : " (as the file says)");
  contactFacts(goal, out.path, out.facts, warnings);
  return out;
}

CsvPath fromProgram(const io::ClProgram& program, const ddf::DisplacementField& goal,
                    const SimulateOptions& o, io::PathFormat format,
                    std::vector<io::ClMessage>& warnings) {
  const std::string what = std::string(io::pathFormatName(format)) + " program " +
                           o.paths.filename().string() + " is placed by its own tool axes";
  if (o.placement.leadDeg != 0.0 || o.placement.tiltDeg != 0.0)
    throw InvalidInput("simulate: --lead/--tilt apply to CSV paths with normals; the " + what);
  if (o.resample())
    throw InvalidInput("simulate: --sample-tolerance/--step apply to CSV paths with normals; the " +
                       what);
  io::PlaceProgramParams params;
  params.actualUnit = o.import.unit;
  params.transform = o.import.transform();
  params.includeRapids = o.import.keepRapids;
  params.name = o.paths.filename().string();
  params.contactSearchMm = kOffPartMm;
  params.vectorMeaning = o.import.vectors;
  params.pointMeaning = o.import.points;
  io::ImportedPath placed = io::placeProgram(program, o.tool, goal, params);
  warnings.insert(warnings.end(), placed.warnings.begin(), placed.warnings.end());
  CsvPath out{std::move(placed.path), std::move(placed.normals), {}, {}};
  ImportFacts& f = out.facts;
  f.placement = "program axes";
  f.vectors = io::pathVectorMeaningName(placed.convention.vectors);
  f.points = pointsName(placed.convention.points);
  f.convention = placed.convention.reason;
  f.pointsOffPart = placed.pointsOffPart;
  f.maxContactDistanceMm = placed.maxAbsContactDistanceMm;
  f.maxOnPartContactDistanceMm = placed.maxOnPartContactDistanceMm;
  f.gougingPoses = placed.gougingPoses;
  f.maxGougeDepthMm = placed.maxGougeDepthMm;
  return out;
}

}  // namespace

void printPathWarnings(const std::filesystem::path& file,
                       const std::vector<io::ClMessage>& messages) {
  const std::string name = file.string();
  for (const io::ClMessage& m : messages) {
    if (m.line > 0)
      std::fprintf(stderr, "warning: %s: line %d: %s\n", name.c_str(), m.line, m.text.c_str());
    else
      std::fprintf(stderr, "warning: %s: %s\n", name.c_str(), m.text.c_str());
  }
}

io::PathFormat pathFormatOf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  // readPathFile() accepted the file, so detection succeeds on the same bytes.
  return io::detectPathFormat(file, head).value_or(io::PathFormat::Csv);
}

io::ClProgram mappedProgram(io::ClProgram program, const ImportOptions& o) {
  const double scale =
      o.unit ? io::millimetresPer(*o.unit) / io::millimetresPer(program.sourceUnit) : 1.0;
  const Eigen::Isometry3d t = o.transform();
  for (io::ClPoint& p : program.points) {
    p.positionMm = t * (scale * p.positionMm);
    p.feedMmPerMin *= scale;
    if (p.axis) p.axis = t.linear() * *p.axis;
    if (p.normal) p.normal = t.linear() * *p.normal;
  }
  if (o.unit) program.sourceUnit = *o.unit;
  return program;
}

CsvPath importSimulationPath(const ddf::DisplacementField& goal, const SimulateOptions& o) {
  const io::ClProgram program = io::readPathFile(o.paths);
  const io::PathFormat format = pathFormatOf(o.paths);
  printPathWarnings(o.paths, program.warnings);
  std::vector<io::ClMessage> warnings;
  // Tables without normals (x,y,z[,i,j,k]) cannot be placed at their contacts: their axes
  // place them, like the other formats.
  const bool withNormals = std::all_of(
      program.points.begin(), program.points.end(),
      [](const io::ClPoint& p) { return p.move != planning::MoveKind::Cut || p.normal; });
  CsvPath out = format == io::PathFormat::Csv && withNormals
                    ? fromCsv(program, goal, o, warnings)
                    : fromProgram(program, goal, o, format, warnings);
  printPathWarnings(o.paths, warnings);
  ImportFacts& f = out.facts;
  f.format = io::pathFormatName(format);
  f.unit = io::unitSymbol(o.import.unit.value_or(program.sourceUnit));
  f.pointsRead = static_cast<int>(program.points.size());
  f.posesPlaced = static_cast<int>(out.path.poses.size());
  f.warnings = static_cast<int>(program.warnings.size() + warnings.size());
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

void writeImportFacts(JsonWriter& json, const ImportFacts& facts) {
  json.key("import").beginObject();
  json.key("format").value(facts.format).key("unit").value(facts.unit);
  json.key("placement").value(facts.placement);
  json.key("vectors").value(facts.vectors).key("points").value(facts.points);
  json.key("convention").value(facts.convention);
  json.key("points_read").value(facts.pointsRead).key("poses_placed").value(facts.posesPlaced);
  json.key("points_off_part").value(facts.pointsOffPart);
  json.key("points_on_part").value(facts.posesPlaced - facts.pointsOffPart);
  json.key("max_contact_distance_mm").value(facts.maxContactDistanceMm);
  json.key("max_contact_distance_on_part_mm");
  if (facts.maxOnPartContactDistanceMm)
    json.value(*facts.maxOnPartContactDistanceMm);
  else
    json.null();
  json.key("gouging_poses");
  if (facts.gougingPoses)
    json.value(*facts.gougingPoses);
  else
    json.null();
  json.key("max_gouge_depth_mm");
  if (facts.maxGougeDepthMm)
    json.value(*facts.maxGougeDepthMm);
  else
    json.null();
  json.key("warnings").value(facts.warnings);
  json.endObject();
}

}  // namespace ddfcam::cli
