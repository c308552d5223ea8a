// SPDX-License-Identifier: MIT
// Test support: errors of a CurvatureField against the exact curvature of an analytic surface.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/analysis/curvature.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::test {

/// Exact principal curvatures (tool-side convention) and directions at a surface point.
struct CurvatureTruth {
  double kMax = 0.0, kMin = 0.0;
  ddf::Vec3 dirMax, dirMin;
};

/// From the implicit function: S = sign * P Hess P / |grad| on the tangent plane (P the
/// tangent projector); sign = +1 when the tool is on the front side of @p s. The Hessian is a
/// central difference of the analytic gradient (relative error ~1e-9).
inline CurvatureTruth curvatureTruth(const ddf::AnalyticSurface& s, const ddf::Vec3& x,
                                     double sign) {
  const ddf::Vec3 g = s.gradient(x);
  const ddf::Vec3 n = g.normalized();
  const double e = 1e-5 * (1.0 + x.norm());
  Eigen::Matrix3d hess;
  for (int a = 0; a < 3; ++a) {
    const ddf::Vec3 da = ddf::Vec3::Unit(a) * e;
    hess.col(a) = (s.gradient(x + da) - s.gradient(x - da)) / (2.0 * e);
  }
  hess = 0.5 * (hess + hess.transpose()).eval();
  const ddf::Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  Eigen::Matrix2d s2;
  s2 << t1.dot(hess * t1), t1.dot(hess * t2), t2.dot(hess * t1), t2.dot(hess * t2);
  s2 *= sign / g.norm();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s2);
  CurvatureTruth t;
  t.kMin = es.eigenvalues()[0];
  t.kMax = es.eigenvalues()[1];
  t.dirMin = es.eigenvectors()(0, 0) * t1 + es.eigenvectors()(1, 0) * t2;
  t.dirMax = es.eigenvectors()(0, 1) * t1 + es.eigenvectors()(1, 1) * t2;
  return t;
}

/// RMS and max of the k errors (both curvatures, 1/mm) and of the kMax direction angle (deg,
/// sign-free, only where the true anisotropy exceeds 10 % of the part's largest |k|).
struct ErrorStats {
  double kRms = 0.0, kMax = 0.0, angleRmsDeg = 0.0, angleMaxDeg = 0.0;
  std::size_t points = 0, directionPoints = 0;
  void add(double dk1, double dk2, double angleDeg, bool withDirection) {
    kRms += dk1 * dk1 + dk2 * dk2;
    kMax = std::max({kMax, std::abs(dk1), std::abs(dk2)});
    points += 2;
    if (withDirection) {
      angleRmsDeg += angleDeg * angleDeg;
      angleMaxDeg = std::max(angleMaxDeg, angleDeg);
      ++directionPoints;
    }
  }
  void finish() {
    kRms = points ? std::sqrt(kRms / points) : 0.0;
    angleRmsDeg = directionPoints ? std::sqrt(angleRmsDeg / directionPoints) : 0.0;
  }
};

/// Errors split by where a point's stencil lies: inside its face, across a seam into a
/// neighbour, or on a face touching the open boundary of the support.
struct CurvatureErrors {
  ErrorStats interior, seam, boundary;
  double spacingMm = 0.0;  ///< mean raster spacing along rows
};

inline CurvatureErrors curvatureErrors(const ddf::GeneratedSurface& part,
                                       const planning::CurvatureField& c, double sign) {
  const ddf::DisplacementField& ddf = part.ddf;
  const int n = ddf.raster().steps();
  const int reach = 2 * c.step;  // the fourth-order stencils sample up to 2 d steps away
  const auto& mesh = ddf.support();
  std::vector<CurvatureTruth> truth(c.size());
  double kScale = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const std::size_t at = f * ddf.pointsPerFace() + ddf.raster().index(i, k);
        truth[at] = curvatureTruth(*part.surface, ddf.surfacePoint(f, i, k), sign);
        kScale = std::max({kScale, std::abs(truth[at].kMax), std::abs(truth[at].kMin)});
      }
  CurvatureErrors out;
  double spacing = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    bool boundaryFace = false;
    for (int v : ddf.faceVertices(f)) boundaryFace |= mesh.is_boundary(mesh.vertex_handle(v));
    spacing += (ddf.surfacePoint(f, 1, 0) - ddf.surfacePoint(f, 0, 0)).norm();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const int j = n - i - k;
        const std::size_t at = f * ddf.pointsPerFace() + ddf.raster().index(i, k);
        const CurvatureTruth& t = truth[at];
        const double cosA = std::min(1.0, std::abs(c.dirMax[at].dot(t.dirMax)));
        const double angle = std::acos(cosA) * 180.0 / std::numbers::pi;
        const bool aniso = t.kMax - t.kMin > 0.1 * kScale;
        ErrorStats& s = boundaryFace                               ? out.boundary
                        : (i >= reach && j >= reach && k >= reach) ? out.interior
                                                                   : out.seam;
        s.add(c.kMax[at] - t.kMax, c.kMin[at] - t.kMin, angle, aniso);
      }
  }
  out.interior.finish();
  out.seam.finish();
  out.boundary.finish();
  out.spacingMm = spacing / ddf.faceCount();
  return out;
}

}  // namespace ddfcam::test
