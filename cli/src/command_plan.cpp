// SPDX-License-Identifier: MIT
// ddfcam-cli plan: streamline tool paths over a whole part, linked and written as CSV.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/scallop_spacing.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/pipeline/region_planning.h>
#include <ddfcam/planning/placement/path_linking.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "plan_tool.h"
#include "unit_options.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Plans streamline tool paths over the whole of PART (a .ddf file, a mesh or CAD file\n"
    "converted on its own support at m = 10, or 'demo' for the built-in demo part):\n"
    "curvature, flow field, lines SPACING apart, optional smoothing and fairing, tool poses,\n"
    "linking; writes the linked program as a tool-path CSV (columns path, point, x y z mm,\n"
    "tool axis i j k, surface normal, feed mm/min, move cut|link|rapid; path = move index)\n"
    "and prints a summary.";

/// The options of the lines: flow field, tracing, seeding, spacing, smoothing, linking.
void addLineOptions(Arguments& args) {
  args.option("--field", "kmax|kmin|fixed", "raw flow direction")->default_str("kmax");
  args.option("--direction", "X,Y,Z", "direction of --field fixed, part frame")
      ->default_str("1,0,0");
  args.flag("--no-smooth", "use the raw field (default: smoothed, weight 0.02)");
  args.option("--method", "rk4|walk|continuous", "streamline tracing")->default_str("rk4");
  args.option("--seeding", "transverse|even",
              "seeds along one transverse line through the centre, or\n"
              "evenly spaced lines (Jobard-Lefer; rk4 only) (default: even\n"
              "with rk4, transverse with walk and continuous)");
  args.option("--spacing", "MM",
              "distance between lines (default: bounding-box diagonal / 40);\n"
              "every line stops after 4 bounding-box diagonals")
      ->check(positiveNumber());
  args.option("--scallop", "MM",
              "instead of --spacing: largest scallop height between lines; the\n"
              "spacing follows the curvature across the feed (needs --tool\n"
              "ball and even seeding; a straight roll needs --spacing)")
      ->check(positiveNumber());
  args.option("--smooth-window", "K", "moving average of half window K, kept on the surface")
      ->check(integerIn(0, 1000))
      ->default_str("0");
  args.flag("--fair", "fair every line (bending energy, 0.05 mm deviation)");
  args.option("--linking", "zigzag|one-way",
              "order of the lines (default zigzag); links up to 2 spacings\n"
              "long stay on the surface, longer ones lift by 1 mm (by the\n"
              "bounding-box diagonal / 20 on smaller parts)");
}

Arguments options() {
  Arguments args("plan", "plan PART -o PATHS.csv [options]", kDescription);
  args.positional("PART", "input part: .ddf, mesh or CAD file, or 'demo'");
  args.option("-o,--output", "FILE", "output CSV (required)");
  addUnitsOption(args, "a mesh or CAD PART", "the unit a CAD file states, mm for meshes");
  addLineOptions(args);
  args.option("--point", "contact|reference", "x y z columns: contact point or tool centre")
      ->default_str("contact");
  addPlanToolOptions(args);
  args.option("--feed", "MM_PER_MIN", "feed rate")->check(positiveNumber())->default_str("1000");
  args.option("--decimals", "N", "digits after the decimal point in the CSV")
      ->check(integerIn(0, 17))
      ->default_str("6");
  return args;
}

std::string help() {
  return options().help();
}

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Everything the command line chooses.
struct PlanOptions {
  std::filesystem::path input;
  std::filesystem::path output;
  std::optional<ddfcam::LengthUnit> unit;  ///< --units of a mesh or CAD input
  planning::FlowFieldParams field;
  planning::StreamlineMethod method = planning::StreamlineMethod::Rk4;
  planning::LineSeeding seeding = planning::LineSeeding::Family;
  std::optional<double> spacingMm;
  std::optional<double> scallopMm;  ///< scallop height, mm: spacing from the curvature
  int smoothWindow = 0;
  bool fair = false;
  planning::LinkingOrder linking = planning::LinkingOrder::ZigZag;
  planning::ClPointKind point = planning::ClPointKind::Contact;
  PlanTool tool;  ///< tool, placement and sampling along the lines
  double feedMmPerMin = 1000.0;
  int decimals = 6;
};

