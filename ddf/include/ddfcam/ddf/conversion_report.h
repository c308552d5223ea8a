// SPDX-License-Identifier: MIT
// ddfcam: what a mesh -> DDF conversion repaired, what it could not, and whether the result is
// a valid DDF (ch. 3), in numbers and in words for the front ends.
#pragma once

#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/ddf/support_reduction.h>
#include <ddfcam/ddf/validation.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::ddf {

/// @brief How well the represented surface follows the input (measured on sample points).
/// Input samples are the vertices, edge midpoints and centroids of the input triangles the
/// support kept (the dropped ones are counted in the report instead); DDF samples are the
/// surface points q = g + h v of every stored raster point.
struct ConversionAccuracy {
  bool measured = false;         ///< the distances below were measured
  double inputToDdfMm = 0.0;     ///< largest distance of an input sample to the DDF surface
  double ddfToInputMm = 0.0;     ///< largest distance of a DDF raster point to the input
  double rasterSpacingMm = 0.0;  ///< longest raster spacing (longest support edge / (m - 1))
  int resolutionTries = 0;       ///< resolutions tried to meet toleranceMm
  int resolution = 0;            ///< raster resolution m the distances were measured at
  double toleranceMm = 0.0;      ///< the tolerance asked for (0: none)
  bool toleranceMet = false;     ///< both distances <= toleranceMm (false without a tolerance)
  /// Input sample farthest from the DDF surface (at inputToDdfMm), mm, part frame.
  Vec3 worstInputPoint = Vec3::Zero();
  /// Raster surface point farthest from the input (at ddfToInputMm), mm, part frame.
  Vec3 worstRasterPoint = Vec3::Zero();
  /// Why the tolerance was not met (empty when met or not asked for).
  std::string note;
};

/// @brief Summary of one conversion, without the field: the repairs, what was dropped, the
/// topology of the input and the check of the result against the three constraints.
struct ConversionReport {
  int inputVertices = 0;     ///< vertices of the input mesh
  int inputTriangles = 0;    ///< triangles of the input mesh
  int supportVertices = 0;   ///< vertices of the converted support
  int supportFaces = 0;      ///< faces of the converted support
  int weldedVertices = 0;    ///< input vertices merged into another one
  int unusedVertices = 0;    ///< input vertices no input triangle refers to (dropped)
  int orphanedVertices = 0;  ///< vertices all of whose triangles were dropped (dropped)
  int degenerateFaces = 0;   ///< triangles dropped for a repeated vertex or zero area
  int duplicateFaces = 0;    ///< triangles dropped for repeating an earlier one's corners
  /// Triangles removed in back-to-back pairs: two faces on the same corners facing opposite
  /// ways (a zero-thickness fin or membrane) that the surface does not need, i.e. no edge of
  /// theirs has exactly one other face; both faces of each such pair go. A pair the surface
  /// needs keeps its first face and counts the other as a duplicate.
  int backToBackFaces = 0;
  int droppedFaces = 0;        ///< triangles dropped as non-manifold or inconsistently oriented
  int nonManifoldEdges = 0;    ///< edges of the welded input shared by more than two triangles
  int boundaryLoops = 0;       ///< boundary curves of the support: holes and open borders
  int repairedDirections = 0;  ///< vectors turned off the pseudo-normal for constraint 1
  int infeasibleVertices = 0;  ///< vertices where no direction faces all incident triangles
  int unifiedVectors = 0;      ///< coincident (unwelded) vertices given one vector (constraint 2)
  int shortenedVectors = 0;    ///< vectors shortened for the crusts (sec. 4.4)
  int lengthRetries = 0;       ///< extra vector length choices made to repair constraint 3
  std::size_t unfilledPoints = 0;    ///< stored heights whose stubble missed the input (kept 0)
  bool validated = false;            ///< the result was checked (not when lengths were skipped)
  ValidationReport validation;       ///< validate() of the result
  bool reducedSupport = false;       ///< the support was reduced (SupportChoice::Reduced)
  SupportReductionReport reduction;  ///< what the reduction did (when reducedSupport)
  int resolution = 0;                ///< raster resolution m of the result
  double rasterSpacingMm = 0.0;      ///< longest support edge / (m - 1), mm
  ConversionAccuracy accuracy;       ///< distances to the input (when measured)
  std::optional<StockFit> stock;     ///< the crust fit to the stock allowance (when asked)

  /// @brief True when the result was checked and satisfies all three constraints.
  bool valid() const { return validated && validation.ok(); }
};

/// @brief One violated constraint of a ValidationReport, counted.
struct ConstraintFailure {
  int constraint = 0;  ///< 1, 2 or 3
  int issues = 0;      ///< listed issues of this constraint
  int vertices = 0;    ///< distinct support vertices the listed issues name
  int faces = 0;       ///< distinct support faces the listed issues name
  int facePairs = 0;   ///< issues naming two faces (constraint 3: intersecting crusts)
  std::string first;   ///< message of the first issue
};

/// @brief The violated constraints of @p report in ascending order (empty when it is ok).
/// Counts cover the listed issues; see ValidationReport::suppressedIssues for the rest.
std::vector<ConstraintFailure> constraintFailures(const ValidationReport& report);

/// @brief Short name of constraint @p c (1..3), e.g. "constraint 1 (front-facing vectors)".
std::string constraintName(int c);

/// @brief Lines saying what the conversion repaired or dropped, one fact per line; empty when
/// it changed nothing.
std::vector<std::string> conversionRepairLines(const ConversionReport& report);

/// @brief Lines saying which constraints the converted DDF violates, where (vertex and face
/// counts, first item), what that means for the user and what to change; empty when valid.
std::vector<std::string> conversionProblemLines(const ConversionReport& report);

/// @brief Lines for the front ends beside the repair lines: support faces before and after the
/// reduction and its time, m and the raster spacing, the both-way distances to the input (and
/// whether the tolerance was met, and why not), and the stock fit's verdict (with the limit's
/// message when the crust cannot hold the allowance). Empty parts are left out.
std::vector<std::string> conversionSummaryLines(const ConversionReport& report);

/// @brief One line: "valid DDF (...)" or "INVALID DDF: violates constraint 1 (...), ...".
std::string conversionVerdict(const ConversionReport& report);

}  // namespace ddfcam::ddf
