// SPDX-License-Identifier: MIT
// Benchmarks of the DDF depth buffer (dissertation ch. 5, fig. 5.5/5.6, 8.14, 8.16).
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <random>

#include "ddf/grinding_workloads.h"

namespace ddfcam::bench {
namespace {

using ddf::Vec3;

// ns per raster point as a Google Benchmark counter: value * iterations / time, inverted.
benchmark::Counter nsPerPoint(double points) {
  return benchmark::Counter(
      points * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <class Fn>
double bestSeconds(int repeats, Fn&& fn) {
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// Fig. 5.5: one support triangle, parallel vectors, a tool triangle large enough to cut every
// stubble (its plane at h = 0.5, facing the stubbles).
ddf::DisplacementField singleTriangle(int m) {
  const std::vector<Vec3> corners = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  return ddf::DisplacementField(ddf::makeSupportMesh(corners, {{0, 1, 2}}),
                                std::vector<Vec3>(3, {0, 0, 1}), m, 1.0f);
}
const Vec3 kBig1{-50, -50, 0.5}, kBig2{-50, 150, 0.6}, kBig3{150, -50, 0.4};

void BM_Fig5_6_FullCut(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  auto ddf = singleTriangle(m);
  const double points = static_cast<double>(ddf.pointsPerFace());
  for (auto _ : state) {
    benchmark::DoNotOptimize(ddf::cutFaceByTriangle(ddf, 0, kBig1, kBig2, kBig3));
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_point"] = nsPerPoint(points);
  // Same run: incremental rows vs direct per-point V-shooting on a fresh copy.
  auto fresh = singleTriangle(m);
  const double incremental =
      bestSeconds(3, [&] { ddf::cutFaceByTriangle(fresh, 0, kBig1, kBig2, kBig3); });
  auto fresh2 = singleTriangle(m);
  const double direct =
      bestSeconds(1, [&] { ddf::cutFaceByTriangleDirect(fresh2, 0, kBig1, kBig2, kBig3); });
  state.counters["direct_ns_per_point"] = direct / points * 1e9;
  state.counters["ratio_direct_over_incremental"] = direct / incremental;
}
BENCHMARK(BM_Fig5_6_FullCut)
    ->Arg(2000)
    ->Arg(4000)
    ->Arg(6000)
    ->Arg(8000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

// Small tool triangles (about 1 % of the support edge) against a large raster: the interval
// restriction of sec. 5.2 (fig. 5.7) against shooting every raster point.
void BM_SmallTriangles_IntervalRestriction(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  auto ddf = singleTriangle(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.5, 4.5), d(-0.1, 0.1);
  std::vector<std::array<Vec3, 3>> tris;
  for (int t = 0; t < 64; ++t) {
    const Vec3 c(u(rng), u(rng), 0.5);
    // Clockwise seen from above: outward normal points down, against the vectors.
    tris.push_back({c + Vec3(0, 0, d(rng)), c + Vec3(0, 0.1, d(rng)), c + Vec3(0.1, 0, d(rng))});
  }
  auto run = [&](ddf::DisplacementField& f, bool restrict) {
    for (const auto& t : tris)
      ddf::cutFaceByTriangle(f, 0, t[0], t[1], t[2], {.restrictIntervals = restrict});
  };
  for (auto _ : state) {
    run(ddf, true);
    benchmark::ClobberMemory();
  }
  state.counters["us_per_triangle"] =
      benchmark::Counter(tris.size() * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                 benchmark::Counter::kInvert);
  auto a = singleTriangle(m), b = singleTriangle(m);
  const double with = bestSeconds(3, [&] { run(a, true); });
  const double without = bestSeconds(1, [&] { run(b, false); });
  state.counters["ratio_without_over_with"] = without / with;
}
BENCHMARK(BM_SmallTriangles_IntervalRestriction)->Arg(2000)->Unit(benchmark::kMillisecond);

void runGrinding(benchmark::State& state, GrindingWorkload& w) {
  const bool parallel = state.range(0) != 0;
  const ddf::CrustHash hash(w.ddf);
  std::size_t lowered = 0;
  for (auto _ : state) {
    state.PauseTiming();
    w.ddf.allHeights() = w.initialHeights;
    state.ResumeTiming();
    lowered = 0;
    for (const auto& pose : w.poses)
      lowered += ddf::cutByMesh(w.ddf, hash, w.tool, pose, {.parallel = parallel}).pointsLowered;
  }
  state.counters["poses"] = static_cast<double>(w.poses.size());
  state.counters["tool_triangles"] = static_cast<double>(w.tool.triangles.size());
  state.counters["heights_lowered"] = static_cast<double>(lowered);
  state.counters["ms_per_pose"] =
      benchmark::Counter(w.poses.size() * 1e-3, benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
}

void BM_Fig8_16_Grinding(benchmark::State& state) {
  static GrindingWorkload w = fig8_16Workload();
  runGrinding(state, w);
}
BENCHMARK(BM_Fig8_16_Grinding)->ArgName("parallel")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_Fig8_14_Grinding(benchmark::State& state) {
  static GrindingWorkload w = fig8_14Workload();
  runGrinding(state, w);
}
BENCHMARK(BM_Fig8_14_Grinding)->ArgName("parallel")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// Localization queries (sec. 5.1) on the 20,000-triangle free-form patch: tool-sized triangles
// near the surface.
void BM_LocalizationQueries(benchmark::State& state) {
  static const auto part = ddf::freeformPatch();
  static const ddf::CrustHash hash(part.ddf);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(5.0, 95.0), d(-1.0, 1.0);
  const auto& design = dynamic_cast<const ddf::HeightFieldSurface&>(*part.design);
  std::vector<std::array<Vec3, 3>> tris;
  for (int t = 0; t < 4096; ++t) {
    const Vec3 c = design.pointAbove(u(rng), u(rng));
    tris.push_back({c + Vec3(d(rng), d(rng), d(rng)), c + Vec3(d(rng), d(rng), d(rng)),
                    c + Vec3(d(rng), d(rng), d(rng))});
  }
  std::vector<int> out;
  std::size_t candidates = 0, i = 0;
  for (auto _ : state) {
    const auto& t = tris[i++ % tris.size()];
    hash.queryTriangle(t[0], t[1], t[2], out);
    candidates += out.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["candidates_per_query"] = static_cast<double>(candidates) / state.iterations();
  state.counters["occupied_cells"] = static_cast<double>(hash.occupiedCells());
}
BENCHMARK(BM_LocalizationQueries);

// Memory per raster point at m = 50, everything included (support, vectors, topology, heights,
// crust hash).
void BM_MemoryPerPoint(benchmark::State& state) {
  ddf::FreeformPatchParams params;
  params.cellsX = 30;
  params.cellsY = 30;
  params.m = static_cast<int>(state.range(0));
  const auto part = ddf::freeformPatch(params);
  std::size_t hashBytes = 0;
  for (auto _ : state) {
    const ddf::CrustHash hash(part.ddf);
    hashBytes = hash.memoryBytes();
  }
  const double points = static_cast<double>(part.ddf.faceCount()) * part.ddf.pointsPerFace();
  state.counters["bytes_per_point"] = (part.ddf.memoryBytes() + hashBytes) / points;
  state.counters["hash_bytes_per_point"] = hashBytes / points;
}
BENCHMARK(BM_MemoryPerPoint)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace ddfcam::bench
