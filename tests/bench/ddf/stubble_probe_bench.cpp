// SPDX-License-Identifier: MIT
// ddfcam-bench: the stubble probe (V-convexity and collision checks, sec. 8.4-8.5) on fig. 8.16.
#include "ddf/grinding_workloads.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/stubble_probe.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ddfcam::bench {
namespace {

using ddf::Vec3;

// The probe as first written (section SM): every stubble segment against every triangle whose
// box it touches. Kept verbatim as the reference of the speed-up (serial).
namespace reference {

struct Triangle {
  Vec3 a, e1, e2;
  Eigen::AlignedBox3d box;
  double scale = 0.0;
};
struct Hit {
  double h;
  bool entry;
};
struct Mesh {
  std::vector<Triangle> triangles;
  Eigen::AlignedBox3d box;
};

Mesh placeMesh(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  const bool flip = mesh.signedVolume() < 0.0;
  Mesh out;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = pose * mesh.vertices[t[0]];
    const Vec3 b = pose * mesh.vertices[t[flip ? 2 : 1]];
    const Vec3 c = pose * mesh.vertices[t[flip ? 1 : 2]];
    Triangle pt{a, b - a, c - a, {}, (b - a).norm() * (c - a).norm()};
    pt.box.extend(a), pt.box.extend(b), pt.box.extend(c);
    out.box.extend(pt.box);
    out.triangles.push_back(pt);
  }
  return out;
}

std::vector<Hit> lineHits(const Mesh& mesh, const Vec3& g, const Vec3& v, double hMin, double hMax,
                          const Eigen::AlignedBox3d* filter, double merge) {
  std::vector<Hit> hits;
  const double vLength = v.norm();
  for (const Triangle& t : mesh.triangles) {
    if (filter && !filter->intersects(t.box)) continue;
    const Vec3 pv = v.cross(t.e2);
    const double det = t.e1.dot(pv);
    if (std::abs(det) <= 1e-12 * t.scale * vLength) continue;
    const Vec3 tv = g - t.a;
    const double u = tv.dot(pv) / det;
    if (u < -1e-9 || u > 1.0 + 1e-9) continue;
    const Vec3 qv = tv.cross(t.e1);
    const double w = v.dot(qv) / det;
    if (w < -1e-9 || u + w > 1.0 + 1e-9) continue;
    const double h = t.e2.dot(qv) / det;
    if (h > hMin && h <= hMax) hits.push_back({h, det > 0.0});
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.h < y.h; });
  std::vector<Hit> merged;
  for (const Hit& hit : hits) {
    bool duplicate = false;
    for (auto it = merged.rbegin(); it != merged.rend() && hit.h - it->h <= merge; ++it)
      duplicate = duplicate || it->entry == hit.entry;
    if (!duplicate) merged.push_back(hit);
  }
  return merged;
}

bool intervalsOf(const Mesh& mesh, const Vec3& g, const Vec3& v, const Eigen::AlignedBox3d& segment,
                 ddf::StubbleCrossing& c) {
  const auto hits = lineHits(mesh, g, v, -1.0 - 1e-12, 1.0, &segment, 1e-7);
  bool inside;
  if (!hits.empty()) {
    inside = !hits.front().entry;
  } else {
    if (!mesh.box.contains(g)) return false;
    const auto above =
        lineHits(mesh, g, v, 1.0, std::numeric_limits<double>::infinity(), nullptr, 1e-7);
    if (above.empty() || above.front().entry) return false;
    c.entry = -1.0f, c.exit = 1.0f, c.intervals = 1;
    return true;
  }
  double start = -1.0;
  c.intervals = 0;
  auto close = [&](double end) {
    if (c.intervals++ == 0) c.entry = static_cast<float>(start), c.exit = static_cast<float>(end);
  };
  for (const Hit& hit : hits) {
    if (hit.entry && !inside)
      start = hit.h, inside = true;
    else if (!hit.entry && inside)
      close(hit.h), inside = false;
  }
  if (inside) close(1.0);
  return c.intervals > 0;
}

