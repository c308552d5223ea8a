// SPDX-License-Identifier: MIT
// ddfcam: correctPenetrations and penetrationDepth (tangential DDF, sec. 8.4.2).
#include <ddfcam/planning/placement/penetration_correction.h>

#include "tangential_raster.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tangential_grid.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning {

namespace {

using detail::GridBox;
using detail::Local;

/// Cells per side of a culling tile: min h_T per tile bounds what a workpiece face can reach.
constexpr int kTile = 5;

struct Scratch {
  std::vector<Local> tool, pts;
  std::vector<float> toolHeight, tileMin;
  std::vector<int> faces;
  std::vector<std::pair<int, detail::LocalBounds>> kept;
  float minTool = detail::kInf;  // lowest tool height on the grid
};

/// What one pose needs: the goal index, the tool and the grid settings.
struct Evaluator {
  const SurfacePatchIndex& index;
  const ddf::TriangleMesh& toolMesh;
  int gridSize;
  double marginMm;

  /// Tool z-buffer on @p g up to @p cutoff, with the minimum per culling tile.
  void rasterizeTool(const GridBox& g, double cutoff, Scratch& s) const {
    s.toolHeight.assign(g.cells(), detail::kInf);
    detail::rasterizeMin(toolMesh, s.tool, g, s.toolHeight, cutoff);
    const int tu = (g.nu + kTile - 1) / kTile, tv = (g.nv + kTile - 1) / kTile;
    s.tileMin.assign(static_cast<std::size_t>(tu) * tv, detail::kInf);
    for (int b = 0; b < g.nv; ++b)
      for (int a = 0; a < g.nu; ++a) {
        float& t = s.tileMin[a / kTile + (b / kTile) * tu];
        t = std::min(t, s.toolHeight[a + b * g.nu]);
      }
    s.minTool = *std::min_element(s.tileMin.begin(), s.tileMin.end());
  }

  /// Smallest tool height over the tiles under the (u, v) rectangle of @p b.
  static float tileRangeMin(const GridBox& g, const detail::LocalBounds& b, const Scratch& s) {
    const int tu = (g.nu + kTile - 1) / kTile;
    const int a0 = std::max(0, static_cast<int>((b.u0 - g.u0) / g.du));
    const int a1 = std::min(g.nu - 1, static_cast<int>((b.u1 - g.u0) / g.du));
    const int b0 = std::max(0, static_cast<int>((b.v0 - g.v0) / g.dv));
    const int b1 = std::min(g.nv - 1, static_cast<int>((b.v1 - g.v0) / g.dv));
    float m = detail::kInf;
    for (int y = b0 / kTile; y <= b1 / kTile; ++y)
      for (int x = a0 / kTile; x <= a1 / kTile; ++x) m = std::min(m, s.tileMin[x + y * tu]);
    return m;
  }

  /// Faces whose hull reaches into the box above @p wLow, with their local bounds; returns
  /// the highest hull top (the tool cutoff), or -inf if none.
  double gatherFaces(const GridBox& g, const TangentFrame& frame, double wLow, Scratch& s) const {
    index.query(detail::partBox(g, frame, wLow), s.faces);
    const double uEnd = g.u0 + g.nu * g.du, vEnd = g.v0 + g.nv * g.dv;
    double top = -std::numeric_limits<double>::infinity();
    s.kept.clear();
    for (int f : s.faces) {
      const detail::LocalBounds b = detail::localHullBounds(index, f, frame);
      if (b.u1 < g.u0 || b.u0 > uEnd || b.v1 < g.v0 || b.v0 > vEnd || b.w1 <= wLow) continue;
      if (b.w0 > g.wTop) continue;
      s.kept.emplace_back(f, b);
      top = std::max(top, b.w1);
    }
    return std::min(top, g.wTop);
  }

