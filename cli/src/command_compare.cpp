// SPDX-License-Identifier: MIT
// ddfcam-cli compare: deviation of a formed surface from its mould on the mould's DDF
// (dissertation ch. 9): statistics, staged sequence, deviation map and vectors.
#include <ddfcam/error.h>
#include <ddfcam/io/results/deviation_export.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/mould/surface_alignment.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "json_output.h"
#include "mould_options.h"
#include "run_warnings.h"
#include "unit_options.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Compares the formed (deformed) surface FORMED with the mould (or target) surface MOULD\n"
    "(.stl/.obj/.ply/.off/.vtp/.vtu, in --units): builds a DDF on the mould, represents the\n"
    "formed surface as its heights (split into a sequence of smaller deformations where the\n"
    "unique-projection property fails, fig. 9.5) and reports the signed deviation along the\n"
    "mould normal: > 0 short of the mould (blue), < 0 beyond it (red), inside the band green.\n"
    "Beside the statistics it reports their coverage: the share of the mould's area with a\n"
    "trusted deviation. Faces the deformation sequence leaves unresolved are excluded from the\n"
    "statistics and counted; a sequence that stalls (splits carrying only slivers of the\n"
    "deformation) stops early and says what to change.\n"
    "Warns when the coverage is below --min-coverage, faces are unresolved or the sequence\n"
    "stalled; with --strict any warning makes the exit code 3 (after writing the outputs).";

Arguments options() {
  Arguments args("compare", "compare MOULD FORMED [options]", kDescription);
  args.positional("MOULD", "mould (or target) surface file");
  args.positional("FORMED", "formed surface file");
  args.option("-o,--output", "FILE",
              "deviation map as VTK PolyData (.vtp): the mould's raster mesh with\n"
              "'deviation' (mm), 'tolerance_class' (-1, 0, +1), 'deviation_vector'");
  args.option("--csv", "FILE", "deviation vectors, one row per raster point (x,y,z,dx,dy,dz,dev)");
  addMouldOptions(args, {.surfaces = "MOULD and FORMED",
                         .written = "the outputs are in mm",
                         .ddf = "the mould DDF",
                         .reach = "length of the displacement vectors (default: from the distance)",
                         .json = "statistics, stages, histogram and timings as JSON"});
  args.option("--tolerance", "T", "tolerance band [-T, T], mm (default 0.5)")
      ->check(positiveNumber());
  args.option("--band", "LO,HI",
              "tolerance band [LO, HI], mm, LO <= 0 <= HI (instead of --tolerance)");
  args.flag("--flip-normal", "reverse the mould normal (and the sign of every deviation)");
  args.option("--align", "none|best-fit", "alignment of FORMED onto MOULD (none: as positioned)")
      ->check(oneOf({"none", "best-fit"}))
      ->default_str("none");
  args.option("--max-stages", "N", "most DDFs in the deformation sequence")
      ->check(integerIn(1, 1000))
      ->default_str(std::to_string(planning::ComparisonParams{}.sequence.maxStages));
  addMinCoverageOption(args,
                       "warn when the statistics cover less than P % of the mould's area\n"
                       "(default 50: a formed part and its mould overlap almost entirely)");
  args.flag("--strict",
            "exit with code 3 when the run had any warning (the best-fit\nnote excepted)");
  return args;
}

std::string help() {
  return options().help();
}

struct CompareRun {
  planning::LoadedSurface mould, formed;
  std::optional<planning::RigidAlignment> alignment;
  planning::SurfaceComparison result;
  planning::ComparisonCoverage coverage;
  RunWarnings warnings;
  double loadSeconds = 0, alignSeconds = 0, compareSeconds = 0;
};

planning::ComparisonParams comparisonParams(const Arguments& args) {
  planning::ComparisonParams params;
  params.resolution = args.integer("resolution", params.resolution);
  if (args.has("tolerance") && args.has("band"))
    throw UsageError("compare: give either --tolerance or --band, not both");
  if (const auto t = args.number("tolerance")) params.band = {-*t, *t};
  if (const auto band = args.value("band")) {
    const std::vector<double> v = parseNumberList(*band, 2, "band");
    if (v[0] > 0.0 || v[1] < 0.0) throw UsageError("--band: need LO <= 0 <= HI, got " + *band);
    params.band = {v[0], v[1]};
  }
  params.flipNormal = args.has("flip-normal");
  params.sequence.maxStages = args.integer("max-stages", params.sequence.maxStages);
  if (const auto reach = args.number("reach")) params.sequence.reachMm = *reach;
  return params;
}

