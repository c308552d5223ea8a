// SPDX-License-Identifier: MIT
// ddfcam: V-projection of a point onto a support triangle along its vector field (sec. 4.1).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>

#include <vector>

namespace ddfcam::ddf {

/// @brief One V-projection of a point q: q = sum mu_i (p_i + h v_i), sum mu_i = 1.
struct VProjection {
  double h = 0.0;          ///< height along the stubble, in units of the local vector
  Vec3 mu = Vec3::Zero();  ///< barycentric coordinates of the foot point on the support plane
  bool inside = false;     ///< every mu_i >= -insideTolerance: the foot lies on the triangle
};

/// @brief Tolerances of V-projection.
struct VProjectionParams {
  /// A solution is inside the triangle when every mu_i >= -insideTolerance. Default 1e-9.
  double insideTolerance = 1e-9;
  /// Newton steps on the full system (mu1, mu2, h) that polish every root. Default 4.
  int newtonIterations = 4;
  /// A polished solution is kept when |sum mu_i (p_i + h v_i) - q| <= residualTolerance x
  /// (max_i |p_i - q| + |h| max_i |v_i|). Default 1e-7.
  double residualTolerance = 1e-7;
};

/// @brief All V-projections of @p q onto the plane of the support triangle (p1, p2, p3) with
/// vertex vectors (v1, v2, v3).
///
/// The 4x4 determinant of sec. 4.1 is evaluated as det[p_i - q + h v_i], a cubic in h with
/// coefficients built from differences only (translation invariant). Its real roots are
/// isolated between the critical points and refined by safeguarded Newton steps; leading
/// coefficients that vanish relative to the others degrade it to a quadratic or linear
/// equation (e.g. all v_i parallel: a parallel projection has exactly one solution). For each
/// root mu spans the null space of the 3x3 system; a few Newton steps on (mu1, mu2, h) polish
/// both. Roots whose null vector has sum 0 (foot at infinity) are dropped.
/// @param q point to project, mm.
/// @param p1,p2,p3 support triangle vertices, mm. @param v1,v2,v3 vertex vectors, mm.
/// @return 0..3 solutions sorted by increasing h. Empty also when q makes the system
/// degenerate (a continuum of solutions, e.g. q on a degenerate offset triangle).
std::vector<VProjection> vProject(const Vec3& q, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                  const Vec3& v1, const Vec3& v2, const Vec3& v3,
                                  const VProjectionParams& params = {});

/// @brief All V-projections of @p q onto support face @p face of @p ddf (mu in the face's local
/// vertex order ddf.faceVertices(face)); see the raw overload.
std::vector<VProjection> vProject(const DisplacementField& ddf, int face, const Vec3& q,
                                  const VProjectionParams& params = {});

/// @brief Real roots of c3 x^3 + c2 x^2 + c1 x + c0, sorted ascending, multiple roots once.
/// Leading coefficients with |c_k| <= 1e-14 max_j |c_j| lower the degree (scale the variable
/// first so that the roots of interest are of order 1). A zero polynomial has no listed roots.
std::vector<double> realCubicRoots(double c0, double c1, double c2, double c3);

}  // namespace ddfcam::ddf
