// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: command-line options, the tool, and the tool path from a tool-path CSV.
#include "simulate_inputs.h"

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/io/project/tool_library_file.h>

#include <Eigen/Geometry>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "arguments.h"
#include "run_warnings.h"
#include "unit_options.h"

namespace ddfcam::cli {
namespace {

constexpr planning::ToolKind kAllKinds[] = {
    planning::ToolKind::CylinderRoll,     planning::ToolKind::Sphere,
    planning::ToolKind::BeltContactWheel, planning::ToolKind::BallEnd,
    planning::ToolKind::FlatEnd,          planning::ToolKind::TorusCutter};

/// A finite number given for @p name, or @p fallback if absent.
double number(const Arguments& args, const std::string& name, double fallback) {
  const std::optional<std::string> text = args.value(name);
  if (!text) return fallback;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || !std::isfinite(value))
    throw UsageError("--" + name + " " + *text + ": expected a number");
  return value;
}

double angle(const Arguments& args, const std::string& name) {
  const double deg = number(args, name, 0.0);
  if (std::abs(deg) >= 90.0)
    throw UsageError("--" + name + " " + std::to_string(deg) + ": expected |angle| < 90 deg");
  return deg;
}

void rejectWithout(const Arguments& args, std::initializer_list<const char*> names, bool allowed,
                   const std::string& needed) {
  for (const char* name : names)
    if (!allowed && args.has(name)) throw UsageError(std::string("--") + name + " needs " + needed);
}

planning::ToolKind kindFromOption(const std::string& name) {
  if (name == "roll") return planning::ToolKind::CylinderRoll;
  if (name == "ball") return planning::ToolKind::Sphere;
  if (const auto kind = planning::toolKindFromName(name)) return *kind;
  std::string expected = "roll|ball";
  for (const planning::ToolKind k : kAllKinds) {
    expected += '|';
    expected += planning::toolKindName(k);
  }
  throw UsageError("--tool " + name + ": expected " + expected);
}

planning::Tool toolFromLibrary(const Arguments& args) {
  rejectWithout(args, {"tool", "radius", "width", "corner-radius"}, false,
                "no --tool-file (the library file sets the tool)");
  const std::filesystem::path file = args.required("tool-file");
  const std::string name = args.required("tool-name");
  const std::vector<planning::Tool> tools = io::readToolLibrary(file);
  std::string names;
  for (const planning::Tool& t : tools) {
    if (t.name == name) return t;
    names += (names.empty() ? "\"" : ", \"") + t.name + "\"";
  }
  throw InvalidInput("--tool-name \"" + name + "\": no such tool in " + file.string() +
                     " (it has " + (names.empty() ? "no tools" : names) + ")");
}

planning::Tool toolFromOptions(const Arguments& args, const std::string& kindName,
                               double toleranceMm) {
  planning::Tool tool;
  tool.kind = kindFromOption(kindName);
  const bool sphere = tool.kind == planning::ToolKind::Sphere;
  const bool wheel = tool.kind == planning::ToolKind::CylinderRoll ||
                     tool.kind == planning::ToolKind::BeltContactWheel;
  const bool torus = tool.kind == planning::ToolKind::TorusCutter;
  if (sphere && args.has("width")) throw UsageError("--width does not apply to --tool ball");
  if (!wheel && !torus && args.has("corner-radius"))
    throw UsageError("--corner-radius applies to wheels and torus_cutter only");
  if (torus && !args.has("corner-radius"))
    throw UsageError("--tool torus_cutter needs --corner-radius MM");
  tool.radiusMm = args.positiveNumber("radius").value_or(5.0);
  tool.widthMm = args.positiveNumber("width").value_or(2.0 * tool.radiusMm);
  tool.edgeRadiusMm = number(args, "corner-radius", 0.0);
  // Facets from the chord error, a quarter of the tolerance band, so that the polygonal tool
  // (vertices on the true surface) cannot move the statistics by more than that.
  tool.segments = 0;
  tool.chordToleranceMm = 0.25 * toleranceMm;
  char name[128];
  std::snprintf(name, sizeof name, "%s R%g W%g", kindName.c_str(), tool.radiusMm, tool.widthMm);
  tool.name = name;
  planning::validateTool(tool);
  return tool;
}

const std::array<OptionSpec, 37> kSpecs = {kUnitsOption,
                                           OptionSpec{"paths", '\0', true},
                                           OptionSpec{"path-units", '\0', true},
                                           OptionSpec{"translate", '\0', true},
                                           OptionSpec{"rotate", '\0', true},
                                           OptionSpec{"keep-rapids", '\0', false},
                                           OptionSpec{"vectors", '\0', true},
                                           OptionSpec{"points", '\0', true},
                                           OptionSpec{"output", 'o', true},
                                           OptionSpec{"error-map", '\0', true},
                                           OptionSpec{"report", '\0', true},
                                           OptionSpec{"tool", '\0', true},
                                           OptionSpec{"tool-file", '\0', true},
                                           OptionSpec{"tool-name", '\0', true},
                                           OptionSpec{"radius", '\0', true},
                                           OptionSpec{"width", '\0', true},
                                           OptionSpec{"corner-radius", '\0', true},
                                           OptionSpec{"allowance", '\0', true},
                                           OptionSpec{"stock-mesh", '\0', true},
                                           OptionSpec{"tolerance", '\0', true},
                                           OptionSpec{"no-vconvexity-check", '\0', false},
                                           OptionSpec{"lead", '\0', true},
                                           OptionSpec{"tilt", '\0', true},
                                           OptionSpec{"sample-tolerance", '\0', true},
                                           OptionSpec{"step", '\0', true},
                                           OptionSpec{"swept", '\0', false},
                                           OptionSpec{"correct", '\0', false},
                                           OptionSpec{"correct-every", '\0', true},
                                           OptionSpec{"correct-grid", '\0', true},
                                           OptionSpec{"preston", '\0', false},
                                           OptionSpec{"force", '\0', true},
                                           OptionSpec{"kp", '\0', true},
                                           OptionSpec{"wheel-speed", '\0', true},
                                           OptionSpec{"feed", '\0', true},
                                           OptionSpec{"infeed", '\0', true},
                                           OptionSpec{"min-coverage", '\0', true},
                                           OptionSpec{"strict", '\0', false}};

void parseProcess(const Arguments& args, SimulateOptions& o) {
  o.sampleToleranceMm = args.positiveNumber("sample-tolerance");
  o.stepMm = args.positiveNumber("step");
  o.swept = args.has("swept");
  o.correction.enabled = args.has("correct");
  rejectWithout(args, {"correct-every", "correct-grid"}, o.correction.enabled, "--correct");
  o.correction.every = args.integer("correct-every", 1, 1, 1000000);
  o.correction.grid = args.integer("correct-grid", 50, 2, 4096);
  PrestonOptions& p = o.preston;
  p.enabled = args.has("preston");
  rejectWithout(args, {"force", "kp", "wheel-speed", "feed", "infeed"}, p.enabled, "--preston");
  if (p.enabled && o.swept) throw UsageError("--swept cannot be combined with --preston");
  p.kpMm2PerN = args.positiveNumber("kp").value_or(p.kpMm2PerN);
  p.forceN = args.positiveNumber("force").value_or(p.forceN);
  p.wheelSpeedMPerS = args.positiveNumber("wheel-speed").value_or(p.wheelSpeedMPerS);
  p.feedMmPerMin = args.positiveNumber("feed");
  p.infeedMm = args.positiveNumber("infeed").value_or(p.infeedMm);
}

// Three finite numbers "X,Y,Z" given for @p name, or zero.
ddf::Vec3 triple(const Arguments& args, const std::string& name) {
  const std::optional<std::string> text = args.value(name);
  if (!text) return ddf::Vec3::Zero();
  ddf::Vec3 v;
  const char* at = text->data();
  const char* const end = text->data() + text->size();
  for (int i = 0; i < 3; ++i) {
    if (i > 0 && (at == end || *at++ != ','))
      throw UsageError("--" + name + " " + *text + ": expected three numbers X,Y,Z");
    const auto [next, error] = std::from_chars(at, end, v[i]);
    if (error != std::errc() || !std::isfinite(v[i]))
      throw UsageError("--" + name + " " + *text + ": expected three numbers X,Y,Z");
    at = next;
  }
  if (at != end) throw UsageError("--" + name + " " + *text + ": expected three numbers X,Y,Z");
  return v;
}

ImportOptions parseImport(const Arguments& args) {
  ImportOptions im;
  if (const auto unit = args.value("path-units")) {
    if (*unit == "mm")
      im.unit = io::LengthUnit::Millimetre;
    else if (*unit == "in")
      im.unit = io::LengthUnit::Inch;
    else if (*unit == "m")
      im.unit = io::LengthUnit::Metre;
    else
      throw UsageError("--path-units " + *unit + ": expected mm|in|m");
  }
  im.translateMm = triple(args, "translate");
  im.rotateDeg = triple(args, "rotate");
  im.keepRapids = args.has("keep-rapids");
  if (const auto v = args.value("vectors")) {
    const auto meaning = io::pathVectorMeaningFromName(*v);
    if (!meaning) throw UsageError("--vectors " + *v + ": expected axis|approach|normal|auto");
    im.vectors = *meaning;
  }
  if (const auto v = args.value("points")) {
    const auto meaning = io::pathPointMeaningFromName(*v);
    if (!meaning) throw UsageError("--points " + *v + ": expected contact|tip|file|auto");
    im.points = *meaning;
  }
  return im;
}

}  // namespace

