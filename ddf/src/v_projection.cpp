// SPDX-License-Identifier: MIT
// ddfcam: V-projection by robust real roots of the cubic det[p_i - q + h v_i] = 0.
#include <ddfcam/ddf/v_projection.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ddfcam::ddf {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double evalPoly(const std::array<double, 4>& c, int degree, double x) {
  double y = c[degree];
  for (int k = degree - 1; k >= 0; --k) y = y * x + c[k];
  return y;
}

double evalDerivative(const std::array<double, 4>& c, int degree, double x) {
  double y = degree * c[degree];
  for (int k = degree - 1; k >= 1; --k) y = y * x + k * c[k];
  return y;
}

/// Sum |c_k| |x|^k: the scale of the rounding error of evalPoly at x.
double evalMagnitude(const std::array<double, 4>& c, int degree, double x) {
  double y = std::abs(c[degree]);
  for (int k = degree - 1; k >= 0; --k) y = y * std::abs(x) + std::abs(c[k]);
  return y;
}

/// Roots of a x^2 + b x + c, a != 0, by the cancellation-free formula.
std::vector<double> quadraticRoots(double a, double b, double c) {
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) {
    if (disc < -64.0 * kEps * (b * b + std::abs(4.0 * a * c))) return {};
    return {-b / (2.0 * a)};
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) return {0.0};
  double r1 = q / a, r2 = c / q;
  if (r1 > r2) std::swap(r1, r2);
  if (r1 == r2) return {r1};
  return {r1, r2};
}

/// The root of the cubic in [lo, hi], where it changes sign: Newton steps kept inside the
/// shrinking bracket, bisection when a step would leave it (rtsafe).
double bracketedRoot(const std::array<double, 4>& c, int degree, double lo, double hi) {
  double flo = evalPoly(c, degree, lo);
  if (flo > 0.0) std::swap(lo, hi);  // from here on f(lo) < 0 < f(hi)
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double f = evalPoly(c, degree, x);
    if (f == 0.0) return x;
    (f < 0.0 ? lo : hi) = x;
    const double df = evalDerivative(c, degree, x);
    double next = df != 0.0 ? x - f / df : 0.5 * (lo + hi);
    if (!((next - lo) * (next - hi) < 0.0)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 4.0 * kEps * std::max(std::abs(x), 1e-300)) return next;
    x = next;
  }
  return x;
}

std::vector<double> cubicRoots(const std::array<double, 4>& c) {
  const auto crit = quadraticRoots(3.0 * c[3], 2.0 * c[2], c[1]);
  // Cauchy bound: every root lies in (-bound, bound).
  const double bound =
      1.0 + std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])}) / std::abs(c[3]);
  std::vector<double> breaks = {-bound};
  for (double x : crit)
    if (std::abs(x) < bound) breaks.push_back(x);
  breaks.push_back(bound);
  std::vector<double> roots;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double fl = evalPoly(c, 3, breaks[i]), fr = evalPoly(c, 3, breaks[i + 1]);
    if ((fl < 0.0 && fr > 0.0) || (fl > 0.0 && fr < 0.0))
      roots.push_back(bracketedRoot(c, 3, breaks[i], breaks[i + 1]));
  }
  // A critical point where the value vanishes within rounding is a double (or triple) root.
  for (double x : crit)
    if (std::abs(evalPoly(c, 3, x)) <= 16.0 * kEps * evalMagnitude(c, 3, x)) roots.push_back(x);
  return roots;
}

/// Sorts and merges roots closer than the accuracy of a multiple root.
void sortUnique(std::vector<double>& roots) {
  std::sort(roots.begin(), roots.end());
  std::vector<double> out;
  for (double r : roots)
    if (out.empty() || std::abs(r - out.back()) > 1e-7 * (1.0 + std::abs(r))) out.push_back(r);
  roots = std::move(out);
}

}  // namespace

std::vector<double> realCubicRoots(double c0, double c1, double c2, double c3) {
  std::array<double, 4> c = {c0, c1, c2, c3};
  const double largest = std::max({std::abs(c0), std::abs(c1), std::abs(c2), std::abs(c3)});
  if (largest == 0.0 || !std::isfinite(largest)) return {};
  int degree = 3;
  while (degree > 0 && std::abs(c[degree]) <= 1e-14 * largest) --degree;
  std::vector<double> roots;
  if (degree == 1) roots = {-c[0] / c[1]};
  if (degree == 2) roots = quadraticRoots(c[2], c[1], c[0]);
  if (degree == 3) roots = cubicRoots(c);
  sortUnique(roots);
  return roots;
}

namespace {

/// The system of one V-projection: columns a_i = p_i - q and v_i.
struct ProjectionSystem {
  Eigen::Matrix3d a;
  Eigen::Matrix3d v;

