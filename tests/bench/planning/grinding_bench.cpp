// SPDX-License-Identifier: MIT
// ddfcam-bench: grinding with placement and correction (fig. 8.14, 8.16), the turbine blade,
// and the OpenVDB level-set peer measured in the same run.
#include "ddf/grinding_workloads.h"
#include "planning/blade_workload.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/planning/placement/penetration_correction.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/simulation/workpiece.h>

#ifdef DDFCAM_HAVE_OPENVDB
#include "planning/openvdb_peer.h"
#endif

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <span>
#include <vector>

namespace ddfcam::bench {
namespace {

using Clock = std::chrono::steady_clock;
using ddf::Vec3;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::size_t cutAll(ddf::DisplacementField& ddf, const ddf::CrustHash& hash,
                   const ddf::TriangleMesh& tool, std::span<const Eigen::Isometry3d> poses) {
  std::size_t lowered = 0;
  for (const auto& pose : poses) lowered += ddf::cutByMesh(ddf, hash, tool, pose).pointsLowered;
  return lowered;
}

void perPoseCounter(benchmark::State& state, std::size_t poses) {
  state.counters["poses"] = static_cast<double>(poses);
  state.counters["ms_per_pose"] = benchmark::Counter(
      poses * 1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// 217 positions of a 200-triangle roll across the turbine blade (shared data; skipped when the
// file is missing). The roll is scaled to the blade (see blade_workload.h).
void BM_Grinding_Blade217(benchmark::State& state) {
  static std::optional<BladeWorkload> w = bladeWorkload();
  if (!w) {
    state.SkipWithError("turbine-blade-jigsaw.stl not found under DDFCAM_SHARED_DATA_DIR");
    return;
  }
  static const ddf::CrustHash hash(w->ddf);
  std::size_t lowered = 0;
  for (auto _ : state) {
    state.PauseTiming();
    w->ddf.allHeights() = w->initialHeights;
    state.ResumeTiming();
    lowered = cutAll(w->ddf, hash, w->tool, w->poses);
  }
  perPoseCounter(state, w->poses.size());
  state.counters["faces"] = w->ddf.faceCount();
  state.counters["m"] = w->ddf.raster().m;
  state.counters["roll_radius"] = w->radius;
  state.counters["heights_lowered"] = static_cast<double>(lowered);
}
BENCHMARK(BM_Grinding_Blade217)->Unit(benchmark::kMillisecond);

// Contacts and feed of a workload: the design points the poses were made for (a pose of
// rollPoseAtContact sits R - depth above its contact along its +z column).
struct Contacts {
  std::vector<Vec3> points;
  Vec3 feed;
};

constexpr double kRollRadiusMm = 5.0;  // the roll of grinding_workloads.cpp
constexpr double kDepthMm = 0.3;       // its infeed

Contacts contactsOf(const GrindingWorkload& w) {
  Contacts c;
  for (const auto& pose : w.poses)
    c.points.push_back(pose.translation() - (kRollRadiusMm - kDepthMm) * pose.linear().col(2));
  c.feed = c.points.back() - c.points.front();
  return c;
}

// The whole pipeline per iteration: placement at the contacts (PL's placeTool, touching the
// design), penetration correction against the design (PC's correctPenetrations, 50 x 50
// tangential grid at every pose) and the cut into the stock, the design raised by the
// workload's 0.3 mm infeed (workpieceWithAllowance), so the same layer is removed as by the
// plain cutting benchmarks.
void runPipeline(benchmark::State& state, GrindingWorkload& w) {
  const ddf::DisplacementField goal = w.ddf;  // heights = the design (initialHeights)
  const std::vector<float> stock = planning::workpieceWithAllowance(goal, kDepthMm).allHeights();
  const ddf::CrustHash hash(w.ddf);
  const Contacts c = contactsOf(w);
  planning::Tool roll;
  roll.radiusMm = kRollRadiusMm;
  roll.widthMm = 10.0;
  roll.segments = 50;
  planning::PenetrationCorrectionParams correction;
  planning::ToolPath path;
  path.poses.resize(c.points.size());
  path.passStarts = {0};
  double placeSeconds = 0, correctSeconds = 0, cutSeconds = 0, maxLift = 0;
  int lifted = 0;
  for (auto _ : state) {
    state.PauseTiming();
    w.ddf.allHeights() = stock;
    state.ResumeTiming();
    auto start = Clock::now();
    correction.normals.clear();
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      correction.normals.push_back(w.design->normal(c.points[i]));
      path.poses[i] = {planning::placeTool(roll, c.points[i], correction.normals[i], c.feed),
                       c.points[i]};
    }
    placeSeconds += secondsSince(start);
    start = Clock::now();
    const auto report = planning::correctPenetrations(goal, w.tool, path, correction);
    correctSeconds += secondsSince(start);
    start = Clock::now();
    for (const auto& p : path.poses) ddf::cutByMesh(w.ddf, hash, w.tool, p.pose);
    cutSeconds += secondsSince(start);
    lifted = report.penetratingPoses;
    maxLift = report.maxLiftMm;
  }
  const double runs = static_cast<double>(state.iterations());
  perPoseCounter(state, path.poses.size());
  state.counters["place_ms"] = 1e3 * placeSeconds / runs;
  state.counters["correct_ms"] = 1e3 * correctSeconds / runs;
  state.counters["cut_ms"] = 1e3 * cutSeconds / runs;
  state.counters["lifted_poses"] = lifted;
  state.counters["max_lift_mm"] = maxLift;
}

void BM_GrindingPipeline_Fig8_16(benchmark::State& state) {
  static GrindingWorkload w = fig8_16Workload();
  runPipeline(state, w);
}
BENCHMARK(BM_GrindingPipeline_Fig8_16)->Unit(benchmark::kMillisecond);

void BM_GrindingPipeline_Fig8_14(benchmark::State& state) {
  static GrindingWorkload w = fig8_14Workload();
  runPipeline(state, w);
}
BENCHMARK(BM_GrindingPipeline_Fig8_14)->Unit(benchmark::kMillisecond);

#ifdef DDFCAM_HAVE_OPENVDB

/// Smallest distance between neighbouring raster points over all support edges, mm.
double rasterSpacing(const ddf::DisplacementField& ddf) {
  double spacing = std::numeric_limits<double>::infinity();
  const int n = ddf.raster().m - 1;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e)
      spacing = std::min(spacing, (ddf.position(v[(e + 1) % 3]) - ddf.position(v[e])).norm() / n);
  }
  return spacing;
}

/// The represented raster point nearest to @p p in x and y (brute force).
Vec3 nearestRasterPoint(const ddf::DisplacementField& ddf, const Vec3& p) {
  Vec3 best = Vec3::Constant(std::numeric_limits<double>::infinity());
  const int n = ddf.raster().m - 1;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const Vec3 q = ddf.surfacePoint(f, i, k);
        if ((q - p).head<2>().squaredNorm() < (best - p).head<2>().squaredNorm()) best = q;
      }
  return best;
}

