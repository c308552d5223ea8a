// SPDX-License-Identifier: MIT
// ddfcam: adaptive triangulation of a DDF-represented surface: phases and mesh assembly.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/error.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "adaptive_assembly.h"
#include "adaptive_face.h"
#include "canonical_points.h"

namespace ddfcam::ddf {
namespace {

using detail::FaceResult;

// Runs fn(face) over all faces in parallel blocks; progress is reported between blocks from
// the calling thread, mapped to [lo, hi].
template <class Fn>
void forFaceBlocks(const DisplacementField& ddf, const ProgressCallback& progress, double lo,
                   double hi, Fn&& fn) {
  const int faces = ddf.faceCount();
  // About 2^18 raster points per block keeps progress calls frequent at every m.
  const std::size_t points = std::max<std::size_t>(ddf.pointsPerFace(), 1);
  const int block = std::max<int>(1, static_cast<int>((std::size_t{1} << 18) / points));
  reportProgress(progress, lo);
  for (int begin = 0; begin < faces; begin += block) {
    const int end = std::min(faces, begin + block);
    tbb::parallel_for(tbb::blocked_range<int>(begin, end), [&](const auto& range) {
      for (int f = range.begin(); f != range.end(); ++f) fn(f);
    });
    reportProgress(progress, lo + (hi - lo) * end / faces);
  }
}

// A mesh vertex inside a support edge: the edge, its canonical scaled position, its index.
struct SupportVertex {
  std::uint32_t edge;
  std::int64_t t;
  int vertex;
  bool operator<(const SupportVertex& o) const { return edge != o.edge ? edge < o.edge : t < o.t; }
};

// A face vertex on the border of its face, keyed by its place on the support: support vertex
// v -> (~0 << 32 | v), point t inside support edge e -> (e << 32 | t).
struct BorderSlot {
  std::uint64_t key;
  int face;
  int slot;
  bool operator<(const BorderSlot& o) const {
    return key != o.key ? key < o.key : face != o.face ? face < o.face : slot < o.slot;
  }
};

// Mesh vertices for all face vertices: points on the support's vertices and edges once (keyed
// by their place; both faces computed them bitwise identically), inner points per face. Returns
// the vertices inside every support edge in edge order.
std::vector<SupportVertex> numberVertices(const DisplacementField& ddf, std::int64_t S,
                                          std::vector<FaceResult>& results,
                                          std::vector<Vec3>& vertices) {
  const int faces = ddf.faceCount();
  std::vector<std::size_t> borderOffset(faces + 1, 0), innerOffset(faces + 1, 0);
  tbb::parallel_for(0, faces, [&](int f) {
    FaceResult& r = results[f];
    r.vertexIndex.assign(r.vertices.size(), -1);
    std::size_t border = 0;
    for (const auto& v : r.vertices) border += detail::borderKey(ddf, S, f, v) != 0 ? 1 : 0;
    borderOffset[f + 1] = border;
    innerOffset[f + 1] = r.vertices.size() - border;
  });
  for (int f = 0; f < faces; ++f) {
    borderOffset[f + 1] += borderOffset[f];
    innerOffset[f + 1] += innerOffset[f];
  }
  std::vector<BorderSlot> border(borderOffset[faces]);
  tbb::parallel_for(0, faces, [&](int f) {
    std::size_t at = borderOffset[f];
    for (std::size_t v = 0; v < results[f].vertices.size(); ++v) {
      const std::uint64_t key = detail::borderKey(ddf, S, f, results[f].vertices[v]);
      if (key != 0) border[at++] = {key, f, static_cast<int>(v)};
    }
  });
  tbb::parallel_sort(border.begin(), border.end());
  std::vector<SupportVertex> onEdges;
  for (std::size_t b = 0; b < border.size(); ++b) {
    assert((b == 0 || border[b].key != border[b - 1].key ||
            results[border[b].face].vertices[border[b].slot].position == vertices.back()) &&
           "both faces of a support edge compute its points bitwise identically");
    if (b == 0 || border[b].key != border[b - 1].key) {
      const auto& first = results[border[b].face].vertices[border[b].slot];
      vertices.push_back(first.position);
      if (!detail::isSupportVertexKey(border[b].key)) {
        onEdges.push_back({static_cast<std::uint32_t>(border[b].key >> 32),
                           static_cast<std::int64_t>(border[b].key & 0xffffffffu),
                           static_cast<int>(vertices.size()) - 1});
      }
    }
    results[border[b].face].vertexIndex[border[b].slot] = static_cast<int>(vertices.size()) - 1;
  }
  const std::size_t base = vertices.size();
  vertices.resize(base + innerOffset[faces]);
  tbb::parallel_for(0, faces, [&](int f) {
    FaceResult& r = results[f];
    std::size_t at = base + innerOffset[f];
    for (std::size_t v = 0; v < r.vertices.size(); ++v) {
      if (r.vertexIndex[v] >= 0) continue;
      vertices[at] = r.vertices[v].position;
      r.vertexIndex[v] = static_cast<int>(at++);
    }
  });
  return onEdges;
}

// The mesh vertices strictly inside support edge @p edge between positions ta and tb, in order
// from ta to tb, from the list of all vertices inside support edges in edge order.
struct SortedEdgeChain {
  const std::vector<SupportVertex>* onEdges;
  void operator()(std::uint32_t edge, std::int64_t ta, std::int64_t tb,
                  std::vector<int>& out) const {
    const auto first = std::upper_bound(onEdges->begin(), onEdges->end(),
                                        SupportVertex{edge, std::min(ta, tb), 0});
    const auto last =
        std::lower_bound(first, onEdges->end(), SupportVertex{edge, std::max(ta, tb), 0});
    const std::size_t begin = out.size();
    for (auto it = first; it != last; ++it) out.push_back(it->vertex);
    if (ta > tb) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
  }
};

void concatenate(std::vector<FaceResult>& results, AdaptiveTriangulation& out) {
  std::size_t triangles = 0;
  for (const auto& r : results) triangles += r.triangles.size();
  out.mesh.triangles.reserve(triangles);
  out.triangleFace.reserve(triangles);
  for (int f = 0; f < static_cast<int>(results.size()); ++f) {
    FaceResult& r = results[f];
    const int base = static_cast<int>(out.mesh.vertices.size());
    out.mesh.vertices.insert(out.mesh.vertices.end(), r.centroids.begin(), r.centroids.end());
    for (auto t : r.triangles) {
      for (int& v : t)
        if (v < 0) v = base - v - 1;
      out.mesh.triangles.push_back(t);
      out.triangleFace.push_back(f);
    }
    out.leafTriangles += r.leaves.size() + r.finals.size();
    out.maxErrorMm = std::max(out.maxErrorMm, r.maxError);
    r = FaceResult{};  // release memory early
  }
}

}  // namespace

void checkFaceEps(const DisplacementField& ddf, std::span<const float> faceEpsMm) {
  if (faceEpsMm.empty()) return;
  if (faceEpsMm.size() != static_cast<std::size_t>(ddf.faceCount()))
    throw InvalidInput("adaptive triangulation: " + std::to_string(faceEpsMm.size()) +
                       " face error bounds for " + std::to_string(ddf.faceCount()) + " faces");
  for (std::size_t f = 0; f < faceEpsMm.size(); ++f)
    if (!(faceEpsMm[f] > 0.0f) || !std::isfinite(faceEpsMm[f]))
      throw InvalidInput("adaptive triangulation: the error bound of face " + std::to_string(f) +
                         " must be positive, got " + std::to_string(faceEpsMm[f]));
}

AdaptiveTriangulation triangulateAdaptiveWithStats(const DisplacementField& ddf,
                                                   const AdaptiveTriangulationParams& params) {
  if (!(params.epsMm > 0.0)) {
    throw InvalidInput("adaptive triangulation: error bound epsMm must be positive, got " +
                       std::to_string(params.epsMm));
  }
  checkFaceEps(ddf, params.faceEpsMm);
  const detail::PointOwners owners(ddf);
  const std::vector<Vec3> boundary = detail::canonicalBoundaryPoints(ddf, owners);
  detail::AdaptiveContext ctx;
  if (!params.faceEpsMm.empty()) ctx.faceEps = &params.faceEpsMm;
  ctx.ddf = &ddf;
  ctx.boundary = &boundary;
  ctx.eps = params.epsMm;
  ctx.collectChains = params.removeTVertices;
  while (ctx.scale < ddf.raster().steps()) ctx.scale *= 2;

  std::vector<FaceResult> results(ddf.faceCount());
  tbb::enumerable_thread_specific<detail::FaceSubdivider> workers(
      [&] { return detail::FaceSubdivider(ctx); });
  forFaceBlocks(ddf, params.progress, 0.0, 0.8, [&](int f) { workers.local().run(f, results[f]); });

  AdaptiveTriangulation out;
  const std::vector<SupportVertex> onEdges =
      numberVertices(ddf, ctx.scale, results, out.mesh.vertices);
  if (params.removeTVertices) {
    const detail::TVertexRemoval removal(ddf, ctx.scale, SortedEdgeChain{&onEdges});
    tbb::enumerable_thread_specific<std::vector<int>> polygons;
    forFaceBlocks(ddf, params.progress, 0.8, 0.95, [&](int f) {
      removal.retriangulate(f, results[f], out.mesh.vertices, polygons.local());
    });
  } else {
    forFaceBlocks(ddf, params.progress, 0.8, 0.95, [&](int f) { detail::leafTriangles(results[f]); });
  }
  concatenate(results, out);
  reportProgress(params.progress, 1.0);
  return out;
}

TriangleMesh triangulateAdaptive(const DisplacementField& ddf,
                                 const AdaptiveTriangulationParams& params) {
  return triangulateAdaptiveWithStats(ddf, params).mesh;
}

std::size_t adaptiveTriangleCount(const DisplacementField& ddf, double epsMm,
                                  bool removeTVertices) {
  AdaptiveTriangulationParams params;
  params.epsMm = epsMm;
  params.removeTVertices = removeTVertices;
  return triangulateAdaptiveWithStats(ddf, params).mesh.triangles.size();
}

}  // namespace ddfcam::ddf
