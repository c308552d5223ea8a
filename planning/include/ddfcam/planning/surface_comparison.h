// SPDX-License-Identifier: MIT
// ddfcam: point-by-point comparison of a deformed (formed) surface with a mould surface on the
// mould's DDF (dissertation ch. 9): signed deviation, deviation vectors, statistics.
#pragma once

#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/error_map.h>
#include <ddfcam/planning/scalar_field.h>
#include <ddfcam/progress.h>

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
  /// Area-weighted statistics of deviation over the mould (band of the params).
  ErrorStatistics statistics;
  /// Band used for statistics and colours.
  ToleranceBand band;
};

/// @brief Builds the mould DDF of @p mould (ddf::convertMeshToDdf with the given resolution:
/// support = the mould mesh, repaired pseudo-normals) and compares @p deformed with it.
/// @param mould mould (or target) surface, mm. @param deformed deformed surface in the mould's
/// frame, mm.
/// @throws InvalidInput for empty meshes, bad parameters, or when no raster point of the mould
/// finds the deformed surface ("the surfaces do not overlap: ..."). @throws Cancelled.
SurfaceComparison compareSurfaces(const ddf::TriangleMesh& mould, const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params = {});

/// @brief As above on an existing mould DDF (its support, resolution and directions are used).
SurfaceComparison compareSurfaces(const ddf::DisplacementField& mouldDdf,
                                  const ddf::TriangleMesh& deformed,
                                  const ComparisonParams& params = {});

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
/// over the mould's area. The result equals compareSurfaces() run with the new band and
/// flipNormal.
/// @throws InvalidInput for an invalid band or a comparison without stages.
void updateComparisonBand(SurfaceComparison& comparison, const ToleranceBand& band,
                          bool reverseSign);

}  // namespace ddfcam::planning
