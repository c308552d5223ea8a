// SPDX-License-Identifier: MIT
// ddfcam gui adapters: crust offset surfaces.
#include <ddfcam/gui/adapters/crust_surface.h>

#include <ddfcam/gui/adapters/poly_data.h>

#include <numeric>
#include <vector>

#include <vtkPolyData.h>

namespace ddfcam::gui {

ddf::TriangleMesh crustOffsetMesh(const ddf::DisplacementField& ddf, double h) {
  ddf::TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(ddf.vertexCount()));
  for (int v = 0; v < ddf.vertexCount(); ++v)
    mesh.vertices.push_back(ddf.position(v) + h * ddf.vector(v));
  mesh.triangles.reserve(static_cast<std::size_t>(ddf.faceCount()));
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& t = ddf.faceVertices(f);
    mesh.triangles.push_back({t[0], t[1], t[2]});
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> toCrustPolyData(const ddf::DisplacementField& ddf, double h) {
  std::vector<int> faces(static_cast<std::size_t>(ddf.faceCount()));
  std::iota(faces.begin(), faces.end(), 0);
  return toSurfacePolyData(crustOffsetMesh(ddf, h), faces);
}

}  // namespace ddfcam::gui
