// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/error.h>

#include <OpenMesh/Core/System/omstream.hh>

#include <string>

namespace ddfcam::ddf {

SupportMesh makeSupportMesh(const std::vector<Vec3>& points,
                            const std::vector<std::array<int, 3>>& triangles) {
  SupportMesh mesh;
  mesh.reserve(points.size(), triangles.size() * 3 / 2 + 3, triangles.size());
  std::vector<SupportMesh::VertexHandle> handles;
  handles.reserve(points.size());
  for (const Vec3& p : points) handles.push_back(mesh.add_vertex(toOpenMesh(p)));
  const auto vertexCount = static_cast<int>(points.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    for (int v : t) {
      if (v < 0 || v >= vertexCount) {
        throw InvalidInput("support triangle " + std::to_string(f) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(vertexCount));
      }
    }
    // OpenMesh reports a rejected face on its error stream; ddfcam reports it by exception.
    const bool wasEnabled = omerr().is_enabled();
    omerr().disable();
    const auto fh = mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    if (wasEnabled) omerr().enable();
    if (!fh.is_valid()) {
      throw InvalidInput("support triangle " + std::to_string(f) + " (vertices " +
                         std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                         std::to_string(t[2]) + ") makes the mesh non-manifold or is degenerate");
    }
  }
  return mesh;
}

}  // namespace ddfcam::ddf
