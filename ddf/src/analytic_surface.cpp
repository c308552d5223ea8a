// SPDX-License-Identifier: MIT
// ddfcam: exact analytic surfaces (implicit function + normal), the oracles of the generators.
#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ddfcam::ddf {

namespace {

std::string describe(const char* kind, std::initializer_list<std::pair<const char*, double>> ps) {
  std::ostringstream out;
  out << kind;
  for (const auto& [key, value] : ps) out << ' ' << key << '=' << value;
  return out.str();
}

}  // namespace

std::string PlaneSurface::name() const {
  return describe("plane", {{"z", z_}});
}

SphereSurface::SphereSurface(double radiusMm) : radius_(radiusMm) {
  if (!(radiusMm > 0.0)) throw InvalidInput("sphere radius must be positive");
}

std::string SphereSurface::name() const {
  return describe("sphere", {{"R", radius_}});
}

CylinderSurface::CylinderSurface(double radiusMm) : radius_(radiusMm) {
  if (!(radiusMm > 0.0)) throw InvalidInput("cylinder radius must be positive");
}

double CylinderSurface::value(const Vec3& x) const {
  return std::hypot(x.x(), x.y()) - radius_;
}

Vec3 CylinderSurface::gradient(const Vec3& x) const {
  const double rho = std::hypot(x.x(), x.y());
  return {x.x() / rho, x.y() / rho, 0.0};
}

std::string CylinderSurface::name() const {
  return describe("cylinder", {{"r", radius_}});
}

TorusSurface::TorusSurface(double majorRadiusMm, double minorRadiusMm)
    : major_(majorRadiusMm), minor_(minorRadiusMm) {
  if (!(minorRadiusMm > 0.0) || !(majorRadiusMm > minorRadiusMm)) {
    throw InvalidInput("torus needs 0 < minor radius < major radius");
  }
}

double TorusSurface::value(const Vec3& x) const {
  return std::hypot(std::hypot(x.x(), x.y()) - major_, x.z()) - minor_;
}

Vec3 TorusSurface::gradient(const Vec3& x) const {
  const double rho = std::hypot(x.x(), x.y());
  const double dr = rho - major_;
  const double d = std::hypot(dr, x.z());
  const double radial = dr / d / rho;
  return {radial * x.x(), radial * x.y(), x.z() / d};
}

Vec3 TorusSurface::point(double u, double v) const {
  const double rho = major_ + minor_ * std::cos(v);
  return {rho * std::cos(u), rho * std::sin(u), minor_ * std::sin(v)};
}

std::string TorusSurface::name() const {
  return describe("torus", {{"R", major_}, {"r", minor_}});
}

Vec3 HeightFieldSurface::gradient(const Vec3& x) const {
  const HeightDerivatives d = evaluate(x.x(), x.y());
  return {-d.fx, -d.fy, 1.0};
}

double HeightFieldSurface::valueAndGradient(const Vec3& x, Vec3& grad) const {
  const HeightDerivatives d = evaluate(x.x(), x.y());
  grad = {-d.fx, -d.fy, 1.0};
  return x.z() - d.f;
}

std::pair<double, double> HeightFieldSurface::principalCurvatures(double x, double y) const {
  const HeightDerivatives d = evaluate(x, y);
  const double w2 = 1.0 + d.fx * d.fx + d.fy * d.fy;
  const double w = std::sqrt(w2);
  const double gauss = (d.fxx * d.fyy - d.fxy * d.fxy) / (w2 * w2);
  const double mean =
      ((1.0 + d.fy * d.fy) * d.fxx - 2.0 * d.fx * d.fy * d.fxy + (1.0 + d.fx * d.fx) * d.fyy) /
      (2.0 * w2 * w);
  // H^2 - K >= 0 analytically; rounding can make it slightly negative at umbilics.
  const double root = std::sqrt(std::max(0.0, mean * mean - gauss));
  return {mean + root, mean - root};
}

RaisedHeightField::RaisedHeightField(std::shared_ptr<const HeightFieldSurface> base,
                                     double offsetMm)
    : base_(std::move(base)), offset_(offsetMm) {
  if (!base_) throw InvalidInput("raised height field needs a base surface");
}

HeightDerivatives RaisedHeightField::evaluate(double x, double y) const {
  HeightDerivatives d = base_->evaluate(x, y);
  d.f += offset_;
  return d;
}

std::string RaisedHeightField::name() const {
  std::ostringstream out;
  out << base_->name() << " raised by " << offset_ << " mm";
  return out.str();
}

HeightDerivatives SaddleSurface::evaluate(double x, double y) const {
  return {a_ * x * x - b_ * y * y, 2.0 * a_ * x, -2.0 * b_ * y, 2.0 * a_, 0.0, -2.0 * b_};
}

std::string SaddleSurface::name() const {
  return describe("saddle", {{"a", a_}, {"b", b_}});
}

SinSinSurface::SinSinSurface(double amplitudeMm, double scaleMm)
    : amplitude_(amplitudeMm), scale_(scaleMm) {
  if (!(scaleMm > 0.0)) throw InvalidInput("sin x sin y surface needs a positive scale");
}

double SinSinSurface::height(double x, double y) const {
  return amplitude_ * std::sin(x / scale_) * std::sin(y / scale_);
}

HeightDerivatives SinSinSurface::evaluate(double x, double y) const {
  const double sx = std::sin(x / scale_), cx = std::cos(x / scale_);
  const double sy = std::sin(y / scale_), cy = std::cos(y / scale_);
  const double a1 = amplitude_ / scale_;
  const double a2 = a1 / scale_;
  return {amplitude_ * sx * sy, a1 * cx * sy, a1 * sx * cy,
          -a2 * sx * sy,        a2 * cx * cy, -a2 * sx * sy};
}

std::string SinSinSurface::name() const {
  return describe("sin x sin y", {{"A", amplitude_}, {"s", scale_}});
}

EllipsoidSurface::EllipsoidSurface(double aMm, double bMm, double cMm) : axes_(aMm, bMm, cMm) {
  if (!(aMm > 0.0 && bMm > 0.0 && cMm > 0.0))
    throw InvalidInput("ellipsoid semi-axes must be positive");
}

double EllipsoidSurface::value(const Vec3& x) const {
  return 0.5 * axes_.minCoeff() * (x.cwiseQuotient(axes_).squaredNorm() - 1.0);
}

Vec3 EllipsoidSurface::gradient(const Vec3& x) const {
  return axes_.minCoeff() * x.cwiseQuotient(axes_.cwiseProduct(axes_));
}

std::string EllipsoidSurface::name() const {
  return describe("ellipsoid", {{"a", axes_.x()}, {"b", axes_.y()}, {"c", axes_.z()}});
}

}  // namespace ddfcam::ddf
