// SPDX-License-Identifier: MIT
// ddfcam: mesh assembly pieces shared by the full and the incremental adaptive triangulation.
#include "adaptive_assembly.h"

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

}  // namespace ddfcam::ddf::detail
