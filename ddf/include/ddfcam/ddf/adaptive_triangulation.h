// SPDX-License-Identifier: MIT
// ddfcam: adaptive triangulation of DDF-represented surfaces (ch. 7, after Clay et al.).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <span>
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
  /// Error bound per support face, mm (each > 0), instead of epsMm everywhere: e.g. coarser
  /// where the view sees a face small (a view-dependent level of detail). A support edge is
  /// held to the smaller bound of its two faces, so the mesh stays crack-free and without
  /// T-vertices; each face's raster points lie within its own bound. Default empty (epsMm).
  std::vector<float> faceEpsMm;
  /// Progress in [0, 1] and cancellation, called from the calling thread. Default none.
  ProgressCallback progress;
};

/// @brief An adaptive triangulation and its statistics.
struct AdaptiveTriangulation {
  /// Vertices (mm, part frame): DDF points and straight midpoints of the subdivision, points
  /// on support edges and vertices welded across faces (bitwise identical from both sides),
  /// plus one centroid per leaf re-triangulated around it. Triangles are oriented like their
  /// support faces and grouped by face in face order.
  TriangleMesh mesh;
  /// #T support face of each triangle.
  std::vector<int> triangleFace;
  /// Triangles of the subdivision before T-vertex removal.
  std::size_t leafTriangles = 0;
  /// Largest distance measured between an approximating triangle and the DDF surface at an
  /// accepted sample, mm (<= epsMm).
  double maxErrorMm = 0.0;
};

/// @brief Adaptive triangulation of the surface represented by @p ddf (dissertation ch. 7,
/// after Clay et al.). Per support face, the raster triangle is split recursively into four at
/// its edge midpoints until the flat triangle over a sub-triangle approximates the DDF within
/// eps (E_t): at every raster point inside, and along its edges (E_e). A split edge takes the
/// straight midpoint s_ij when E_e holds (and all its sub-edges inherit E_e), else the DDF point
/// q_ij; so a long edge facing several short ones never opens a crack.
///
/// Any m works, with triangles of one shape at all levels: midpoints are exact (on a lattice
/// 2^p times finer than the raster) and the DDF surface between raster points is the raster
/// mesh (fig. 7.1a), so E_e measures an edge at its crossings with the raster lattice (at the
/// raster points when it runs along a lattice line). For m - 1 a power of two every midpoint is
/// a raster point and this is exactly the algorithm of ch. 7; otherwise a sub-triangle smaller
/// than two raster steps that still fails takes raster points as vertices (those on failing
/// edges, then the worst inner one until all are within eps). Above the raster's own error the
/// triangle count does not depend on m (fig. 7.3). Shared points are computed from canonical
/// copies in canonical order, so faces run in parallel and agree bitwise.
///
/// Guarantee: the DDF point q of every raster point lies within epsMm of the mesh (of the
/// triangles of its own face). The count falls as eps grows on generic surfaces, but is not
/// monotone in general (straight midpoints pass their error on to their sub-triangles).
/// @throws InvalidInput if params.epsMm is not positive; Cancelled if params.progress asks.
TriangleMesh triangulateAdaptive(const DisplacementField& ddf,
                                 const AdaptiveTriangulationParams& params = {});

/// @brief As triangulateAdaptive(), with the face of every triangle and statistics.
/// @throws InvalidInput if params.epsMm is not positive; Cancelled if params.progress asks.
AdaptiveTriangulation triangulateAdaptiveWithStats(const DisplacementField& ddf,
                                                   const AdaptiveTriangulationParams& params = {});

/// @brief Checks per-face error bounds: empty, or one finite positive bound per face.
/// @throws InvalidInput naming the first bad one.
void checkFaceEps(const DisplacementField& ddf, std::span<const float> faceEpsMm);

/// @brief Number of triangles triangulateAdaptive() produces at error bound @p epsMm (mm).
/// @throws InvalidInput if epsMm is not positive.
std::size_t adaptiveTriangleCount(const DisplacementField& ddf, double epsMm,
                                  bool removeTVertices = true);

}  // namespace ddfcam::ddf