/// Bytes of what the cut reads and writes per raster point: heights and vertex vectors.
double ddfStateBytes(const ddf::DisplacementField& ddf) {
  return static_cast<double>(ddf.allHeights().size() * sizeof(float) +
                             ddf.vertexCount() * sizeof(Vec3));
}

// The fig. 8.16 poses subtracted from the same part by the DDF depth buffer and by OpenVDB
// level-set CSG at a voxel size equal to the raster spacing; both timed in every iteration.
void BM_GrindingPeer_OpenVdb(benchmark::State& state) {
  static GrindingWorkload w = fig8_16Workload();
  static const ddf::CrustHash hash(w.ddf);
  const double voxel = rasterSpacing(w.ddf);
  // The design patch over its whole domain (z within about +-2 mm) extruded down to z = -5 mm.
  const auto& design = *w.design;
  auto height = [&](double x, double y) { return design.height(x, y); };
  const ddf::TriangleMesh slab = extrudedSlab(height, {0.0, 0.0}, {50.0, 25.0}, -5.0, voxel);
  static VdbPart part(slab, {.voxelMm = voxel});
  double ddfSeconds = 0, vdbSeconds = 0, scanSeconds = 0, csgSeconds = 0;
  double ddfCpu = 0, vdbCpu = 0;  // process CPU time (all threads): robust to a loaded machine
  for (auto _ : state) {
    state.PauseTiming();
    w.ddf.allHeights() = w.initialHeights;
    part.reset();
    state.ResumeTiming();
    auto start = Clock::now();
    std::clock_t cpu = std::clock();
    cutAll(w.ddf, hash, w.tool, w.poses);
    ddfCpu += static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    ddfSeconds += secondsSince(start);
    start = Clock::now();
    cpu = std::clock();
    const VdbCsgTimes t = part.subtractTools(w.tool, w.poses);
    vdbCpu += static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    vdbSeconds += secondsSince(start);
    scanSeconds += t.meshToLevelSetSeconds;
    csgSeconds += t.csgSeconds;
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["voxel_mm"] = voxel;
  state.counters["ddf_ms"] = 1e3 * ddfSeconds / runs;
  state.counters["vdb_ms"] = 1e3 * vdbSeconds / runs;
  state.counters["vdb_scan_ms"] = 1e3 * scanSeconds / runs;
  state.counters["vdb_csg_ms"] = 1e3 * csgSeconds / runs;
  state.counters["speed_ratio"] = vdbSeconds / ddfSeconds;
  state.counters["ddf_cpu_ms"] = 1e3 * ddfCpu / runs;
  state.counters["vdb_cpu_ms"] = 1e3 * vdbCpu / runs;
  state.counters["cpu_ratio"] = vdbCpu / ddfCpu;
  state.counters["ddf_bytes"] = ddfStateBytes(w.ddf);
  state.counters["ddf_total_bytes"] = static_cast<double>(w.ddf.memoryBytes());
  state.counters["vdb_bytes"] = static_cast<double>(part.memoryBytes());
  state.counters["vdb_active_voxels"] = static_cast<double>(part.activeVoxels());
  state.counters["memory_ratio"] = part.memoryBytes() / ddfStateBytes(w.ddf);
  state.counters["memory_ratio_total"] =
      part.memoryBytes() / static_cast<double>(w.ddf.memoryBytes());
  // Both removed the same material: groove depth below the design at the middle pose's contact
  // (0.3 mm along the normal), the DDF at its raster point nearest in x, y.
  const Vec3 mid = w.poses[w.poses.size() / 2].translation();
  const double top = design.height(mid.x(), mid.y());
  if (const auto z = part.surfaceZ(mid.x(), mid.y(), top + 1.0, -5.0))
    state.counters["vdb_groove_depth_mm"] = top - *z;
  state.counters["ddf_groove_depth_mm"] = top - nearestRasterPoint(w.ddf, mid).z();
}
BENCHMARK(BM_GrindingPeer_OpenVdb)->Unit(benchmark::kMillisecond)->Iterations(1);

#endif  // DDFCAM_HAVE_OPENVDB

}  // namespace
}  // namespace ddfcam::bench
