// SPDX-License-Identifier: MIT
// ddfcam: V-shooting in affine (translation-invariant) form.
#include <ddfcam/ddf/v_shooting.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace ddfcam::ddf {
namespace {

/// Target plane data: normal n_t, and per barycentric coordinate j its gradient g_j and the
/// reference vertex r_j on the opposite edge, so that lambda_j(x) = g_j . (x - r_j).
struct TargetFrame {
  Vec3 q1;
  Vec3 normal;
  double normalNorm = 0.0;
  std::array<Vec3, 3> gradient;
  std::array<Vec3, 3> reference;
};

std::optional<TargetFrame> makeTargetFrame(const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                           double degenerateTolerance) {
  TargetFrame t;
  t.q1 = q1;
  t.normal = (q2 - q1).cross(q3 - q1);
  const double n2 = t.normal.squaredNorm();
  t.normalNorm = std::sqrt(n2);
  const double longest =
      std::max({(q2 - q1).squaredNorm(), (q3 - q2).squaredNorm(), (q1 - q3).squaredNorm()});
  if (!(t.normalNorm > degenerateTolerance * longest) || n2 == 0.0) return std::nullopt;
  // g_j lies in the plane, is perpendicular to the edge opposite q_j and has length 1/height_j.
  t.gradient = {t.normal.cross(q3 - q2) / n2, t.normal.cross(q1 - q3) / n2,
                t.normal.cross(q2 - q1) / n2};
  t.reference = {q2, q3, q1};
  return t;
}

std::optional<VShot> shootFrame(const TargetFrame& t, const Vec3& p, const Vec3& v,
                                double parallelTolerance) {
  const double denom = v.dot(t.normal);
  if (!(std::abs(denom) > parallelTolerance * v.norm() * t.normalNorm)) return std::nullopt;
  VShot shot;
  shot.h = -(p - t.q1).dot(t.normal) / denom;
  // Differences first, then the step along v: keeps precision when p is far from the origin.
  for (int j = 0; j < 3; ++j)
    shot.lambda[j] = t.gradient[j].dot(p - t.reference[j]) + shot.h * t.gradient[j].dot(v);
  return shot;
}

}  // namespace

std::optional<VShot> vShootLine(const Vec3& p, const Vec3& v, const Vec3& q1, const Vec3& q2,
                                const Vec3& q3, const VShootParams& params) {
  const auto frame = makeTargetFrame(q1, q2, q3, params.degenerateTolerance);
  if (!frame) return std::nullopt;
  return shootFrame(*frame, p, v, params.parallelTolerance);
}

std::optional<VShot> vShoot(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& v1,
                            const Vec3& v2, const Vec3& v3, const Vec3& mu, const Vec3& q1,
                            const Vec3& q2, const Vec3& q3, const VShootParams& params) {
  const auto frame = makeTargetFrame(q1, q2, q3, params.degenerateTolerance);
  if (!frame) return std::nullopt;
  // p - r written as a combination of differences (sum mu = 1) so that translating everything
  // leaves every intermediate value unchanged.
  const Vec3 pRel = mu[0] * (p1 - q1) + mu[1] * (p2 - q1) + mu[2] * (p3 - q1);
  const Vec3 v = mu[0] * v1 + mu[1] * v2 + mu[2] * v3;
  return shootFrame(*frame, q1 + pRel, v, params.parallelTolerance);
}

std::optional<VShot> vShoot(const DisplacementField& ddf, int face, const Vec3& mu, const Vec3& q1,
                            const Vec3& q2, const Vec3& q3, const VShootParams& params) {
  const auto& fv = ddf.faceVertices(face);
  return vShoot(ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]), ddf.vector(fv[0]),
                ddf.vector(fv[1]), ddf.vector(fv[2]), mu, q1, q2, q3, params);
}

std::optional<VShooter> VShooter::make(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                       const Vec3& v1, const Vec3& v2, const Vec3& v3,
                                       const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                       const VShootParams& params) {
  const auto frame = makeTargetFrame(q1, q2, q3, params.degenerateTolerance);
  if (!frame) return std::nullopt;
  VShooter s;
  const std::array<Vec3, 3> p = {p1, p2, p3};
  const std::array<Vec3, 3> v = {v1, v2, v3};
  for (int i = 0; i < 3; ++i) {
    s.a_[i] = (p[i] - q1).dot(frame->normal);
    s.b_[i] = v[i].dot(frame->normal);
    s.vectors_.col(i) = v[i];
    for (int j = 0; j < 3; ++j) {
      s.lambdaBase_(j, i) = frame->gradient[j].dot(p[i] - frame->reference[j]);
      s.lambdaSlope_(j, i) = frame->gradient[j].dot(v[i]);
    }
  }
  s.normalNorm_ = frame->normalNorm;
  s.parallelTolerance_ = params.parallelTolerance;
  return s;
}

std::optional<VShot> VShooter::shoot(const Vec3& mu) const {
  const double denom = b_.dot(mu);
  const double vNorm = (vectors_ * mu).norm();
  if (!(std::abs(denom) > parallelTolerance_ * vNorm * normalNorm_)) return std::nullopt;
  VShot shot;
  shot.h = -a_.dot(mu) / denom;
  shot.lambda = lambdaBase_ * mu + shot.h * (lambdaSlope_ * mu);
  return shot;
}

}  // namespace ddfcam::ddf
