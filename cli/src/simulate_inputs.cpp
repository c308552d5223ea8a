// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: command-line options and the tool.
#include "simulate_inputs.h"

#include <ddfcam/error.h>
#include <ddfcam/io/project/tool_library_file.h>

#include <Eigen/Geometry>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

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
  tool.radiusMm = args.number("radius").value_or(5.0);
  tool.widthMm = args.number("width").value_or(2.0 * tool.radiusMm);
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

constexpr const char* kDescription =
    "Grinds the cut moves of a tool-path file (a CSV as written by 'ddfcam-cli plan',\n"
    "APT/CLDATA, ROS toolpath YAML or FANUC .ls; see 'ddfcam-cli paths') into PART (a .ddf\n"
    "file, a mesh or CAD file converted as 'plan' does, in --units, a .ddfproj\n"
    "project's part, or 'demo'). PART's heights are the desired surface; the workpiece is that\n"
    "surface raised by the allowance along its normal, or a stock mesh. The tool is placed at\n"
    "every contact point (x y z, or the tool reference point minus the tool's reference offset\n"
    "for 'tool' CSVs) with the CSV's normal, wheels with the planned axis, touching the\n"
    "surface; every pose is cut by the DDF depth buffer (or by Preston removal). Writes the\n"
    "simulated part, optionally the signed deviation from the desired surface (mm along its\n"
    "normal; > 0 material left, < 0 overcut) as a .vtp error map and the statistics as JSON,\n"
    "and prints a summary. APT, YAML and .ls programs and CSV tables without normals are placed\n"
    "by their own tool axes (contacts found on PART; a point without an axis points +z); their\n"
    "link moves are cut, rapid moves only with --keep-rapids.\n"
    "Beside the statistics it reports the coverage (the share of the part the tool came within\n"
    "0.1 mm of the desired surface at some pose) and the raster points cut below the crust\n"
    "bottom, where the depth buffer clamps the cut, so the true overcut is deeper than the\n"
    "minimum shown. Warns about those, a coverage below --min-coverage, poses off the part,\n"
    "non-V-convex cuts and collisions; with --strict any warning makes the exit code 3 (after\n"
    "writing the outputs).";

void addPathOptions(Arguments& args) {
  args.option("--paths", "FILE",
              "tool-path file (required): CSV (link and rapid rows are not\n"
              "cut), APT/CLDATA, ROS toolpath YAML or FANUC .ls");
  args.option("--path-units", "mm|in|m",
              "the file's numbers are in this unit (overrides the file's)");
  args.option("--rotate", "AX,AY,AZ",
              "rotate the path about the part's x, y, z axes, deg, as\n"
              "Rz(AZ) Ry(AY) Rx(AX) (x first), before --translate");
  args.option("--translate", "X,Y,Z",
              "move the path by this vector, mm, after the unit and rotation");
  args.flag("--keep-rapids", "also place and cut the rapid moves (not for CSVs with normals)");
  args.option("--vectors", "axis|approach|normal|auto",
              "what the file's i,j,k vectors are: tool axes (tip to holder),\n"
              "approach directions (into the part, as robots give them) or\n"
              "surface normals; auto (default) decides from PART (into it:\n"
              "approach) and the report says why; a gouging choice is warned");
  args.option("--points", "contact|tip|file|auto",
              "what the file's points are: contacts on the surface, tool tips\n"
              "(wheel and ball centres), as the file says; auto (default)\n"
              "decides from their distance to PART");
}

void addOutputOptions(Arguments& args) {
  args.option("-o,--output", "FILE", "simulated part as .ddf (required)");
  args.option("--error-map", "FILE", "deviation per raster point as VTK PolyData (.vtp)");
  args.option("--report", "FILE", "statistics as JSON");
  addMinCoverageOption(args,
                       "warn when the tool touches less than P % of the part (default\n"
                       "5: even a path for one region covers more)");
  args.flag("--strict", "exit with code 3 when the run had any warning");
}

void addToolOptions(Arguments& args) {
  const std::string group = "tool";
  args.option("--tool", "KIND",
              "roll (= cylinder_roll, default), ball (bare sphere = sphere),\n"
              "cylinder_roll, sphere, belt_contact_wheel, ball_end, flat_end,\n"
              "torus_cutter")
      ->group(group);
  args.option("--radius", "MM", "tool radius")
      ->check(positiveNumber())
      ->default_str("5")
      ->group(group);
  args.option("--width", "MM",
              "wheel width or cutter flute length (default 2 x radius; not\nfor ball)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--corner-radius", "MM",
              "wheel rim radius, or torus_cutter corner radius (required there)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--tool-file", "FILE",
              "take the tool --tool-name from a tool library file instead of\n"
              "--tool, --radius, --width, --corner-radius")
      ->group(group);
  args.option("--tool-name", "NAME", "the tool's name in --tool-file")->group(group);
  args.option("--lead", "DEG",
              "lead angle of the tool at the contact, |angle| < 90 (default 0;\n"
              "CSVs with normals only: programs carry their tool axes)")
      ->group(group);
  args.option("--tilt", "DEG", "tilt angle of the tool at the contact (as --lead)")->group(group);
}

void addSamplingOptions(Arguments& args) {
  const std::string group =
      "sampling along the feed (CSVs with normals only; default: one pose per CSV row)";
  args.option("--sample-tolerance", "MM",
              "resample every pass at the step derived from this tolerance\n"
              "(feed chord, raster spacing, tool profile cusp; default rule\n"
              "tolerance = --tolerance when only --step is given)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--step", "MM", "resample every pass at this fixed step instead")
      ->check(positiveNumber())
      ->group(group);
}

