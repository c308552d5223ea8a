// SPDX-License-Identifier: MIT
// ddfcam: loading a part from a .ddf or a mesh file.
#include <ddfcam/io/part_loader.h>

#include <ddfcam/error.h>
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/mesh_io.h>

#include "file_access.h"

#include <algorithm>
#include <cctype>

namespace ddfcam::io {
namespace {

bool isDdfFile(const std::filesystem::path& path) {
  return detail::lowerExtension(path) == ".ddf";
}

ddf::DisplacementField convertMesh(const std::filesystem::path& path, const LoadPartParams& params,
                                   LoadPartReport& report) {
  // Reading is a small share of the work next to choosing vector lengths.
  constexpr double kReadShare = 0.05;
  const ddf::TriangleMesh mesh = readMesh(path);
  reportProgress(params.progress, kReadShare);
  ddf::ConversionParams conversion = params.conversion;
  conversion.progress = nullptr;
  if (params.progress) {
    conversion.progress = [&progress = params.progress](double fraction) {
      return progress(kReadShare + (1.0 - kReadShare) * fraction);
    };
  }
  ddf::ConversionResult result = ddf::convertMeshToDdf(mesh, conversion);
  report.converted = true;
  report.meshVertices = static_cast<int>(mesh.vertices.size());
  report.meshTriangles = static_cast<int>(mesh.triangles.size());
  report.conversion = std::move(result.report);
  return std::move(result.ddf);
}

}  // namespace

ddf::DisplacementField loadPart(const std::filesystem::path& path, const LoadPartParams& params,
                                LoadPartReport* report) {
  LoadPartReport local;
  try {
    if (!isDdfFile(path) && !meshFormatOf(path))
      throw IoError(path.string() + ": unknown part file extension '" + path.extension().string() +
                    "' (expected .ddf, .stl, .obj, .ply or .off)");
    reportProgress(params.progress, 0.0);
    ddf::DisplacementField field =
        isDdfFile(path) ? readDdf(path) : convertMesh(path, params, local);
    reportProgress(params.progress, 1.0);
    if (report) *report = local;
    return field;
  } catch (const Cancelled&) {
    throw;  // a normal outcome, not a loading error
  } catch (...) {
    std::throw_with_nested(IoError("loading " + path.string()));
  }
}

}  // namespace ddfcam::io
