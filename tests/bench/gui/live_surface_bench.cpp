// SPDX-License-Identifier: MIT
// ddfcam-gui-bench: the UI thread's share of a live display update on the turbine blade: copying
// a published frame of the live simulation into the polydata the view draws (shared vertex
// slots, or per-corner points with the raster-resolution tolerance texture). The worker's share
// is BM_LiveDisplay_* and BM_LiveSimulation_* in ddfcam-bench.
#include "planning/blade_workload.h"

#include <ddfcam/gui/adapters/live_surface.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/tools/tool.h>

#include <benchmark/benchmark.h>

#include <memory>

namespace ddfcam::bench {
namespace {

// Two frames of the blade's roll path, 10 poses apart, with the live tolerance classes against
// a design 0.1 % of the blade's size below the stock (so the cut shows all three classes).
struct BladeFrames {
  std::shared_ptr<const planning::LiveFrame> a, b;
};

std::optional<BladeFrames> bladeFrames(int resolution) {
  std::optional<BladeWorkload> w = bladeWorkload(resolution);
  if (!w) return std::nullopt;
  planning::ToolPath path;
  path.name = "blade";
  for (const auto& pose : w->poses) path.poses.push_back({pose, pose.translation()});
  planning::LiveSimulationParams params;
  params.displayEpsMm = 1e-4 * w->size;
  params.posesPerSecond = 0.0;
  params.designHeights = w->initialHeights;
  const double lengthDrop = 1e-3 * w->size;
  const double vectorLength = w->ddf.vector(0).norm();
  for (float& h : params.designHeights) h -= static_cast<float>(lengthDrop / vectorLength);
  params.overcutToleranceMm = 1e-4 * w->size;
  params.toleranceBand = {-1e-4 * w->size, 1e-4 * w->size};
  w->ddf.allHeights() = w->initialHeights;
  planning::LiveSimulation live(w->ddf, {w->tool, {}}, path, params);
  live.seek(100);
  BladeFrames out;
  out.a = live.latestFrame();
  live.seek(110);
  out.b = live.latestFrame();
  return out;
}

void applyFrames(benchmark::State& state, const std::optional<BladeFrames>& frames,
                 bool textured) {
  if (!frames) {
    state.SkipWithError("turbine-blade-jigsaw.stl not found under DDFCAM_SHARED_DATA_DIR");
    return;
  }
  const planning::LiveFrame& a = *frames->a;
  gui::LiveSurfacePolyData surface(textured ? a.faceCount : 0, a.rasterSteps);
  bool flip = false;
  for (auto _ : state) {
    surface.apply(flip ? *frames->b : a);  // alternating: the texture really changes
    flip = !flip;
    benchmark::ClobberMemory();
  }
  state.counters["triangles"] = static_cast<double>(a.triangleFace.size());
  state.counters["ms_per_update"] = benchmark::Counter(
      1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  if (textured && surface.atlas()) {
    state.counters["texels"] =
        static_cast<double>(surface.atlas()->width()) * surface.atlas()->height();
    state.counters["faces_rewritten"] = surface.atlas()->lastRewrittenFaces();
  }
}

const std::optional<BladeFrames>& blade() {
  static const std::optional<BladeFrames> frames = bladeFrames(kBladeResolution);
  return frames;
}

// m = 20: 13,306 x 231 = 3.07 million raster points (as BM_LiveDisplay_Blade3M).
const std::optional<BladeFrames>& blade3M() {
  static const std::optional<BladeFrames> frames = bladeFrames(20);
  return frames;
}

void BM_LiveSurfaceApply_Blade(benchmark::State& state) {
  applyFrames(state, blade(), false);
}
void BM_LiveSurfaceApply_BladeTolerance(benchmark::State& state) {
  applyFrames(state, blade(), true);
}
void BM_LiveSurfaceApply_Blade3M(benchmark::State& state) {
  applyFrames(state, blade3M(), false);
}
void BM_LiveSurfaceApply_Blade3MTolerance(benchmark::State& state) {
  applyFrames(state, blade3M(), true);
}
BENCHMARK(BM_LiveSurfaceApply_Blade)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSurfaceApply_BladeTolerance)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSurfaceApply_Blade3M)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSurfaceApply_Blade3MTolerance)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ddfcam::bench
