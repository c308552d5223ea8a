// SPDX-License-Identifier: MIT
// ddfcam: canonical copies of shared raster points.
#include "canonical_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace ddfcam::ddf::detail {

PointOwners::PointOwners(const DisplacementField& ddf) : topology_(&ddf.topology()) {
  const int n = ddf.raster().steps();
  vertexCount_ = static_cast<PointId>(ddf.vertexCount());
  perEdge_ = static_cast<PointId>(std::max(n - 1, 1));
  boundaryCount_ = static_cast<PointId>(ddf.vertexCount() +
                                        ddf.support().n_edges() * static_cast<std::size_t>(n - 1));
  vertexOwner_.resize(ddf.vertexCount(), -1);
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const auto& faces = topology_->vertexFaces(v);
    if (!faces.empty()) vertexOwner_[v] = *std::min_element(faces.begin(), faces.end());
  }
}

std::vector<Vec3> canonicalBoundaryPoints(const DisplacementField& ddf, const PointOwners& owners) {
  std::vector<Vec3> out(owners.boundaryIdCount());
  for (int v = 0; v < ddf.vertexCount(); ++v) out[v] = ddf.position(v);
  const RasterTopology& topo = ddf.topology();
  const int n = ddf.raster().steps();
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      // Only the three border rows hold shared points; each owner writes its own points.
      auto visit = [&](int i, int k) {
        const PointId id = topo.id(f, i, k);
        if (owners.owner(id, f) == f) out[id] = ddf.surfacePoint(f, i, k);
      };
      for (int i = 0; i <= n; ++i) visit(i, 0);
      for (int k = 1; k <= n; ++k) visit(0, k);
      for (int k = 1; k < n; ++k) visit(n - k, k);
    }
  });
  return out;
}

void faceSurfacePoints(const DisplacementField& ddf, const std::vector<Vec3>& boundary, int f,
                       std::vector<Vec3>& out) {
  const Raster& raster = ddf.raster();
  const int n = raster.steps();
  const RasterTopology& topo = ddf.topology();
  const auto& fv = ddf.faceVertices(f);
  const Vec3 p0 = ddf.position(fv[0]), p1 = ddf.position(fv[1]), p2 = ddf.position(fv[2]);
  const Vec3 v0 = ddf.vector(fv[0]), v1 = ddf.vector(fv[1]), v2 = ddf.vector(fv[2]);
  const auto heights = ddf.heights(f);
  const double inv = 1.0 / n;
  out.resize(raster.pointCount());
  std::size_t local = 0;
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i + k <= n; ++i, ++local) {
      if (i == 0 || k == 0 || i + k == n) {
        out[local] = boundary[topo.id(f, i, k)];
        continue;
      }
      // The arithmetic of DisplacementField::surfacePoint, inlined for the hot loop.
      const double b0 = i * inv, b1 = (n - i - k) * inv, b2 = k * inv;
      const Vec3 g = b0 * p0 + b1 * p1 + b2 * p2;
      const Vec3 v = b0 * v0 + b1 * v1 + b2 * v2;
      out[local] = g + static_cast<double>(heights[local]) * v;
    }
  }
}

}  // namespace ddfcam::ddf::detail
