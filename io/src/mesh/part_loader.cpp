// SPDX-License-Identifier: MIT
// ddfcam: loading a part from a .ddf, a mesh or a CAD file, in the file's length unit.
#include <ddfcam/io/mesh/part_loader.h>

#include <ddfcam/error.h>
#include <ddfcam/io/cad/cad_model.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/log.h>

#include "../common/file_access.h"

#include <algorithm>
#include <cstdio>

namespace ddfcam::io {
namespace {

// Reading (and for CAD, tessellating) is a small share of the work next to the conversion.
constexpr double kReadShare = 0.05;

bool isDdfFile(const std::filesystem::path& path) {
  return detail::lowerExtension(path) == ".ddf";
}

/// @p progress mapped from [0, 1] onto [from, to] of the whole load (none stays none).
ProgressCallback scaledProgress(const ProgressCallback& progress, double from, double to) {
  if (!progress) return nullptr;
  return [&progress, from, to](double fraction) { return progress(from + (to - from) * fraction); };
}

ddf::ConversionParams conversionWithProgress(const LoadPartParams& params) {
  ddf::ConversionParams conversion = params.conversion;
  conversion.progress = nullptr;
  if (params.progress) {
    conversion.progress = [&progress = params.progress](double fraction) {
      return progress(kReadShare + (1.0 - kReadShare) * fraction);
    };
  }
  return conversion;
}

void fillBounds(const ddf::TriangleMesh& meshMm, LoadPartReport& report) {
  const auto [lo, hi] = meshMm.bounds();
  report.boundsMm = {lo, hi};
}

ddf::ConversionResult convert(const ddf::TriangleMesh& meshMm, ddf::ConversionParams conversion,
                              LoadPartReport& report) {
  ddf::ConversionResult result = ddf::convertMeshToDdf(meshMm, conversion);
  report.converted = true;
  report.meshVertices = static_cast<int>(meshMm.vertices.size());
  report.meshTriangles = static_cast<int>(meshMm.triangles.size());
  report.conversion = std::move(result.report);
  report.accuracy = result.accuracy;
  report.reduction = result.reduction;
  report.stock = result.stock;
  return result;
}

LoadedPart convertMesh(const std::filesystem::path& path, const LoadPartParams& params,
                       LoadPartReport& report) {
  LoadedPart part;
  ddf::TriangleMesh mesh = readMesh(path);
  reportProgress(params.progress, kReadShare);
  report.unit = params.unit.value_or(ddfcam::LengthUnit::Millimetre);
  report.unitFromFile = false;
  report.fileDiagonal = boundingBoxDiagonal(mesh);
  part.inputMesh = scaledToMm(std::move(mesh), report.unit);
  fillBounds(part.inputMesh, report);
  part.ddf = std::move(convert(part.inputMesh, conversionWithProgress(params), report).ddf);
  return part;
}

/// Per support face its CAD face: the conversion's labels when it kept them, else through the
/// input triangle each face came from.
std::vector<int> cadFacesOfSupport(const ddf::ConversionResult& result,
                                   const std::vector<int>& faceOfTriangle) {
  if (!result.supportLabels.empty()) return result.supportLabels;
  std::vector<int> faces;
  faces.reserve(result.sourceTriangle.size());
  for (const int triangle : result.sourceTriangle)
    faces.push_back(triangle >= 0 && triangle < static_cast<int>(faceOfTriangle.size())
                        ? faceOfTriangle[triangle]
                        : -1);
  return faces;
}

LoadedPart convertCad(const std::filesystem::path& path, const LoadPartParams& params,
                      LoadPartReport& report) {
  CadReadParams read;
  read.unit = params.unit;
  read.progress = scaledProgress(params.progress, 0.0, 0.4 * kReadShare);
  const CadModel model = readCadModel(path, read);
  report.unit = model.unit();
  report.unitFromFile = model.unitFromFile();
  report.boundsMm = model.boundsMm();
  const double diagonalMm = (report.boundsMm[1] - report.boundsMm[0]).norm();
  report.fileDiagonal = diagonalMm / millimetresPer(model.unit());
  // A unit the file states is trusted; a file without one is judged like a mesh.
  report.cadHealing = model.healing();
  report.cadFaceNames = model.faceNames();

  CadTessellationParams tessellation;
  tessellation.chordDeflectionMm = cadChordDeflectionMm(params.conversion, diagonalMm);
  tessellation.progress = scaledProgress(params.progress, 0.4 * kReadShare, kReadShare);
  CadTessellation triangles = tessellateCadModel(model, tessellation);
  reportProgress(params.progress, kReadShare);

  ddf::ConversionParams conversion = conversionWithProgress(params);
  conversion.inputLabels = triangles.faceOfTriangle;
  LoadedPart part;
  ddf::ConversionResult result = convert(triangles.mesh, std::move(conversion), report);
  report.cadFaceOfSupportFace = cadFacesOfSupport(result, triangles.faceOfTriangle);
  part.ddf = std::move(result.ddf);
  part.inputMesh = std::move(triangles.mesh);
  return part;
}

}  // namespace

double cadChordDeflectionMm(const ddf::ConversionParams& conversion, double diagonalMm) {
  constexpr double kShare = 0.1;  // the tessellation's share of the accuracy budget
  double spacingMm = conversion.rasterSpacingMm;
  if (conversion.toleranceMm > 0.0) return std::max(kShare * conversion.toleranceMm, 1e-9);
  if (!(spacingMm > 0.0)) spacingMm = 0.01 * diagonalMm / std::max(conversion.resolution - 1, 1);
  return std::max(kShare * spacingMm, 1e-7 * diagonalMm);
}

LoadedPart loadPartWithInput(const std::filesystem::path& path, const LoadPartParams& params,
                             LoadPartReport* report) {
  LoadPartReport local;
  try {
    if (!isDdfFile(path) && !meshFormatOf(path) && !isCadFile(path))
      throw IoError(path.string() + ": unknown part file extension '" + path.extension().string() +
                    "' (expected .ddf, .stl, .obj, .ply, .off, .step, .stp, .iges or .igs)");
    reportProgress(params.progress, 0.0);
    LoadedPart part;
    if (isDdfFile(path)) {
      DdfMetadata metadata;
      part.ddf = readDdf(path, &metadata);
      local.unit = metadata.sourceUnit;
      local.unitFromFile = metadata.stored;
      local.cadFaceOfSupportFace = std::move(metadata.cadFaceOfSupportFace);
      local.cadFaceNames = std::move(metadata.cadFaceNames);
      if (metadata.designMesh) part.inputMesh = std::move(*metadata.designMesh);
    } else if (isCadFile(path)) {
      part = convertCad(path, params, local);
    } else {
      part = convertMesh(path, params, local);
    }
    reportProgress(params.progress, 1.0);
    if (report) *report = std::move(local);
    return part;
  } catch (const Cancelled&) {
    throw;  // a normal outcome, not a loading error
  } catch (...) {
    std::throw_with_nested(IoError("loading " + path.string()));
  }
}

ddf::DisplacementField loadPart(const std::filesystem::path& path, const LoadPartParams& params,
                                LoadPartReport* report) {
  return std::move(loadPartWithInput(path, params, report).ddf);
}

}  // namespace ddfcam::io
