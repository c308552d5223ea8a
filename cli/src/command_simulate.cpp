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
#include <ddfcam/planning/simulation/workpiece.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "error_map_vtp.h"
#include "json_writer.h"
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

constexpr const char* kHelp =
    "usage: ddfcam-cli simulate PART --paths FILE -o OUT.ddf [options]\n\n"
    "Grinds the cut moves of a tool-path file (a CSV as written by 'ddfcam-cli plan', APT/CLDATA,\n"
    "ROS toolpath YAML or FANUC .ls; see 'ddfcam-cli paths') into PART (a .ddf\n"
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
    "writing the outputs).\n\n"
    "options:\n"
    "  --paths FILE             tool-path file (required): CSV (link and rapid rows are not\n"
    "                           cut), APT/CLDATA, ROS toolpath YAML or FANUC .ls\n"
    "  --path-units mm|in|m     the file's numbers are in this unit (overrides the file's)\n"
    "  --rotate AX,AY,AZ        rotate the path about the part's x, y, z axes, deg, as\n"
    "                           Rz(AZ) Ry(AY) Rx(AX) (x first), before --translate\n"
    "  --translate X,Y,Z        move the path by this vector, mm, after the unit and rotation\n"
    "  --keep-rapids            also place and cut the rapid moves (not for CSVs with normals)\n"
    "  --vectors axis|approach|normal|auto\n"
    "                           what the file's i,j,k vectors are: tool axes (tip to holder),\n"
    "                           approach directions (into the part, as robots give them) or\n"
    "                           surface normals; auto (default) decides from PART (into it:\n"
    "                           approach) and the report says why; a gouging choice is warned\n"
    "  --points contact|tip|file|auto\n"
    "                           what the file's points are: contacts on the surface, tool tips\n"
    "                           (wheel and ball centres), as the file says; auto (default)\n"
    "                           decides from their distance to PART\n"
    "  -o, --output FILE        simulated part as .ddf (required)\n"
    "  --error-map FILE         deviation per raster point as VTK PolyData (.vtp)\n"
    "  --report FILE            statistics as JSON\n"
    "  --min-coverage P         warn when the tool touches less than P % of the part (default\n"
    "                           5: even a path for one region covers more)\n"
    "  --strict                 exit with code 3 when the run had any warning\n"
    "tool:\n"
    "  --tool KIND              roll (= cylinder_roll, default), ball (bare sphere = sphere),\n"
    "                           cylinder_roll, sphere, belt_contact_wheel, ball_end, flat_end,\n"
    "                           torus_cutter\n"
    "  --radius MM              tool radius (default 5)\n"
    "  --width MM               wheel width or cutter flute length (default 2 x radius; not\n"
    "                           for ball)\n"
    "  --corner-radius MM       wheel rim radius, or torus_cutter corner radius (required there)\n"
    "  --tool-file FILE --tool-name NAME\n"
    "                           take the tool NAME from a tool library file instead of --tool,\n"
    "                           --radius, --width, --corner-radius\n"
    "  --lead DEG, --tilt DEG   lead and tilt angles of the tool at the contact (default 0;\n"
    "                           CSVs with normals only: programs carry their tool axes)\n"
    "sampling along the feed (CSVs with normals only; default: one pose per CSV row):\n"
    "  --sample-tolerance MM    resample every pass at the step derived from this tolerance\n"
    "                           (feed chord, raster spacing, tool profile cusp; default rule\n"
    "                           tolerance = --tolerance when only --step is given)\n"
    "  --step MM                resample every pass at this fixed step instead\n"
    "workpiece and process:\n"
    "  --allowance MM           stock above the desired surface along its normal (default 0:\n"
    "                           the workpiece is the desired surface, so only gouges show)\n"
    "  --stock-mesh FILE        workpiece from a stock mesh (.stl/.obj/.ply/.off) converted onto\n"
    "                           PART's support instead of --allowance (read in --units)\n"
    "  --units U                unit of a mesh or CAD PART and of the stock mesh: mm, cm, m\n"
    "                           or in (default: the unit a CAD file states, mm for meshes)\n"
    "  --swept                  cut the swept volume between consecutive poses (convex tools)\n"
    "  --correct                lift every pose off the desired surface until it no longer\n"
    "                           penetrates it (tangential DDF, sec. 8.4.2) before cutting\n"
    "  --correct-every K        exact lift at every K-th pose, interpolated between (default 1)\n"
    "  --correct-grid N         tangential grid N x N (default 50)\n"
    "  --preston                Preston removal (depth = K_p p v_s dt) instead of the rigid cut\n"
    "  --kp MM2_PER_N           Preston coefficient K_p, mm^2/N (default 1e-7)\n"
    "  --force N                normal force, N (default 10)\n"
    "  --wheel-speed M_PER_S    wheel surface speed, m/s (default 30)\n"
    "  --feed MM_PER_MIN        feed (default: the CSV's feed)\n"
    "  --infeed MM              infeed of the undeformed tool setting the contact patch (0.1)\n"
    "  --tolerance MM           tolerance band [-T, T] of the statistics (default 0.01)\n"
    "  --no-vconvexity-check    skip the check for cuts that are not V-convex (fig. 8.15);\n"
    "                           the check probes every stubble under the tool at every pose\n"
    "  -h, --help               show this help\n";

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

void writeTool(JsonWriter& json, const SimulateOptions& o) {
  json.key("tool").beginObject();
  json.key("name").value(o.tool.name).key("kind").value(o.toolKind);
  json.key("source").value(o.toolSource);
  json.key("radius_mm").value(o.tool.radiusMm);
  if (o.tool.kind != planning::ToolKind::Sphere) json.key("width_mm").value(o.tool.widthMm);
  json.key("edge_radius_mm").value(o.tool.edgeRadiusMm);
  json.key("lead_deg").value(o.placement.leadDeg).key("tilt_deg").value(o.placement.tiltDeg);
  json.endObject();
}

