// SPDX-License-Identifier: MIT
// ddfcam: loading a mould or formed surface from any supported mesh file (STL/OBJ/PLY/OFF/VTK XML).
#include <ddfcam/io/mesh/surface_file.h>

#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/vtk_xml_mesh.h>

#include "../common/file_access.h"

#include <algorithm>

namespace ddfcam::io {

const std::vector<std::string>& surfaceFileExtensions() {
  static const std::vector<std::string> kExtensions = {".stl", ".obj", ".ply",
                                                       ".off", ".vtp", ".vtu"};
  return kExtensions;
}

std::string surfaceFileDialogFilter() {
  std::string filter = "Surfaces (";
  for (const auto& ext : surfaceFileExtensions())
    filter += (filter.back() == '(' ? "*" : " *") + ext;
  return filter + ")";
}

bool isSurfaceFile(const std::filesystem::path& path) {
  const auto& exts = surfaceFileExtensions();
  return std::find(exts.begin(), exts.end(), detail::lowerExtension(path)) != exts.end();
}

planning::LoadedSurface readSurfaceFile(const std::filesystem::path& path) {
  const std::string ext = detail::lowerExtension(path);
  planning::LoadedSurface surface;
  surface.name = path.filename().string();
  surface.sourcePath = path.string();
  if (ext == ".vtp" || ext == ".vtu") {
    VtkXmlMesh read = readVtkXmlMesh(path);
    surface.mesh = std::move(read.mesh);
    surface.fields = std::move(read.fields);
  } else if (isSurfaceFile(path)) {
    surface.mesh = readMesh(path);
  } else {
    throw IoError(path.string() + ": unknown surface file extension '" + path.extension().string() +
                  "' (expected .stl, .obj, .ply, .off, .vtp or .vtu)");
  }
  return surface;
}

}  // namespace ddfcam::io
