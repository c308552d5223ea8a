// SPDX-License-Identifier: MIT
// Benchmark: Jobard-Lefer coverage of the fig. 8.16 part by k_max streamlines at several d_sep.
#include "ddf/grinding_workloads.h"

#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddfcam::bench {
namespace {

struct CoverageWorkload {
  GrindingWorkload part = fig8_16Workload();
  planning::LineField dirMax;
};

const CoverageWorkload& workload() {
  static const CoverageWorkload w = [] {
    CoverageWorkload out;
    const planning::CurvatureField c = planning::computeCurvature(out.part.ddf);
    out.dirMax = c.dirMax;
    for (std::size_t i = 0; i < out.dirMax.size(); ++i)
      if (c.umbilic[i]) out.dirMax[i] = ddf::Vec3::Zero();
    return out;
  }();
  return w;
}

// Brute force over all point pairs of different lines (the check the grid replaces).
double bruteForceSeparation(const std::vector<planning::Streamline>& lines) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (std::size_t b = a + 1; b < lines.size(); ++b)
      for (const auto& p : lines[a].points)
        for (const auto& q : lines[b].points) best = std::min(best, (p.point - q.point).norm());
  return best;
}

// Largest distance from a raster point (every 4th in each direction) to the nearest line point.
double coverageGap(const ddf::DisplacementField& ddf,
                   const std::vector<planning::Streamline>& lines) {
  double worst = 0.0;
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; k += 4)
      for (int i = 0; i <= n - k; i += 4) {
        const ddf::Vec3 q = ddf.surfacePoint(f, i, k);
        double best = std::numeric_limits<double>::infinity();
        for (const auto& line : lines)
          for (const auto& p : line.points) best = std::min(best, (p.point - q).norm());
        worst = std::max(worst, best);
      }
  return worst;
}

// Argument: d_sep in hundredths of a millimetre.
void BM_EvenlySpaced_Fig8_16(benchmark::State& state) {
  const CoverageWorkload& w = workload();
  planning::EvenSpacingParams params;
  params.separationMm = static_cast<double>(state.range(0)) / 100.0;
  std::vector<planning::Streamline> lines;
  for (auto _ : state) {
    lines = planning::evenlySpacedStreamlines(w.part.ddf, w.dirMax, params);
    benchmark::DoNotOptimize(lines.data());
  }
  std::size_t points = 0;
  double length = 0.0;
  for (const auto& line : lines) points += line.points.size(), length += line.lengthMm;
  const planning::LinkedPaths linked = planning::linkStreamlines(w.part.ddf, lines, {});
  state.counters["d_sep_mm"] = params.separationMm;
  state.counters["lines"] = static_cast<double>(lines.size());
  state.counters["points"] = static_cast<double>(points);
  state.counters["length_mm"] = length;
  state.counters["idle_mm"] = linked.idleLengthMm;
  state.counters["min_sep_over_dsep"] = bruteForceSeparation(lines) / params.separationMm;
  state.counters["max_gap_over_dsep"] = coverageGap(w.part.ddf, lines) / params.separationMm;
}
BENCHMARK(BM_EvenlySpaced_Fig8_16)
    ->Arg(200)
    ->Arg(100)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The brute-force separation check of a coverage, for the ratio to the grid-based build.
void BM_EvenlySpaced_BruteForceCheck_Fig8_16(benchmark::State& state) {
  const CoverageWorkload& w = workload();
  planning::EvenSpacingParams params;
  params.separationMm = static_cast<double>(state.range(0)) / 100.0;
  const auto lines = planning::evenlySpacedStreamlines(w.part.ddf, w.dirMax, params);
  double sep = 0.0;
  for (auto _ : state) {
    sep = bruteForceSeparation(lines);
    benchmark::DoNotOptimize(sep);
  }
  state.counters["lines"] = static_cast<double>(lines.size());
}
BENCHMARK(BM_EvenlySpaced_BruteForceCheck_Fig8_16)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