void align(const std::string& method, CompareRun& run) {
  if (method == "none") return;
  const auto start = std::chrono::steady_clock::now();
  planning::BestFitParams params;
  params.progress = consoleProgress("aligning");
  run.alignment = planning::alignBestFit(run.formed.mesh, run.mould.mesh, params);
  endProgressLine();
  for (Eigen::Vector3d& v : run.formed.mesh.vertices) v = run.alignment->transform * v;
  run.alignSeconds = secondsSince(start);
  std::fprintf(stderr, "warning: %s\n", planning::kBestFitWarning);
  std::printf(
      "  best fit: RMS %.4g -> %.4g mm, rotation %.4g deg, shift %.4g mm, %d iterations%s\n",
      run.alignment->rmsBeforeMm, run.alignment->rmsMm,
      planning::rotationAngleDeg(run.alignment->transform),
      run.alignment->transform.translation().norm(), run.alignment->iterations,
      run.alignment->converged ? "" : " (not converged)");
}

/// Standard deviation from the area-weighted mean and RMS.
double sigmaOf(const planning::ErrorStatistics& s) {
  return std::sqrt(std::max(0.0, s.rmsMm * s.rmsMm - s.meanMm * s.meanMm));
}

void printSummary(const CompareRun& run) {
  const planning::ErrorStatistics& s = run.result.statistics;
  const planning::ToleranceBand& band = run.result.band;
  const ddf::DeformationSequence& seq = run.result.sequence;
  std::printf("  deviation (mm): max %.4g, min %.4g, mean %.4g, sigma %.4g, rms %.4g\n", s.maxMm,
              s.minMm, s.meanMm, sigmaOf(s), s.rmsMm);
  std::printf("  within [%.4g, %.4g] mm: %.2f %% of %.6g mm^2 (short %.2f %%, beyond %.2f %%)\n",
              band.lowerMm, band.upperMm, s.inTolerancePercent, s.areaMm2, s.materialLeftPercent,
              s.overcutPercent);
  const planning::ComparisonCoverage& c = run.coverage;
  std::printf(
      "  coverage: %.2f %% of the mould's %.6g mm^2 (unresolved %zu faces, %.6g mm^2 excluded; "
      "formed surface not found on %.6g mm^2)\n",
      c.compared.percent(), c.compared.totalAreaMm2, c.unresolvedFaces, c.unresolvedAreaMm2,
      c.missingAreaMm2);
  std::printf("  stages: %zu (fractions", seq.stages.size());
  for (const ddf::DeformationStage& stage : seq.stages) std::printf(" %.3g", stage.fraction);
  std::printf("), crossing faces %zu, unresolved faces %zu, missing points %zu\n",
              seq.crossingFaces.size(), seq.unresolvedFaces.size(), seq.missingPoints);
  std::printf("  time (s): load %.3f, align %.3f, compare %.3f\n", run.loadSeconds,
              run.alignSeconds, run.compareSeconds);
}

// Low coverage and unresolved faces: the statistics describe only part of the mould.
void warnAbout(CompareRun& run, double minCoveragePercent) {
  const planning::ComparisonCoverage& c = run.coverage;
  char text[400];
  if (c.compared.percent() < minCoveragePercent) {
    std::snprintf(text, sizeof text,
                  "the statistics cover only %.3g %% of the mould (%.6g of %.6g mm^2, "
                  "--min-coverage %.3g %%): the formed surface overlaps little of it; check "
                  "the files, their units and the alignment",
                  c.compared.percent(), c.compared.coveredAreaMm2, c.compared.totalAreaMm2,
                  minCoveragePercent);
    run.warnings.add(text);
  }
  if (run.result.sequence.stalled) run.warnings.add(planning::stallAdvice(run.result));
  if (c.unresolvedFaces > 0) {
    std::snprintf(text, sizeof text,
                  "%zu faces (%.6g mm^2) are unresolved by the deformation sequence and left "
                  "out of the statistics; allow more stages (--max-stages) or check the "
                  "alignment",
                  c.unresolvedFaces, c.unresolvedAreaMm2);
    run.warnings.add(text);
  }
}

JsonReport histogramJson(const CompareRun& run) {
  const planning::ErrorStatistics& s = run.result.statistics;
  const double pad = std::max(1e-9, 1e-6 * (std::abs(s.maxMm) + std::abs(s.minMm)));
  // Weighted by the mould's area, as the statistics are (stage 0's heights describe the formed
  // surface, whose area differs).
  ddf::DisplacementField mould = run.result.sequence.stages.front().ddf;
  std::fill(mould.allHeights().begin(), mould.allHeights().end(), 0.0f);
  // Over the faces the statistics use: unresolved deviations would widen the range and fill it.
  const planning::AreaHistogram h =
      planning::errorHistogram(run.result.deviation, mould, 40, s.minMm - pad, s.maxMm + pad,
                               planning::resolvedFaces(run.result));
  JsonReport json;
  json["lower_mm"] = h.lowerMm;
  json["upper_mm"] = h.upperMm;
  json["bin_width_mm"] = h.binWidthMm();
  json["area_mm2"] = h.areaMm2;
  json["below_mm2"] = h.belowMm2;
  json["above_mm2"] = h.aboveMm2;
  return json;
}

