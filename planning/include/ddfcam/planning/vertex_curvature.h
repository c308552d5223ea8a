// SPDX-License-Identifier: MIT
// ddfcam: principal curvature of a DDF whose faces are flat (a converted triangle mesh), from
// quadric fits at the support vertices.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/curvature.h>
#include <ddfcam/progress.h>

namespace ddfcam::planning {

/// @brief Options of computeVertexCurvature().
struct VertexCurvatureParams {
  /// Neighbourhood of a vertex fit: the vertices within this many rings of support edges
  /// (default 2, as the libigl baseline in the oracles note).
  int rings = 2;
  /// Gaussian weight exp(-(d / sigma)^2) of a neighbour at distance d, with sigma this factor
  /// times the vertex's mean distance to its first ring; 0 weights all neighbours equally
  /// (default 1: the first ring dominates, the second keeps irregular fans well posed; on the
  /// torus grid of the oracles note this is 2.7x more accurate than the unweighted fit).
  double weightRadius = 1.0;
  /// Umbilic flag rule, as CurvatureParams::umbilicTolerance (default 0.05).
  double umbilicTolerance = 0.05;
  /// As CurvatureParams::flatCurvaturePerMm, 1/mm (default 1e-6).
  double flatCurvaturePerMm = 1e-6;
  /// Process faces in parallel with TBB (default true).
  bool parallel = true;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief True when the represented surface of every face is flat: every raster point lies
/// within @p relativeTolerance x the face's longest edge of the plane through the face's three
/// corner points. This is what a DDF converted from a triangle mesh looks like (its support is
/// the mesh, its heights ~0): its curvature sits on the seams, and the raster differences of
/// computeCurvature() see only creases.
bool hasFlatFaces(const ddf::DisplacementField& ddf, double relativeTolerance = 1e-5);

/// @brief Principal curvatures and directions at every raster point of @p ddf (CurvatureField
/// layout and tool-side sign convention), estimated from the support vertices: at every
/// vertex a quadric z = a x^2 + b x y + c y^2 + d x + e y is fitted by weighted least squares to
/// the represented points of the vertices within params.rings rings, in the frame of the
/// area-weighted normal of the incident represented triangles; its shape operator (with the
/// slope d, e) gives a curvature tensor S = k1 t1 t1^T + k2 t2 t2^T. Inside a face the three
/// corner tensors and normals are blended barycentrically, the tensor is projected onto the
/// plane of the blended normal, and its two tangential eigenpairs give k_max >= k_min and
/// their directions. Vertices with fewer than 5 neighbours in reach (e.g. isolated corners)
/// get the tensor 0 and flag their points umbilic. Converges like a 2-ring quadric fit at the
/// vertices (O(h^2) on regular sampling) and is smooth across seams by construction.
/// @throws InvalidInput if the DDF has no faces, params.rings < 1 or params.weightRadius < 0.
/// @throws Cancelled if params.progress asks to stop.
CurvatureField computeVertexCurvature(const ddf::DisplacementField& ddf,
                                      const VertexCurvatureParams& params = {});

}  // namespace ddfcam::planning
