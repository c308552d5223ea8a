// SPDX-License-Identifier: MIT
// Benchmark: whole-surface principal curvature of the fig. 8.16 part (sec. 8.2; goal <= 20 ms).
#include "ddf/grinding_workloads.h"

#include <ddfcam/planning/analysis/curvature.h>

#include <benchmark/benchmark.h>

namespace ddfcam::bench {
namespace {

const ddf::DisplacementField& fig8_16Part() {
  static const GrindingWorkload workload = fig8_16Workload();
  return workload.ddf;
}

// Arg 1: parallel (TBB), 0: one thread. Arg 2: difference step d (0 = automatic).
void BM_Curvature_Fig8_16(benchmark::State& state) {
  const ddf::DisplacementField& ddf = fig8_16Part();
  planning::CurvatureParams params;
  params.parallel = state.range(0) != 0;
  params.step = static_cast<int>(state.range(1));
  int step = 0;
  for (auto _ : state) {
    planning::CurvatureField field = planning::computeCurvature(ddf, params);
    step = field.step;
    benchmark::DoNotOptimize(field.kMax.data());
  }
  const double points = static_cast<double>(ddf.allHeights().size());
  state.counters["raster_points"] = points;
  state.counters["faces"] = ddf.faceCount();
  state.counters["m"] = ddf.resolution();
  state.counters["step_d"] = step;
  state.counters["ns_per_point"] = benchmark::Counter(
      points, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Curvature_Fig8_16)
    ->ArgNames({"parallel", "d"})
    ->Args({1, 0})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
