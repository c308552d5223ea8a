// SPDX-License-Identifier: MIT
// ddfcam benchmarks: one compensation step and the linear model's response on the shared
// deep-drawn springback pair (target DDF at m = 4, 41,010 faces).
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <optional>

namespace {

using namespace ddfcam;

// Raster resolution 4, unit pseudo-normal directions and heights 0 (the target is the support).
ddf::ConversionParams conversionParams() {
  ddf::ConversionParams params;
  params.resolution = 4;
  params.chooseLengths = false;
  return params;
}

struct SharedPairLoop {
  planning::CompensationHistory history;
  planning::LinearSpringbackModel model;
};

// The loop after the measured first forming, built once: formedHeightsFromMesh + calibration.
const std::optional<SharedPairLoop>& sharedPairLoop() {
  static const std::optional<SharedPairLoop> loop = []() -> std::optional<SharedPairLoop> {
    const auto dir =
        std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";
    if (!std::filesystem::exists(dir / "target_AF_bs.stl")) return std::nullopt;
    ddf::DisplacementField target =
        ddf::convertMeshToDdf(io::readMesh(dir / "target_AF_bs.stl"), conversionParams()).ddf;
    std::vector<ddf::Vec3> vectors = target.vectors();
    for (ddf::Vec3& v : vectors) v = 10.0 * v.normalized();
    target.setVectors(std::move(vectors));
    SharedPairLoop result{planning::startCompensation(std::move(target)), {}};
    std::vector<float> formed = planning::formedHeightsFromMesh(
        result.history.target, io::readMesh(dir / "mesh_ausgerichtet1.stl"));
    result.model = planning::calibrateSpringback(result.history.target, formed, 0.3);
    planning::recordFormedResponse(result.history, std::move(formed), "mesh_ausgerichtet1.stl");
    return result;
  }();
  return loop;
}

// compensationStep + linearSpringback + recordFormedResponse (deviation map and statistics).
void BM_CompensationStepSharedPair(benchmark::State& state) {
  const auto& loop = sharedPairLoop();
  if (!loop) {
    state.SkipWithError("shared pair not found");
    return;
  }
  for (auto _ : state) {
    planning::CompensationHistory history = loop->history;
    planning::compensationStep(history, 1.0);
    planning::recordFormedResponse(
        history,
        planning::linearSpringback(loop->model, history.target,
                                   history.iterations.back().mouldHeights),
        "linear model alpha=0.3");
    benchmark::DoNotOptimize(history.iterations.back().rmsDeviationMm);
  }
  state.counters["copies"] = static_cast<double>(loop->history.target.allHeights().size());
}
BENCHMARK(BM_CompensationStepSharedPair)->Unit(benchmark::kMillisecond);

// The anisotropic response alone (3D springback, raster mesh, crust hash, fill).
void BM_AnisotropicResponseSharedPair(benchmark::State& state) {
  const auto& loop = sharedPairLoop();
  if (!loop) {
    state.SkipWithError("shared pair not found");
    return;
  }
  planning::LinearSpringbackModel model = loop->model;
  model.axisAlpha = Eigen::Vector3d(0.2, 0.3, 0.4);
  for (auto _ : state) {
    benchmark::DoNotOptimize(planning::linearSpringback(
        model, loop->history.target, loop->history.iterations.back().mouldHeights));
  }
}
BENCHMARK(BM_AnisotropicResponseSharedPair)->Unit(benchmark::kMillisecond);

}  // namespace