JsonReport statisticsJson(const planning::ErrorStatistics& s) {
  JsonReport json;
  json["max_mm"] = s.maxMm;
  json["min_mm"] = s.minMm;
  json["mean_mm"] = s.meanMm;
  json["sigma_mm"] = sigmaOf(s);
  json["rms_mm"] = s.rmsMm;
  json["within_band_percent"] = s.inTolerancePercent;
  json["short_percent"] = s.materialLeftPercent;
  json["beyond_percent"] = s.overcutPercent;
  json["area_mm2"] = s.areaMm2;
  json["points"] = s.points;
  return json;
}

JsonReport coverageJson(const planning::ComparisonCoverage& c) {
  JsonReport json;
  json["coverage_percent"] = c.compared.percent();
  json["compared_area_mm2"] = c.compared.coveredAreaMm2;
  json["mould_area_mm2"] = c.compared.totalAreaMm2;
  json["unresolved_area_mm2"] = c.unresolvedAreaMm2;
  json["missing_area_mm2"] = c.missingAreaMm2;
  return json;
}

void writeSequence(JsonReport& json, const ddf::DeformationSequence& seq) {
  JsonReport& stages = json["stages"] = JsonReport::array();
  for (const ddf::DeformationStage& stage : seq.stages)
    stages.push_back(
        {{"fraction", stage.fraction}, {"crossing_faces", stage.crossingFaces.size()}});
  json["crossing_faces"] = seq.crossingFaces.size();
  json["unresolved_faces"] = seq.unresolvedFaces.size();
  json["missing_points"] = seq.missingPoints;
}

JsonReport alignmentJson(const CompareRun& run) {
  JsonReport json;
  json["method"] = run.alignment ? "best-fit" : "none";
  if (run.alignment) {
    json["rms_before_mm"] = run.alignment->rmsBeforeMm;
    json["rms_mm"] = run.alignment->rmsMm;
    json["rotation_deg"] = planning::rotationAngleDeg(run.alignment->transform);
  }
  return json;
}

void writeJson(const Arguments& args, const CompareRun& run, const std::filesystem::path& file) {
  JsonReport json;
  json["mould"] = run.mould.sourcePath;
  json["formed"] = run.formed.sourcePath;
  json["resolution"] = run.result.sequence.stages.front().ddf.resolution();
  json["band"] = {{"lower_mm", run.result.band.lowerMm}, {"upper_mm", run.result.band.upperMm}};
  json["flip_normal"] = args.has("flip-normal");
  json["alignment"] = alignmentJson(run);
  json["statistics"] = statisticsJson(run.result.statistics);
  json["coverage"] = coverageJson(run.coverage);
  writeSequence(json, run.result.sequence);
  run.warnings.write(json);
  json["histogram"] = histogramJson(run);
  json["seconds"] = {
      {"load", run.loadSeconds}, {"align", run.alignSeconds}, {"compare", run.compareSeconds}};
  writeTextFile(jsonText(json), file, "compare");
}

void writeOutputs(const Arguments& args, const CompareRun& run) {
  if (const auto vtp = args.value("output")) {
    io::writeDeviationVtp(run.result, *vtp);
    std::printf("wrote %s\n", vtp->c_str());
  }
  if (const auto csv = args.value("csv")) {
    io::writeDeviationCsv(run.result, *csv);
    std::printf("wrote %s\n", csv->c_str());
  }
  if (const auto json = args.value("json")) {
    writeJson(args, run, *json);
    std::printf("wrote %s\n", json->c_str());
  }
}

int runCompare(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(2, "MOULD FORMED");
  installLogSink();
  planning::ComparisonParams params = comparisonParams(args);
  const double minCoverage = minCoverageOption(args, planning::kLowComparisonCoveragePercent);
  const std::string method = *args.value("align");
  auto start = std::chrono::steady_clock::now();
  CompareRun run;
  const std::optional<ddfcam::LengthUnit> unit = unitOption(args);
  run.mould = loadSurface(args.positionals()[0], "mould", unit);
  run.formed = loadSurface(args.positionals()[1], "formed", unit);
  run.loadSeconds = secondsSince(start);
  std::printf("compare %s with mould %s (m = %d)\n", run.formed.name.c_str(),
              run.mould.name.c_str(), params.resolution);
  align(method, run);
  start = std::chrono::steady_clock::now();
  params.progress = consoleProgress("comparing");
  run.result = planning::compareSurfaces(run.mould.mesh, run.formed.mesh, params);
  endProgressLine();
  run.compareSeconds = secondsSince(start);
  run.coverage = planning::comparisonCoverage(run.result);
  printSummary(run);
  warnAbout(run, minCoverage);
  writeOutputs(args, run);
  return run.warnings.exitCode(args.has("strict"), "compare");
}

}  // namespace

const Command kCompareCommand{"compare",
                              "deviation of a formed surface from its mould: map, vectors, JSON",
                              &help, &runCompare};

}  // namespace ddfcam::cli
