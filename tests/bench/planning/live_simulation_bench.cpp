// SPDX-License-Identifier: MIT
// ddfcam-bench: the simulation's own speed on the turbine blade (217 poses of a 200-triangle
// roll with flanges), with and without its V-convexity and collision checks and with the live
// display update per pose: the differences between the variants say where the time goes.
#include "planning/blade_workload.h"

#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <benchmark/benchmark.h>

#include <memory>

namespace ddfcam::bench {
namespace {

enum Variant { kCutOnly, kVConvexity, kAllChecks, kAllChecksAndDisplay };

// The blade workload's roll as cutting part and, as the non-cutting part (so the collision
// probe has work), flanges of 0.95 of its radius, 0.1 of its width thick, on both ends of its
// axis (x).
planning::ToolMeshes rollWithFlanges(const BladeWorkload& w) {
  planning::ToolMeshes tool{w.tool, {}};
  const double r = 0.95 * w.radius, t = 0.1 * w.width;
  for (const double side : {-1.0, 1.0}) {
    Eigen::Isometry3d shift = Eigen::Isometry3d::Identity();
    shift.translation().x() = side * 0.5 * (w.width + t);
    const ddf::TriangleMesh flange = planning::makeCylinderTool({r, t, 32}).transformed(shift);
    const int base = static_cast<int>(tool.nonCutting.vertices.size());
    tool.nonCutting.vertices.insert(tool.nonCutting.vertices.end(), flange.vertices.begin(),
                                    flange.vertices.end());
    for (auto t3 : flange.triangles) {
      for (int& v : t3) v += base;
      tool.nonCutting.triangles.push_back(t3);
    }
  }
  return tool;
}

// The blade workload (loaded once, heights reset) and its poses as a path; null (and the
// benchmark skipped) without the shared file.
BladeWorkload* bladeAndPath(benchmark::State& state, planning::ToolPath& path) {
  static std::optional<BladeWorkload> w = bladeWorkload();
  if (!w) {
    state.SkipWithError("turbine-blade-jigsaw.stl not found under DDFCAM_SHARED_DATA_DIR");
    return nullptr;
  }
  path.name = "blade";
  for (const auto& pose : w->poses) path.poses.push_back({pose, pose.translation()});
  w->ddf.allHeights() = w->initialHeights;
  return &*w;
}

void simulateBlade(benchmark::State& state, Variant variant) {
  planning::ToolPath path;
  BladeWorkload* w = bladeAndPath(state, path);
  if (!w) return;
  planning::GrindingSimulationParams params;
  params.checkVConvexity = variant != kCutOnly;
  params.checkCollisions = variant == kAllChecks || variant == kAllChecksAndDisplay;
  params.recordUndo = true;  // as the workbench's playback runs it
  const planning::ToolMeshes tool = rollWithFlanges(*w);
  std::size_t collisions = 0, violations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    planning::GrindingSimulation simulation(w->ddf, tool, path, params);
    std::unique_ptr<ddf::IncrementalTriangulation> display;
    if (variant == kAllChecksAndDisplay)
      display = std::make_unique<ddf::IncrementalTriangulation>(simulation.workpiece(),
                                                                1e-4 * w->size);
    state.ResumeTiming();
    while (!simulation.finished()) {
      simulation.advance(1);
      if (display) display->update(simulation.takeChangedFaces());
    }
    collisions = simulation.report().collisions.size();
    violations = simulation.report().vConvexity.size();
  }
  const double poses = static_cast<double>(path.poses.size());
  state.counters["poses"] = poses;
  state.counters["ms_per_pose"] = benchmark::Counter(
      poses * 1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["poses_per_s"] =
      benchmark::Counter(poses, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["collision_poses"] = static_cast<double>(collisions);
  state.counters["vconvexity_poses"] = static_cast<double>(violations);
}

// The worker's whole share per pose as the workbench runs it: LiveSimulation::step() cuts a
// pose with every check, updates the incremental display and publishes a frame (the whole mesh
// copied out); with a design also the overcut inspection, the tolerance classes of the changed
// faces and the corner parameters of the textured display.
void stepBlade(benchmark::State& state, bool inspected) {
  planning::ToolPath path;
  BladeWorkload* w = bladeAndPath(state, path);
  if (!w) return;
  planning::LiveSimulationParams params;
  params.simulation.checkVConvexity = true;
  params.simulation.checkCollisions = true;
  params.displayEpsMm = 1e-4 * w->size;
  params.posesPerSecond = 0.0;
  if (inspected) {
    params.designHeights = w->initialHeights;
    const double drop = 1e-3 * w->size / w->ddf.vector(0).norm();
    for (float& h : params.designHeights) h -= static_cast<float>(drop);
    params.overcutToleranceMm = params.displayEpsMm;
    params.toleranceBand = {-params.displayEpsMm, params.displayEpsMm};
  }
  const planning::ToolMeshes tool = rollWithFlanges(*w);
  for (auto _ : state) {
    state.PauseTiming();
    planning::LiveSimulation live(w->ddf, tool, path, params);
    state.ResumeTiming();
    while (live.step()) {
    }
  }
  const double poses = static_cast<double>(path.poses.size());
  state.counters["ms_per_pose"] = benchmark::Counter(
      poses * 1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_LiveSimulation_BladeStep(benchmark::State& state) {
  stepBlade(state, false);
}
void BM_LiveSimulation_BladeStepInspected(benchmark::State& state) {
  stepBlade(state, true);
}
BENCHMARK(BM_LiveSimulation_BladeStep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSimulation_BladeStepInspected)->Unit(benchmark::kMillisecond);

void BM_LiveSimulation_BladeCutOnly(benchmark::State& state) {
  simulateBlade(state, kCutOnly);
}
void BM_LiveSimulation_BladeVConvexity(benchmark::State& state) {
  simulateBlade(state, kVConvexity);
}
void BM_LiveSimulation_BladeAllChecks(benchmark::State& state) {
  simulateBlade(state, kAllChecks);
}
void BM_LiveSimulation_BladeAllChecksAndDisplay(benchmark::State& state) {
  simulateBlade(state, kAllChecksAndDisplay);
}
BENCHMARK(BM_LiveSimulation_BladeCutOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSimulation_BladeVConvexity)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSimulation_BladeAllChecks)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveSimulation_BladeAllChecksAndDisplay)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ddfcam::bench
