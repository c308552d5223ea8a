// SPDX-License-Identifier: MIT
// ddfcam: principal curvature of a DDF whose faces are flat (a converted triangle mesh), from
// quadric fits at the support vertices.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/progress.h>

#include <vector>

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
  /// Two represented triangles sharing an edge whose normals differ by more than this meet at a
  /// crease (a sharp CAD edge), rad: a vertex on it gets one fit per smooth side, from that
  /// side's faces only (default 0.7854, 45 degrees; the tessellation of a smooth surface turns
  /// by a few degrees per triangle).
  double creaseAngleRad = 0.7854;
  /// Per support face a label, e.g. its CAD face (LoadPartReport::cadFaceOfSupportFace), or
  /// empty: faces with different labels never share a fit, so a vertex on a tangent edge (a
  /// cylinder running into a fillet) gets one fit per face, from that face's side only
  /// (default empty: creases alone split).
  std::vector<int> faceLabels;
  /// Directions of the vertex fit's coefficient space whose singular value is below this share
  /// of the largest count as undetermined by the vertices and are taken from samples of the
  /// represented faces instead (default 0.005; at 0.02 a few vertices of the tessellated
  /// sphere of the CAD tests had well-sampled directions replaced, with a 34 % error).
  double minSingularRatio = 0.005;
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
/// layout and tool-side sign convention), estimated from the support vertices. Every vertex's
/// fan is split at crease edges (params.creaseAngleRad) and between params.faceLabels into
/// wedges, and every wedge gets its own fit from the faces reachable within params.rings rings
/// without crossing a crease: a quadric z = a x^2 + b x y + c y^2 + d x + e y, fitted by
/// weighted least squares to the represented points of those faces' vertices in the frame of
/// the wedge's area-weighted normal (x, y along the principal axes of the vertices' spread,
/// each scaled by its extent). Directions of the coefficients that the vertices leave
/// undetermined (singular value below params.minSingularRatio of the largest, e.g. a strip of
/// long triangles with its vertices on the two end circles of a cylinder, as CAD tessellations
/// and their STL exports have) are fitted to sample points of the represented faces instead
/// (up to 15 per face, area-weighted; the tessellation keeps them within its chord deflection
/// of the surface), which pins the axial curvature of a straight strip at 0. Its shape operator
/// (with the slope d, e) gives a curvature tensor S = k1 t1 t1^T + k2 t2 t2^T. Inside a face
/// the three corner wedges' tensors and normals are blended barycentrically (corners whose fit
/// failed drop out and the face's points are flagged umbilic), the tensor is projected onto
/// the plane of the blended normal, and its two tangential eigenpairs give k_max >= k_min and
/// their directions. A wedge with fewer than 5 neighbours within params.rings + 2 rings, or
/// whose face samples cannot pin the undetermined directions either, has no fit. Converges
/// like a 2-ring quadric fit at the vertices (O(h^2) on regular sampling).
/// @throws InvalidInput if the DDF has no faces, params.rings < 1, params.weightRadius < 0 or
/// params.faceLabels is neither empty nor one label per face.
/// @throws Cancelled if params.progress asks to stop.
CurvatureField computeVertexCurvature(const ddf::DisplacementField& ddf,
                                      const VertexCurvatureParams& params = {});

}  // namespace ddfcam::planning