/// The value of @p name among @p names (index), or @p fallback if the option is absent.
template <std::size_t N>
int choice(const Arguments& args, const std::string& name, const std::array<const char*, N>& names,
           int fallback) {
  const std::optional<std::string> value = args.value(name);
  if (!value) return fallback;
  std::string list;
  for (std::size_t i = 0; i < N; ++i) {
    if (*value == names[i]) return static_cast<int>(i);
    if (i > 0) list += '|';
    list += names[i];
  }
  throw UsageError("--" + name + " " + *value + ": expected " + list);
}

ddf::Vec3 parseDirection(const std::string& text) {
  ddf::Vec3 v;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 3; ++i) {
    const auto [next, error] = std::from_chars(at, end, v[i]);
    const bool last = i == 2;
    if (error != std::errc() || (last ? next != end : (next == end || *next != ',')))
      throw UsageError("--direction " + text + ": expected three numbers X,Y,Z");
    at = next + 1;
  }
  if (!v.allFinite() || v.squaredNorm() == 0.0)
    throw UsageError("--direction " + text + ": must be finite and non-zero");
  return v;
}

void parseField(const Arguments& args, PlanOptions& o) {
  static constexpr std::array<const char*, 3> kFields = {"kmax", "kmin", "fixed"};
  static constexpr std::array<planning::FlowFieldSource, 3> kSources = {
      planning::FlowFieldSource::MaxCurvatureDirection,
      planning::FlowFieldSource::MinCurvatureDirection, planning::FlowFieldSource::FixedDirection};
  o.field.source = kSources[choice(args, "field", kFields, 0)];
  if (args.has("direction")) {
    if (o.field.source != planning::FlowFieldSource::FixedDirection)
      throw UsageError("--direction needs --field fixed");
    o.field.fixedDirection = parseDirection(*args.value("direction"));
  }
  o.field.smoothing = !args.has("no-smooth");
}

void parseLines(const Arguments& args, PlanOptions& o) {
  static constexpr std::array<const char*, 3> kMethods = {"rk4", "walk", "continuous"};
  static constexpr std::array<planning::StreamlineMethod, 3> kMethodValues = {
      planning::StreamlineMethod::Rk4, planning::StreamlineMethod::RasterWalk,
      planning::StreamlineMethod::Continuous};
  o.method = kMethodValues[choice(args, "method", kMethods, 0)];
  static constexpr std::array<const char*, 2> kSeedings = {"transverse", "even"};
  // Even seeding covers closed free forms; one transverse line stops at the first singularity.
  const int byMethod = o.method == planning::StreamlineMethod::Rk4 ? 1 : 0;
  o.seeding = choice(args, "seeding", kSeedings, byMethod) == 0 ? planning::LineSeeding::Family
                                                                : planning::LineSeeding::Coverage;
  // evenlySpacedStreamlines traces with RK4 only; another method would be silently ignored.
  if (o.seeding == planning::LineSeeding::Coverage && o.method != planning::StreamlineMethod::Rk4)
    throw UsageError("--method " + *args.value("method") +
                     " is not available with --seeding even (it traces with rk4 only)");
  o.spacingMm = args.number("spacing");
  o.scallopMm = args.number("scallop");
  o.smoothWindow = args.integer("smooth-window", 0);
  o.fair = args.has("fair");
  static constexpr std::array<const char*, 2> kLinkings = {"zigzag", "one-way"};
  o.linking = choice(args, "linking", kLinkings, 0) == 0 ? planning::LinkingOrder::ZigZag
                                                         : planning::LinkingOrder::OneDirection;
}

void parseOutput(const Arguments& args, PlanOptions& o) {
  static constexpr std::array<const char*, 2> kPoints = {"contact", "reference"};
  o.point = choice(args, "point", kPoints, 0) == 0 ? planning::ClPointKind::Contact
                                                   : planning::ClPointKind::ToolReference;
  o.tool = parsePlanTool(args);
  o.feedMmPerMin = args.number("feed").value_or(1000.0);
  o.decimals = args.integer("decimals", 6);
}

