// SPDX-License-Identifier: MIT
// ddfcam: support reduction by constrained edge contraction (dissertation ch. 6, sec. 6.1-6.2).
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of reduceSupport(). Every constraint of sec. 6.2 can be switched off, so
/// that the unconstrained reduction of sec. 6.1 (fig. 6.13, 6.21) is available too.
struct SupportReductionParams {
  /// Raster resolution m the coverage constraints are checked at (points per support edge,
  /// >= 2). Default 10.
  int resolution = 10;
  /// Candidate items of a modified face: the items of the modified faces and of their immediate
  /// neighbours, kept when they intersect the new crust (fig. 6.7). false: the union of the
  /// modified faces' items only. Default true.
  bool neighbourCandidates = true;
  /// Constraint (a): every input triangle is hit by at least one V-ray. Default true.
  bool requireInputCoverage = true;
  /// Constraint (b): every V-ray from a raster point hits the input. Default true.
  bool requireRayCoverage = true;
  /// Containment: every item height of the modified faces in [-1, 1]. Default true.
  bool requireContainment = true;
  /// Unique projection (sec. 4.3/4.4): each modified face has crust height h0 >= 1 after the
  /// length choice, and its +-1 crust meets no crust of a non-adjacent face. Default true.
  bool requireUniqueProjection = true;
  /// Angle bound between the displacement vectors and the normals of the items they hit.
  /// Default true.
  bool requireAngleBound = true;
  /// The angle bound, degrees. Default 45.
  double maxAngleDeg = 45.0;
  /// Feature edges: an input edge whose two faces' normals differ by more than this angle,
  /// degrees, is kept like a boundary edge (its vertices are never moved or removed), so no support
  /// face spans a sharp edge, which a raster can only cut at a distance proportional to its
  /// spacing. 180 switches it off (the dissertation's runs). Default 40.
  double featureAngleDeg = 40.0;
  /// Longest support edge the reduction may create, mm (0 = no limit). Default 0.
  double maxEdgeMm = 0.0;
  /// Longest displacement vector, mm (0 = no limit). Default 0.
  double maxVectorLengthMm = 0.0;
  /// Upper bound on the sweeps over the sorted edge list. Default 200.
  int maxSweeps = 200;
  /// Progress in [0, 1] and cancellation (throws Cancelled). Default none.
  ProgressCallback progress;
};

/// @brief What reduceSupport() did.
struct SupportReductionReport {
  int inputFaces = 0;             ///< faces of the support before reduction
  int supportFaces = 0;           ///< faces after reduction
  int contractions = 0;           ///< edges contracted
  int sweeps = 0;                 ///< passes over the sorted edge list
  int rejectedCritical = 0;       ///< contractions refused: critical edge (3-cycle, no face), fold
  int rejectedBoundary = 0;       ///< contractions refused: boundary or label-border edge
  int rejectedEdgeLength = 0;     ///< refused: a new edge longer than maxEdgeMm
  int rejectedInputCoverage = 0;  ///< refused by constraint (a)
  int rejectedRayCoverage = 0;    ///< refused by constraint (b)
  int rejectedContainment = 0;    ///< refused: an item height outside [-1, 1]
  int rejectedUniqueProjection = 0;  ///< refused: h0 < 1 or a non-adjacent crust conflict
  int rejectedAngle = 0;             ///< refused by the angle bound
  double seconds = 0.0;              ///< wall time of the reduction, set-up included
};

/// @brief The reduced support with its vectors and, per face, the input label it carries.
struct SupportReductionResult {
  SupportMesh support;            ///< reduced support, mm, part frame
  std::vector<Vec3> vectors;      ///< #V displacement vectors, mm per unit height
  std::vector<int> faceLabels;    ///< per support face, the label of its items (empty if none)
  SupportReductionReport report;  ///< counts of contractions and refusals
};