  Eigen::Matrix3d at(double h) const { return a + h * v; }
  /// F(mu1, mu2, h) = sum mu_i (a_i + h v_i), mu3 = 1 - mu1 - mu2.
  Vec3 residual(const Vec3& mu, double h) const { return at(h) * mu; }
};

/// mu spanning the null space of M(h) with sum 1; false if none (rank <= 1 or at infinity).
bool nullVector(const Eigen::Matrix3d& m, Vec3& mu) {
  const std::array<Vec3, 3> cross = {Vec3(m.row(0)).cross(Vec3(m.row(1))),
                                     Vec3(m.row(1)).cross(Vec3(m.row(2))),
                                     Vec3(m.row(2)).cross(Vec3(m.row(0)))};
  const Vec3* best = &cross[0];
  for (const Vec3& c : cross)
    if (c.squaredNorm() > best->squaredNorm()) best = &c;
  const double rowScale = m.squaredNorm();
  if (!(best->norm() > 1e-12 * rowScale)) return false;
  const double sum = best->sum();
  if (!(std::abs(sum) > 1e-12 * best->lpNorm<1>())) return false;
  mu = *best / sum;
  return true;
}

/// Newton steps on (mu1, mu2, h): the Jacobian columns are c1 - c3, c2 - c3 and v(mu).
void polish(const ProjectionSystem& sys, Vec3& mu, double& h, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Matrix3d m = sys.at(h);
    Eigen::Matrix3d jac;
    jac.col(0) = m.col(0) - m.col(2);
    jac.col(1) = m.col(1) - m.col(2);
    jac.col(2) = sys.v * mu;
    Eigen::FullPivLU<Eigen::Matrix3d> lu(jac);
    if (!lu.isInvertible()) return;  // on a fold: the root-based value is the best available
    const Vec3 step = lu.solve(-sys.residual(mu, h));
    mu[0] += step[0];
    mu[1] += step[1];
    mu[2] = 1.0 - mu[0] - mu[1];
    h += step[2];
    if (step.norm() <= 4.0 * kEps * (1.0 + std::abs(h))) return;
  }
}

/// Coefficients of det[a_i + h v_i] in h, lowest degree first.
std::array<double, 4> determinantCubic(const ProjectionSystem& s) {
  auto det = [](const Vec3& x, const Vec3& y, const Vec3& z) { return x.dot(y.cross(z)); };
  const Vec3 a1 = s.a.col(0), a2 = s.a.col(1), a3 = s.a.col(2);
  const Vec3 v1 = s.v.col(0), v2 = s.v.col(1), v3 = s.v.col(2);
  return {det(a1, a2, a3), det(v1, a2, a3) + det(a1, v2, a3) + det(a1, a2, v3),
          det(a1, v2, v3) + det(v1, a2, v3) + det(v1, v2, a3), det(v1, v2, v3)};
}

}  // namespace

std::vector<VProjection> vProject(const Vec3& q, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                  const Vec3& v1, const Vec3& v2, const Vec3& v3,
                                  const VProjectionParams& params) {
  ProjectionSystem sys;
  sys.a << p1 - q, p2 - q, p3 - q;
  sys.v << v1, v2, v3;
  const double aMax = sys.a.colwise().norm().maxCoeff();
  const double vMax = sys.v.colwise().norm().maxCoeff();
  if (!(vMax > 0.0) || !std::isfinite(aMax)) return {};
  // Balance the variable: with h = s t, the coefficients of t are all of the order aMax^3, so
  // relative thresholds on them are meaningful.
  const double s = aMax > 0.0 ? aMax / vMax : 1.0;
  const auto c = determinantCubic(sys);
  const auto roots = realCubicRoots(c[0], c[1] * s, c[2] * s * s, c[3] * s * s * s);
  std::vector<VProjection> out;
  for (double t : roots) {
    VProjection sol;
    sol.h = t * s;
    if (!nullVector(sys.at(sol.h), sol.mu)) continue;
    polish(sys, sol.mu, sol.h, params.newtonIterations);
    const double scale = aMax + std::abs(sol.h) * vMax;
    if (!(sys.residual(sol.mu, sol.h).norm() <= params.residualTolerance * scale)) continue;
    const bool duplicate = std::any_of(out.begin(), out.end(), [&](const VProjection& o) {
      return std::abs(o.h - sol.h) <= 1e-9 * (1.0 + std::abs(sol.h)) &&
             (o.mu - sol.mu).lpNorm<Eigen::Infinity>() <= 1e-9;
    });
    if (duplicate) continue;
    sol.inside = sol.mu.minCoeff() >= -params.insideTolerance;
    out.push_back(sol);
  }
  std::sort(out.begin(), out.end(),
            [](const VProjection& x, const VProjection& y) { return x.h < y.h; });
  return out;
}

std::vector<VProjection> vProject(const DisplacementField& ddf, int face, const Vec3& q,
                                  const VProjectionParams& params) {
  const auto& fv = ddf.faceVertices(face);
  return vProject(q, ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]),
                  ddf.vector(fv[0]), ddf.vector(fv[1]), ddf.vector(fv[2]), params);
}

}  // namespace ddfcam::ddf