void checkScallop(const PlanOptions& o) {
  if (!o.scallopMm) return;
  if (o.spacingMm) throw UsageError("--scallop and --spacing exclude each other");
  const std::optional<double> radius = planning::effectiveCrossFeedRadiusMm(o.tool.tool);
  if (!radius)
    throw UsageError(
        "--scallop needs --tool ball: a straight roll has a flat profile across the "
        "feed, so no scallop height follows from the curvature; give --spacing "
        "(at most the roll width) instead");
  if (*o.scallopMm >= *radius)
    throw UsageError("--scallop must be smaller than the ball radius (--radius)");
  if (o.seeding != planning::LineSeeding::Coverage)
    throw UsageError("--scallop needs --seeding even (the spacing varies over the part)");
}

PlanOptions parseOptions(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input part (.ddf, mesh or 'demo')");
  PlanOptions o;
  o.input = args.positionals()[0];
  o.output = args.required("output");
  o.unit = unitOption(args);
  parseField(args, o);
  parseLines(args, o);
  parseOutput(args, o);
  checkScallop(o);
  return o;
}

planning::Project loadInput(const std::filesystem::path& input,
                            const std::optional<ddfcam::LengthUnit>& unit) {
  if (input == "demo") {
    planning::Project project;
    project.part = ddf::demoPart().ddf;
    return project;
  }
  io::LoadPartParams params;
  params.unit = unit;
  return openPartInUnit(input, params, "loading");
}

double boxDiagonal(const ddf::DisplacementField& part) {
  Eigen::AlignedBox3d box;
  for (int v = 0; v < part.vertexCount(); ++v) box.extend(part.position(v));
  return box.isEmpty() ? 1.0 : box.diagonal().norm();
}

/// The plan of the whole part the options describe: field, spacing (fixed, default the
/// bounding-box diagonal / 40, or from the scallop height) and linking order.
planning::RegionPlan regionPlanOf(const PlanOptions& o, double diagonal) {
  planning::RegionPlan plan;
  plan.flowSource = o.field.source;
  plan.fixedDirection = o.field.fixedDirection;
  plan.smoothField = o.field.smoothing;
  plan.smoothnessWeight = o.field.smoothnessWeight;
  plan.spacingMm = o.spacingMm.value_or(diagonal / 40.0);
  if (o.scallopMm) {
    plan.spacingMode = planning::SpacingMode::ScallopTolerance;
    plan.scallopToleranceMm = *o.scallopMm;
  }
  plan.linking = o.linking;
  return plan;
}

/// Milliseconds of each stage, for the summary.
struct StageTimes {
  double load = 0, curvature = 0, field = 0, lines = 0, paths = 0;
};

void printSummary(const PlanOptions& o, const planning::LinkedPaths& linked, std::size_t rows,
                  const planning::LineSpacing& spacing, const StageTimes& t) {
  const double cutMin = linked.cuttingLengthMm / o.feedMmPerMin;
  const double idleMin = linked.idleLengthMm / o.feedMmPerMin;
  if (o.scallopMm) {
    std::printf("  lines: %d, scallop %.4g mm: spacing %.4g to %.4g mm, links: %d (%d lifted)\n",
                linked.pathCount, *o.scallopMm, spacing.minMm, spacing.maxMm, linked.linkCount,
                linked.liftedLinkCount);
    if (spacing.gougingFraction > 0.0)
      std::printf(
          "  warning: %.3g %% of the part is too concave for the ball (spacing %.4g mm "
          "there)\n",
          100.0 * spacing.gougingFraction, spacing.minMm);
  } else
    std::printf("  lines: %d, spacing %.4g mm, links: %d (%d lifted)\n", linked.pathCount,
                spacing.minMm, linked.linkCount, linked.liftedLinkCount);
  std::printf("  cutting length: %.6g mm, idle length: %.6g mm\n", linked.cuttingLengthMm,
              linked.idleLengthMm);
  std::printf(
      "  machining time at %.0f mm/min: %.4g min (cutting %.4g, idle %.4g; rapids "
      "counted at feed)\n",
      o.feedMmPerMin, cutMin + idleMin, cutMin, idleMin);
  std::printf("wrote %s: %zu rows\n", o.output.string().c_str(), rows);
  std::printf(
      "  time: load %.0f ms, curvature %.0f ms, field %.0f ms, lines %.0f ms, paths %.0f "
      "ms\n",
      t.load, t.curvature, t.field, t.lines, t.paths);
}

