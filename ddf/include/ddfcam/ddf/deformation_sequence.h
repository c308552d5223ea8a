// SPDX-License-Identifier: MIT
// ddfcam: a deformed surface as heights over a mould DDF, split into a sequence of DDFs where
// the unique-projection property would fail (dissertation ch. 9, fig. 9.5).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of buildDeformationSequence().
struct DeformationSequenceParams {
  /// Length of the displacement vectors of each stage, mm: the crust must contain the deformed
  /// surface. 0 = 1.25 x the largest distance from a support vertex of the stage to the deformed
  /// surface (at least 1e-3 x the bounding-box diagonal). Default 0.
  double reachMm = 0.0;
  /// A stage's heights must stay below crustSafety x h0 of their face and side (h0 = the
  /// unique-projection crust height of sec. 4.3, crustHeights()); beyond it the face is a
  /// crossing face and the deformation is split. In (0, 1]. Default 0.8.
  double crustSafety = 0.8;
  /// Most DDFs in the sequence; faces still crossing in the last stage are reported as
  /// unresolved. >= 1. Default 12.
  int maxStages = 12;
  /// Stop early, with the faces still crossing reported unresolved and DeformationSequence::
  /// stalled set, after this many consecutive splits that made no headway: each carried less
  /// than a quarter of the remaining deformation and the crossing faces fell by less than 10 %.
  /// That happens when the deformed surface lies far beyond the crust the mould's support allows
  /// (a dense or noisy mould whose vectors cross at small heights, mould and formed swapped, a
  /// bad alignment); more stages would only cost time. 0 = never. Default 2.
  int stallStages = 2;
  /// Progress in [0, 1] and cancellation (throws Cancelled). Default none.
  ProgressCallback progress;
};

/// @brief One DDF of the sequence. Every stage has the connectivity, face order and raster
/// resolution of stage 0, so a raster point (face, raster index) means the same material point
/// in every stage.
struct DeformationStage {
  /// Support = the previous stage's support with its vertices moved by fraction x h v (stage 0:
  /// the mould); vectors = repaired pseudo-normals of that support with length reachMm; heights =
  /// the deformed surface along the stubbles (nearest hit in [-1, 1]; NaN where the stubble
  /// misses it).
  DisplacementField ddf;
  /// Share of this stage's heights carried into the next stage's support, in (0, 1]; 1 for the
  /// last stage, whose heights reach the deformed surface.
  double fraction = 1.0;
  /// Faces whose heights leave crustSafety x h0 in this stage (before splitting), ascending.
  std::vector<int> crossingFaces;
};

/// @brief The deformed surface as a chain of DDFs starting on the mould (sec. 9, fig. 9.5).
struct DeformationSequence {
  /// At least one stage; stages[0].ddf has the mould as support.
  std::vector<DeformationStage> stages;
  /// Per raster point copy (layout of stages[0].ddf.allHeights()): the point of the deformed
  /// surface that the raster point is carried to, mm, mould frame; NaN coordinates where a
  /// stubble of the chain missed the deformed surface.
  std::vector<Vec3> deformedPoints;
  /// Stage-0 faces whose heights left the unique-projection crust (the region of fig. 9.5 where
  /// a single DDF would return wrong heights), ascending.
  std::vector<int> crossingFaces;
  /// Faces still crossing in the last stage (maxStages reached, or the support folded),
  /// ascending; their deformed points are not trustworthy.
  std::vector<int> unresolvedFaces;
  /// Raster point copies whose chain missed the deformed surface (NaN in deformedPoints).
  std::size_t missingPoints = 0;
  /// The sequence stopped early because it made no headway (DeformationSequenceParams::
  /// stallStages): unresolvedFaces then holds the faces still crossing, usually many, and the
  /// deformed points are a poor approximation. Not stored with a mould study.
  bool stalled = false;
};

/// @brief Represents @p deformed as heights over the mould DDF @p mould, splitting the
/// deformation into a sequence of smaller ones where the unique-projection property fails.
///
/// Stage 0 keeps the support, resolution and vector directions of @p mould and gives the vectors
/// the length reachMm; heights come from fillFromMesh(). Faces whose heights leave crustSafety x
/// h0 are crossing faces. If there are any, the stage carries only the fraction t = min(1,
/// crustSafety x h0 / |h|) over the crossing faces of its heights: the next support is this
/// support with every vertex moved by t h v (vertices whose stubble missed move by the mean of
/// their neighbours' moves), and the next stage is built on it with fresh pseudo-normals, until
/// no face crosses, maxStages is reached or the splitting stalls (stallStages). The vector field
/// thus follows the deformation and the crust stays unique-projection (the dissertation's remedy at
/// the end of ch. 9).
/// @param mould DDF whose support is the mould surface (heights are ignored), mm.
/// @param deformed deformed surface, mm, in the mould's frame (already aligned).
/// @throws InvalidInput for an empty mesh or bad parameters. @throws Cancelled via progress.
DeformationSequence buildDeformationSequence(const DisplacementField& mould,
                                             const TriangleMesh& deformed,
                                             const DeformationSequenceParams& params = {});

/// @brief Morph positions of every raster point copy at time @p lambda (layout of
/// stages[0].ddf.allHeights()), mm: the piecewise linear path from the mould point through the
/// stage supports to the deformed point, parametrised so that lambda = 0 is the mould, 1 the
/// deformed surface, and with a single stage F(lambda) = S + lambda h v exactly. lambda outside
/// [0, 1] extrapolates along the first or last segment (lambda < 0 bends beyond the mould away
/// from the deformed surface, as a compensated mould does). NaN where deformedPoints is NaN.
std::vector<Vec3> morphPositions(const DeformationSequence& sequence, double lambda);

/// @brief As above with a time per raster point copy (the blended surface f = s + d h v of ch. 9
/// with d = @p lambdas). @p lambdas has one value per copy.
/// @throws InvalidInput if @p lambdas has the wrong size.
std::vector<Vec3> morphPositions(const DeformationSequence& sequence,
                                 std::span<const float> lambdas);

}  // namespace ddfcam::ddf
