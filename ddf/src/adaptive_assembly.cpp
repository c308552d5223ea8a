// SPDX-License-Identifier: MIT
// ddfcam: mesh assembly pieces shared by the full and the incremental adaptive triangulation.
#include "adaptive_assembly.h"

#include <ddfcam/error.h>

#include <algorithm>
#include <string>
#include <utility>

namespace ddfcam::ddf::detail {

std::uint64_t borderKey(const DisplacementField& ddf, std::int64_t scale, int face,
                        const FaceVertex& v) {
  const std::int64_t n = ddf.raster().steps(), NS = n * scale;
  const int side = borderSide(v.I, v.K, NS);
  if (side >= 0) {
    return (static_cast<std::uint64_t>(ddf.topology().faceEdge(face, side)) << 32) |
           static_cast<std::uint64_t>(canonicalT(ddf, face, side, v.I, v.K, NS));
  }
  if (v.I % scale != 0 || v.K % scale != 0) return 0;  // inner point
  const int i = static_cast<int>(v.I / scale), k = static_cast<int>(v.K / scale);
  if (i != n && k != n && i + k != 0) return 0;
  return kVertexKey | ddf.topology().id(face, i, k);
}

void leafTriangles(FaceResult& r) {
  r.triangles.clear();
  for (const auto& leaf : r.leaves)
    r.triangles.push_back({r.vertexIndex[leaf.corner[0]], r.vertexIndex[leaf.corner[1]],
                           r.vertexIndex[leaf.corner[2]]});
  for (const auto& t : r.finals)
    r.triangles.push_back({r.vertexIndex[t[0]], r.vertexIndex[t[1]], r.vertexIndex[t[2]]});
}

namespace {

// The scaled position (I, K) on face f of the point at canonical position t of support edge
// `edge` (the inverse of canonicalT on the side of f that is that edge).
std::array<std::int64_t, 2> edgePointOnFace(const DisplacementField& ddf, int f,
                                            std::uint32_t edge, std::int64_t t,
                                            std::int64_t NS) {
  const auto& fv = ddf.faceVertices(f);
  for (int side = 0; side < 3; ++side) {
    if (static_cast<std::uint32_t>(ddf.topology().faceEdge(f, side)) != edge) continue;
    const std::int64_t tl = fv[side] < fv[(side + 1) % 3] ? t : NS - t;
    if (side == 0) return {NS - tl, 0};
    if (side == 1) return {0, tl};
    return {tl, NS - tl};
  }
  throw InvalidInput("cornerParams: support edge " + std::to_string(edge) +
                     " is not a side of face " + std::to_string(f));
}

}  // namespace

void cornerParams(const DisplacementField& ddf, std::int64_t scale, int f, const FaceResult& r,
                  const std::vector<std::uint64_t>& slotKey,
                  std::vector<std::array<std::array<float, 2>, 3>>& out) {
  const std::int64_t NS = ddf.raster().steps() * scale;
  std::vector<std::pair<int, int>> local;  // (mesh vertex, face vertex), sorted
  local.reserve(r.vertexIndex.size());
  for (std::size_t v = 0; v < r.vertexIndex.size(); ++v)
    local.emplace_back(r.vertexIndex[v], static_cast<int>(v));
  std::sort(local.begin(), local.end());
  const auto unit = static_cast<float>(scale);
  auto param = [&](int vertex) -> std::array<float, 2> {
    if (vertex < 0) {
      const auto& sum = r.centroidSums[static_cast<std::size_t>(-vertex - 1)];
      return {static_cast<float>(sum[0]) / (3.0f * unit),
              static_cast<float>(sum[1]) / (3.0f * unit)};
    }
    const auto it = std::lower_bound(local.begin(), local.end(), std::pair{vertex, -1});
    if (it != local.end() && it->first == vertex) {
      const FaceVertex& fv = r.vertices[static_cast<std::size_t>(it->second)];
      return {static_cast<float>(fv.I) / unit, static_cast<float>(fv.K) / unit};
    }
    const std::uint64_t key = slotKey[static_cast<std::size_t>(vertex)];
    const auto p = edgePointOnFace(ddf, f, static_cast<std::uint32_t>(key >> 32),
                                   static_cast<std::int64_t>(key & 0xffffffffu), NS);
    return {static_cast<float>(p[0]) / unit, static_cast<float>(p[1]) / unit};
  };
  out.clear();
  out.reserve(r.triangles.size());
  for (const auto& t : r.triangles) out.push_back({param(t[0]), param(t[1]), param(t[2])});
}

}  // namespace ddfcam::ddf::detail
