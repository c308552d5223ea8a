// SPDX-License-Identifier: MIT
// ddfcam gui: buildPartGeometry, the display policy over the core's surface extractions.
#include <ddfcam/gui/part_geometry.h>

#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/stubble_lines.h>
#include <ddfcam/gui/adapters/poly_data.h>

#include <algorithm>
#include <cmath>

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

void buildSurface(const ddf::DisplacementField& ddf, const DisplayParams& params, double diagonalMm,
                  PartGeometry& out) {
  const double n = ddf.resolution() - 1;
  const double rasterTriangles = static_cast<double>(ddf.faceCount()) * n * n;
  if (rasterTriangles <= static_cast<double>(params.rasterTriangleBudget)) {
    const ddf::RasterMesh raster = ddf::extractRasterMesh(ddf);
    out.surfaceTriangles = raster.mesh.triangles.size();
    out.scene.surface = toSurfacePolyData(raster.mesh);
    return;
  }
  ddf::AdaptiveTriangulationParams adaptive;
  adaptive.epsMm = std::max(params.adaptiveEpsFraction * diagonalMm, 1e-6);
  ddf::TriangleMesh mesh = ddf::triangulateAdaptive(ddf, adaptive);
  // Coarsen until the budget holds; a few rounds suffice since the count falls ~4x per round.
  for (int round = 0; round < 6 && mesh.triangles.size() > params.adaptiveTriangleBudget; ++round) {
    adaptive.epsMm *= 4.0;
    mesh = ddf::triangulateAdaptive(ddf, adaptive);
  }
  out.adaptiveSurface = true;
  out.adaptiveEpsMm = adaptive.epsMm;
  out.surfaceTriangles = mesh.triangles.size();
  out.scene.surface = toSurfacePolyData(mesh);
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
