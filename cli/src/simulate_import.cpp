// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: the path file of any readable format read and placed on the part.
#include "simulate_import.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/io/imported_path.h>
#include <ddfcam/io/path_file.h>
#include <ddfcam/planning/mesh_distance.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
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
    const auto near = mesh.closestPoint(path.poses[i].contact, kOffPartMm);
    if (!near) {
      if (facts.pointsOffPart++ == 0) firstOff = static_cast<int>(i);
    } else {
      facts.maxContactDistanceMm = std::max(facts.maxContactDistanceMm, near->distance);
    }
  }
  if (facts.pointsOffPart > 0)
    warnings.push_back({0, std::to_string(facts.pointsOffPart) +
                               " poses have their contact farther than 2 mm from the part "
                               "(first: pose " +
                               std::to_string(firstOff) + ")"});
}

CsvPath fromCsv(const io::ClProgram& program, const ddf::DisplacementField& goal,
                const SimulateOptions& o, std::vector<io::ClMessage>& warnings) {
  if (o.import.keepRapids)
    throw InvalidInput("simulate: --keep-rapids: " + o.paths.filename().string() +
                       " is a CSV, of which only the cut rows are simulated");
  CsvPath out = pathFromCsv(mappedProgram(program, o.import), goal, o, o.paths.filename().string());
  out.facts.placement = "contacts";
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
  io::ImportedPath placed = io::placeProgram(program, o.tool, goal, params);
  warnings.insert(warnings.end(), placed.warnings.begin(), placed.warnings.end());
  CsvPath out{std::move(placed.path), std::move(placed.normals), {}, {}};
  out.facts.placement = "program axes";
  out.facts.pointsOffPart = placed.pointsOffPart;
  out.facts.maxContactDistanceMm = placed.maxContactDistanceMm;
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
  f.unit = io::lengthUnitName(o.import.unit.value_or(program.sourceUnit));
  f.pointsRead = static_cast<int>(program.points.size());
  f.posesPlaced = static_cast<int>(out.path.poses.size());
  f.warnings = static_cast<int>(program.warnings.size() + warnings.size());
  std::printf(
      "  paths: %s in %s, %d points read, %d poses placed by %s, %d off the part, "
      "max contact distance %.4g mm\n",
      f.format.c_str(), f.unit.c_str(), f.pointsRead, f.posesPlaced, f.placement.c_str(),
      f.pointsOffPart, f.maxContactDistanceMm);
  return out;
}

void writeImportFacts(JsonWriter& json, const ImportFacts& facts) {
  json.key("import").beginObject();
  json.key("format").value(facts.format).key("unit").value(facts.unit);
  json.key("placement").value(facts.placement);
  json.key("points_read").value(facts.pointsRead).key("poses_placed").value(facts.posesPlaced);
  json.key("points_off_part").value(facts.pointsOffPart);
  json.key("max_contact_distance_mm").value(facts.maxContactDistanceMm);
  json.key("warnings").value(facts.warnings);
  json.endObject();
}

}  // namespace ddfcam::cli
