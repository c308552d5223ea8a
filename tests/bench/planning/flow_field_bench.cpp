// SPDX-License-Identifier: MIT
// Benchmark: the smoothed tool flow field on the fig. 8.16 part (sec. 8.1; goal <= 300 ms),
// the coarse-to-fine Ceres solve against the direct (sparse Cholesky) reference.
#include "ddf/grinding_workloads.h"

#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/flow_field.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace ddfcam::bench {
namespace {

struct FlowWorkload {
  GrindingWorkload part = fig8_16Workload();
  planning::CurvatureField curvature;
  std::vector<std::uint8_t> quarter;  // the faces of the left quarter of the patch
  planning::LineField reference;      // direct solve of the whole part
  double directMs = 0.0;
};

const FlowWorkload& workload() {
  static const FlowWorkload w = [] {
    FlowWorkload out;
    const ddf::DisplacementField& ddf = out.part.ddf;
    out.curvature = planning::computeCurvature(ddf);
    out.quarter.resize(ddf.faceCount());
    for (int f = 0; f < ddf.faceCount(); ++f)
      out.quarter[f] = ddf.basePoint(f, ddf::Vec3::Constant(1.0 / 3.0)).x() < 12.5 ? 1 : 0;
    planning::FlowFieldParams direct;
    direct.solver = planning::FlowFieldSolver::Direct;
    const auto t0 = std::chrono::steady_clock::now();
    out.reference = planning::flowField(ddf, out.curvature, direct);
    out.directMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }();
  return w;
}

// Largest angle between the lines of two fields where both are defined, degrees.
double maxAngleDeg(const planning::LineField& a, const planning::LineField& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!a[i].isZero() && !b[i].isZero())
      worst = std::max(worst, std::acos(std::min(1.0, std::abs(a[i].dot(b[i])))));
  return worst * 180.0 / std::numbers::pi;
}

// Percentile (0..1) of the angles between the lines of two fields, degrees.
double angleQuantileDeg(const planning::LineField& a, const planning::LineField& b, double q) {
  std::vector<double> angles;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!a[i].isZero() && !b[i].isZero())
      angles.push_back(std::acos(std::min(1.0, std::abs(a[i].dot(b[i])))));
  if (angles.empty()) return 0.0;
  auto it = angles.begin() + static_cast<std::ptrdiff_t>(q * (angles.size() - 1));
  std::nth_element(angles.begin(), it, angles.end());
  return *it * 180.0 / std::numbers::pi;
}

// state.range(0): 0 = direct reference, 1 = coarse to fine (default solver).
void BM_FlowField_Fig8_16(benchmark::State& state) {
  const FlowWorkload& w = workload();
  planning::FlowFieldParams params;
  if (state.range(0) == 0) params.solver = planning::FlowFieldSolver::Direct;
  planning::LineField field;
  for (auto _ : state) {
    field = planning::flowField(w.part.ddf, w.curvature, params);
    benchmark::DoNotOptimize(field.data());
  }
  state.counters["points"] = static_cast<double>(field.size());
  state.counters["direct_ms"] = w.directMs;
  state.counters["max_angle_deg"] = maxAngleDeg(field, w.reference);
  state.counters["p99_angle_deg"] = angleQuantileDeg(field, w.reference, 0.99);
}
BENCHMARK(BM_FlowField_Fig8_16)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The speed-up of the default solver over the direct one, both timed here in the same run.
void BM_FlowField_Fig8_16_Speedup(benchmark::State& state) {
  const FlowWorkload& w = workload();
  double fastMs = 0.0;
  int runs = 0;
  planning::LineField field;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    field = planning::flowField(w.part.ddf, w.curvature);
    fastMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ++runs;
  }
  state.counters["direct_ms"] = w.directMs;
  state.counters["multilevel_ms"] = fastMs / std::max(runs, 1);
  state.counters["ratio"] = w.directMs / (fastMs / std::max(runs, 1));
  state.counters["max_angle_deg"] = maxAngleDeg(field, w.reference);
}
BENCHMARK(BM_FlowField_Fig8_16_Speedup)->Unit(benchmark::kMillisecond)->UseRealTime();

// One region: a quarter of the part (state.range(0) as above).
void BM_FlowField_Fig8_16_Region(benchmark::State& state) {
  const FlowWorkload& w = workload();
  planning::FlowFieldParams params;
  params.faceMask = w.quarter;
  if (state.range(0) == 0) params.solver = planning::FlowFieldSolver::Direct;
  planning::LineField field;
  for (auto _ : state) {
    field = planning::flowField(w.part.ddf, w.curvature, params);
    benchmark::DoNotOptimize(field.data());
  }
  state.counters["defined"] = static_cast<double>(
      std::count_if(field.begin(), field.end(), [](const ddf::Vec3& v) { return !v.isZero(); }));
}
BENCHMARK(BM_FlowField_Fig8_16_Region)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// User strokes: two strokes across the part, harmonic fill everywhere else.
void BM_FlowField_Fig8_16_Strokes(benchmark::State& state) {
  const FlowWorkload& w = workload();
  planning::FlowFieldParams params;
  params.source = planning::FlowFieldSource::UserStrokes;
  for (double y : {6.0, 19.0}) {
    std::vector<ddf::Vec3> stroke;
    for (int i = 0; i <= 100; ++i) stroke.emplace_back(2.0 + 0.46 * i, y + std::sin(0.1 * i), 0.0);
    params.strokes.push_back(stroke);
  }
  if (state.range(0) == 0) params.solver = planning::FlowFieldSolver::Direct;
  for (auto _ : state)
    benchmark::DoNotOptimize(planning::flowField(w.part.ddf, w.curvature, params));
}
BENCHMARK(BM_FlowField_Fig8_16_Strokes)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace ddfcam::bench
