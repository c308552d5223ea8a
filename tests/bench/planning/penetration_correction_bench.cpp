// SPDX-License-Identifier: MIT
// Benchmark: penetration correction of a grinding roll moved around a torus (sec. 8.4.2,
// fig. 8.19-8.21): 400 poses, 50x50 tangential grids, every 1st / 25th / 50th pose exact
// (dissertation: 9.8 s / 0.6 s; goal: <= 20 ms for all 400), and a naive per-cell
// ray / triangle reference for the speed ratio.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/placement/penetration_correction.h>
#include <ddfcam/planning/placement/tangential_grid.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <limits>
#include <numbers>

namespace ddfcam::bench {
namespace {

/// Torus R = 30, r = 10 (48 x 24 support, m = 17); a roll of radius 5, width 10 (200
/// triangles) placed at 400 contacts around the tube in the x-z plane (the meridian circle,
/// through the concave hole side), its axis along the parallel circles.
struct TorusRollWorkload {
  ddf::GeneratedSurface torus = ddf::torusPart({});
  ddf::TriangleMesh roll = planning::makeCylinderTool({});
  planning::ToolPath path;
  std::vector<ddf::Vec3> normals;

  TorusRollWorkload() {
    constexpr int kPoses = 400;
    for (int i = 0; i < kPoses; ++i) {
      const double v = 2.0 * std::numbers::pi * i / kPoses;
      const ddf::Vec3 n(std::cos(v), 0.0, std::sin(v));
      const ddf::Vec3 c = ddf::Vec3(30.0, 0.0, 0.0) + 10.0 * n;
      const ddf::Vec3 feed(-std::sin(v), 0.0, std::cos(v));
      path.poses.push_back({planning::rollPoseAtContact(c, n, feed, 5.0, 0.0), c});
      normals.push_back(n);
    }
    path.passStarts = {0};
  }
};

const TorusRollWorkload& workload() {
  static const TorusRollWorkload w;
  return w;
}

/// Poses of @p path still penetrating by more than @p tol (an every-pose evaluation).
int penetratingAfter(const planning::ToolPath& path, double tol) {
  planning::ToolPath copy = path;
  planning::PenetrationCorrectionParams p;
  p.normals = workload().normals;
  p.toleranceMm = tol;
  return planning::correctPenetrations(workload().torus.ddf, workload().roll, copy, p)
      .penetratingPoses;
}

void BM_PenetrationCorrection_Fig8_19(benchmark::State& state) {
  const TorusRollWorkload& w = workload();
  planning::PenetrationCorrectionParams p;
  p.every = static_cast<int>(state.range(0));
  p.parallel = state.range(1) != 0;
  p.normals = w.normals;
  planning::PenetrationCorrectionReport report;
  planning::ToolPath corrected;
  for (auto _ : state) {
    state.PauseTiming();
    corrected = w.path;
    state.ResumeTiming();
    report = planning::correctPenetrations(w.torus.ddf, w.roll, corrected, p);
    benchmark::DoNotOptimize(report.liftMm.data());
  }
  state.counters["poses_per_s"] =
      benchmark::Counter(400.0 * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["exact_poses"] = report.exactPoses;
  state.counters["recomputed_by_check"] = report.correctedAfterCheck;
  state.counters["lifted_poses"] = report.penetratingPoses;
  state.counters["max_lift_mm"] = report.maxLiftMm;
  // Poses the check pass left with more than 1 um / 10 um of penetration.
  state.counters["penetrating_after_1um"] = penetratingAfter(corrected, 1e-3);
  state.counters["penetrating_after_10um"] = penetratingAfter(corrected, 1e-2);
}
// Args: every, parallel. The machine is shared, so process CPU time (all threads) is the
// figure to read; wall time is only meaningful on an idle machine.
BENCHMARK(BM_PenetrationCorrection_Fig8_19)
    ->ArgsProduct({{1, 25, 50}, {0, 1}})
    ->ArgNames({"every", "parallel"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

/// Naive tangential DDF of one pose: every cell centre's ray against every tool triangle and
/// every raster triangle of the faces in the box (no z-buffer, no culling).
double naiveLift(const planning::SurfacePatchIndex& index, const ddf::TriangleMesh& tool,
                 const Eigen::Isometry3d& pose, const planning::TangentFrame& frame, int grid) {
  const ddf::DisplacementField& field = index.field();
  std::vector<ddf::Vec3> t;
  for (const auto& v : tool.vertices) t.push_back(frame.toLocal(pose * v));
  Eigen::AlignedBox3d box;
  for (const auto& p : t) box.extend(p);
  std::vector<std::array<ddf::Vec3, 3>> work;
  std::vector<int> faces;
  Eigen::AlignedBox3d part;
  for (int c = 0; c < 8; ++c)
    part.extend(frame.toPart(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))));
  index.query(part, faces);
  const int n = field.resolution() - 1;
  for (int f : faces)
    for (int k = 0; k < n; ++k)
      for (int i = 0; i + k < n; ++i) {
        const auto q = [&](int a, int b) { return frame.toLocal(field.surfacePoint(f, a, b)); };
        work.push_back({q(i, k), q(i + 1, k), q(i, k + 1)});
        if (i + k + 2 <= n) work.push_back({q(i + 1, k), q(i + 1, k + 1), q(i, k + 1)});
      }
  const auto cross = [](const ddf::Vec3& a, const ddf::Vec3& b, const ddf::Vec3& c, double u,
                        double v) {
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-14) return std::numeric_limits<double>::quiet_NaN();
    const double s = ((u - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (v - a.y())) / det;
    const double r = ((b.x() - a.x()) * (v - a.y()) - (u - a.x()) * (b.y() - a.y())) / det;
    if (s < 0 || r < 0 || s + r > 1) return std::numeric_limits<double>::quiet_NaN();
    return a.z() + s * (b.z() - a.z()) + r * (c.z() - a.z());
  };
  double lift = 0.0;
  const ddf::Vec3 size = box.sizes();
  for (int b = 0; b < grid; ++b)
    for (int a = 0; a < grid; ++a) {
      const double u = box.min().x() + (a + 0.5) * size.x() / grid;
      const double v = box.min().y() + (b + 0.5) * size.y() / grid;
      double ht = std::numeric_limits<double>::infinity(), hw = -ht;
      for (const auto& tri : tool.triangles)
        if (const double w = cross(t[tri[0]], t[tri[1]], t[tri[2]], u, v); w == w)
          ht = std::min(ht, w);
      for (const auto& tri : work)
        if (const double w = cross(tri[0], tri[1], tri[2], u, v); w == w && w <= box.max().z())
          hw = std::max(hw, w);
      if (std::isfinite(ht) && std::isfinite(hw)) lift = std::max(lift, hw - ht);
    }
  return lift;
}

/// Naive reference on 8 poses of the hole side, scaled to 400 poses; the ratio compares it
/// with the serial every-pose correction of all 400 poses measured in the same run, both as
/// process CPU time (the machine is shared, so wall time would measure the neighbours).
void BM_PenetrationCorrection_Naive(benchmark::State& state) {
  const TorusRollWorkload& w = workload();
  const planning::SurfacePatchIndex index(w.torus.ddf);
  double naiveMs = 0.0, maxDifference = 0.0;
  for (auto _ : state) {
    const std::clock_t start = std::clock();
    for (int j = 0; j < 8; ++j) {
      const int i = 150 + 12 * j;
      const auto& pp = w.path.poses[i];
      const auto frame = planning::tangentFrame(pp.contact, w.normals[i], pp.pose.linear().col(0));
      const double naive = naiveLift(index, w.roll, pp.pose, frame, 50);
      const double fast =
          planning::penetrationDepth(w.torus.ddf, w.roll, pp.pose, pp.contact, w.normals[i]);
      maxDifference = std::max(maxDifference, std::abs(naive - fast));
    }
    naiveMs = 1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC * 400.0 / 8.0;
  }
  planning::PenetrationCorrectionParams p;
  p.normals = w.normals;
  p.parallel = false;
  double fastMs = std::numeric_limits<double>::infinity();
  for (int run = 0; run < 5; ++run) {
    planning::ToolPath copy = w.path;
    const std::clock_t start = std::clock();
    planning::correctPenetrations(w.torus.ddf, w.roll, copy, p);
    fastMs = std::min(fastMs, 1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC);
  }
  state.counters["naive_ms_per_400"] = naiveMs;
  state.counters["fast_ms_per_400"] = fastMs;
  state.counters["ratio"] = naiveMs / fastMs;
  state.counters["max_abs_lift_difference_mm"] = maxDifference;
}
BENCHMARK(BM_PenetrationCorrection_Naive)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace ddfcam::bench
