// SPDX-License-Identifier: MIT
// ddfcam: checks of the three DDF constraints (ch. 3) with issues that name vertices and faces.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <limits>
#include <string>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of DDF validation.
struct ValidationParams {
  /// Support vertices closer than this are coincident (constraint 2), mm. Default 1e-6.
  double coincidentToleranceMm = 1e-6;
  /// Coincident vertices carry different vectors when |v_a - v_b| > vectorTolerance x
  /// max(|v_a|, |v_b|). Default 1e-9.
  double vectorTolerance = 1e-9;
  /// Crust height both sides of every face must reach (constraint 3). Default 1.
  double minCrustHeight = 1.0;
  /// Also look for intersecting +-1 crusts of faces sharing no vertex (constraint 3), using a
  /// CrustHash. Default true.
  bool checkNonAdjacent = true;
  /// Issues listed at most; further ones are only counted. Default 1000.
  int maxIssues = 1000;
};

/// @brief One violated constraint, with the items involved.
struct ValidationIssue {
  int constraint = 0;         ///< 1, 2 or 3 (chapter 3 numbering)
  std::vector<int> vertices;  ///< support vertices involved
  std::vector<int> faces;     ///< support faces involved
  std::string message;        ///< human-readable, names the items and values
};

/// @brief Result of validate().
struct ValidationReport {
  std::vector<ValidationIssue> issues;  ///< the first maxIssues issues
  int suppressedIssues = 0;             ///< issues beyond maxIssues
  /// Smallest min(h0+, h0-) over faces satisfying constraint 1 (+inf if unbounded or none).
  double minCrustHeight = std::numeric_limits<double>::infinity();

  /// @brief True when no constraint is violated.
  bool ok() const { return issues.empty() && suppressedIssues == 0; }
  /// @brief Number of listed issues of constraint @p c.
  int count(int c) const;
};

/// @brief Checks the three DDF constraints of chapter 3 on @p ddf.
///
/// Constraint 1: every vector is nonzero and points to the front side of every incident face
/// (v . n_f > 0); a zero-area face has no front side and is reported too. Constraint 2: support
/// vertices at the same position (e.g. an unwelded STL) carry the same vector. Constraint 3: the
/// crust heights h0 of both sides of every face are >= minCrustHeight, and (optionally) the +-1
/// crusts of faces sharing no vertex do not intersect (coincident vertices count as shared).
/// Faces failing constraint 1 are not checked for crust heights.
ValidationReport validate(const DisplacementField& ddf, const ValidationParams& params = {});

}  // namespace ddfcam::ddf
