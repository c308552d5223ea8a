// SPDX-License-Identifier: MIT
// ddfcam: a uniform bicubic B-spline height patch z = B(x, y), exact evaluation (sec. 6.3).
#include <ddfcam/ddf/bspline_patch.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

namespace ddfcam::ddf {

namespace {

/// The four non-zero uniform cubic basis values of a span and their first and second
/// derivatives with respect to the span parameter u (u in [0, 1] inside the span).
struct SpanBasis {
  int first = 0;  // index of the first of the four control heights
  std::array<double, 4> b{};
  std::array<double, 4> d1{};
  std::array<double, 4> d2{};
};

/// Locates coordinate @p t (in span units from the domain start) and evaluates the basis;
/// beyond the ends the boundary span's polynomials are continued (u < 0 or u > 1).
SpanBasis spanBasis(double t, int spans, bool derivatives) {
  SpanBasis s;
  s.first = std::clamp(static_cast<int>(std::floor(t)), 0, spans - 1);
  const double u = t - s.first;
  const double v = 1.0 - u;
  const double u2 = u * u, u3 = u2 * u;
  s.b = {v * v * v / 6.0, (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0,
         (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0, u3 / 6.0};
  if (derivatives) {
    s.d1 = {-0.5 * v * v, 0.5 * (3.0 * u2 - 4.0 * u), 0.5 * (-3.0 * u2 + 2.0 * u + 1.0), 0.5 * u2};
    s.d2 = {v, 3.0 * u - 2.0, 1.0 - 3.0 * u, u};
  }
  return s;
}

}  // namespace

BSplinePatch::BSplinePatch(const Eigen::Vector2d& origin, const Eigen::Vector2d& size,
                           Eigen::MatrixXd control)
    : origin_(origin), size_(size), control_(std::move(control)) {
  if (!(size.x() > 0.0) || !(size.y() > 0.0)) {
    throw InvalidInput("B-spline patch size must be positive in x and y");
  }
  if (control_.rows() < 4 || control_.cols() < 4) {
    throw InvalidInput("B-spline patch needs at least 4 x 4 control heights, got " +
                       std::to_string(control_.rows()) + " x " + std::to_string(control_.cols()));
  }
  span_ = {size.x() / spansX(), size.y() / spansY()};
}

double BSplinePatch::height(double x, double y) const {
  const SpanBasis bx = spanBasis((x - origin_.x()) / span_.x(), spansX(), false);
  const SpanBasis by = spanBasis((y - origin_.y()) / span_.y(), spansY(), false);
  double z = 0.0;
  for (int a = 0; a < 4; ++a) {
    double row = 0.0;
    for (int b = 0; b < 4; ++b) row += control_(bx.first + a, by.first + b) * by.b[b];
    z += bx.b[a] * row;
  }
  return z;
}

HeightDerivatives BSplinePatch::evaluate(double x, double y) const {
  const SpanBasis bx = spanBasis((x - origin_.x()) / span_.x(), spansX(), true);
  const SpanBasis by = spanBasis((y - origin_.y()) / span_.y(), spansY(), true);
  HeightDerivatives d;
  for (int a = 0; a < 4; ++a) {
    double c0 = 0.0, c1 = 0.0, c2 = 0.0;  // contractions with the y basis and its derivatives
    for (int b = 0; b < 4; ++b) {
      const double c = control_(bx.first + a, by.first + b);
      c0 += c * by.b[b], c1 += c * by.d1[b], c2 += c * by.d2[b];
    }
    d.f += bx.b[a] * c0;
    d.fx += bx.d1[a] * c0;
    d.fy += bx.b[a] * c1;
    d.fxx += bx.d2[a] * c0;
    d.fxy += bx.d1[a] * c1;
    d.fyy += bx.b[a] * c2;
  }
  const double hx = span_.x(), hy = span_.y();
  d.fx /= hx, d.fy /= hy;
  d.fxx /= hx * hx, d.fxy /= hx * hy, d.fyy /= hy * hy;
  return d;
}

Eigen::Vector2d BSplinePatch::controlAbscissa(int i, int j) const {
  return {origin_.x() + (i - 1) * span_.x(), origin_.y() + (j - 1) * span_.y()};
}

std::string BSplinePatch::name() const {
  std::ostringstream out;
  out << "bicubic B-spline " << spansX() << "x" << spansY() << " spans over " << size_.x() << "x"
      << size_.y() << " mm";
  return out.str();
}

BSplinePatch makeBumpPatch(const BumpPatchParams& params) {
  if (params.spansX < 1 || params.spansY < 1) {
    throw InvalidInput("bump patch needs at least one span per direction");
  }
  const int nx = params.spansX + 3, ny = params.spansY + 3;
  const double twoPi = 2.0 * std::numbers::pi;
  Eigen::MatrixXd control(nx, ny);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const double u = (i - 1.0) / params.spansX, v = (j - 1.0) / params.spansY;
      const double wave = 0.55 * std::sin(twoPi * (u + 0.1)) * std::sin(twoPi * (0.75 * v + 0.05));
      const double ripple = 0.3 * std::cos(twoPi * (1.25 * u - 0.5 * v));
      const double du = u - 0.3, dv = v - 0.65;
      const double bump = 0.45 * std::exp(-(du * du + dv * dv) / 0.02);
      control(i, j) = params.amplitudeMm * (wave + ripple + bump);
    }
  }
  return BSplinePatch(params.origin, params.size, std::move(control));
}

}  // namespace ddfcam::ddf
