// SPDX-License-Identifier: MIT
// ddfcam: point-by-point comparison of a deformed (formed) surface with a mould surface on the
// mould's DDF (dissertation ch. 9): signed deviation, deviation vectors, statistics.
#pragma once

#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/inspection/coverage.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/model/scalar_field.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Parameters of compareSurfaces().
struct ComparisonParams {
  /// Raster resolution m of the mould DDF (points per support edge, >= 2). Default 4.
  int resolution = 4;
  /// Tolerance band of the deviation, mm: green inside, blue above (short of the mould, on the
  /// side its normal points to), red below (beyond the mould). Default +-0.5 mm.
  ToleranceBand band{-0.5, 0.5};
  /// Reverse the mould's normal (and so the sign of every deviation), for a mould mesh whose
  /// triangles face away from the formed part. Default false.
  bool flipNormal = false;
  /// Sequence settings (reach, crust safety, most stages). Default: their defaults.
  ddf::DeformationSequenceParams sequence;
  /// Progress in [0, 1] and cancellation (throws Cancelled); overrides sequence.progress.
  /// Default none.
  ProgressCallback progress;
};

/// @brief Result of comparing a deformed surface with a mould.
struct SurfaceComparison {
  /// The deformed surface over the mould DDF (stages[0].ddf: support = mould, resolution m).
  ddf::DeformationSequence sequence;
  /// Signed deviation (q - g) . n per raster point copy, mm: g the mould point, q its deformed
  /// point, n the mould's unit normal (area-weighted over the raster triangles around the point,
  /// oriented like the vectors, reversed by flipNormal). Name "deviation", unit "mm", signed;
  /// NaN where the deformed point is missing. Layout of stages[0].ddf.allHeights().
  ScalarField deviation;
  /// Deviation vectors q - g per raster point copy, mm, mould frame (NaN where missing).
  std::vector<ddf::Vec3> deviationVectors;
  /// Area-weighted statistics of deviation over the mould's resolved faces (resolvedFaces(); band
  /// of the params): deviations on unresolved faces are not trustworthy and left out; see
  /// comparisonCoverage() for the share of the mould the statistics describe.
  ErrorStatistics statistics;
  /// Band used for statistics and colours.
  ToleranceBand band;
};

/// @brief Builds the mould DDF of @p mould (ddf::convertMeshToDdf with the given resolution:
/// support = the mould mesh, repaired pseudo-normals) and compares @p deformed with it.
/// @param mould mould (or target) surface, mm. @param deformed deformed surface in the mould's
/// frame, mm.
/// @throws InvalidInput for empty meshes, bad parameters, when no raster point of the mould
/// finds the deformed surface ("the surfaces do not overlap: ..."), or when every deviation found
/// lies on an unresolved face. A sequence that stalls (ddf::DeformationSequence::stalled) stops
/// early; its unresolved faces are left out of the statistics and stallAdvice() says what to
/// change. @throws Cancelled.
SurfaceComparison compareSurfaces(const ddf::TriangleMesh& mould, const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params = {});

/// @brief As above on an existing mould DDF (its support, resolution and directions are used).
SurfaceComparison compareSurfaces(const ddf::DisplacementField& mouldDdf,
                                  const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params = {});

/// @brief The faces of the comparison's mould DDF whose deviations count: all faces but the
/// sequence's unresolved ones, ascending.
/// @throws std::out_of_range if @p comparison has no stage.
std::vector<int> resolvedFaces(const SurfaceComparison& comparison);

/// @brief For a comparison whose deformation sequence stalled: one message naming the stages
/// and the unresolved faces and saying what to change (alignment, swapping mould and formed, a
/// coarser mould support); empty otherwise.
std::string stallAdvice(const SurfaceComparison& comparison);

/// @brief How much of the mould a comparison describes.
struct ComparisonCoverage {
  /// Area with a trusted deviation (finite, on a resolved face) over the mould's area: the area
  /// the statistics are taken over.
  Coverage compared;
  double unresolvedAreaMm2 = 0.0;   ///< area with a finite deviation on unresolved faces, mm^2
  std::size_t unresolvedFaces = 0;  ///< unresolved faces (sequence.unresolvedFaces)
  double missingAreaMm2 = 0.0;      ///< area where the deformed surface was not found, mm^2
};

/// @brief Coverage of the mould by @p comparison (areas weighted by rasterPointAreas() of the
/// mould surface, heights 0). An unrelated 10 x 10 mm patch over a large mould covers a small
/// share even when all of its deviations lie in the band.
/// @throws std::out_of_range if @p comparison has no stage.
ComparisonCoverage comparisonCoverage(const SurfaceComparison& comparison);

/// @brief Where the unique-projection property of the mould DDF fails (fig. 9.5), for display:
/// per raster point copy (layout of the deviation) 0 where the mould DDF alone represents the
/// deformed surface, 1 on a crossing face the sequence resolved (sequence.crossingFaces), 2 on a
/// face still crossing in the last stage (sequence.unresolvedFaces: deviations untrustworthy).
/// Name "unique projection fails", unitless, unsigned.
/// @throws std::out_of_range if @p comparison has no stage.
ScalarField crossingRegionField(const SurfaceComparison& comparison);

/// @brief Re-evaluates @p comparison for another tolerance band and normal orientation without
/// recomputing the sequence (the deformed points do not depend on either): every deviation
/// changes sign when @p reverseSign is set, and band and statistics are recomputed for @p band
/// over the mould's resolved faces. The result equals compareSurfaces() run with the new band and
/// flipNormal.
/// @throws InvalidInput for an invalid band or a comparison without stages.
void updateComparisonBand(SurfaceComparison& comparison, const ToleranceBand& band,
                          bool reverseSign);

}  // namespace ddfcam::planning
