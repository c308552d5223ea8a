// SPDX-License-Identifier: MIT
// ddfcam: baseline conversion of a triangle mesh into a DDF with the mesh as support (ch. 6).
#pragma once

#include <ddfcam/ddf/conversion_report.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/ddf/support_reduction.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/ddf/vector_lengths.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace ddfcam::ddf {

/// @brief Which support the converted DDF gets.
enum class SupportChoice {
  Input,   ///< the welded input mesh itself (the baseline of ch. 6)
  Reduced  ///< the input reduced by constrained edge contraction (sec. 6.1-6.2)
};

/// @brief Parameters of the mesh to DDF conversion.
struct ConversionParams {
  /// Raster resolution m of the DDF (points per support edge, >= 2). Default 10.
  int resolution = 10;
  /// Vertices closer than this are welded into one, mm; 0 = the larger of 1e-9 x the
  /// bounding-box diagonal (merges exact duplicates as in an unwelded STL) and
  /// validation.coincidentToleranceMm (what the check of constraint 2 calls coincident).
  /// Default 0.
  double weldToleranceMm = 0.0;
  /// Direction repair margin for constraint 1. Default: PseudoNormalParams defaults.
  PseudoNormalParams normals;
  /// Choice of vector lengths (sec. 4.4). Default: VectorLengthParams defaults. Its progress
  /// callback is replaced by a share of @ref progress.
  VectorLengthParams lengths;
  /// Choose the vector lengths (sec. 4.4) and fill the heights from the input. false keeps the
  /// unit pseudo-normal directions, leaves every height at 0 (the support itself) and skips both
  /// steps, for callers that set lengths and heights themselves (e.g. a deformation sequence,
  /// which resets the lengths). Default true.
  bool chooseLengths = true;
  /// Check the result against the three constraints with validate() (as `ddfcam-cli info`
  /// does) and repair what the conversion can: one vector for coincident vertices
  /// (constraint 2), shorter vectors for crust heights and crossing crusts (constraint 3).
  /// Ignored when chooseLengths is false. Default true.
  bool validateResult = true;
  /// The check of the result (and the coincidence tolerance of the weld). Default:
  /// ValidationParams defaults, the check `ddfcam-cli info` runs.
  ValidationParams validation;
  /// The support: the input mesh, or the input reduced by edge contraction. The library's
  /// default keeps the input mesh; the import dialog and `ddfcam-cli convert` default to
  /// Reduced. Default Input.
  SupportChoice support = SupportChoice::Input;
  /// Constraints of the reduction (support == Reduced); its resolution and progress are set
  /// by the conversion (the resolution to @ref resolution), and with toleranceMm > 0 also its
  /// maxEdgeMm (the smaller of the one given, when > 0, and that of the tolerance tries).
  /// Default: SupportReductionParams defaults.
  SupportReductionParams reduction;
  /// Accuracy, mm: when > 0 the raster spacing is chosen so that the represented surface lies
  /// within this distance of the input, measured both ways on sample points
  /// (ConversionAccuracy). resolution (or the spacing rule's m when rasterSpacingMm > 0) is the
  /// first try and each further try refills the same support at (m - 1) x 1.5 to 4 (from the
  /// measured ratio, as the chord error falls with the square of the spacing), up to m = 256
  /// and maxRasterPoints, stopping early when the distance no longer shrinks (then the better
  /// raster is kept). A reduced support is first reduced with support edges at most (m - 1) x a
  /// target spacing d (d = rasterSpacingMm, or the median input edge length; m = resolution,
  /// the m its stubbles are checked at), then refilled at larger m the same way; a larger m
  /// whose fill has stubbles that miss the input is not taken. Where that does not meet the
  /// tolerance the input is reduced again with the edge bound shortened by the measured ratio
  /// (to a half to a quarter), at most 4 reductions; the best is returned. A tolerance not met
  /// is reported (accuracy.note, a warning, naming the limit: the point budget, the tries,
  /// stubbles that miss the input, or a distance that no longer shrinks with the resolution,
  /// i.e. a crease or sharp edge inside a support face), not thrown. Default 0 (resolution as
  /// given).
  double toleranceMm = 0.0;
  /// Target raster spacing, mm: when > 0 the resolution is the smallest m with
  /// longest support edge / (m - 1) <= rasterSpacingMm (the first try when toleranceMm > 0).
  /// Default 0.
  double rasterSpacingMm = 0.0;
  /// Largest number of stored heights (faces x m (m + 1) / 2) the spacing rule and the
  /// tolerance tries may give the field (4 bytes each, and about ten times that while the
  /// distances are measured). Default 20,000,000.
  std::size_t maxRasterPoints = 20'000'000;
  /// Stock allowance the crust must reach above the surface, mm (0 = none): support offsets
  /// and vector lengths are fitted by fitCrustToStock. Default 0.
  double stockMm = 0.0;
  /// Empty, or one label per input triangle (e.g. its CAD face): a reduced support never
  /// merges triangles of different labels, and the result says each support face's label.
  /// Default empty.
  std::vector<int> inputLabels;
  /// Progress in [0, 1] and cancellation (throws Cancelled). Default none.
  ProgressCallback progress;
};

