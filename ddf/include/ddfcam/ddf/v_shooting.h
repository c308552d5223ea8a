// SPDX-License-Identifier: MIT
// ddfcam: V-shooting, the intersection of a stubble line with a target triangle's plane (sec. 4.2).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>

#include <optional>

namespace ddfcam::ddf {

/// @brief Result of V-shooting: the stubble line p + h v hits the plane of the target triangle
/// (q1, q2, q3) at q = p + h v = lambda1 q1 + lambda2 q2 + lambda3 q3.
struct VShot {
  double h = 0.0;              ///< height along the stubble, in units of the local vector
  Vec3 lambda = Vec3::Zero();  ///< barycentric coordinates of q on the target, sum 1
};

/// @brief Tolerances of V-shooting.
struct VShootParams {
  /// The line counts as parallel to the target plane when |v . n_t| <= parallelTolerance
  /// |v| |n_t| (the sine of the angle between line and plane). Default 1e-12.
  double parallelTolerance = 1e-12;
  /// The target counts as degenerate when |n_t| <= degenerateTolerance x (longest edge)^2
  /// (twice its area relative to its size). Default 1e-14.
  double degenerateTolerance = 1e-14;
};

/// @brief V-shooting from the point with barycentric coordinates @p mu on the support triangle
/// (p1, p2, p3) with vertex vectors (v1, v2, v3) onto the plane of (q1, q2, q3).
///
/// Uses the affine form h = -((p - q1) . n_t)/(v . n_t), n_t = (q2 - q1) x (q3 - q1), and
/// lambda_j = g_j . (q - r_j) with g_j the gradient of lambda_j and r_j a vertex of the edge
/// opposite q_j. Only coordinate differences enter, so the result is invariant under a common
/// translation of both triangles and needs none of the "translate away from the origin" trick
/// of the dissertation's 3x3 determinants.
/// @param p1,p2,p3 support triangle vertices, mm (part frame).
/// @param v1,v2,v3 displacement vectors at those vertices, mm per unit height.
/// @param mu barycentric coordinates of the stubble origin on the support triangle (sum 1).
/// @param q1,q2,q3 target triangle vertices, mm.
/// @return std::nullopt when the stubble line is parallel to the target plane or the target
/// is degenerate (see VShootParams); otherwise the hit. lambda may lie outside [0, 1]: the
/// caller decides whether the hit is inside the target.
std::optional<VShot> vShoot(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& v1,
                            const Vec3& v2, const Vec3& v3, const Vec3& mu, const Vec3& q1,
                            const Vec3& q2, const Vec3& q3, const VShootParams& params = {});

/// @brief V-shooting from barycentric @p mu of support face @p face of @p ddf onto the plane of
/// (q1, q2, q3); see the raw overload. mu refers to the face's local vertex order
/// ddf.faceVertices(face).
std::optional<VShot> vShoot(const DisplacementField& ddf, int face, const Vec3& mu, const Vec3& q1,
                            const Vec3& q2, const Vec3& q3, const VShootParams& params = {});

/// @brief V-shooting of the line p + h v (any point @p p and direction @p v, mm) onto the plane
/// of (q1, q2, q3); the core of both overloads above.
std::optional<VShot> vShootLine(const Vec3& p, const Vec3& v, const Vec3& q1, const Vec3& q2,
                                const Vec3& q3, const VShootParams& params = {});

/// @brief V-shooting of one support triangle onto one target triangle, prepared for many
/// stubbles (the incremental cutting of ch. 5).
///
/// For a fixed pair of triangles, h(mu) = -(sum mu_i a_i)/(sum mu_i b_i) with
/// a_i = (p_i - q1) . n_t and b_i = v_i . n_t, and lambda_j(mu, h) =
/// sum mu_i (A_ji + h B_ji): both are cheap per stubble once these coefficients are known.
class VShooter {
 public:
  /// @brief Precomputes the coefficients; see vShoot for the parameters.
  /// @return std::nullopt if the target triangle is degenerate.
  static std::optional<VShooter> make(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                      const Vec3& v1, const Vec3& v2, const Vec3& v3,
                                      const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                      const VShootParams& params = {});

  /// @brief The shot from barycentric @p mu; std::nullopt when the stubble is parallel to the
  /// target plane.
  std::optional<VShot> shoot(const Vec3& mu) const;

  /// @brief Numerator coefficients a_i of h (h = -(mu . a)/(mu . b)), mm^3.
  const Vec3& numerator() const { return a_; }
  /// @brief Denominator coefficients b_i of h, mm^3.
  const Vec3& denominator() const { return b_; }

 private:
  VShooter() = default;

  Vec3 a_ = Vec3::Zero();
  Vec3 b_ = Vec3::Zero();
  Eigen::Matrix3d lambdaBase_ = Eigen::Matrix3d::Zero();   // A_ji (row j, column i)
  Eigen::Matrix3d lambdaSlope_ = Eigen::Matrix3d::Zero();  // B_ji
  Eigen::Matrix3d vectors_ = Eigen::Matrix3d::Zero();      // columns v_i
  double normalNorm_ = 0.0;
  double parallelTolerance_ = 0.0;
};

}  // namespace ddfcam::ddf
