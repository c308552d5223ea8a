// SPDX-License-Identifier: MIT
// ddfcam: exact analytic surfaces (implicit function + normal), the oracles of the generators.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <memory>
#include <string>
#include <utility>

namespace ddfcam::ddf {

/// @brief An exact surface given implicitly: value(x) = 0 exactly on the surface, value < 0 on
/// the back (material) side and > 0 on the front side the unit normal points to.
///
/// For the closed shapes (plane, sphere, cylinder, torus) value is the signed Euclidean distance,
/// mm. For graph surfaces z = f(x, y) (HeightFieldSurface) value is z - f(x, y), mm along z: zero
/// exactly on the surface with the same sign convention, but not a distance (|grad| = W =
/// sqrt(1 + fx^2 + fy^2) >= 1, so |value| over-estimates the distance by at most the factor W).
/// Instances are immutable and thread-safe.
class AnalyticSurface {
 public:
  virtual ~AnalyticSurface() = default;
  /// @brief Implicit function at @p x (part frame, mm); see the class comment for its scale.
  virtual double value(const Vec3& x) const = 0;
  /// @brief Gradient of value() at @p x; undefined on the singular set (sphere centre,
  /// cylinder axis, torus core circle).
  virtual Vec3 gradient(const Vec3& x) const = 0;
  /// @brief value() and gradient() at @p x in one call (root finders need both); the default
  /// calls the two, implementations override it when they share work.
  /// @param grad receives the gradient.
  virtual double valueAndGradient(const Vec3& x, Vec3& grad) const {
    grad = gradient(x);
    return value(x);
  }
  /// @brief Unit normal of the level set through @p x (normalized gradient), pointing to the
  /// front side: outward for sphere, cylinder and torus, +z side for the plane and graphs.
  Vec3 normal(const Vec3& x) const { return gradient(x).normalized(); }
  /// @brief True if value() is a signed Euclidean distance (|grad| = 1 everywhere).
  virtual bool isDistance() const = 0;
  /// @brief Short human-readable description with parameters, e.g. "sphere R=10".
  virtual std::string name() const = 0;
};

/// @brief The plane z = c with normal +z.
class PlaneSurface : public AnalyticSurface {
 public:
  /// @param zMm height c of the plane, mm.
  explicit PlaneSurface(double zMm) : z_(zMm) {}
  double value(const Vec3& x) const override { return x.z() - z_; }
  Vec3 gradient(const Vec3&) const override { return Vec3::UnitZ(); }
  bool isDistance() const override { return true; }
  std::string name() const override;
  double z() const { return z_; }

 private:
  double z_;
};

/// @brief Sphere of radius R centred at the origin, outward normal; value = |x| - R.
class SphereSurface : public AnalyticSurface {
 public:
  /// @param radiusMm R > 0, mm.
  /// @throws InvalidInput if R <= 0.
  explicit SphereSurface(double radiusMm);
  double value(const Vec3& x) const override { return x.norm() - radius_; }
  Vec3 gradient(const Vec3& x) const override { return x.normalized(); }
  bool isDistance() const override { return true; }
  std::string name() const override;
  double radius() const { return radius_; }

 private:
  double radius_;
};

/// @brief Infinite circular cylinder of radius r around the z axis, outward normal;
/// value = sqrt(x^2 + y^2) - r.
class CylinderSurface : public AnalyticSurface {
 public:
  /// @param radiusMm r > 0, mm.
  /// @throws InvalidInput if r <= 0.
  explicit CylinderSurface(double radiusMm);
  double value(const Vec3& x) const override;
  Vec3 gradient(const Vec3& x) const override;
  bool isDistance() const override { return true; }
  std::string name() const override;
  double radius() const { return radius_; }

 private:
  double radius_;
};

/// @brief Torus around the z axis, centred at the origin: major radius R (axis to tube centre),
/// minor radius r (tube); points ((R + r cos v) cos u, (R + r cos v) sin u, r sin v); outward
/// normal; value = sqrt((sqrt(x^2 + y^2) - R)^2 + z^2) - r.
class TorusSurface : public AnalyticSurface {
 public:
  /// @throws InvalidInput unless 0 < r < R.
  TorusSurface(double majorRadiusMm, double minorRadiusMm);
  double value(const Vec3& x) const override;
  Vec3 gradient(const Vec3& x) const override;
  bool isDistance() const override { return true; }
  std::string name() const override;
  double majorRadius() const { return major_; }
  double minorRadius() const { return minor_; }
  /// @brief Surface point at angles (u around the z axis, v around the tube), rad.
  Vec3 point(double u, double v) const;

