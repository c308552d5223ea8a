// SPDX-License-Identifier: MIT
// ddfcam: a uniform bicubic B-spline height patch z = B(x, y), exact evaluation (sec. 6.3).
#pragma once

#include <ddfcam/ddf/analytic_surface.h>

#include <Eigen/Core>

namespace ddfcam::ddf {

/// @brief Free-form height patch z = B(x, y) = sum_ij c_ij N_i(x) N_j(y) with uniform cubic
/// B-spline bases over the rectangle [x0, x0 + width] x [y0, y0 + depth].
///
/// With sx x sy uniform spans there are (sx + 3) x (sy + 3) control heights; N_i is the cubic
/// B-spline centred at the Greville abscissa x0 + (i - 1) width/sx (likewise in y). Because the
/// bases form a partition of unity and reproduce linear functions, control heights taken from a
/// plane a + b x + c y at the abscissae give exactly that plane. Outside the rectangle the
/// polynomial piece of the nearest boundary span is continued, so B is C^2 inside and C-infinity
/// (polynomial) beyond the boundary spans. Evaluation is exact up to double rounding.
class BSplinePatch : public HeightFieldSurface {
 public:
  /// @param origin (x0, y0), mm.
  /// @param size (width, depth) > 0, mm.
  /// @param control (sx + 3) x (sy + 3) control heights, mm, c(i, j) belongs to abscissa
  ///   controlAbscissa(i, j); at least 4 x 4 (one span each way).
  /// @throws InvalidInput for a non-positive size or fewer than 4 control heights per direction.
  BSplinePatch(const Eigen::Vector2d& origin, const Eigen::Vector2d& size, Eigen::MatrixXd control);

  HeightDerivatives evaluate(double x, double y) const override;
  double height(double x, double y) const override;
  std::string name() const override;

  /// @brief Greville abscissa (x, y), mm, of control height (i, j); may lie one span outside
  /// the rectangle.
  Eigen::Vector2d controlAbscissa(int i, int j) const;
  /// @brief Control heights, (sx + 3) x (sy + 3), mm.
  const Eigen::MatrixXd& control() const { return control_; }
  int spansX() const { return static_cast<int>(control_.rows()) - 3; }
  int spansY() const { return static_cast<int>(control_.cols()) - 3; }
  const Eigen::Vector2d& origin() const { return origin_; }
  const Eigen::Vector2d& size() const { return size_; }

 private:
  Eigen::Vector2d origin_;
  Eigen::Vector2d size_;
  Eigen::Vector2d span_;  // span width in x and y, mm
  Eigen::MatrixXd control_;
};

/// @brief Parameters of the deterministic smooth "bumps" control heights.
struct BumpPatchParams {
  Eigen::Vector2d origin{0.0, 0.0};    ///< (x0, y0), mm (default: origin)
  Eigen::Vector2d size{100.0, 100.0};  ///< (width, depth), mm (default: 100 x 100)
  int spansX = 10;                     ///< B-spline spans in x (default: 10)
  int spansY = 10;                     ///< B-spline spans in y (default: 10)
  double amplitudeMm = 8.0;            ///< peak-to-mean height scale A, mm (default: 8)
};

/// @brief A smooth free-form B-spline patch standing in for the dissertation's fig. 6.17 patch
/// (whose control net is not published): control heights sampled at the Greville abscissae
/// from A [0.55 sin(2 pi (u + 0.1)) sin(2 pi (0.75 v + 0.05)) + 0.3 cos(2 pi (1.25 u - 0.5 v))
/// + 0.45 exp(-((u - 0.3)^2 + (v - 0.65)^2)/0.02)] with (u, v) in [0, 1]^2 the relative position
/// in the rectangle: one large wave, a diagonal ripple and a Gaussian bump.
/// @throws InvalidInput for a non-positive size or fewer than 1 span per direction.
BSplinePatch makeBumpPatch(const BumpPatchParams& params);

}  // namespace ddfcam::ddf