std::vector<ddf::StubbleCrossing> probe(const ddf::DisplacementField& ddf,
                                        const ddf::CrustHash& hash, const ddf::TriangleMesh& tool,
                                        const Eigen::Isometry3d& pose) {
  const Mesh mesh = placeMesh(tool, pose);
  std::vector<int> candidates;
  hash.queryBox(mesh.box, candidates);
  std::vector<ddf::StubbleCrossing> out;
  const ddf::Raster& raster = ddf.raster();
  for (int f : candidates) {
    if (!ddf::CrustHash::crustBox(ddf, f).intersects(mesh.box)) continue;
    for (int k = 0; k <= raster.steps(); ++k)
      for (int i = 0; i < raster.rowLength(k); ++i) {
        const Vec3 bary = ddf.rasterBary(i, k);
        const Vec3 g = ddf.basePoint(f, bary), v = ddf.vectorAt(f, bary);
        Eigen::AlignedBox3d segment(g - v);
        segment.extend(g + v);
        ddf::StubbleCrossing c;
        if (!segment.intersects(mesh.box) || !intervalsOf(mesh, g, v, segment, c)) continue;
        c.face = f;
        c.index = static_cast<std::uint32_t>(raster.index(i, k));
        c.point = ddf.topology().id(f, i, k);
        c.height = ddf.heights(f)[c.index];
        out.push_back(c);
      }
  }
  return out;
}

}  // namespace reference

GrindingWorkload& workload() {
  static GrindingWorkload w = fig8_16Workload();
  return w;
}

bool sameCrossing(const ddf::StubbleCrossing& a, const ddf::StubbleCrossing& b) {
  return a.face == b.face && a.index == b.index && a.entry == b.entry && a.exit == b.exit &&
         a.intervals == b.intervals && a.height == b.height;
}

// Arg 0: reference (serial), 1: grid (serial), 2: grid (TBB over faces). Every pose of the
// path probed against the initial heights; counters per pose.
void BM_StubbleProbe_Fig8_16(benchmark::State& state) {
  const GrindingWorkload& w = workload();
  const ddf::CrustHash hash(w.ddf);
  const int mode = static_cast<int>(state.range(0));
  std::size_t crossings = 0;
  for (auto _ : state) {
    crossings = 0;
    for (const auto& pose : w.poses) {
      if (mode == 0) {
        crossings += reference::probe(w.ddf, hash, w.tool, pose).size();
      } else {
        const auto p = ddf::probeStubbles(w.ddf, hash, w.tool, pose, {.parallel = mode == 2});
        crossings += p.crossings.size();
      }
    }
  }
  // The speed-up must not change the results.
  for (const auto& pose : w.poses) {
    auto ref = reference::probe(w.ddf, hash, w.tool, pose);
    std::sort(ref.begin(), ref.end(), [](const auto& a, const auto& b) {
      return std::pair(a.face, a.index) < std::pair(b.face, b.index);
    });
    const auto fast = ddf::probeStubbles(w.ddf, hash, w.tool, pose).crossings;
    if (!std::equal(ref.begin(), ref.end(), fast.begin(), fast.end(), sameCrossing))
      state.SkipWithError("grid probe differs from the reference");
  }
  const double poses = static_cast<double>(w.poses.size());
  state.counters["poses"] = poses;
  state.counters["crossings_per_pose"] = static_cast<double>(crossings) / poses;
  state.counters["ms_per_pose"] = benchmark::Counter(
      poses * 1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StubbleProbe_Fig8_16)
    ->ArgName("grid_parallel")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

// The whole simulation of the fig. 8.16 path with the checks off (arg 0) and on (arg 1);
// non-cutting part: a 3 mm arbor through the roll, 20 mm long.
void BM_SimulateGrinding_Fig8_16(benchmark::State& state) {
  GrindingWorkload& w = workload();
  const planning::ToolMeshes tool{
      w.tool, planning::makeCylinderTool({.radiusMm = 1.5, .widthMm = 20.0, .segments = 16})};
  planning::ToolPath path;
  for (const auto& pose : w.poses) path.poses.push_back({pose, pose.translation()});
  path.passStarts = {0};
  planning::GrindingSimulationParams params;
  params.checkVConvexity = params.checkCollisions = state.range(0) != 0;
  std::size_t violations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ddf::DisplacementField part = w.ddf;
    part.allHeights() = w.initialHeights;
    state.ResumeTiming();
    const auto report = planning::simulateGrinding(part, tool, path, params);
    violations = report.vConvexity.size() + report.collisions.size();
  }
  state.counters["flagged_poses"] = static_cast<double>(violations);
  state.counters["ms_per_pose"] = benchmark::Counter(
      static_cast<double>(w.poses.size()) * 1e-3,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SimulateGrinding_Fig8_16)
    ->ArgName("checks")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace ddfcam::bench
