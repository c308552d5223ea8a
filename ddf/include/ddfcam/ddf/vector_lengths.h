// SPDX-License-Identifier: MIT
// ddfcam: choice of the displacement vector lengths so that constraint 3 holds (sec. 4.4).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/progress.h>

#include <limits>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of the vector length choice.
struct VectorLengthParams {
  /// Length given where no crust height limits the vectors, mm; 0 = the mean support edge
  /// length. Default 0.
  double maxLengthMm = 0.0;
  /// Scaling by safety x h0 instead of h0 leaves every crust height at 1/safety > 1, a margin
  /// against rounding and against the next shortening. In (0, 1]. Default 0.95.
  double safety = 0.95;
  /// Bound on the per-face re-check passes between two conflict rounds (then the fallback
  /// applies) and on the number of non-adjacent conflict rounds. Default 50.
  int maxIterations = 50;
  /// How a face with h0 < 1 is repaired. true: its three vectors are scaled by safety x h0, as
  /// in sec. 4.4. false: its longest vectors are capped at the largest common length that gives
  /// h0 = 1/safety; the face's shortest vector is never shortened, so repeated fixes do not
  /// drive vectors next to sliver triangles towards zero. Default false.
  bool uniformShrink = false;
  /// Also resolve intersections of the +-1 crusts of faces sharing no vertex. Default true.
  bool checkNonAdjacent = true;
  /// Vertices closer than this count as one for the non-adjacent test (an unwelded seam does
  /// not separate faces), mm; 0 = 1e-9 x the bounding-box diagonal. Default 0.
  double coincidentToleranceMm = 0.0;
  /// Factor applied to the vectors of the six vertices of a conflicting face pair per round.
  /// In (0, 1). Default 0.8.
  double conflictShrink = 0.8;
  /// Progress in [0, 1] and cancellation (throws Cancelled). Default none.
  ProgressCallback progress;
};

/// @brief What the vector length choice did.
struct VectorLengthReport {
  /// Smallest crust height min(h0+, h0-) over the faces that satisfy constraint 1, after the
  /// choice (>= 1 on success; +inf if no face limits the vectors).
  double minH0 = std::numeric_limits<double>::infinity();
  int iterations = 0;                    ///< per-face re-check passes, in total
  int conflictRounds = 0;                ///< non-adjacent conflict rounds
  int shortenedVertices = 0;             ///< vertices shortened after the initial per-face step
  int nonAdjacentConflictsResolved = 0;  ///< distinct conflicting face pairs that were resolved
  int remainingConflicts = 0;            ///< conflicting face pairs left when the rounds ran out
  /// Faces whose directions violate constraint 1 (h0 = 0); ignored by the choice.
  std::vector<int> constraint1Faces;
  bool usedFallback = false;  ///< per-face passes did not converge; all vectors scaled uniformly
};

/// @brief Chooses the lengths of the vectors of @p ddf (sec. 4.4); their directions are kept.
///
/// Every direction is normalised; per face the crust heights h0 of both sides are computed
/// with unit vectors and the face's vectors are given safety x min(h0+, h0-) (or maxLength
/// when that is smaller or infinite); every vertex takes the shortest length proposed by its
/// faces. Then, until h0 >= 1 everywhere, faces with min h0 < 1 shorten their vectors (see
/// VectorLengthParams::uniformShrink). Once that holds, pairs of faces sharing no vertex (nor a
/// vertex position, for unwelded meshes) whose +-1 crusts intersect (candidates from a CrustHash,
/// exact test crustsIntersect) shrink their six vertices by conflictShrink, the per-face passes run
/// again, and so on for at most maxIterations rounds (pairs left are counted in
/// remainingConflicts). If the per-face passes do not converge within maxIterations, all vectors
/// are scaled by safety x min h0, which guarantees h0 >= 1 because h0 scales inversely with a
/// uniform scaling of a face's vectors.
/// @param ddf field whose vectors give the directions; its vectors are replaced (heights are
/// untouched).
/// @throws InvalidInput if a vector is zero or not finite (names the vertex) or a parameter
/// is out of range. @throws Cancelled through params.progress.
VectorLengthReport chooseVectorLengths(DisplacementField& ddf,
                                       const VectorLengthParams& params = {});

/// @brief Mean length of the support edges of @p ddf, mm (0 without edges).
double meanEdgeLength(const DisplacementField& ddf);

}  // namespace ddfcam::ddf