Eigen::Isometry3d ImportOptions::transform() const {
  const ddf::Vec3 rad = rotateDeg * (M_PI / 180.0);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(translateMm);
  t.rotate(Eigen::AngleAxisd(rad.z(), ddf::Vec3::UnitZ()) *
           Eigen::AngleAxisd(rad.y(), ddf::Vec3::UnitY()) *
           Eigen::AngleAxisd(rad.x(), ddf::Vec3::UnitX()));
  return t;
}

SimulateOptions parseSimulateOptions(std::span<const std::string> words) {
  const Arguments args(words, kSpecs, "simulate");
  args.expectPositionals(1, "an input part (.ddf, mesh, .ddfproj or 'demo')");
  SimulateOptions o;
  o.input = args.positionals()[0];
  o.paths = args.required("paths");
  o.output = args.required("output");
  if (const auto v = args.value("error-map")) o.errorMap = *v;
  if (const auto v = args.value("report")) o.report = *v;
  o.toleranceMm = args.positiveNumber("tolerance").value_or(0.01);
  if (args.has("stock-mesh") && args.has("allowance"))
    throw UsageError("--stock-mesh and --allowance exclude each other");
  if (const auto v = args.value("stock-mesh")) o.stockMesh = *v;
  o.unit = unitOption(args);
  o.allowanceMm = number(args, "allowance", 0.0);
  if (args.has("tool-name") && !args.has("tool-file"))
    throw UsageError("--tool-name needs --tool-file FILE");
  o.placement.leadDeg = angle(args, "lead");
  o.placement.tiltDeg = angle(args, "tilt");
  o.checkVConvexity = !args.has("no-vconvexity-check");
  parseProcess(args, o);
  o.import = parseImport(args);
  o.minCoveragePercent = minCoverageOption(args, o.minCoveragePercent);
  o.strict = args.has("strict");
  if (args.has("tool-file")) {
    o.tool = toolFromLibrary(args);
    o.toolKind = std::string(planning::toolKindName(o.tool.kind));
    o.toolSource = *args.value("tool-file");
  } else {
    o.toolKind = args.value("tool").value_or("roll");
    o.tool = toolFromOptions(args, o.toolKind, o.toleranceMm);
  }
  return o;
}