 private:
  double major_;
  double minor_;
};

/// @brief Height f(x, y), mm, and its partial derivatives up to second order at one (x, y).
struct HeightDerivatives {
  double f = 0.0;    ///< height, mm
  double fx = 0.0;   ///< df/dx
  double fy = 0.0;   ///< df/dy
  double fxx = 0.0;  ///< d2f/dx2, 1/mm
  double fxy = 0.0;  ///< d2f/dxdy, 1/mm
  double fyy = 0.0;  ///< d2f/dy2, 1/mm
};

/// @brief A graph surface z = f(x, y) defined for all (x, y) (implementations extend beyond
/// their nominal domain smoothly). value = z - f(x, y) (not a distance, see AnalyticSurface);
/// normal = (-fx, -fy, 1)/W, the upward side is the front.
class HeightFieldSurface : public AnalyticSurface {
 public:
  /// @brief f and its derivatives at (x, y), mm.
  virtual HeightDerivatives evaluate(double x, double y) const = 0;
  /// @brief f(x, y), mm. Default: evaluate(x, y).f; override when cheaper.
  virtual double height(double x, double y) const { return evaluate(x, y).f; }

  double value(const Vec3& x) const override { return x.z() - height(x.x(), x.y()); }
  Vec3 gradient(const Vec3& x) const override;
  double valueAndGradient(const Vec3& x, Vec3& grad) const override;
  bool isDistance() const override { return false; }
  /// @brief The surface point (x, y, f(x, y)), mm.
  Vec3 pointAbove(double x, double y) const { return {x, y, height(x, y)}; }
  /// @brief Principal curvatures (k1 >= k2), 1/mm, of the second fundamental form with respect
  /// to the upward unit normal (Monge patch formulas): z = x^2 has k1 = 2 at the origin, the
  /// peak of z = sin x sin y has k1 = k2 = -1.
  std::pair<double, double> principalCurvatures(double x, double y) const;
};

/// @brief The graph surface z = f(x, y) + offset of another height field: a stock allowance
/// measured along z (the normal allowance is offset / W, i.e. offset times the cosine of the
/// slope angle).
class RaisedHeightField : public HeightFieldSurface {
 public:
  /// @param base the design surface f (not null). @param offsetMm added height, mm.
  /// @throws InvalidInput if @p base is null.
  RaisedHeightField(std::shared_ptr<const HeightFieldSurface> base, double offsetMm);
  HeightDerivatives evaluate(double x, double y) const override;
  double height(double x, double y) const override { return base_->height(x, y) + offset_; }
  std::string name() const override;
  const HeightFieldSurface& base() const { return *base_; }
  double offset() const { return offset_; }

 private:
  std::shared_ptr<const HeightFieldSurface> base_;
  double offset_;
};

/// @brief Saddle z = a x^2 - b y^2 (a = b = 0 gives the plane z = 0; z = xy is this saddle
/// with a = b = 1/2 rotated by 45 degrees).
class SaddleSurface : public HeightFieldSurface {
 public:
  /// @param a, b curvature coefficients, 1/mm.
  SaddleSurface(double a, double b) : a_(a), b_(b) {}
  HeightDerivatives evaluate(double x, double y) const override;
  double height(double x, double y) const override { return a_ * x * x - b_ * y * y; }
  std::string name() const override;

 private:
  double a_;
  double b_;
};

/// @brief Egg-crate z = A sin(x/s) sin(y/s); A = s = 1 is the curvature oracle z = sin x sin y.
class SinSinSurface : public HeightFieldSurface {
 public:
  /// @param amplitudeMm A, mm. @param scaleMm s > 0, mm (period 2 pi s).
  /// @throws InvalidInput if s <= 0.
  explicit SinSinSurface(double amplitudeMm = 1.0, double scaleMm = 1.0);
  HeightDerivatives evaluate(double x, double y) const override;
  double height(double x, double y) const override;
  std::string name() const override;

 private:
  double amplitude_;
  double scale_;
};

/// @brief Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 centred at the origin, outward normal;
/// value = (x^2/a^2 + y^2/b^2 + z^2/c^2 - 1) min(a, b, c) / 2 (not a distance; |grad| = 1 at
/// the ends of the shortest axis). The (3, 2, 1) ellipsoid is the umbilic oracle.
class EllipsoidSurface : public AnalyticSurface {
 public:
  /// @param aMm, bMm, cMm semi-axes along x, y, z, mm.
  /// @throws InvalidInput unless all are positive.
  EllipsoidSurface(double aMm, double bMm, double cMm);
  double value(const Vec3& x) const override;
  Vec3 gradient(const Vec3& x) const override;
  bool isDistance() const override { return false; }
  std::string name() const override;
  /// @brief Semi-axes (a, b, c), mm.
  const Vec3& axes() const { return axes_; }

 private:
  Vec3 axes_;
};

}  // namespace ddfcam::ddf