/// @brief The converted DDF and what the conversion had to give up.
struct ConversionResult {
  /// Support = the welded input mesh (Input) or its reduction (Reduced), heights by fill.
  DisplacementField ddf;
  /// Counts of every repair and drop, the input's topology and the check of the result.
  ConversionReport report;
  /// Per DDF face, the index of its input triangle; empty for a reduced support, whose faces
  /// stand for many input triangles (supportLabels then says which labelled region each is in).
  std::vector<int> sourceTriangle;
  /// DDF vertices whose direction left the pseudo-normal (empty for a reduced support: the
  /// indices would name vertices of the unreduced one; report.repairedDirections counts them).
  std::vector<int> repairedVertices;
  /// DDF vertices with no front-facing direction (empty for a reduced support, as above).
  std::vector<int> infeasibleVertices;
  VectorLengthReport lengths;        ///< report of the vector length choice
  std::size_t filledPoints = 0;      ///< stored heights set from the input mesh by fill
  std::size_t unfilledPoints = 0;    ///< stored heights whose stubble missed it (kept at 0)
  std::vector<int> supportLabels;    ///< per DDF face, its input label (empty without labels)
  SupportReductionReport reduction;  ///< what the reduction did (support == Reduced)
  /// Distances to the input, measured when toleranceMm or rasterSpacingMm is set or the support
  /// is Reduced (a copy is in report.accuracy).
  ConversionAccuracy accuracy;
  std::optional<StockFit> stock;  ///< the crust fit to stockMm (when stockMm > 0; in report too)
};

/// @brief Converts @p mesh into a DDF whose support is the mesh itself (the baseline of ch. 6).
///
/// Steps: weld vertices; drop triangles with a repeated vertex or zero area and repeats of an
/// earlier triangle's corners; build the support mesh, dropping (with a warning through
/// ddfcam::log) the triangles OpenMesh rejects as non-manifold or inconsistently oriented, and
/// unused vertices (all counted in the report); directions = angle-weighted pseudo-normals
/// repaired for constraint 1; lengths by chooseVectorLengths; the check of the three
/// constraints and its repairs (see ConversionParams::validateResult); heights by the
/// depth buffer's fill mode from the input mesh (the nearest intersection of every stubble with
/// it in [-1, 1]; lengths and fill are skipped when params.chooseLengths is false). With the mesh
/// as support the heights come out ~0 and the represented surface lies on the input up to float
/// rounding (one-sided Hausdorff distance checked in the tests). A result that still violates a
/// constraint is returned, not thrown: report.valid() is false and report.validation and
/// conversionProblemLines() say where and why; the caller decides whether to use it.
/// With support == Reduced the welded support is reduced by reduceSupport() (labels carried
/// through welding and dropping) before the lengths are chosen; with toleranceMm or
/// rasterSpacingMm the resolution is chosen as documented there; with stockMm the crust is
/// fitted by fitCrustToStock() after the fill (and the distances measured again).
/// @throws InvalidInput for a bad resolution, an index out of range, inputLabels of the wrong
/// size, a negative or non-finite tolerance, spacing or stock, a spacing that needs more than
/// m = 256 or maxRasterPoints, or when no triangle survives. @throws Cancelled through
/// params.progress.
ConversionResult convertMeshToDdf(const TriangleMesh& mesh, const ConversionParams& params = {});

}  // namespace ddfcam::ddf
