// SPDX-License-Identifier: MIT
// Benchmarks of the core work behind the workbench shell on the demo session: the deviation
// field (BVH vs brute force), cancel latency of a simulated path, project files, undo deltas.
#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/planning/model/builtin_fields.h>
#include <ddfcam/planning/model/demo_project.h>
#include <ddfcam/planning/model/height_delta.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace ddfcam::bench {
namespace {

using Clock = std::chrono::steady_clock;
using ddf::Vec3;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// The demo session after its path was ground (what a user has after one Simulate).
const planning::Project& groundDemo() {
  static const planning::Project project = [] {
    planning::Project p = planning::demoProject();
    planning::simulatePath(*p.part, p.tools[0], p.paths[0]);
    return p;
  }();
  return project;
}

/// Naive oracle: distance to a triangle as the smaller of the in-plane foot (when inside) and
/// the three edge distances.
double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

double triangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  double best =
      std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
  if (n.squaredNorm() > 0) {
    const Vec3 foot = p - n * (p - a).dot(n) / n.squaredNorm();
    const bool inside = (b - a).cross(foot - a).dot(n) >= 0 &&
                        (c - b).cross(foot - b).dot(n) >= 0 && (a - c).cross(foot - c).dot(n) >= 0;
    if (inside) best = std::min(best, (foot - p).norm());
  }
  return best;
}

double bruteForceSecondsPerPoint(const ddf::DisplacementField& part, const ddf::TriangleMesh& mesh,
                                 int samples) {
  const auto start = Clock::now();
  double sink = 0;
  const int n = part.resolution() - 1;
  for (int s = 0; s < samples; ++s) {
    const int f = (s * 7919) % part.faceCount();
    const Vec3 q = part.surfacePoint(f, n / 3, n / 3);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
      best = std::min(
          best, triangleDistance(q, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
    sink += best;
  }
  benchmark::DoNotOptimize(sink);
  return seconds(start) / samples;
}

void BM_DeviationField_Demo(benchmark::State& state) {
  const planning::Project& p = groundDemo();
  const double points = static_cast<double>(p.part->allHeights().size());
  double best = 1e30;
  for (auto _ : state) {
    const auto start = Clock::now();
    benchmark::DoNotOptimize(planning::deviationField(*p.part, *p.designMesh));
    best = std::min(best, seconds(start));
  }
  // Same run: the naive scan over every design triangle, on a sample of points.
  const double naive = bruteForceSecondsPerPoint(*p.part, *p.designMesh, 200);
  state.counters["design_triangles"] = static_cast<double>(p.designMesh->triangles.size());
  state.counters["best_ms"] = best * 1e3;
  state.counters["ns_per_point"] = best / points * 1e9;
  state.counters["bruteforce_ns_per_point"] = naive * 1e9;
  state.counters["ratio_bruteforce_over_bvh"] = naive / (best / points);
}
BENCHMARK(BM_DeviationField_Demo)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

/// Time from a cancel request to simulatePath throwing Cancelled, on the demo path repeated
/// forty times (long enough never to finish first).
void BM_SimulatePath_CancelLatency(benchmark::State& state) {
  planning::Project p = planning::demoProject();
  planning::ToolPath path = p.paths[0];
  const auto poses = path.poses;
  for (int r = 1; r < 40; ++r) path.poses.insert(path.poses.end(), poses.begin(), poses.end());
  double worst = 0, total = 0;
  int runs = 0;
  for (auto _ : state) {
    ddf::DisplacementField part = *p.part;
    std::atomic<bool> cancel{false};
    std::atomic<bool> cancelled{false};
    Clock::time_point done;
    std::thread worker([&] {
      planning::PathSimulationParams params;
      params.progress = [&](double) { return !cancel.load(); };
      try {
        planning::simulatePath(part, p.tools[0], path, params);
      } catch (const Cancelled&) {
        cancelled = true;
      }
      done = Clock::now();
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    const auto requested = Clock::now();
    cancel = true;
    worker.join();
    if (!cancelled) state.SkipWithError("the path finished before the cancel request");
    const double latency = std::chrono::duration<double>(done - requested).count();
    worst = std::max(worst, latency);
    total += latency;
    ++runs;
  }
  state.counters["mean_latency_ms"] = total / std::max(runs, 1) * 1e3;
  state.counters["worst_latency_ms"] = worst * 1e3;
}
BENCHMARK(BM_SimulatePath_CancelLatency)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->UseRealTime();

void BM_ProjectFile_RoundTrip_Demo(benchmark::State& state) {
  planning::Project p = groundDemo();
  p.fields.push_back(planning::materialRemovedField(*p.part, p.states.front().heights));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string encoded = io::encodeProject(p);
    bytes = encoded.size();
    benchmark::DoNotOptimize(io::decodeProject(encoded, "bench.ddfproj"));
  }
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_ProjectFile_RoundTrip_Demo)->Unit(benchmark::kMillisecond);

/// Undo cost of one simulated demo pass: the delta against a full copy of the heights.
void BM_HeightDelta_DemoPass(benchmark::State& state) {
  const planning::Project& ground = groundDemo();
  const auto& before = ground.states.front().heights;
  const auto& after = ground.part->allHeights();
  planning::HeightDelta delta;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        delta = planning::HeightDelta::between(before, after, ground.part->pointsPerFace()));
  const double full = 2.0 * static_cast<double>(after.size() * sizeof(float));
  state.counters["delta_MB"] = static_cast<double>(delta.memoryBytes()) / 1e6;
  state.counters["changed_faces"] = static_cast<double>(delta.changedFaces());
  state.counters["ratio_full_copies_over_delta"] = full / static_cast<double>(delta.memoryBytes());
}
BENCHMARK(BM_HeightDelta_DemoPass)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ddfcam::bench