  /// max over the cells of h_W - h_T if it exceeds @p threshold, else a value <= threshold.
  /// Faces that cannot beat the best difference so far are culled by their hull.
  double maxDifference(const TangentFrame& frame, const Eigen::Isometry3d& pose, double threshold,
                       Scratch& s) const {
    detail::transformMesh(toolMesh, pose, frame, s.tool);
    const GridBox g = detail::footprintBox(s.tool, gridSize, marginMm);
    double wMin = g.wTop;
    for (const Local& p : s.tool) wMin = std::min(wMin, p.w);
    double best = threshold;
    const double wLow = wMin + threshold;  // the lowest crossing is no lower than any vertex
    if (wLow > g.wTop) return best;
    const double top = gatherFaces(g, frame, wLow, s);
    if (s.kept.empty()) return best;
    rasterizeTool(g, top, s);
    // Most promising faces first, so the best difference rises early and culls the rest.
    for (auto& [f, b] : s.kept) b.w0 = b.w1 - tileRangeMin(g, b, s);
    std::sort(s.kept.begin(), s.kept.end(),
              [](const auto& x, const auto& y) { return x.second.w0 > y.second.w0; });
    for (const auto& [f, b] : s.kept) {
      if (b.w0 <= best) break;
      detail::faceLocalPoints(index.field(), f, frame, s.pts);
      rasterizeFaceCulled(g, s, best);
    }
    return best;
  }

  /// Rasterizes the raster triangles of the face in s.pts that can beat @p best.
  void rasterizeFaceCulled(const GridBox& g, const Scratch& s, double& best) const {
    const ddf::Raster& r = index.field().raster();
    const int n = r.steps();
    const auto visit = [&](int cell, double w) {
      if (w <= g.wTop) best = std::max(best, w - double(s.toolHeight[cell]));
    };
    const auto triangle = [&](const Local& a, const Local& b, const Local& c) {
      const double top = std::max({a.w, b.w, c.w});
      if (top - s.minTool <= best) return;
      const detail::LocalBounds box{std::min({a.u, b.u, c.u}),
                                    std::max({a.u, b.u, c.u}),
                                    std::min({a.v, b.v, c.v}),
                                    std::max({a.v, b.v, c.v}),
                                    0,
                                    0};
      if (top - tileRangeMin(g, box, s) > best) detail::rasterizeTriangle(g, a, b, c, visit);
    };
    for (int k = 0; k < n; ++k) {
      const std::size_t row = r.rowOffset(k), next = r.rowOffset(k + 1);
      for (int i = 0; i + k < n; ++i) {
        triangle(s.pts[row + i], s.pts[row + i + 1], s.pts[next + i]);
        if (i + k + 2 <= n) triangle(s.pts[row + i + 1], s.pts[next + i + 1], s.pts[next + i]);
      }
    }
  }
};

void validate(const ddf::TriangleMesh& toolMesh, const PenetrationCorrectionParams& p) {
  if (toolMesh.triangles.empty())
    throw InvalidInput("penetration correction: the tool mesh is empty");
  if (p.gridSize < 2)
    throw InvalidInput("penetration correction: gridSize " + std::to_string(p.gridSize) +
                       " must be at least 2");
  if (p.every < 1)
    throw InvalidInput("penetration correction: every " + std::to_string(p.every) +
                       " must be at least 1");
  if (!(p.toleranceMm >= 0.0) || !(p.marginMm >= 0.0))
    throw InvalidInput("penetration correction: toleranceMm and marginMm must be non-negative");
}

/// Runs body(i) for i in [0, count) in chunks, reporting progress between chunks.
template <class Body>
void forEachChunked(int count, bool parallel, const ProgressCallback& progress, double from,
                    double to, Body&& body) {
  const int chunk = 64;
  for (int start = 0; start < count; start += chunk) {
    const int end = std::min(count, start + chunk);
    if (parallel)
      tbb::parallel_for(start, end, [&](int i) { body(i); });
    else
      for (int i = start; i < end; ++i) body(i);
    reportProgress(progress, from + (to - from) * end / std::max(count, 1));
  }
}

/// Poses [begin, end) of every pass: passStarts, or one pass over all poses.
std::vector<std::pair<int, int>> passRanges(const ToolPath& path) {
  const int count = static_cast<int>(path.poses.size());
  std::vector<int> starts = path.passStarts;
  if (starts.empty() || starts.front() != 0) starts.insert(starts.begin(), 0);
  std::vector<std::pair<int, int>> out;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const int b = std::clamp(starts[i], 0, count);
    const int e = i + 1 < starts.size() ? std::clamp(starts[i + 1], b, count) : count;
    if (e > b) out.emplace_back(b, e);
  }
  return out;
}

