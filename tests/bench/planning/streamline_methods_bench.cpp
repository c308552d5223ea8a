// SPDX-License-Identifier: MIT
// Benchmark: 50 k_max streamlines on the fig. 8.16 part by each tracer of sec. 8.3 (goal <= 50 ms).
#include "ddf/grinding_workloads.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_continuous.h>
#include <ddfcam/planning/lines/streamline_raster_walk.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace ddfcam::bench {
namespace {

using planning::Streamline;
using planning::StreamlineMethod;

struct MethodsWorkload {
  GrindingWorkload part = fig8_16Workload();
  planning::LineField dirMax;
  std::vector<ddf::SurfaceLocation> seeds;  // 50 seeds along the k_min line
  ddf::CrustHash hash;
  double hashMs = 0.0;
};

// The k_max field, seeded along the RK4 k_min line through the face nearest the patch centre
// with the spacing that puts 50 seeds on it (as streamline_bench.cpp).
const MethodsWorkload& workload() {
  static const MethodsWorkload w = [] {
    MethodsWorkload out;
    const ddf::DisplacementField& ddf = out.part.ddf;
    const planning::CurvatureField c = planning::computeCurvature(ddf);
    out.dirMax = c.dirMax;
    planning::LineField dirMin = c.dirMin;
    for (std::size_t i = 0; i < c.umbilic.size(); ++i)
      if (c.umbilic[i]) out.dirMax[i] = dirMin[i] = ddf::Vec3::Zero();
    const ddf::Vec3 bary(0.31, 0.33, 0.36);
    const ddf::Vec3 centre(25.0, 12.5, 0.0);
    int best = 0;
    auto gap = [&](int f) { return (ddf.basePoint(f, bary) - centre).head<2>().norm(); };
    for (int f = 1; f < ddf.faceCount(); ++f)
      if (gap(f) < gap(best)) best = f;
    const Streamline transverse = planning::traceStreamline(ddf, dirMin, {best, bary});
    out.seeds = planning::seedsAlong(ddf, transverse, transverse.lengthMm / 49.5);
    const auto t0 = std::chrono::steady_clock::now();
    out.hash = ddf::CrustHash(ddf);
    out.hashMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }();
  return w;
}

std::vector<Streamline> family(StreamlineMethod method) {
  const MethodsWorkload& w = workload();
  std::vector<Streamline> lines;
  lines.reserve(w.seeds.size());
  for (const auto& seed : w.seeds) {
    switch (method) {
      case StreamlineMethod::Rk4:
        lines.push_back(planning::traceStreamline(w.part.ddf, w.dirMax, seed));
        break;
      case StreamlineMethod::RasterWalk:
        lines.push_back(planning::traceStreamlineRasterWalk(w.part.ddf, w.dirMax, seed));
        break;
      case StreamlineMethod::Continuous:
        lines.push_back(planning::traceStreamlineContinuous(w.part.ddf, w.dirMax, seed, {},
                                                            {.crustHash = &w.hash}));
        break;
    }
  }
  return lines;
}

double familyMs(StreamlineMethod method) {
  const auto t0 = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(family(method).data());
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The RK4 family's time in this run: the median of 7 runs, the reference of every ratio.
double rk4Ms() {
  static const double ms = [] {
    std::vector<double> runs;
    for (int i = 0; i < 7; ++i) runs.push_back(familyMs(StreamlineMethod::Rk4));
    std::nth_element(runs.begin(), runs.begin() + 3, runs.end());
    return runs[3];
  }();
  return ms;
}

void BM_StreamlineMethods_Fig8_16(benchmark::State& state) {
  const auto method = static_cast<StreamlineMethod>(state.range(0));
  state.SetLabel(planning::streamlineMethodName(method));
  const double reference = rk4Ms();
  std::size_t lines = 0, points = 0;
  double length = 0.0, total = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto result = family(method);
    total +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    lines = result.size(), points = 0, length = 0.0;
    for (const auto& line : result) points += line.points.size(), length += line.lengthMm;
    benchmark::DoNotOptimize(result.data());
  }
  const double ms = total / static_cast<double>(state.iterations());
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["points"] = static_cast<double>(points);
  state.counters["length_mm"] = length;
  state.counters["family_ms"] = ms;
  state.counters["rk4_ms"] = reference;
  state.counters["ratio_to_rk4"] = ms / reference;
  state.counters["hash_build_ms"] =
      method == StreamlineMethod::Continuous ? workload().hashMs : 0.0;
}
BENCHMARK(BM_StreamlineMethods_Fig8_16)
    ->Arg(static_cast<int>(StreamlineMethod::Rk4))
    ->Arg(static_cast<int>(StreamlineMethod::RasterWalk))
    ->Arg(static_cast<int>(StreamlineMethod::Continuous))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