namespace {

using CutRows = std::vector<const io::ClPoint*>;

std::string rowName(const io::ClPoint& r) {
  return "row of path " + std::to_string(r.path) + " point " + std::to_string(r.point);
}

// Crust boxes of the faces (vertices +- vectors), grown by a tenth of the longest vector.
CsvPath resampled(const CutRows& rows, const std::vector<ddf::Vec3>& contacts,
                  const ddf::DisplacementField& goal, const SimulateOptions& o,
                  const std::string& source) {
  const ddf::SurfaceLocator locator(goal);
  std::vector<std::vector<ddf::SurfaceLocation>> passes;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i == 0 || rows[i - 1]->path != rows[i]->path) passes.emplace_back();
    const auto location = locator.locate(contacts[i]);
    if (!location)
      throw InvalidInput("simulate: " + source + ": " + rowName(*rows[i]) +
                         ": contact does not lie on the part");
    passes.back().push_back(*location);
  }
  planning::PathSamplingParams sampling;
  sampling.toleranceMm = o.sampleToleranceMm.value_or(o.toleranceMm);
  sampling.stepOverrideMm = o.stepMm;
  sampling.name = source;
  planning::PlacedPath placed =
      planning::placeAlongPathDetailed(goal, passes, o.tool, 0, o.placement, sampling);
  return {std::move(placed.path), {}, std::move(placed.passes), {}};
}

