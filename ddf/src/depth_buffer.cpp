// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/depth_buffer.h>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "cut_kernel.h"
#include "pair_scan.h"

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

// The slab |n.(x - p1)| <= top around the support plane (n a unit normal) that contains the
// +-1 crust of a face.
struct CrustSlab {
  Vec3 normal;
  double top = 0.0;
  double distance(const Vec3& x, const Vec3& p1) const { return normal.dot(x - p1); }
};

CrustSlab slabOf(const detail::FaceCorners& s) {
  CrustSlab slab{(s.p[1] - s.p[0]).cross(s.p[2] - s.p[0]).normalized()};
  for (const Vec3& v : s.v) slab.top = std::max(slab.top, std::abs(slab.normal.dot(v)));
  return slab;
}

// Whether tool triangle q can meet the +-1 crust of face s at all.
bool mayMeetCrust(const detail::FaceCorners& s, const std::array<Vec3, 3>& q) {
  const CrustSlab slab = slabOf(s);
  int above = 0, below = 0;
  for (const Vec3& x : q) {
    const double d = slab.distance(x, s.p[0]);
    above += d > slab.top;
    below += d < -slab.top;
  }
  return above < 3 && below < 3;
}

// A convex polygon of at most 5 corners: a triangle clipped by two planes.
struct SmallPolygon {
  std::array<Vec3, 6> corner;
  int size = 0;
};

// Clips @p poly to the half-space {x : normal.(x - origin) <= limit}, keeping its orientation.
void clipPolygon(SmallPolygon& poly, const Vec3& normal, const Vec3& origin, double limit) {
  SmallPolygon out;
  for (int i = 0; i < poly.size; ++i) {
    const Vec3& a = poly.corner[i];
    const Vec3& b = poly.corner[(i + 1) % poly.size];
    const double da = normal.dot(a - origin) - limit, db = normal.dot(b - origin) - limit;
    if (da <= 0.0) out.corner[out.size++] = a;
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
      out.corner[out.size++] = a + (b - a) * (da / (da - db));
  }
  poly = out;
}

// Forms and kernel for one (face, triangle) pair. The tool triangle is first clipped to the part
// of space where its hits can matter: below the crust top for cuts (higher hits have h > 1),
// inside the crust slab for fills. That keeps the projected triangle small, so the row range
// seeded from its corners is tight.
void processCandidate(float* heights, const Raster& raster, const detail::FaceCorners& s,
                      const std::array<Vec3, 3>& q, KernelMode mode,
                      const DepthBufferParams& params, KernelCounts& counts) {
  if (!mayMeetCrust(s, q)) return;
  const CrustSlab slab = slabOf(s);
  SmallPolygon poly{{q[0], q[1], q[2]}, 3};
  clipPolygon(poly, slab.normal, s.p[0], slab.top);
  if (mode == KernelMode::Fill) clipPolygon(poly, -slab.normal, s.p[0], slab.top);
  for (int i = 1; i + 1 < poly.size; ++i) {
    const std::array<Vec3, 3> piece = {poly.corner[0], poly.corner[i], poly.corner[i + 1]};
    const auto forms = detail::makePairForms(s, piece[0], piece[1], piece[2], raster.steps(), mode);
    if (forms) detail::scanPair(heights, raster, s, piece, *forms, mode, params, counts);
  }
}

// (face, triangle) candidate pairs grouped by face.
struct PairGroups {
  std::vector<std::pair<int, int>> pairs;  // sorted by face
  std::vector<std::size_t> groupStart;     // start of each face's run, plus the end
};

// Candidate faces for the triangles from one query of their common bounding box, when that box
// meets few faces (a tool at one pose); otherwise one hash query per triangle (a large mesh).
constexpr std::size_t kBoxQueryFaceLimit = 256;

void appendCandidates(const DisplacementField& ddf, const std::vector<int>& faces,
                      std::span<const Vec3> corners, PairGroups& g) {
  std::vector<Eigen::AlignedBox3d> crusts;
  crusts.reserve(faces.size());
  Eigen::AlignedBox3d reach;
  for (int f : faces) reach.extend(crusts.emplace_back(CrustHash::crustBox(ddf, f)));
  // The crust is thin: most triangles of a fine tool mesh (a ball has ~200k) lie outside every
  // crust box, and one test against their union drops them before the per-face tests.
  std::vector<std::pair<int, Eigen::AlignedBox3d>> near;
  const std::size_t triangles = corners.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t) {
    Eigen::AlignedBox3d box;
    for (int c = 0; c < 3; ++c) box.extend(corners[3 * t + c]);
    if (reach.intersects(box)) near.emplace_back(static_cast<int>(t), box);
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const detail::FaceCorners s = cornersOf(ddf, faces[i]);
    for (const auto& [t, box] : near) {
      if (!crusts[i].intersects(box)) continue;
      if (!mayMeetCrust(s, {corners[3 * t], corners[3 * t + 1], corners[3 * t + 2]})) continue;
      g.pairs.emplace_back(faces[i], t);
    }
  }
}

