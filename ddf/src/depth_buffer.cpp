// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/depth_buffer.h>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cut_kernel.h"

namespace ddfcam::ddf {
namespace {

using detail::KernelCounts;
using detail::KernelMode;

detail::FaceCorners cornersOf(const DisplacementField& ddf, int f) {
  detail::FaceCorners c;
  const auto& fv = ddf.faceVertices(f);
  for (int i = 0; i < 3; ++i) c.p[i] = ddf.position(fv[i]), c.v[i] = ddf.vector(fv[i]);
  return c;
}

// Runs the row kernel of one (face, triangle) pair over the whole face raster.
void processPair(float* heights, const Raster& raster, const detail::PairForms& forms,
                 KernelMode mode, const DepthBufferParams& params, KernelCounts& counts) {
  const int n = raster.steps();
  std::array<std::pair<int, int>, 5> ranges;
  for (int k = 0; k <= n; ++k) {
    const int length = raster.rowLength(k);
    int count = 1;
    if (params.restrictIntervals) {
      count = detail::rowIntervals(forms, k, length, mode, params.lambdaTolerance, ranges);
    } else {
      ranges[0] = {0, length - 1};
    }
    if (count == 0) continue;
    const detail::RowForms row = detail::rowForms(forms, k);
    float* rowHeights = heights + raster.rowOffset(k);
    for (int r = 0; r < count; ++r) {
      if (mode == KernelMode::Cut) {
        detail::cutRow(rowHeights, ranges[r].first, ranges[r].second, row,
                       params.lambdaTolerance, counts);
      } else {
        detail::fillRow(rowHeights, ranges[r].first, ranges[r].second, row,
                        params.lambdaTolerance);
      }
    }
  }
}

// (face, triangle) candidate pairs grouped by face.
struct PairGroups {
  std::vector<std::pair<int, int>> pairs;  // sorted by face
  std::vector<std::size_t> groupStart;     // start of each face's run, plus the end
};

PairGroups localize(const CrustHash& hash, std::span<const Vec3> corners,
                    const ProgressCallback& progress) {
  PairGroups g;
  std::vector<int> faces;
  const std::size_t triangles = corners.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t) {
    if (progress && t % 4096 == 0) reportProgress(progress, 0.2 * t / triangles);
    hash.queryTriangle(corners[3 * t], corners[3 * t + 1], corners[3 * t + 2], faces);
    for (int f : faces) g.pairs.emplace_back(f, static_cast<int>(t));
  }
  std::sort(g.pairs.begin(), g.pairs.end());
  for (std::size_t i = 0; i < g.pairs.size(); ++i)
    if (i == 0 || g.pairs[i].first != g.pairs[i - 1].first) g.groupStart.push_back(i);
  g.groupStart.push_back(g.pairs.size());
  return g;
}

// Calls fn(group index) for every face group, in parallel when asked to.
template <class Fn>
void forEachGroup(const PairGroups& g, bool parallel, Fn&& fn) {
  const std::size_t groups = g.groupStart.size() - 1;
  if (!parallel || groups < 2) {
    for (std::size_t i = 0; i < groups; ++i) fn(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) fn(i);
  });
}

std::vector<int> groupFaces(const PairGroups& g) {
  std::vector<int> faces;
  for (std::size_t i = 0; i + 1 < g.groupStart.size(); ++i)
    faces.push_back(g.pairs[g.groupStart[i]].first);
  return faces;
}

}  // namespace

std::size_t cutFaceByTriangle(DisplacementField& ddf, int face, const Vec3& q1, const Vec3& q2,
                              const Vec3& q3, const DepthBufferParams& params) {
  const auto forms =
      detail::makePairForms(cornersOf(ddf, face), q1, q2, q3, ddf.raster().steps(), KernelMode::Cut);
  if (!forms) return 0;
  KernelCounts counts;
  processPair(ddf.heights(face).data(), ddf.raster(), *forms, KernelMode::Cut, params, counts);
  return counts.lowered;
}

CutStats cutByTriangles(DisplacementField& ddf, const CrustHash& hash,
                        std::span<const Vec3> corners, const DepthBufferParams& params) {
  const PairGroups groups = localize(hash, corners, {});
  tbb::combinable<KernelCounts> totals;
  const int n = ddf.raster().steps();
  forEachGroup(groups, params.parallel, [&](std::size_t gi) {
    const int face = groups.pairs[groups.groupStart[gi]].first;
    const detail::FaceCorners c = cornersOf(ddf, face);
    float* heights = ddf.heights(face).data();
    KernelCounts& counts = totals.local();
    for (std::size_t p = groups.groupStart[gi]; p < groups.groupStart[gi + 1]; ++p) {
      const std::size_t t = static_cast<std::size_t>(groups.pairs[p].second);
      const auto forms = detail::makePairForms(c, corners[3 * t], corners[3 * t + 1],
                                               corners[3 * t + 2], n, KernelMode::Cut);
      if (forms) processPair(heights, ddf.raster(), *forms, KernelMode::Cut, params, counts);
    }
  });
  CutStats stats;
  stats.candidatePairs = groups.pairs.size();
  totals.combine_each([&](const KernelCounts& c) {
    stats.pointsLowered += c.lowered;
    stats.pointsClamped += c.clamped;
  });
  stats.touchedFaces = groupFaces(groups);
  ddf.synchronizeShared(SharedPolicy::Minimum, stats.touchedFaces);
  return stats;
}