void addWorkpieceOptions(Arguments& args) {
  const std::string group = "workpiece and process";
  args.option("--allowance", "MM",
              "stock above the desired surface along its normal (default 0:\n"
              "the workpiece is the desired surface, so only gouges show)")
      ->group(group);
  args.option("--stock-mesh", "FILE",
              "workpiece from a stock mesh (.stl/.obj/.ply/.off) converted onto\n"
              "PART's support instead of --allowance (read in --units)")
      ->group(group);
  addUnitsOption(args, "a mesh or CAD PART and of the stock mesh",
                 "the unit a CAD file states, mm for meshes")
      ->group(group);
  args.flag("--swept", "cut the swept volume between consecutive poses (convex tools)")
      ->group(group);
  args.flag("--correct",
            "lift every pose off the desired surface until it no longer\n"
            "penetrates it (tangential DDF, sec. 8.4.2) before cutting")
      ->group(group);
  args.option("--correct-every", "K", "exact lift at every K-th pose, interpolated between")
      ->check(integerIn(1, 1000000))
      ->default_str("1")
      ->group(group);
  args.option("--correct-grid", "N", "tangential grid N x N")
      ->check(integerIn(2, 4096))
      ->default_str("50")
      ->group(group);
}

void addPrestonOptions(Arguments& args) {
  const std::string group = "workpiece and process";
  args.flag("--preston", "Preston removal (depth = K_p p v_s dt) instead of the rigid cut")
      ->group(group);
  args.option("--kp", "MM2_PER_N", "Preston coefficient K_p, mm^2/N (default 1e-7)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--force", "N", "normal force, N (default 10)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--wheel-speed", "M_PER_S", "wheel surface speed, m/s (default 30)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--feed", "MM_PER_MIN", "feed (default: the CSV's feed)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--infeed", "MM", "infeed of the undeformed tool setting the contact patch (0.1)")
      ->check(positiveNumber())
      ->group(group);
  args.option("--tolerance", "MM", "tolerance band [-T, T] of the statistics")
      ->check(positiveNumber())
      ->default_str("0.01")
      ->group(group);
  args.flag("--no-vconvexity-check",
            "skip the check for cuts that are not V-convex (fig. 8.15);\n"
            "the check probes every stubble under the tool at every pose")
      ->group(group);
}

void parseProcess(const Arguments& args, SimulateOptions& o) {
  o.sampleToleranceMm = args.number("sample-tolerance");
  o.stepMm = args.number("step");
  o.swept = args.has("swept");
  o.correction.enabled = args.has("correct");
  rejectWithout(args, {"correct-every", "correct-grid"}, o.correction.enabled, "--correct");
  o.correction.every = args.integer("correct-every", 1);
  o.correction.grid = args.integer("correct-grid", 50);
  PrestonOptions& p = o.preston;
  p.enabled = args.has("preston");
  rejectWithout(args, {"force", "kp", "wheel-speed", "feed", "infeed"}, p.enabled, "--preston");
  if (p.enabled && o.swept) throw UsageError("--swept cannot be combined with --preston");
  p.kpMm2PerN = args.number("kp").value_or(p.kpMm2PerN);
  p.forceN = args.number("force").value_or(p.forceN);
  p.wheelSpeedMPerS = args.number("wheel-speed").value_or(p.wheelSpeedMPerS);
  p.feedMmPerMin = args.number("feed");
  p.infeedMm = args.number("infeed").value_or(p.infeedMm);
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
      im.unit = LengthUnit::Millimetre;
    else if (*unit == "in")
      im.unit = LengthUnit::Inch;
    else if (*unit == "m")
      im.unit = LengthUnit::Metre;
    else
      throw UsageError("--path-units " + *unit + ": expected mm|in|m");
  }
  im.translateMm = triple(args, "translate");
  im.rotateDeg = triple(args, "rotate");
  im.keepRapids = args.has("keep-rapids");
  if (const auto v = args.value("vectors")) {
    const auto meaning = planning::pathVectorMeaningFromName(*v);
    if (!meaning) throw UsageError("--vectors " + *v + ": expected axis|approach|normal|auto");
    im.vectors = *meaning;
  }
  if (const auto v = args.value("points")) {
    const auto meaning = planning::pathPointMeaningFromName(*v);
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

Arguments simulateArguments() {
  Arguments args("simulate", "simulate PART --paths FILE -o OUT.ddf [options]", kDescription);
  args.positional("PART", "the part: .ddf, mesh or CAD file, .ddfproj or 'demo'");
  addPathOptions(args);
  addOutputOptions(args);
  addToolOptions(args);
  addSamplingOptions(args);
  addWorkpieceOptions(args);
  addPrestonOptions(args);
  return args;
}

SimulateOptions parseSimulateOptions(std::span<const std::string> words) {
  Arguments args = simulateArguments();
  args.parse(words);
  args.expectPositionals(1, "an input part (.ddf, mesh, .ddfproj or 'demo')");
  SimulateOptions o;
  o.input = args.positionals()[0];
  o.paths = args.required("paths");
  o.output = args.required("output");
  if (const auto v = args.value("error-map")) o.errorMap = *v;
  if (const auto v = args.value("report")) o.report = *v;
  o.toleranceMm = args.number("tolerance").value_or(0.01);
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

}  // namespace ddfcam::cli
