// SPDX-License-Identifier: MIT
// ddfcam: meshes and surfaces scaled from their file unit to millimetres.
#include <ddfcam/io/mesh/mesh_units.h>

#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/surface_file.h>

namespace ddfcam::io {

ddf::TriangleMesh scaledToMm(ddf::TriangleMesh mesh, ddfcam::LengthUnit unit) {
  const double factor = millimetresPer(unit);
  if (factor != 1.0)
    for (Eigen::Vector3d& v : mesh.vertices) v *= factor;
  return mesh;
}

double boundingBoxDiagonal(const ddf::TriangleMesh& mesh) {
  const auto [lo, hi] = mesh.bounds();
  return (hi - lo).norm();
}

ddf::TriangleMesh readMeshInUnit(const std::filesystem::path& path, ddfcam::LengthUnit unit) {
  return scaledToMm(readMesh(path), unit);
}

planning::LoadedSurface readSurfaceFileInUnit(const std::filesystem::path& path,
                                              ddfcam::LengthUnit unit) {
  planning::LoadedSurface surface = readSurfaceFile(path);
  surface.mesh = scaledToMm(std::move(surface.mesh), unit);
  return surface;
}

}  // namespace ddfcam::io