/// The sampling step range and the rules that bound it, when the lines were resampled.
void printSampling(const PlacedProgram& program) {
  if (program.passes.empty()) return;
  double lo = 1e300, hi = 0;
  std::string rules;
  for (const planning::PassSampling& pass : program.passes) {
    lo = std::min(lo, pass.step.stepMm);
    hi = std::max(hi, pass.step.stepMm);
    const std::string rule = planning::stepRuleName(pass.bindingRule);
    if (rules.find(rule) == std::string::npos) rules += (rules.empty() ? "" : ", ") + rule;
  }
  std::printf("  sampling: %zu poses, step %.6g to %.6g mm (%s)\n", program.path.poses.size(), lo,
              hi, rules.c_str());
}

int runPlan(std::span<const std::string> words) {
  PlanOptions o = parseOptions(words);
  StageTimes t;
  Clock::time_point start = Clock::now();
  const planning::Project project = loadInput(o.input, o.unit);
  const ddf::DisplacementField& part = *project.part;
  t.load = msSince(start);
  std::printf("plan on %s: %d faces, m = %d\n", o.input.string().c_str(), part.faceCount(),
              part.raster().m);
  start = Clock::now();
  planning::CurvatureParams curvatureParams = planning::partCurvatureParams(project);
  curvatureParams.progress = consoleProgress("curvature");
  const planning::CurvatureField curvature = planning::computeCurvature(part, curvatureParams);
  endProgressLine();
  t.curvature = msSince(start);
  start = Clock::now();
  const double diagonal = boxDiagonal(part);
  const planning::RegionPlan plan = regionPlanOf(o, diagonal);
  const planning::RegionFields fields =
      planning::regionFields(part, curvature, plan, {}, consoleProgress("flow field"));
  endProgressLine();
  t.field = msSince(start);
  start = Clock::now();
  const planning::LineSpacing spacing =
      planning::regionSpacing(part, curvature, fields, plan, o.tool.tool);
  planning::RegionLinesParams lineParams;
  lineParams.seeding = o.seeding;
  lineParams.tracing = o.method;
  lineParams.smoothHalfWindow = o.smoothWindow;
  lineParams.fair = o.fair;
  lineParams.progress = consoleProgress("lines");
  std::vector<planning::Streamline> lines =
      planning::planRegionLines(part, fields, {}, spacing, lineParams);
  endProgressLine();
  t.lines = msSince(start);
  start = Clock::now();
  planning::LinkingParams linking;
  // Concave areas barely wider than a ball allow huge spacings; links that long lift instead.
  const double linkSpacing =
      o.scallopMm ? std::min(spacing.maxMm, 2.0 * o.tool.tool.radiusMm) : spacing.maxMm;
  linking.directLinkMaxMm = 2.0 * linkSpacing;
  linking.clearanceMm = std::min(1.0, diagonal / 20.0);  // parts in metres are tiny in mm
  const PlacedProgram program =
      placeAndLink(part, lines, o.tool, o.feedMmPerMin, planning::linkingParamsOf(plan, linking));
  const planning::LinkedPaths& linked = program.linked;
  const planning::ClProgram table =
      planning::clProgramFromLinked(linked, program.path, o.tool.tool, o.point, program.normals);
  io::writeToolPathCsv(table, o.output, {.decimals = o.decimals});
  t.paths = msSince(start);
  printSummary(o, linked, table.points.size(), spacing, t);
  printSampling(program);
  return 0;
}

}  // namespace

const Command kPlanCommand{"plan", "streamline tool paths over a part, linked, as CSV", &help,
                           &runPlan};

}  // namespace ddfcam::cli