PairGroups localize(const DisplacementField& ddf, const CrustHash& hash,
                    std::span<const Vec3> corners, const ProgressCallback& progress) {
  PairGroups g;
  std::vector<int> faces;
  Eigen::AlignedBox3d all;
  for (const Vec3& c : corners) all.extend(c);
  hash.queryBox(all, faces);
  if (faces.size() <= kBoxQueryFaceLimit) {
    appendCandidates(ddf, faces, corners, g);
  } else {
    // A triangle outside the union of the nearby crust boxes meets no stubble (a hit lies in
    // both boxes), so it needs no hash query; most of a fine tool mesh lies there.
    Eigen::AlignedBox3d reach;
    for (int f : faces) reach.extend(CrustHash::crustBox(ddf, f));
    const std::size_t triangles = corners.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
      if (progress && t % 4096 == 0) reportProgress(progress, 0.2 * t / triangles);
      const std::array<Vec3, 3> q = {corners[3 * t], corners[3 * t + 1], corners[3 * t + 2]};
      Eigen::AlignedBox3d box(q[0]);
      box.extend(q[1]).extend(q[2]);
      if (!reach.intersects(box)) continue;
      hash.queryTriangle(q[0], q[1], q[2], faces);
      for (int f : faces)
        if (mayMeetCrust(cornersOf(ddf, f), q)) g.pairs.emplace_back(f, static_cast<int>(t));
    }
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

// A copy of a shared raster point that the kernel missed in its own face while another copy of
// the same stubble got a hit (float rounding at an edge of the surface or of a clipped piece)
// takes that hit: the canonical synchronization would otherwise give every copy the missed
// copy's stale height, unreported, although the stubble meets the surface.
void adoptSharedHits(const DisplacementField& ddf, std::vector<float>& result) {
  const RasterTopology& topology = ddf.topology();
  const int n = ddf.raster().steps();
  const std::size_t per = ddf.pointsPerFace();
  for (int e = 0; e < static_cast<int>(ddf.support().n_edges()); ++e) {
    const auto& sides = topology.edgeFaces(e);
    if (sides[0] < 0 || sides[1] < 0) continue;
    const int e0 = topology.localEdgeOf(sides[0], e), e1 = topology.localEdgeOf(sides[1], e);
    for (int t = 1; t < n; ++t) {
      float& a = result[sides[0] * per + topology.edgeCopyLocal(sides[0], e0, t)];
      float& b = result[sides[1] * per + topology.edgeCopyLocal(sides[1], e1, t)];
      if (std::isnan(a)) a = b;
      if (std::isnan(b)) b = a;
    }
  }
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const auto copy = [&](int f) -> float& {
      const auto& fv = ddf.faceVertices(f);
      return result[f * per + ddf.raster().index(fv[0] == v ? n : 0, fv[2] == v ? n : 0)];
    };
    float hit = std::numeric_limits<float>::quiet_NaN();
    for (int f : topology.vertexFaces(v))
      if (std::isnan(hit)) hit = copy(f);
    for (int f : topology.vertexFaces(v))
      if (std::isnan(copy(f))) copy(f) = hit;
  }
}

}  // namespace

std::size_t cutFaceByTriangle(DisplacementField& ddf, int face, const Vec3& q1, const Vec3& q2,
                              const Vec3& q3, const DepthBufferParams& params) {
  KernelCounts counts;
  processCandidate(ddf.heights(face).data(), ddf.raster(), cornersOf(ddf, face), {q1, q2, q3},
                   KernelMode::Cut, params, counts);
  return counts.lowered;
}

CutStats cutByTriangles(DisplacementField& ddf, const CrustHash& hash,
                        std::span<const Vec3> corners, const DepthBufferParams& params) {
  const PairGroups groups = localize(ddf, hash, corners, {});
  tbb::combinable<KernelCounts> totals;
  forEachGroup(groups, params.parallel, [&](std::size_t gi) {
    const int face = groups.pairs[groups.groupStart[gi]].first;
    const detail::FaceCorners c = cornersOf(ddf, face);
    float* heights = ddf.heights(face).data();
    KernelCounts& counts = totals.local();
    for (std::size_t p = groups.groupStart[gi]; p < groups.groupStart[gi + 1]; ++p) {
      const std::size_t t = static_cast<std::size_t>(groups.pairs[p].second);
      processCandidate(heights, ddf.raster(), c,
                       {corners[3 * t], corners[3 * t + 1], corners[3 * t + 2]}, KernelMode::Cut,
                       params, counts);
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
  // Moller-Trumbore on the full line g + h v, entry side only, in double. Like localization,
  // only tool triangles that reach into the crust slab take part.
  if (!mayMeetCrust(cornersOf(ddf, face), {q1, q2, q3})) return 0;
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
  const PairGroups groups = localize(ddf, hash, corners, params.progress);
  std::vector<float> result(ddf.allHeights().size(), std::numeric_limits<float>::quiet_NaN());
  const std::size_t per = ddf.pointsPerFace();
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
          processCandidate(result.data() + face * per, ddf.raster(), c,
                           {corners[3 * t], corners[3 * t + 1], corners[3 * t + 2]},
                           KernelMode::Fill, params.kernel, unused);
        }
      }
    });
  }
  adoptSharedHits(ddf, result);
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