// Wheels keep the planned axis (feed = axis x n); other tools, or an axis along the normal,
// feed along the chord through the neighbours of the pass (the reference offset is the same
// for both neighbours, so the chord of the raw points serves either CSV kind).
ddf::Vec3 feedAt(const CutRows& rows, std::size_t i, const ddf::Vec3& n, bool wheel) {
  const io::ClPoint& r = *rows[i];
  ddf::Vec3 feed = r.axis ? r.axis->cross(n) : ddf::Vec3::Zero();
  if (wheel && feed.norm() >= 1e-6) return feed;
  const bool passStart = i == 0 || rows[i - 1]->path != r.path;
  const bool passEnd = i + 1 == rows.size() || rows[i + 1]->path != r.path;
  feed = (passEnd ? r.positionMm : rows[i + 1]->positionMm) -
         (passStart ? r.positionMm : rows[i - 1]->positionMm);
  if ((feed - feed.dot(n) * n).norm() < 1e-12) feed = n.unitOrthogonal();
  return feed;
}

}  // namespace

CsvPath pathFromCsv(const io::ClProgram& table, const ddf::DisplacementField& goal,
                    const SimulateOptions& o, const std::string& source) {
  CutRows rows;
  for (const io::ClPoint& row : table.points)
    if (row.move == planning::MoveKind::Cut) rows.push_back(&row);
  if (rows.empty()) throw InvalidInput("simulate: " + source + " has no cut rows");
  const bool wheel = o.tool.kind == planning::ToolKind::CylinderRoll ||
                     o.tool.kind == planning::ToolKind::BeltContactWheel;
  CsvPath out;
  out.path.name = source;
  std::vector<ddf::Vec3> contacts;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const io::ClPoint& r = *rows[i];
    const bool passStart = i == 0 || rows[i - 1]->path != r.path;
    if (passStart) out.path.passStarts.push_back(static_cast<int>(out.path.poses.size()));
    const ddf::Vec3 n = r.normal ? r.normal->normalized()
                                 : ddf::Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    if (!n.allFinite() || !r.positionMm.allFinite())
      throw InvalidInput("simulate: " + source + ": " + rowName(r) + " has no usable normal");
    const ddf::Vec3 feed = feedAt(rows, i, n, wheel);
    const ddf::Vec3 contact =
        table.pointKind == io::ClPointKind::Contact
            ? r.positionMm
            : ddf::Vec3(r.positionMm -
                        planning::placeToolDetailed(o.tool, r.positionMm, n, feed, o.placement)
                            .referenceOffset);
    contacts.push_back(contact);
    out.normals.push_back(n);
    out.path.poses.push_back({planning::placeTool(o.tool, contact, n, feed, o.placement), contact});
  }
  out.path.feedMmPerMin = rows.front()->feedMmPerMin > 0 ? rows.front()->feedMmPerMin : 1000.0;
  if (!o.resample()) return out;
  CsvPath placed = resampled(rows, contacts, goal, o, source);
  placed.path.feedMmPerMin = out.path.feedMmPerMin;
  return placed;
}

}  // namespace ddfcam::cli