CutStats cutByMesh(DisplacementField& ddf, const CrustHash& hash, const TriangleMesh& tool,
                   const Eigen::Isometry3d& pose, const DepthBufferParams& params) {
  const bool flip = tool.signedVolume() < 0.0;
  std::vector<Vec3> corners;
  corners.reserve(tool.triangles.size() * 3);
  for (const auto& t : tool.triangles) {
    corners.push_back(pose * tool.vertices[t[0]]);
    corners.push_back(pose * tool.vertices[t[flip ? 2 : 1]]);
    corners.push_back(pose * tool.vertices[t[flip ? 1 : 2]]);
  }
  return cutByTriangles(ddf, hash, corners, params);
}

std::size_t cutFaceByTriangleDirect(DisplacementField& ddf, int face, const Vec3& q1,
                                    const Vec3& q2, const Vec3& q3) {
  // Moller-Trumbore on the full line g + h v, entry side only, in double.
  const Vec3 e1 = q2 - q1, e2 = q3 - q1;
  const Vec3 normal = e1.cross(e2);
  const Raster& raster = ddf.raster();
  auto heights = ddf.heights(face);
  std::size_t lowered = 0;
  for (int k = 0; k <= raster.steps(); ++k)
    for (int i = 0; i < raster.rowLength(k); ++i) {
      const Vec3 bary = ddf.rasterBary(i, k);
      const Vec3 g = ddf.basePoint(face, bary), v = ddf.vectorAt(face, bary);
      if (!(v.dot(normal) < 0.0)) continue;
      const Vec3 pv = v.cross(e2);
      const double det = e1.dot(pv);
      const Vec3 tv = g - q1;
      const double u = tv.dot(pv) / det;
      const Vec3 qv = tv.cross(e1);
      const double w = v.dot(qv) / det;
      if (u < -1e-9 || w < -1e-9 || u + w > 1.0 + 1e-9) continue;
      const double h = e2.dot(qv) / det;
      const float hc = static_cast<float>(std::max(h, -1.0));
      float& stored = heights[raster.index(i, k)];
      if (hc < stored) stored = hc, ++lowered;
    }
  return lowered;
}

FillReport fillFromMesh(DisplacementField& ddf, const CrustHash& hash, const TriangleMesh& surface,
                        const FillParams& params) {
  std::vector<Vec3> corners;
  corners.reserve(surface.triangles.size() * 3);
  for (const auto& t : surface.triangles)
    for (int c = 0; c < 3; ++c) corners.push_back(surface.vertices[t[c]]);
  const PairGroups groups = localize(hash, corners, params.progress);
  std::vector<float> result(ddf.allHeights().size(), std::numeric_limits<float>::quiet_NaN());
  const std::size_t per = ddf.pointsPerFace();
  const int n = ddf.raster().steps();
  const std::size_t groupCount = groups.groupStart.size() - 1;
  const std::size_t batch = std::max<std::size_t>(1, groupCount / 20);
  for (std::size_t begin = 0; begin < groupCount; begin += batch) {
    reportProgress(params.progress, 0.2 + 0.75 * begin / std::max<std::size_t>(groupCount, 1));
    const std::size_t end = std::min(groupCount, begin + batch);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end), [&](const auto& range) {
      KernelCounts unused;
      for (std::size_t gi = range.begin(); gi != range.end(); ++gi) {
        const int face = groups.pairs[groups.groupStart[gi]].first;
        const detail::FaceCorners c = cornersOf(ddf, face);
        for (std::size_t p = groups.groupStart[gi]; p < groups.groupStart[gi + 1]; ++p) {
          const std::size_t t = static_cast<std::size_t>(groups.pairs[p].second);
          const auto forms = detail::makePairForms(c, corners[3 * t], corners[3 * t + 1],
                                                   corners[3 * t + 2], n, KernelMode::Fill);
          if (forms)
            processPair(result.data() + face * per, ddf.raster(), *forms, KernelMode::Fill,
                        params.kernel, unused);
        }
      }
    });
  }
  FillReport report;
  report.missingMask.assign(result.size(), 0);
  auto& heights = ddf.allHeights();
  for (std::size_t i = 0; i < result.size(); ++i) {
    if (std::isnan(result[i])) {
      report.missingMask[i] = 1, ++report.missing;
    } else {
      heights[i] = result[i], ++report.filled;
    }
  }
  ddf.synchronizeShared(SharedPolicy::Canonical);
  reportProgress(params.progress, 1.0);
  return report;
}

}  // namespace ddfcam::ddf
