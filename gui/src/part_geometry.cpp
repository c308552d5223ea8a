// SPDX-License-Identifier: MIT
// ddfcam gui: buildPartGeometry, the display policy over the core's surface extractions.
#include <ddfcam/gui/part_geometry.h>

#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/stubble_lines.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/adapters/raster_field_surface.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace ddfcam::gui {

namespace {

double supportDiagonalMm(const ddf::TriangleMesh& support) {
  const auto box = support.bounds();
  return (box[1] - box[0]).norm();
}

/// Stride s draws about F (m-1)^2 / (2 s^2) distinct raster points.
int stubbleStride(const ddf::DisplacementField& ddf, std::size_t budget) {
  const double n = ddf.resolution() - 1;
  const double points = 0.5 * ddf.faceCount() * n * n;
  const double s = std::sqrt(points / static_cast<double>(std::max<std::size_t>(budget, 1)));
  return std::max(1, static_cast<int>(std::ceil(s)));
}

void buildRasterSurface(const ddf::DisplacementField& ddf, PartGeometry& out) {
  const ddf::RasterMesh raster = ddf::extractRasterMesh(ddf);
  // extractRasterMesh lays out (m-1)^2 triangles per face in face order.
  const std::size_t perFace = static_cast<std::size_t>(ddf.resolution() - 1) *
                              static_cast<std::size_t>(ddf.resolution() - 1);
  out.surfaceTriangleFace.resize(raster.mesh.triangles.size());
  for (std::size_t t = 0; t < out.surfaceTriangleFace.size(); ++t)
    out.surfaceTriangleFace[t] = static_cast<int>(t / perFace);
  out.surfaceTriangles = raster.mesh.triangles.size();
  out.surfaceSamples = ddf::sampleRasterMesh(ddf, raster);
  out.scene.surface = toSurfacePolyData(raster.mesh, out.surfaceTriangleFace);
}

/// Corner parameters of every triangle in snapshot order (face after face, each face's
/// triangles in order), for fields at raster resolution.
void setCornerParams(const ddf::DisplacementField& ddf,
                     const ddf::IncrementalTriangulation& triangulation, SceneGeometry& scene) {
  auto params = std::make_shared<std::vector<float>>();
  params->reserve(6 * triangulation.triangleCount());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (const ddf::TriangleParams& corners : triangulation.faceTriangleParams(f))
      for (const auto& ik : corners) params->insert(params->end(), ik.begin(), ik.end());
  scene.surfaceCornerParams = std::move(params);
  scene.rasterFaces = ddf.faceCount();
  scene.rasterSteps = ddf.resolution() - 1;
}

void buildSurface(const ddf::DisplacementField& ddf, const DisplayParams& params, double diagonalMm,
                  PartGeometry& out) {
  const double n = ddf.resolution() - 1;
  const double rasterTriangles = static_cast<double>(ddf.faceCount()) * n * n;
  if (rasterTriangles <= static_cast<double>(params.rasterTriangleBudget))
    return buildRasterSurface(ddf, out);
  double epsMm = std::max(params.adaptiveEpsFraction * diagonalMm, 1e-6);
  ddf::IncrementalTriangulation triangulation(ddf, epsMm);
  // Coarsen until the budget holds; a few rounds suffice since the count falls ~4x per round.
  for (int round = 0;
       round < 6 && triangulation.triangleCount() > params.adaptiveTriangleBudget; ++round) {
    epsMm *= 4.0;
    triangulation.setFaceEps(std::vector<float>(ddf.faceCount(), static_cast<float>(epsMm)));
  }
  ddf::AdaptiveTriangulation result = triangulation.snapshot();
  out.adaptiveSurface = true;
  out.adaptiveEpsMm = epsMm;
  out.surfaceTriangles = result.mesh.triangles.size();
  out.surfaceSamples = ddf::sampleMeshVertices(ddf, result.mesh, result.triangleFace);
  out.scene.surface = toSurfacePolyData(result.mesh, result.triangleFace);
  out.surfaceTriangleFace = std::move(result.triangleFace);
  if (RasterFieldSurface::available(ddf.faceCount(), ddf.resolution() - 1))
    setCornerParams(ddf, triangulation, out.scene);
}

}  // namespace

PartGeometry buildPartGeometry(const ddf::DisplacementField& ddf, const DisplayParams& params) {
  PartGeometry out;
  const ddf::TriangleMesh support = ddf::extractSupportMesh(ddf);
  buildSurface(ddf, params, supportDiagonalMm(support), out);
  out.scene.support = toWireframePolyData(support);

  ddf::StubbleLinesParams stubbles;
  out.stubbleStride = stubbleStride(ddf, params.stubbleBudget);
  stubbles.stride = out.stubbleStride;
  // The whole crust shows where a part can be represented; base-to-surface segments are
  // only a fraction of a vector long and vanish at workbench zoom levels.
  stubbles.range = ddf::StubbleRange::FullCrust;
  const ddf::StubbleLines lines = ddf::stubbleLines(ddf, stubbles);
  out.scene.stubbles = toSegmentPolyData(lines.from, lines.to);
  return out;
}

}  // namespace ddfcam::gui
