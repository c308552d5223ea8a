// SPDX-License-Identifier: MIT
// ddfcam: adaptive triangulation of a DDF-represented surface (dissertation ch. 7, after Clay et
// al.).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of triangulateAdaptive().
struct AdaptiveTriangulationParams {
  /// Error bound eps, mm: every raster point's surface point q lies within eps of the flat
  /// triangle covering it in parameter space (hence within eps of the mesh). Default 0.01.
  double epsMm = 0.01;
  /// Re-triangulate the leaves so that the mesh has no T-vertices: then every mesh edge has
  /// exactly two triangles on a closed DDF (one on a support boundary). Without it the mesh is
  /// crack-free but a long edge may face several short ones (fig. 7.1b). Default true.
  bool removeTVertices = true;
  /// Progress in [0, 1] and cancellation, called from the calling thread. Default none.
  ProgressCallback progress;
};

/// @brief An adaptive triangulation and its statistics.
struct AdaptiveTriangulation {
  /// Vertices: raster points welded by PointId (shared points bitwise identical across faces)
  /// plus one centroid per re-triangulated leaf, mm, part frame; triangles oriented like their
  /// support faces, grouped by face in face order.
  TriangleMesh mesh;
  /// #T support face of each triangle.
  std::vector<int> triangleFace;
  /// Triangles accepted by the subdivision before T-vertex removal.
  std::size_t leafTriangles = 0;
  /// Largest distance measured at an accepted raster point between q and its flat
  /// approximation, mm (<= epsMm).
  double maxErrorMm = 0.0;
};

/// @brief Adaptive triangulation of the surface represented by @p ddf (dissertation ch. 7):
/// per support face, recursive 4-split of the raster triangle until the flat triangle over a
/// sub-triangle approximates q at every raster point inside within eps (E_t); an edge split
/// takes the straight midpoint when the edge approximates within eps (E_e), else the DDF point.
/// Works for any m: midpoints are rounded to raster points along the edge's lattice line
/// (canonically on support edges, so both faces of an edge split alike); edges without an
/// inner raster point are not split and a triangle without splittable edges is fanned around
/// an inner raster point. Faces are processed in parallel.
/// @throws InvalidInput if params.epsMm is not positive; Cancelled if params.progress asks.
TriangleMesh triangulateAdaptive(const DisplacementField& ddf,
                                 const AdaptiveTriangulationParams& params = {});

/// @brief As triangulateAdaptive(), with the face of every triangle and statistics.
/// @throws InvalidInput if params.epsMm is not positive; Cancelled if params.progress asks.
AdaptiveTriangulation triangulateAdaptiveWithStats(const DisplacementField& ddf,
                                                   const AdaptiveTriangulationParams& params = {});

/// @brief Number of triangles triangulateAdaptive() produces at error bound @p epsMm (mm).
/// @throws InvalidInput if epsMm is not positive.
std::size_t adaptiveTriangleCount(const DisplacementField& ddf, double epsMm,
                                  bool removeTVertices = true);

}  // namespace ddfcam::ddf
