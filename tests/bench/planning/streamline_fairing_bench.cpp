// SPDX-License-Identifier: MIT
// Benchmark: Ceres fairing of a noisy 1,000-5,000-point streamline against the moving average.
#include "../../support/surface_locate.h"

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_fairing.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace ddfcam::bench {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;

const ddf::GeneratedSurface& cylinder() {
  static const ddf::GeneratedSurface part = ddf::cylinderPart({.radiusMm = 10.0});
  return part;
}

using ::ddfcam::test::locateNear;

// A 40 mm helix (pitch angle 30 deg) on the r = 10 mm cylinder with a +-0.02 mm zig-zag
// across it within the surface, as @p points surface locations (generated once per size).
const planning::Streamline& noisyHelix(int points) {
  static std::map<int, planning::Streamline> cache;
  auto [it, added] = cache.try_emplace(points);
  if (!added) return it->second;
  const double angle = std::acos(-1.0) / 6.0, length = 40.0, noise = 0.02;
  for (int i = 0; i < points; ++i) {
    const double s = length * i / (points - 1);
    const double lateral = i == 0 || i == points - 1 ? 0.0 : (i % 2 ? noise : -noise);
    const double arc = s * std::cos(angle) - lateral * std::sin(angle);
    const double z = 5.0 + s * std::sin(angle) + lateral * std::cos(angle);
    const double theta = -1.7 + arc / 10.0;
    it->second.points.push_back(
        locateNear(cylinder().ddf, {10.0 * std::cos(theta), 10.0 * std::sin(theta), z}));
  }
  return it->second;
}

void BM_StreamlineFairing(benchmark::State& state) {
  const planning::Streamline& raw = noisyHelix(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const planning::Streamline faired = planning::fairStreamline(cylinder().ddf, raw);
    benchmark::DoNotOptimize(faired.points.data());
  }
  state.counters["points"] = static_cast<double>(raw.points.size());
}
BENCHMARK(BM_StreamlineFairing)->Arg(1000)->Arg(2000)->Arg(5000)->Unit(benchmark::kMillisecond);

// The moving-average filter of sec. 8.3 (window 5) on the same lines, for comparison.
void BM_StreamlineMovingAverage(benchmark::State& state) {
  const planning::Streamline& raw = noisyHelix(static_cast<int>(state.range(0)));
  const std::vector<Vec3> points = raw.polyline();
  for (auto _ : state) {
    const std::vector<Vec3> smooth = planning::smoothMovingAverage(points, 2);
    benchmark::DoNotOptimize(smooth.data());
  }
  state.counters["points"] = static_cast<double>(points.size());
}
BENCHMARK(BM_StreamlineMovingAverage)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(5000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ddfcam::bench