/// Linear interpolation of the lifts between the exact poses of each pass.
void interpolateLifts(const ToolPath& path, PenetrationCorrectionReport& report) {
  for (const auto& [b, e] : passRanges(path)) {
    int prev = b;
    for (int i = b + 1; i < e; ++i) {
      if (!report.exact[i]) continue;
      for (int x = prev + 1; x < i; ++x) {
        const double t = double(x - prev) / (i - prev);
        report.liftMm[x] = (1.0 - t) * report.liftMm[prev] + t * report.liftMm[i];
      }
      prev = i;
    }
  }
}

}  // namespace

PenetrationCorrectionReport correctPenetrations(const ddf::DisplacementField& goal,
                                                const ddf::TriangleMesh& toolMesh, ToolPath& path,
                                                const PenetrationCorrectionParams& params) {
  validate(toolMesh, params);
  const int count = static_cast<int>(path.poses.size());
  if (!params.normals.empty() && static_cast<int>(params.normals.size()) != count)
    throw InvalidInput("penetration correction: " + std::to_string(params.normals.size()) +
                       " normals for " + std::to_string(count) + " poses");
  PenetrationCorrectionReport report;
  report.liftMm.assign(count, 0.0);
  report.exact.assign(count, 0);
  if (count == 0) return report;
  const SurfacePatchIndex index(goal);
  const Evaluator eval{index, toolMesh, params.gridSize, params.marginMm};
  std::vector<TangentFrame> frames(count);
  forEachChunked(count, params.parallel, params.progress, 0.0, 0.1, [&](int i) {
    const PathPose& pp = path.poses[i];
    const ddf::Vec3 n = params.normals.empty() ? index.normalAt(pp.contact) : params.normals[i];
    frames[i] = tangentFrame(pp.contact, n, pp.pose.linear().col(0));
  });
  // The every-k schedule: each pass's first, every k-th and last pose.
  std::vector<int> scheduled, between;
  for (const auto& [b, e] : passRanges(path))
    for (int i = b; i < e; ++i) {
      const bool exact = (i - b) % params.every == 0 || i == e - 1;
      (exact ? scheduled : between).push_back(i);
      report.exact[i] = exact;
    }
  tbb::enumerable_thread_specific<Scratch> scratch;
  forEachChunked(
      static_cast<int>(scheduled.size()), params.parallel, params.progress, 0.1, 0.55, [&](int j) {
        const int i = scheduled[j];
        const double d = eval.maxDifference(frames[i], path.poses[i].pose, 0.0, scratch.local());
        report.liftMm[i] = std::max(0.0, d);
      });
  report.exactPoses = static_cast<int>(scheduled.size());
  interpolateLifts(path, report);
  // Check pass: a lift-threshold evaluation culls nearly everything where the lift suffices
  // and returns the exact lift where it does not.
  std::vector<double> residual(between.size(), 0.0);
  std::vector<char> corrected(between.size(), 0);
  forEachChunked(
      static_cast<int>(between.size()), params.parallel, params.progress, 0.55, 1.0, [&](int j) {
        const int i = between[j];
        const double lift = report.liftMm[i];
        const double d = eval.maxDifference(frames[i], path.poses[i].pose, lift, scratch.local());
        if (d - lift > params.toleranceMm) {
          report.liftMm[i] = d;
          corrected[j] = 1;
        } else {
          residual[j] = std::max(0.0, d - lift);
        }
      });
  report.checkedPoses = static_cast<int>(between.size());
  for (std::size_t j = 0; j < between.size(); ++j) {
    report.correctedAfterCheck += corrected[j];
    if (corrected[j]) report.exact[between[j]] = 1;
    report.maxResidualMm = std::max(report.maxResidualMm, residual[j]);
  }
  for (int i = 0; i < count; ++i) {
    const double lift = report.liftMm[i];
    report.maxLiftMm = std::max(report.maxLiftMm, lift);
    if (lift > params.toleranceMm) ++report.penetratingPoses;
    path.poses[i].pose.pretranslate(lift * frames[i].normal);
  }
  return report;
}

double penetrationDepth(const ddf::DisplacementField& goal, const ddf::TriangleMesh& toolMesh,
                        const Eigen::Isometry3d& pose, const ddf::Vec3& contact,
                        const ddf::Vec3& normal, const PenetrationCorrectionParams& params) {
  validate(toolMesh, params);
  const SurfacePatchIndex index(goal);
  const Evaluator eval{index, toolMesh, params.gridSize, params.marginMm};
  Scratch s;
  return std::max(
      0.0, eval.maxDifference(tangentFrame(contact, normal, pose.linear().col(0)), pose, 0.0, s));
}

}  // namespace ddfcam::planning
