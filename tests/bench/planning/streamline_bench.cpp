// SPDX-License-Identifier: MIT
// Benchmark: a family of 50 k_max streamlines on the fig. 8.16 part (sec. 8.3; goal <= 50 ms).
#include "ddf/grinding_workloads.h"

#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/lines/streamline.h>

#include <benchmark/benchmark.h>

namespace ddfcam::bench {
namespace {

struct StreamlineWorkload {
  GrindingWorkload part = fig8_16Workload();
  planning::LineField dirMax, dirMin;
  ddf::SurfaceLocation seed;
  double spacingMm = 0.0;
};

planning::LineField masked(const std::vector<ddf::Vec3>& dirs,
                           const std::vector<std::uint8_t>& umbilic) {
  planning::LineField out = dirs;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (umbilic[i]) out[i] = ddf::Vec3::Zero();
  return out;
}

// The k_max field, seeded along the k_min line through the face nearest the patch centre,
// with the spacing that puts 50 seeds on that line.
const StreamlineWorkload& workload() {
  static const StreamlineWorkload w = [] {
    StreamlineWorkload out;
    const ddf::DisplacementField& ddf = out.part.ddf;
    const planning::CurvatureField c = planning::computeCurvature(ddf);
    out.dirMax = masked(c.dirMax, c.umbilic);
    out.dirMin = masked(c.dirMin, c.umbilic);
    const ddf::Vec3 bary(0.31, 0.33, 0.36);
    const ddf::Vec3 centre(25.0, 12.5, 0.0);
    int best = 0;
    auto gap = [&](int f) { return (ddf.basePoint(f, bary) - centre).head<2>().norm(); };
    for (int f = 1; f < ddf.faceCount(); ++f)
      if (gap(f) < gap(best)) best = f;
    out.seed = {best, bary};
    const planning::Streamline transverse = planning::traceStreamline(ddf, out.dirMin, out.seed);
    out.spacingMm = transverse.lengthMm / 49.5;
    return out;
  }();
  return w;
}

void BM_Streamlines_Fig8_16(benchmark::State& state) {
  const StreamlineWorkload& w = workload();
  std::size_t lines = 0, points = 0;
  double length = 0.0;
  for (auto _ : state) {
    const auto family =
        planning::seedAlongTransverse(w.part.ddf, w.dirMax, w.dirMin, w.seed, w.spacingMm);
    lines = family.size(), points = 0, length = 0.0;
    for (const auto& line : family) points += line.points.size(), length += line.lengthMm;
    benchmark::DoNotOptimize(family.data());
  }
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["points"] = static_cast<double>(points);
  state.counters["length_mm"] = length;
  state.counters["spacing_mm"] = w.spacingMm;
}
BENCHMARK(BM_Streamlines_Fig8_16)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
