// SPDX-License-Identifier: MIT
// Benchmark: compareSurfaces on the shared deep-drawn springback pair (41k triangles each), and
// the ratio against a per-point distance reference (exact signed distance of every mould raster
// point to the formed mesh, planning::MeshDistance) in the same run.
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <benchmark/benchmark.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <filesystem>
#include <optional>

namespace ddfcam::bench {
namespace {

struct SpringbackPair {
  ddf::TriangleMesh mould, formed;
};

const std::optional<SpringbackPair>& springbackPair() {
  static const std::optional<SpringbackPair> pair = []() -> std::optional<SpringbackPair> {
    const auto dir =
        std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";
    if (!std::filesystem::exists(dir / "target_AF_bs.stl")) return std::nullopt;
    return SpringbackPair{io::readMesh(dir / "target_AF_bs.stl"),
                          io::readMesh(dir / "mesh_ausgerichtet1.stl")};
  }();
  return pair;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Signed distance of every raster point copy of @p mould to @p formed (BVH queries, parallel).
std::vector<double> distanceReference(const ddf::DisplacementField& mould,
                                      const ddf::TriangleMesh& formed) {
  const planning::MeshDistance distance(formed);
  std::vector<double> out(mould.allHeights().size());
  const int n = mould.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, mould.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t l = static_cast<std::size_t>(f) * mould.pointsPerFace();
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i, ++l)
          out[l] =
              distance.closestPoint(mould.basePoint(f, mould.rasterBary(i, k)))->signedDistance;
    }
  });
  return out;
}

/// Full comparison (mould DDF, sequence, deviations, statistics) at resolution m = range(0);
/// then, once, the distance reference over the same raster points and the time ratio.
void BM_CompareSurfaces_SpringbackPair(benchmark::State& state) {
  const auto& pair = springbackPair();
  if (!pair) {
    state.SkipWithError("shared springback pair not found");
    return;
  }
  planning::ComparisonParams params;
  params.resolution = static_cast<int>(state.range(0));
  planning::SurfaceComparison cmp;
  double compareSeconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    cmp = planning::compareSurfaces(pair->mould, pair->formed, params);
    compareSeconds = secondsSince(start);
    benchmark::DoNotOptimize(cmp.deviation.values.data());
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> reference = distanceReference(cmp.sequence.stages[0].ddf, pair->formed);
  const double referenceSeconds = secondsSince(start);
  state.counters["points"] = static_cast<double>(reference.size());
  state.counters["stages"] = static_cast<double>(cmp.sequence.stages.size());
  state.counters["crossing_faces"] = static_cast<double>(cmp.sequence.crossingFaces.size());
  state.counters["unresolved_faces"] = static_cast<double>(cmp.sequence.unresolvedFaces.size());
  state.counters["max_mm"] = cmp.statistics.maxMm;
  state.counters["min_mm"] = cmp.statistics.minMm;
  state.counters["sigma_mm"] = cmp.statistics.sigmaMm;
  state.counters["compare_s"] = compareSeconds;
  state.counters["distance_reference_s"] = referenceSeconds;
  state.counters["compare_over_reference"] = compareSeconds / referenceSeconds;
}
BENCHMARK(BM_CompareSurfaces_SpringbackPair)
    ->Arg(2)
    ->Arg(4)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
