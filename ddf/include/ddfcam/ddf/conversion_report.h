// SPDX-License-Identifier: MIT
// ddfcam: what a mesh -> DDF conversion repaired, what it could not, and whether the result is
// a valid DDF (ch. 3), in numbers and in words for the front ends.
#pragma once

#include <ddfcam/ddf/validation.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ddfcam::ddf {

/// @brief Summary of one conversion, without the field: the repairs, what was dropped, the
/// topology of the input and the check of the result against the three constraints.
struct ConversionReport {
  int inputVertices = 0;       ///< vertices of the input mesh
  int inputTriangles = 0;      ///< triangles of the input mesh
  int supportVertices = 0;     ///< vertices of the converted support
  int supportFaces = 0;        ///< faces of the converted support
  int weldedVertices = 0;      ///< input vertices merged into another one
  int unusedVertices = 0;      ///< input vertices no input triangle refers to (dropped)
  int orphanedVertices = 0;    ///< vertices all of whose triangles were dropped (dropped)
  int degenerateFaces = 0;     ///< triangles dropped for a repeated vertex or zero area
  int duplicateFaces = 0;      ///< triangles dropped for repeating an earlier one's corners
  int droppedFaces = 0;        ///< triangles dropped as non-manifold or inconsistently oriented
  int nonManifoldEdges = 0;    ///< edges of the welded input shared by more than two triangles
  int boundaryLoops = 0;       ///< boundary curves of the support: holes and open borders
  int repairedDirections = 0;  ///< vectors turned off the pseudo-normal for constraint 1
  int infeasibleVertices = 0;  ///< vertices where no direction faces all incident triangles
  int unifiedVectors = 0;      ///< coincident (unwelded) vertices given one vector (constraint 2)
  int shortenedVectors = 0;    ///< vectors shortened for the crusts (sec. 4.4)
  int lengthRetries = 0;       ///< extra vector length choices made to repair constraint 3
  std::size_t unfilledPoints = 0;  ///< stored heights whose stubble missed the input (kept 0)
  bool validated = false;          ///< the result was checked (not when lengths were skipped)
  ValidationReport validation;     ///< validate() of the result

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

/// @brief One line: "valid DDF (...)" or "INVALID DDF: violates constraint 1 (...), ...".
std::string conversionVerdict(const ConversionReport& report);

}  // namespace ddfcam::ddf
