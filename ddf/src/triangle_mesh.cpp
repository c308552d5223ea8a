// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/triangle_mesh.h>

namespace ddfcam::ddf {

std::array<Eigen::Vector3d, 2> TriangleMesh::bounds() const {
  if (vertices.empty()) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d lo = vertices.front(), hi = vertices.front();
  for (const auto& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return {lo, hi};
}

double TriangleMesh::signedVolume() const {
  double sixV = 0.0;
  for (const auto& t : triangles) sixV += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]]));
  return sixV / 6.0;
}

TriangleMesh TriangleMesh::transformed(const Eigen::Isometry3d& pose) const {
  TriangleMesh out;
  out.triangles = triangles;
  out.vertices.reserve(vertices.size());
  for (const auto& v : vertices) out.vertices.push_back(pose * v);
  return out;
}

}  // namespace ddfcam::ddf