// The smallest step over the passes and the rule that bound it, plus every pass.
void writeSampling(JsonWriter& json, const SimulateOptions& o, const SimulationResult& r) {
  if (!o.resample()) {
    json.key("sampling").null();
    return;
  }
  const auto finest =
      std::min_element(r.sampling.begin(), r.sampling.end(),
                       [](const auto& a, const auto& b) { return a.step.stepMm < b.step.stepMm; });
  json.key("sampling").beginObject();
  json.key("sample_tolerance_mm").value(o.sampleToleranceMm.value_or(o.toleranceMm));
  json.key("sample_step_mm").value(finest->step.stepMm);
  json.key("sample_rule").value(planning::stepRuleName(finest->bindingRule));
  json.key("per_pass").beginArray();
  for (const planning::PassSampling& pass : r.sampling) {
    json.beginObject().key("step_mm").value(pass.step.stepMm);
    json.key("rule").value(planning::stepRuleName(pass.bindingRule));
    json.key("length_mm").value(pass.lengthMm);
    json.key("inserted_poses").value(pass.sweepInsertedPoses).endObject();
  }
  json.endArray().endObject();
}

void writeProcess(JsonWriter& json, const SimulateOptions& o, const SimulationResult& r) {
  json.key("mode").value(o.preston.enabled ? "preston" : o.swept ? "swept" : "discrete");
  if (const auto& c = r.correction) {
    json.key("correction").beginObject();
    json.key("poses_lifted").value(c->penetratingPoses).key("max_lift_mm").value(c->maxLiftMm);
    json.key("exact_poses").value(c->exactPoses);
    json.key("corrected_after_check").value(c->correctedAfterCheck);
    json.key("max_residual_mm").value(c->maxResidualMm);
    json.key("ms").value(1e3 * r.correctSeconds).endObject();
  } else {
    json.key("correction").null();
  }
  if (const auto& p = r.preston) {
    double deepest = 0.0;
    for (double d : p->maxDepthMm) deepest = std::max(deepest, d);
    json.key("preston").beginObject();
    json.key("kp_mm2_per_n").value(o.preston.kpMm2PerN).key("force_n").value(o.preston.forceN);
    json.key("wheel_speed_m_per_s").value(o.preston.wheelSpeedMPerS);
    json.key("feed_mm_per_min").value(r.prestonFeedMmPerMin);
    json.key("infeed_mm").value(o.preston.infeedMm);
    json.key("max_removal_depth_mm").value(deepest);
    json.key("poses_without_contact").value(p->posesWithoutContact).endObject();
  } else {
    json.key("preston").null();
  }
}

// The statistics with their coverage and the clamping that bounds the minimum.
void writeDeviation(JsonWriter& json, const SimulationResult& r) {
  const planning::ErrorStatistics& s = r.stats;
  json.key("deviation").beginObject();
  json.key("max_mm").value(s.maxMm).key("min_mm").value(s.minMm);
  json.key("mean_mm").value(s.meanMm).key("rms_mm").value(s.rmsMm);
  json.key("in_tolerance_percent").value(s.inTolerancePercent);
  json.key("material_left_percent").value(s.materialLeftPercent);
  json.key("overcut_percent").value(s.overcutPercent);
  json.key("area_mm2").value(s.areaMm2).key("points").value(s.points);
  json.key("coverage_percent").value(r.coverage.percent());
  json.key("touched_area_mm2").value(r.coverage.coveredAreaMm2);
  json.key("part_area_mm2").value(r.coverage.totalAreaMm2);
  json.key("clamped_points").value(r.clamping.points);
  json.key("clamped_area_mm2").value(r.clamping.areaMm2);
  json.key("min_is_bound").value(r.clamping.points > 0);
  json.endObject();
}

void writeReport(const SimulateOptions& o, const SimulationResult& r) {
  JsonWriter json;
  json.beginObject();
  json.key("part").value(o.input.string()).key("paths").value(o.paths.string());
  writeImportFacts(json, r.import);
  writeTool(json, o);
  if (o.stockMesh)
    json.key("stock_mesh").value(o.stockMesh->string());
  else
    json.key("allowance_mm").value(o.allowanceMm);
  json.key("tolerance_mm").value(o.toleranceMm);
  json.key("poses").value(r.poses).key("passes").value(r.passes);
  writeSampling(json, o, r);
  writeProcess(json, o, r);
  writeDeviation(json, r);
  json.key("removed_volume_mm3").value(r.removedVolumeMm3);
  const bool rigid = !o.preston.enabled;
  if (rigid && o.checkVConvexity)
    json.key("v_convexity_poses").value(r.grinding.vConvexity.size());
  else
    json.key("v_convexity_poses").null();
  if (rigid) {
    json.key("heights_lowered").value(r.grinding.pointsLowered);
    json.key("heights_clamped").value(r.grinding.pointsClamped);
    json.key("collision_poses").value(r.grinding.collisions.size());
  } else {
    json.key("heights_lowered").null().key("heights_clamped").null();
    json.key("collision_poses").null();
  }
  r.warnings.write(json);
  json.key("seconds").beginObject();
  json.key("load").value(r.loadSeconds).key("correct").value(r.correctSeconds);
  json.key("simulate").value(r.simulateSeconds);
  json.key("total").value(r.totalSeconds).endObject();
  json.endObject();
  writeText(json.str(), *o.report);
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
    "simulate", "grind tool paths into a part: DDF, error map, JSON report", kHelp, &runSimulate};

}  // namespace ddfcam::cli
