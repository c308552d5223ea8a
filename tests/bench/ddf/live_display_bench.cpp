// SPDX-License-Identifier: MIT
// ddfcam-bench: the live display of a simulation: the incremental adaptive triangulation
// (ch. 7) updated after each pose of a 200-triangle roll on the turbine blade, against a full
// rebuild of the same surface measured in the same run.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/incremental_triangulation.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>

#include "planning/blade_workload.h"

namespace ddfcam::bench {
namespace {

// Error bound of the display as a fraction of the blade's length: 0.01 mm on a 100 mm part.
constexpr double kEpsFraction = 1e-4;

double secondsOf(const auto& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BladeWorkload* workload(int m) {
  static std::map<int, std::unique_ptr<BladeWorkload>> cache;
  auto& slot = cache[m];
  if (!slot)
    if (auto w = bladeWorkload(m)) slot = std::make_unique<BladeWorkload>(std::move(*w));
  return slot.get();
}

// Per iteration: one pose of the roll is cut (not timed) and the display brought up to date
// (timed). After the last pose the stock and the display are reset (not timed). The counters
// give the triangles shown against the raster mesh and a full rebuild of the final surface.
void liveDisplay(benchmark::State& state, int m) {
  BladeWorkload* w = workload(m);
  if (!w) {
    state.SkipWithError("turbine-blade-jigsaw.stl not found under DDFCAM_SHARED_DATA_DIR");
    return;
  }
  w->ddf.allHeights() = w->initialHeights;
  const double eps = kEpsFraction * w->size;
  const ddf::CrustHash hash(w->ddf);
  auto live = std::make_unique<ddf::IncrementalTriangulation>(w->ddf, eps);
  std::size_t pose = 0, updates = 0, touched = 0, subdivided = 0, reassembled = 0;
  for (auto _ : state) {
    state.PauseTiming();
    if (pose == w->poses.size()) {
      w->ddf.allHeights() = w->initialHeights;
      live = std::make_unique<ddf::IncrementalTriangulation>(w->ddf, eps);
      pose = 0;
    }
    const ddf::CutStats cut = ddf::cutByMesh(w->ddf, hash, w->tool, w->poses[pose++]);
    state.ResumeTiming();
    const ddf::TriangulationUpdate update = live->update(cut.touchedFaces);
    ++updates;
    touched += cut.touchedFaces.size();
    subdivided += update.subdividedFaces.size();
    reassembled += update.reassembledFaces.size();
  }
  // The full rebuild of the surface as it stands at the end, for the ratio.
  std::size_t fullTriangles = 0;
  const double fullSeconds = secondsOf([&] {
    ddf::AdaptiveTriangulationParams params;
    params.epsMm = eps;
    fullTriangles = ddf::triangulateAdaptiveWithStats(w->ddf, params).mesh.triangles.size();
  });
  const double n = static_cast<double>(std::max<std::size_t>(updates, 1));
  state.counters["faces"] = w->ddf.faceCount();
  state.counters["m"] = m;
  state.counters["raster_points"] = static_cast<double>(w->ddf.allHeights().size());
  state.counters["raster_triangles"] =
      static_cast<double>(w->ddf.faceCount()) * (m - 1) * (m - 1);
  state.counters["triangles"] = static_cast<double>(live->triangleCount());
  state.counters["full_rebuild_ms"] = 1e3 * fullSeconds;
  state.counters["full_rebuild_triangles"] = static_cast<double>(fullTriangles);
  state.counters["faces_touched"] = touched / n;
  state.counters["faces_subdivided"] = subdivided / n;
  state.counters["faces_reassembled"] = reassembled / n;
}

void BM_LiveDisplay_Blade(benchmark::State& state) {
  liveDisplay(state, kBladeResolution);
}
BENCHMARK(BM_LiveDisplay_Blade)->Unit(benchmark::kMillisecond)->Iterations(200);

// m = 20: 13,306 x 231 = 3.07 million raster points.
void BM_LiveDisplay_Blade3M(benchmark::State& state) {
  liveDisplay(state, 20);
}
BENCHMARK(BM_LiveDisplay_Blade3M)->Unit(benchmark::kMillisecond)->Iterations(200);

}  // namespace
}  // namespace ddfcam::bench
