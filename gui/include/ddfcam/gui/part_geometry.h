// SPDX-License-Identifier: MIT
// ddfcam gui: chooses which core surface extraction to display and converts the results to VTK.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/gui/part_scene.h>

#include <cstddef>
#include <vector>

namespace ddfcam::gui {

/// @brief How a DDF's surface is triangulated for display.
struct DisplayParams {
  /// Use the raster mesh (exact, F (m-1)^2 triangles) when it has at most this many triangles,
  /// otherwise the adaptive triangulation. Default 100,000: a software renderer (Mesa
  /// llvmpipe) needs ~0.5 s per frame for the 393,216 raster triangles of the demo part, while
  /// its adaptive triangulation at the default eps has a few thousand.
  std::size_t rasterTriangleBudget = 100'000;
  /// Error bound of the adaptive triangulation as a fraction of the support's bounding-box
  /// diagonal (dimensionless). Default 2e-4 (0.02 mm on a 100 mm part).
  double adaptiveEpsFraction = 2e-4;
  /// Triangle budget of the adaptive triangulation: eps is multiplied by 4 until the mesh
  /// fits (at most 6 times). Default 1,500,000.
  std::size_t adaptiveTriangleBudget = 1'500'000;
  /// The stubble stride is chosen so that at most about this many stubbles are drawn: denser
  /// stubbles, a full crust long each, merge into a carpet. Default 3,000.
  std::size_t stubbleBudget = 3'000;
};

/// @brief Scene geometry of one DDF and how it was made.
struct PartGeometry {
  /// Polydata of every layer. The surface carries point data "vertex" (mesh vertex of each
  /// point) and cell data "face" (support face of each triangle, see adapters/poly_data.h).
  SceneGeometry scene;
  std::size_t surfaceTriangles = 0;  ///< triangles of the surface layer
  /// #T support face of each surface triangle (cell c of scene.surface lies in face
  /// surfaceTriangleFace[c]).
  std::vector<int> surfaceTriangleFace;
  /// Where each vertex of the surface mesh lies on the DDF (#V = the surface mesh's vertex
  /// count, indexed like the "vertex" point array): turns per-raster-point fields into
  /// per-vertex values with ddf::valuesAtSamples() for PartScene::setSurfaceField().
  ddf::SurfaceSamples surfaceSamples;
  bool adaptiveSurface = false;  ///< true: ddf::triangulateAdaptive, false: raster mesh
  double adaptiveEpsMm = 0.0;    ///< eps of the adaptive triangulation, mm (0 for raster)
  int stubbleStride = 1;         ///< lattice stride of the stubble layer
};

/// @brief Surface (raster mesh or adaptive triangulation, see DisplayParams), support
/// wireframe and full-crust stubbles of @p ddf, as VTK polydata. Calls the ddf library for
/// every piece of geometry; only the choice of method and budgets is made here.
/// @throws ddfcam::Error from the core (e.g. Cancelled once progress is wired in).
PartGeometry buildPartGeometry(const ddf::DisplacementField& ddf, const DisplayParams& params);

}  // namespace ddfcam::gui
