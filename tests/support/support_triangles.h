// SPDX-License-Identifier: MIT
// Test support: a support mesh (OpenMesh) as a plain triangle mesh, optionally scaled (e.g. a
// shared part in metres read as mm).
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <array>

namespace ddfcam::test {

/// @brief The vertices (times @p scale) and faces of @p mesh, in OpenMesh's order.
inline ddf::TriangleMesh supportTriangles(const ddf::SupportMesh& mesh, double scale = 1.0) {
  ddf::TriangleMesh out;
  for (const auto vh : mesh.vertices())
    out.vertices.push_back(scale * ddf::toEigen(mesh.point(vh)));
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t;
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) t[k++] = vh.idx();
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace ddfcam::test
