// SPDX-License-Identifier: MIT
// ddfcam-cli simulate: grinds a tool-path CSV into a part, writes the result, an error map and
// a JSON report of the deviation statistics (dissertation sec. 8.4).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/results/vtp_writer.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/pipeline/simulation_stage.h>
#include <ddfcam/planning/placement/penetration_correction.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/preston_removal.h>
#include <ddfcam/planning/simulation/simulation_estimate.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "error_map_vtp.h"
#include "json_output.h"
#include "run_warnings.h"
#include "simulate_checks.h"
#include "simulate_import.h"
#include "simulate_inputs.h"
#include "unit_options.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>

namespace ddfcam::cli {
namespace {

std::string help() {
  return simulateArguments().help();
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

ddf::DisplacementField loadInput(const std::filesystem::path& input,
                                 const std::optional<ddfcam::LengthUnit>& unit) {
  if (input == "demo") return ddf::demoPart().ddf;
  if (input.extension() == ".ddfproj") {
    planning::Project project = io::readProject(input);
    if (!project.part) throw InvalidInput("simulate: project " + input.string() + " has no part");
    return std::move(*project.part);
  }
  io::LoadPartParams params;
  params.unit = unit;
  return loadPartInUnit(input, params, "loading");
}

struct SimulationResult {
  planning::GrindingReport grinding;
  std::optional<planning::PenetrationCorrectionReport> correction;
  std::optional<planning::PrestonReport> preston;
  std::vector<planning::PassSampling> sampling;
  ImportFacts import;
  planning::ErrorStatistics stats;
  planning::Coverage coverage;       // area the tool touched over the part's area
  planning::CrustClamping clamping;  // points left at the crust bottom by a deeper cut
  RunWarnings warnings;
  int passes = 0, poses = 0;
  double removedVolumeMm3 = 0, prestonFeedMmPerMin = 0;
  double loadSeconds = 0, correctSeconds = 0, simulateSeconds = 0, totalSeconds = 0;
};

void writeText(const std::string& text, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw IoError("simulate: cannot write " + file.string());
}

JsonReport toolJson(const SimulateOptions& o) {
  JsonReport json;
  json["name"] = o.tool.name;
  json["kind"] = o.toolKind;
  json["source"] = o.toolSource;
  json["radius_mm"] = o.tool.radiusMm;
  if (o.tool.kind != planning::ToolKind::Sphere) json["width_mm"] = o.tool.widthMm;
  json["edge_radius_mm"] = o.tool.edgeRadiusMm;
  json["lead_deg"] = o.placement.leadDeg;
  json["tilt_deg"] = o.placement.tiltDeg;
  return json;
}

// The smallest step over the passes and the rule that bound it, plus every pass.
JsonReport samplingJson(const SimulateOptions& o, const SimulationResult& r) {
  if (!o.resample()) return nullptr;
  const auto finest =
      std::min_element(r.sampling.begin(), r.sampling.end(),
                       [](const auto& a, const auto& b) { return a.step.stepMm < b.step.stepMm; });
  JsonReport json;
  json["sample_tolerance_mm"] = o.sampleToleranceMm.value_or(o.toleranceMm);
  json["sample_step_mm"] = finest->step.stepMm;
  json["sample_rule"] = planning::stepRuleName(finest->bindingRule);
  json["per_pass"] = JsonReport::array();
  for (const planning::PassSampling& pass : r.sampling) {
    JsonReport& p = json["per_pass"].emplace_back();
    p["step_mm"] = pass.step.stepMm;
    p["rule"] = planning::stepRuleName(pass.bindingRule);
    p["length_mm"] = pass.lengthMm;
    p["inserted_poses"] = pass.sweepInsertedPoses;
  }
  return json;
}

JsonReport correctionJson(const SimulationResult& r) {
  const auto& c = r.correction;
  if (!c) return nullptr;
  JsonReport json;
  json["poses_lifted"] = c->penetratingPoses;
  json["max_lift_mm"] = c->maxLiftMm;
  json["exact_poses"] = c->exactPoses;
  json["corrected_after_check"] = c->correctedAfterCheck;
  json["max_residual_mm"] = c->maxResidualMm;
  json["ms"] = 1e3 * r.correctSeconds;
  return json;
}

JsonReport prestonJson(const SimulateOptions& o, const SimulationResult& r) {
  const auto& p = r.preston;
  if (!p) return nullptr;
  double deepest = 0.0;
  for (double d : p->maxDepthMm) deepest = std::max(deepest, d);
  JsonReport json;
  json["kp_mm2_per_n"] = o.preston.kpMm2PerN;
  json["force_n"] = o.preston.forceN;
  json["wheel_speed_m_per_s"] = o.preston.wheelSpeedMPerS;
  json["feed_mm_per_min"] = r.prestonFeedMmPerMin;
  json["infeed_mm"] = o.preston.infeedMm;
  json["max_removal_depth_mm"] = deepest;
  json["poses_without_contact"] = p->posesWithoutContact;
  return json;
}

// The statistics with their coverage and the clamping that bounds the minimum.
JsonReport deviationJson(const SimulationResult& r) {
  const planning::ErrorStatistics& s = r.stats;
  JsonReport json;
  json["max_mm"] = s.maxMm;
  json["min_mm"] = s.minMm;
  json["mean_mm"] = s.meanMm;
  json["rms_mm"] = s.rmsMm;
  json["in_tolerance_percent"] = s.inTolerancePercent;
  json["material_left_percent"] = s.materialLeftPercent;
  json["overcut_percent"] = s.overcutPercent;
  json["area_mm2"] = s.areaMm2;
  json["points"] = s.points;
  json["coverage_percent"] = r.coverage.percent();
  json["touched_area_mm2"] = r.coverage.coveredAreaMm2;
  json["part_area_mm2"] = r.coverage.totalAreaMm2;
  json["clamped_points"] = r.clamping.points;
  json["clamped_area_mm2"] = r.clamping.areaMm2;
  json["min_is_bound"] = r.clamping.points > 0;
  return json;
}

// The grinding counts; null where the mode does not produce them (Preston, no V check).
void writeGrinding(JsonReport& json, const SimulateOptions& o, const SimulationResult& r) {
  const bool rigid = !o.preston.enabled;
  json["v_convexity_poses"] =
      rigid && o.checkVConvexity ? JsonReport(r.grinding.vConvexity.size()) : JsonReport(nullptr);
  json["heights_lowered"] = rigid ? JsonReport(r.grinding.pointsLowered) : JsonReport(nullptr);
  json["heights_clamped"] = rigid ? JsonReport(r.grinding.pointsClamped) : JsonReport(nullptr);
  json["collision_poses"] = rigid ? JsonReport(r.grinding.collisions.size()) : JsonReport(nullptr);
}

void writeReport(const SimulateOptions& o, const SimulationResult& r) {
  JsonReport json;
  json["part"] = o.input.string();
  json["paths"] = o.paths.string();
  json["import"] = importFactsJson(r.import);
  json["tool"] = toolJson(o);
  if (o.stockMesh)
    json["stock_mesh"] = o.stockMesh->string();
  else
    json["allowance_mm"] = o.allowanceMm;
  json["tolerance_mm"] = o.toleranceMm;
  json["poses"] = r.poses;
  json["passes"] = r.passes;
  json["sampling"] = samplingJson(o, r);
  json["mode"] = o.preston.enabled ? "preston" : o.swept ? "swept" : "discrete";
  json["correction"] = correctionJson(r);
  json["preston"] = prestonJson(o, r);
  json["deviation"] = deviationJson(r);
  json["removed_volume_mm3"] = r.removedVolumeMm3;
  writeGrinding(json, o, r);
  r.warnings.write(json);
  json["seconds"] = {{"load", r.loadSeconds},
                     {"correct", r.correctSeconds},
                     {"simulate", r.simulateSeconds},
                     {"total", r.totalSeconds}};
  writeText(jsonText(json), *o.report);
}

void printSummary(const SimulateOptions& o, const SimulationResult& r) {
  const planning::ErrorStatistics& s = r.stats;
  if (!r.sampling.empty()) {
    const auto& first = r.sampling.front();
    std::printf("  sampling: step %.4g mm (%s) on the first pass\n", first.step.stepMm,
                planning::stepRuleName(first.bindingRule));
  }
  if (r.correction)
    std::printf("  correction: %d poses lifted, max lift %.4g mm in %.1f ms\n",
                r.correction->penetratingPoses, r.correction->maxLiftMm, 1e3 * r.correctSeconds);
  std::printf("  poses: %d in %d passes, removed %.6g mm^3 in %.3f s (%s)\n", r.poses, r.passes,
              r.removedVolumeMm3, r.simulateSeconds,
              o.preston.enabled ? "preston"
              : o.swept         ? "swept"
                                : "discrete");
  std::printf("  deviation (mm): max %.4g, min %.4g, mean %.4g, rms %.4g\n", s.maxMm, s.minMm,
              s.meanMm, s.rmsMm);
  std::printf("  within +-%.4g mm: %.2f %% of %.6g mm^2 (material left %.2f %%, overcut %.2f %%)\n",
              o.toleranceMm, s.inTolerancePercent, s.areaMm2, s.materialLeftPercent,
              s.overcutPercent);
  std::printf("  coverage: the tool touched %.2f %% of the part (%.6g of %.6g mm^2)\n",
              r.coverage.percent(), r.coverage.coveredAreaMm2, r.coverage.totalAreaMm2);
  if (r.clamping.points > 0)
    std::printf("  crust bottom: %zu raster points (%.4g mm^2) clamped, min is a bound\n",
                r.clamping.points, r.clamping.areaMm2);
  std::printf("wrote %s\n", o.output.string().c_str());
}

ddf::DisplacementField makeWorkpiece(const SimulateOptions& o, const ddf::DisplacementField& goal) {
  if (!o.stockMesh) return planning::workpieceWithAllowance(goal, o.allowanceMm);
  planning::StockWorkpieceParams params;
  params.fill.progress = consoleProgress("stock");
  const ddf::TriangleMesh mesh = io::readMesh(*o.stockMesh);
  warnIfOtherUnit(*o.stockMesh, io::boundingBoxDiagonal(mesh), o.unit);
  planning::StockWorkpiece stock = planning::workpieceFromStockMesh(
      goal, io::scaledToMm(mesh, o.unit.value_or(ddfcam::LengthUnit::Millimetre)), params);
  endProgressLine();
  return std::move(stock.workpiece);
}

void correct(const SimulateOptions& o, const ddf::DisplacementField& goal, CsvPath& path,
             SimulationResult& r) {
  const Clock::time_point start = Clock::now();
  planning::PenetrationCorrectionParams params;
  params.gridSize = o.correction.grid;
  params.every = o.correction.every;
  params.normals = path.normals;  // the file's, turned towards the tool where they point away
  params.progress = consoleProgress("correcting");
  planning::CorrectedPath corrected =
      planning::correctPathPenetrations(goal, o.tool, std::move(path.path), params);
  path.path = std::move(corrected.path);
  r.correction = std::move(corrected.report);
  endProgressLine();
  r.correctSeconds = secondsSince(start);
}

// Paths with more poses than this are announced with their estimated time before they run.
constexpr std::size_t kLongPathPoses = 5'000;

void announceLongPath(const ddf::DisplacementField& part, const SimulateOptions& o,
                      const planning::ToolPath& path,
                      const planning::GrindingSimulationParams& simulation) {
  if (path.poses.size() <= kLongPathPoses) return;
  const planning::SimulationEstimate e =
      planning::estimateSimulation(part, planning::toolMeshes(o.tool), path, simulation);
  std::cerr << "simulating " << path.poses.size() << " poses: about "
            << static_cast<long long>(std::ceil(e.seconds)) << " s (" << 1e3 * e.secondsPerPose
            << " ms per pose, timed on " << e.sampled << " of them)\n";
}

void cut(const SimulateOptions& o, const CsvPath& path, ddf::DisplacementField& part,
         SimulationResult& r) {
  const Clock::time_point start = Clock::now();
  if (o.preston.enabled) {
    planning::PrestonParams params;
    params.prestonCoefficientMm2PerN = o.preston.kpMm2PerN;
    params.forceN = o.preston.forceN;
    params.surfaceSpeedMmPerS = 1e3 * o.preston.wheelSpeedMPerS;
    r.prestonFeedMmPerMin = o.preston.feedMmPerMin.value_or(path.path.feedMmPerMin);
    params.feedMmPerS = r.prestonFeedMmPerMin / 60.0;
    params.infeedMm = o.preston.infeedMm;
    params.normals = path.normals;
    params.progress = consoleProgress("preston");
    planning::PrestonStageResult ground =
        planning::prestonStage(std::move(part), o.tool, path.path, params);
    part = std::move(ground.workpiece);
    r.preston = std::move(ground.report);
    r.removedVolumeMm3 = r.preston->removedVolumeMm3;
  } else {
    planning::GrindingSimulationParams simulation;
    simulation.checkVConvexity = o.checkVConvexity;
    simulation.mode = o.swept ? planning::SweepMode::Swept : planning::SweepMode::Discrete;
    announceLongPath(part, o, path.path, simulation);
    r.grinding = planning::simulateGrinding(part, planning::toolMeshes(o.tool), path.path,
                                            simulation, consoleProgress("grinding"));
    r.removedVolumeMm3 = r.grinding.removedVolumeMm3;
  }
  endProgressLine();
  r.simulateSeconds = secondsSince(start);
}

int runSimulate(std::span<const std::string> words) {
  const Clock::time_point begin = Clock::now();
  const SimulateOptions o = parseSimulateOptions(words);
  SimulationResult r;
  const ddf::DisplacementField goal = loadInput(o.input, o.unit);
  CsvPath path = importSimulationPath(goal, o);
  r.import = path.facts;
  r.passes = static_cast<int>(path.path.passStarts.size());
  r.poses = static_cast<int>(path.path.poses.size());
  r.sampling = path.sampling;
  std::printf("simulate %s on %s: %d faces, m = %d, %d poses\n", o.tool.name.c_str(),
              o.input.string().c_str(), goal.faceCount(), goal.raster().m, r.poses);
  ddf::DisplacementField part = makeWorkpiece(o, goal);
  r.loadSeconds = secondsSince(begin);
  if (o.correction.enabled) correct(o, goal, path, r);
  cut(o, path, part, r);
  io::writeDdf(part, o.output);
  const planning::ScalarField deviation = planning::deviationMap(part, goal);
  const planning::ToleranceBand band{-o.toleranceMm, o.toleranceMm};
  r.stats = planning::errorStatistics(deviation, goal, band);
  r.clamping = planning::crustClamping(deviation, part);
  r.coverage = simulationCoverage(goal, o, path.path);
  if (o.errorMap) {
    io::VtpPointData data;
    const ddf::TriangleMesh mesh = errorMapMesh(part, deviation, band, data);
    io::writeVtp(mesh, data, *o.errorMap);
  }
  r.totalSeconds = secondsSince(begin);
  collectSimulateWarnings(o, {r.import, r.coverage, r.clamping, r.stats, r.grinding}, r.warnings);
  if (o.report) writeReport(o, r);
  printSummary(o, r);
  return r.warnings.exitCode(o.strict, "simulate");
}

}  // namespace

const Command kSimulateCommand{
    "simulate", "grind tool paths into a part: DDF, error map, JSON report", &help, &runSimulate};

}  // namespace ddfcam::cli
