// SPDX-License-Identifier: MIT
// ddfcam: the non-adaptive surface mesh of a DDF and its support mesh.
#include <ddfcam/ddf/raster_mesh.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>

#include "canonical_points.h"

namespace ddfcam::ddf {
namespace {

constexpr int kNoVertex = -1;

// Positions of every raster point by PointId, each written once by its owner face.
void ownerPositions(const DisplacementField& ddf, const detail::PointOwners& owners,
                    std::vector<Vec3>& positions, std::vector<std::uint8_t>& used) {
  const RasterTopology& topo = ddf.topology();
  const int n = ddf.raster().steps();
  positions.resize(topo.pointCount());
  used.assign(topo.pointCount(), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      for (int k = 0; k <= n; ++k) {
        for (int i = 0; i + k <= n; ++i) {
          const PointId id = topo.id(f, i, k);
          if (owners.owner(id, f) != f) continue;
          positions[id] = ddf.surfacePoint(f, i, k);
          used[id] = 1;
        }
      }
    }
  });
}

// Lattice triangles of one face: n(n+1)/2 upward cells (a+1, b, c), (a, b+1, c), (a, b, c+1)
// and n(n-1)/2 downward ones; both keep the orientation of (p1, p2, p3).
void faceTriangles(const Raster& raster, const std::vector<int>& local, std::array<int, 3>* out) {
  const int n = raster.steps();
  auto at = [&](int i, int k) { return local[raster.index(i, k)]; };
  for (int c = 0; c < n; ++c) {
    for (int a = 0; a + c < n; ++a) *out++ = {at(a + 1, c), at(a, c), at(a, c + 1)};
  }
  for (int c = 0; c + 1 < n; ++c) {
    for (int a = 0; a + c + 1 < n; ++a) *out++ = {at(a, c + 1), at(a + 1, c + 1), at(a + 1, c)};
  }
}

}  // namespace

RasterMesh extractRasterMesh(const DisplacementField& ddf) {
  const RasterTopology& topo = ddf.topology();
  const detail::PointOwners owners(ddf);
  std::vector<Vec3> positions;
  std::vector<std::uint8_t> used;
  ownerPositions(ddf, owners, positions, used);

  RasterMesh out;
  std::vector<int> vertexOf(topo.pointCount(), kNoVertex);
  out.mesh.vertices.reserve(positions.size());
  out.vertexPoint.reserve(positions.size());
  for (std::size_t id = 0; id < positions.size(); ++id) {
    if (!used[id]) continue;
    vertexOf[id] = static_cast<int>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(positions[id]);
    out.vertexPoint.push_back(static_cast<PointId>(id));
  }

  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  const std::size_t perFace = static_cast<std::size_t>(n) * n;
  out.mesh.triangles.resize(perFace * ddf.faceCount());
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    std::vector<int> local(raster.pointCount());
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t l = 0;
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i + k <= n; ++i) local[l++] = vertexOf[topo.id(f, i, k)];
      faceTriangles(raster, local, out.mesh.triangles.data() + perFace * f);
    }
  });
  return out;
}

TriangleMesh extractSupportMesh(const DisplacementField& ddf) {
  TriangleMesh out;
  out.vertices.reserve(ddf.vertexCount());
  for (int v = 0; v < ddf.vertexCount(); ++v) out.vertices.push_back(ddf.position(v));
  out.triangles.reserve(ddf.faceCount());
  for (int f = 0; f < ddf.faceCount(); ++f) out.triangles.push_back(ddf.faceVertices(f));
  return out;
}

}  // namespace ddfcam::ddf