/// @brief Reduces the support @p input (a manifold mesh, usually the welded input surface
/// F_d itself) by shortest-feasible-edge-first contraction (sec. 6.1) under the constraints of
/// sec. 6.2 switched on in @p params; the items are the faces of @p input.
///
/// Sweeps: the edges are sorted by length and tried in order; edges that become incident to a
/// new vertex wait for the next sweep, which sorts the remaining edges again; the reduction ends
/// after a sweep without contraction or after maxSweeps. An edge refused earlier is not tried
/// again while no face around it has changed. A tentative contraction of edge (a, b) is checked
/// in this order, the first failure counted in the report:
/// - boundary: a or b lies on the mesh boundary or between faces of different labels (so the
///   boundary and the label borders are kept exactly, vertex for vertex);
/// - critical: the edge lies on a 3-cycle that is no face, the two apexes and the edge span a
///   tetrahedron, OpenMesh's link test refuses it, or a remaining face would flip its normal or
///   degenerate at the new vertex (always on);
/// - edge length (maxEdgeMm);
/// - unique projection, part 1: the new vertex is the midpoint moved along the averaged vector
///   (v_a + v_b)/2 onto the nearest item of the region within |h| <= 1 (the plain midpoint when
///   the moved one folds a face); its vector keeps the averaged
///   direction and gets the longest length L <= cap for which every modified face has h0 >= 1
///   (sec. 4.4), then 0.8 L when that still holds; cap = maxVectorLengthMm, or the longest new edge
///   when that is 0; refused when no length works. Without requireUniqueProjection the vector is
///   the plain average;
/// - the items of the modified faces (and of their neighbours, neighbourCandidates) are
///   re-assigned by V-shooting the new faces' rasters (resolution m) at them; every ray keeps
///   its nearest hit within |h| <= 1; ray coverage (b), then the angle bound, then input
///   coverage (a) by a counter per item of the faces whose item set holds it (some ray of the
///   face hits it within |h| <= 1, nearest or not); a counter that was positive must not drop
///   to 0 (items never hit at the start, e.g. at m <= 3, are not held to it);
/// - containment: every vertex of a re-assigned item that V-projects onto a new face with mu
///   inside lies at |h| <= 1 there or in the crust of another face of the region;
/// - unique projection, part 2: the +-1 crust of no new face meets the crust of a face sharing
///   no vertex with it (crust boxes in a spatial hash, exact test crustsIntersect); on such a
///   conflict the length choice is repeated with half and a quarter of the cap.
///
/// With requireUniqueProjection the input's directions first get lengths by
/// chooseVectorLengths (sec. 4.4, safety 0.8, maxLengthMm = maxVectorLengthMm), so that the
/// start satisfies constraint 3 too. Every contraction then keeps h0 >= 1 on the faces it
/// modifies and their crusts clear of non-adjacent ones, so the returned vectors already satisfy
/// constraint 3 (validate() passes where the input's start did) and they are the lengths the
/// coverage and containment checks were made with: a caller must NOT re-run
/// chooseVectorLengths on them (it would renormalise and re-choose every length and undo
/// what the constraints verified); validate and fill the heights (fillFromMesh) directly.
/// Without requireUniqueProjection the vectors are averages of the given ones and constraint 3
/// is not guaranteed.
/// @param input the input surface as support mesh, mm.
/// @param vectors #V unit or scaled pseudo-normal directions of @p input (constraint 1 holds).
/// @param inputLabels empty, or one label per face of @p input (e.g. its CAD face): an edge
/// whose contraction would merge faces of different labels is not contracted, so every
/// reduced face carries one label.
/// @return the reduced support (a fresh, garbage-free mesh: surviving vertices and faces in
/// their old order), #V vectors (mm), per-face labels (empty without @p inputLabels) and the
/// report. The support is manifold with no degenerate face.
/// @throws InvalidInput on a size mismatch, a zero or non-finite vector or a bad parameter.
/// @throws Cancelled through params.progress.
SupportReductionResult reduceSupport(const SupportMesh& input, std::span<const Vec3> vectors,
                                     std::span<const int> inputLabels = {},
                                     const SupportReductionParams& params = {});

}  // namespace ddfcam::ddf
