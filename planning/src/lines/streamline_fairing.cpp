// SPDX-License-Identifier: MIT
// ddfcam: Ceres fairing of streamlines on the DDF surface within a deviation bound (sec. 8.3).
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_fairing.h>

#include "streamline_common.h"
#include "streamline_surface_chart.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;
using Tangent = Eigen::Matrix<double, 3, 2>;
using detail::clampBary;
using detail::polylineLength;
using detail::SurfaceChart;

// Bisection steps of the final pull-back towards the raw point.
constexpr int kPullBackSteps = 30;
// Raw segments on each side of a point's index searched for its distance to the raw line.
constexpr int kSegmentWindow = 3;

// The line's unknowns and cached geometry; the cache is refreshed once per Ceres evaluation
// point by the evaluation callback, so each cost function reads three cached points.
struct FairingState {
  std::vector<SurfaceLocation> raw;           // distinct points (a loop's closing copy dropped)
  std::vector<Tangent> frame;                 // (t, b) at each raw point
  std::vector<std::array<double, 2>> offset;  // (along t, along b), mm
  std::vector<SurfaceLocation> cur;
  std::vector<Tangent> jacobian;  // d cur.point / d offset
  bool closed = false;

  Vec3 target(std::size_t i, double scale) const {
    return raw[i].point + scale * frame[i] * Eigen::Vector2d(offset[i][0], offset[i][1]);
  }
  SurfaceLocation place(const SurfaceChart& chart, std::size_t i, double scale) const {
    return chart.closestNear(raw[i], target(i, scale));
  }
};

class PlaceAll final : public ceres::EvaluationCallback {
 public:
  PlaceAll(const SurfaceChart& chart, FairingState& state) : chart_(chart), state_(state) {}
  void PrepareForEvaluation(bool /*jacobians*/, bool newPoint) override {
    if (!newPoint) return;
    // Starting from the previous evaluation point saves most Gauss-Newton steps.
    for (std::size_t i = 0; i < state_.raw.size(); ++i) {
      Vec3 n;
      state_.cur[i] = chart_.closestNear(state_.cur[i], state_.target(i, 1.0), &n);
      state_.jacobian[i] = (Eigen::Matrix3d::Identity() - n * n.transpose()) * state_.frame[i];
    }
  }

 private:
  const SurfaceChart& chart_;
  FairingState& state_;
};

// Residuals cb (d . b_i) and cs (d . t_i) of d = x_{i-1} - 2 x_i + x_{i+1}.
class SecondDifferenceCost final : public ceres::SizedCostFunction<2, 2, 2, 2> {
 public:
  SecondDifferenceCost(const FairingState& state, std::array<std::size_t, 3> index, double cb,
                       double cs)
      : state_(state), index_(index), cb_(cb), cs_(cs) {}

  bool Evaluate(double const* const* /*x*/, double* r, double** jac) const override {
    const auto& p = state_.cur;
    const Vec3 d = p[index_[0]].point - 2.0 * p[index_[1]].point + p[index_[2]].point;
    const Tangent& tb = state_.frame[index_[1]];
    r[0] = cb_ * d.dot(tb.col(1));
    r[1] = cs_ * d.dot(tb.col(0));
    if (!jac) return true;
    constexpr std::array<double, 3> kWeight = {1.0, -2.0, 1.0};
    for (int k = 0; k < 3; ++k) {
      if (!jac[k]) continue;
      const Tangent& j = state_.jacobian[index_[k]];
      const Eigen::RowVector2d db = kWeight[k] * cb_ * tb.col(1).transpose() * j;
      const Eigen::RowVector2d dt = kWeight[k] * cs_ * tb.col(0).transpose() * j;
      jac[k][0] = db[0], jac[k][1] = db[1], jac[k][2] = dt[0], jac[k][3] = dt[1];
    }
    return true;
  }

 private:
  const FairingState& state_;
  std::array<std::size_t, 3> index_;
  double cb_, cs_;
};

// r = cc * lateral offset.
class ClosenessCost final : public ceres::SizedCostFunction<1, 2> {
 public:
  explicit ClosenessCost(double cc) : cc_(cc) {}
  bool Evaluate(double const* const* x, double* r, double** jac) const override {
    r[0] = cc_ * x[0][1];
    if (jac && jac[0]) jac[0][0] = 0.0, jac[0][1] = cc_;
    return true;
  }

 private:
  double cc_;
};

class ProgressForwarder final : public ceres::IterationCallback {
 public:
  explicit ProgressForwarder(const FairingParams& params) : params_(params) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    const double done = std::min(1.0, (summary.iteration + 1.0) / params_.iterations);
    if (params_.progress && !params_.progress(done)) {
      cancelled_ = true;
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool cancelled() const { return cancelled_; }

 private:
  const FairingParams& params_;
  bool cancelled_ = false;
};

void validate(const ddf::DisplacementField& ddf, const Streamline& raw,
              const FairingParams& params) {
  if (!(params.deviationMm > 0.0) || !std::isfinite(params.deviationMm))
    throw InvalidInput("fairStreamline: deviationMm must be finite and > 0");
  if (!(params.bendingWeight >= 0.0) || !(params.spacingWeight >= 0.0) ||
      !(params.closenessWeight >= 0.0))
    throw InvalidInput("fairStreamline: weights must be >= 0");
  if (!(params.maxSlide >= 0.0 && params.maxSlide <= 0.5))
    throw InvalidInput("fairStreamline: maxSlide must be in [0, 0.5]");
  if (params.iterations < 1) throw InvalidInput("fairStreamline: iterations must be >= 1");
  for (std::size_t i = 0; i < raw.points.size(); ++i) {
    const SurfaceLocation& p = raw.points[i];
    if (p.face < 0 || p.face >= ddf.faceCount())
      throw InvalidInput("fairStreamline: point " + std::to_string(i) + " has face " +
                         std::to_string(p.face) + " out of range [0, " +
                         std::to_string(ddf.faceCount()) + ")");
    if (!p.bary.allFinite())
      throw InvalidInput("fairStreamline: point " + std::to_string(i) +
                         " has non-finite barycentric coordinates");
  }
}

std::size_t wrap(std::ptrdiff_t i, std::size_t n, bool closed) {
  const auto sn = static_cast<std::ptrdiff_t>(n);
  if (closed) return static_cast<std::size_t>(((i % sn) + sn) % sn);
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, sn - 1));
}

// (t, b) at raw point i: t along the chord over four segments (which averages out a zig-zag)
// in the tangent plane, b = n x t.
Tangent rawFrame(const SurfaceChart& chart, const FairingState& s, std::size_t i) {
  const std::size_t n = s.raw.size();
  const auto si = static_cast<std::ptrdiff_t>(i);
  const Vec3 normal = chart.normal(s.raw[i]);
  Vec3 t = Vec3::Zero();
  for (int reach = 2; reach >= 1 && t.norm() < 1e-12; --reach) {
    t = s.raw[wrap(si + reach, n, s.closed)].point - s.raw[wrap(si - reach, n, s.closed)].point;
    t -= t.dot(normal) * normal;
  }
  if (t.norm() < 1e-12) t = normal.unitOrthogonal();
  t.normalize();
  Tangent out;
  out.col(0) = t;
  out.col(1) = normal.cross(t);
  return out;
}

double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

// Distance of @p q to the raw segments within kSegmentWindow of index i: an upper bound of
// its distance to the whole raw line.
double distanceToRaw(const FairingState& s, std::size_t i, const Vec3& q) {
  const std::size_t n = s.raw.size();
  const auto si = static_cast<std::ptrdiff_t>(i);
  double best = (q - s.raw[i].point).norm();
  for (std::ptrdiff_t j = si - kSegmentWindow; j < si + kSegmentWindow; ++j) {
    if (!s.closed && (j < 0 || j + 1 >= static_cast<std::ptrdiff_t>(n))) continue;
    best = std::min(best, segmentDistance(q, s.raw[wrap(j, n, s.closed)].point,
                                          s.raw[wrap(j + 1, n, s.closed)].point));
  }
  return best;
}

void buildProblem(ceres::Problem& problem, FairingState& s, const FairingParams& params,
                  double lengthMm, double spacingMm) {
  const std::size_t n = s.raw.size();
  const double scale = std::sqrt(lengthMm / (spacingMm * spacingMm * spacingMm));
  const double cb = std::sqrt(params.bendingWeight) * scale;
  const double cs = std::sqrt(params.spacingWeight) * scale;
  const double cc = std::sqrt(params.closenessWeight * spacingMm / lengthMm) / params.deviationMm;
  for (std::size_t i = 0; i < n; ++i) {
    double* u = s.offset[i].data();
    problem.AddParameterBlock(u, 2);
    problem.SetParameterLowerBound(u, 0, -params.maxSlide * spacingMm);
    problem.SetParameterUpperBound(u, 0, params.maxSlide * spacingMm);
    problem.SetParameterLowerBound(u, 1, -params.deviationMm);
    problem.SetParameterUpperBound(u, 1, params.deviationMm);
    if (cc > 0.0) problem.AddResidualBlock(new ClosenessCost(cc), nullptr, u);
  }
  const std::size_t first = s.closed ? 0 : 1, last = s.closed ? n : n - 1;
  for (std::size_t i = first; i < last; ++i) {
    const std::array<std::size_t, 3> idx = {wrap(static_cast<std::ptrdiff_t>(i) - 1, n, s.closed),
                                            i,
                                            wrap(static_cast<std::ptrdiff_t>(i) + 1, n, s.closed)};
    problem.AddResidualBlock(new SecondDifferenceCost(s, idx, cb, cs), nullptr,
                             s.offset[idx[0]].data(), s.offset[idx[1]].data(),
                             s.offset[idx[2]].data());
  }
  if (!s.closed && params.fixEnds) {
    problem.SetParameterBlockConstant(s.offset.front().data());
    problem.SetParameterBlockConstant(s.offset.back().data());
  }
}

void solve(ceres::Problem& problem, const FairingParams& params) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = params.iterations;
  options.initial_trust_region_radius = 1e8;
  // Past a relative change of 1e-6 the points move by far less than a micrometre.
  options.function_tolerance = 1e-6;
  options.parameter_tolerance = 1e-12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ProgressForwarder forwarder(params);
  options.callbacks.push_back(&forwarder);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (forwarder.cancelled()) throw Cancelled();
}

// Final placement: each point from its solved offset, pulled back by bisection on the offset's
// scale where it ends farther than the bound from the raw line (scale 0 is the raw point).
std::vector<SurfaceLocation> finalPoints(const SurfaceChart& chart, const FairingState& s,
                                         double deviationMm) {
  std::vector<SurfaceLocation> out(s.raw.size());
  for (std::size_t i = 0; i < s.raw.size(); ++i) {
    out[i] = s.place(chart, i, 1.0);
    if (distanceToRaw(s, i, out[i].point) <= deviationMm) continue;
    double lo = 0.0, hi = 1.0;
    for (int step = 0; step < kPullBackSteps; ++step) {
      const double mid = 0.5 * (lo + hi);
      (distanceToRaw(s, i, s.place(chart, i, mid).point) <= deviationMm ? lo : hi) = mid;
    }
    out[i] = s.place(chart, i, lo);
  }
  return out;
}

}  // namespace

Streamline fairStreamline(const ddf::DisplacementField& ddf, const Streamline& raw,
                          const FairingParams& params) {
  validate(ddf, raw, params);
  const SurfaceChart chart(ddf);
  FairingState s;
  for (const SurfaceLocation& p : raw.points)
    s.raw.push_back(chart.locate(p.face, clampBary(p.bary)));
  Streamline out = raw;
  out.points = s.raw;
  const double rawLength = polylineLength(s.raw);
  s.closed = s.raw.size() > 3 &&
             (s.raw.front().point - s.raw.back().point).norm() <= 1e-9 * (1.0 + rawLength);
  if (s.closed) s.raw.pop_back();
  const std::size_t n = s.raw.size();
  const std::size_t segments = s.closed ? n : n - 1;
  if (n < 3 || !(rawLength > 0.0)) {
    out.lengthMm = rawLength;
    return out;
  }
  const double spacing = rawLength / static_cast<double>(segments);
  for (std::size_t i = 0; i < n; ++i) s.frame.push_back(rawFrame(chart, s, i));
  s.offset.assign(n, {0.0, 0.0});
  s.cur = s.raw;
  s.jacobian.assign(n, Tangent::Zero());

  PlaceAll placeAll(chart, s);
  ceres::Problem::Options problemOptions;
  problemOptions.evaluation_callback = &placeAll;
  ceres::Problem problem(problemOptions);
  buildProblem(problem, s, params, rawLength, spacing);
  solve(problem, params);

  out.points = finalPoints(chart, s, params.deviationMm);
  if (s.closed) out.points.push_back(out.points.front());
  out.lengthMm = polylineLength(out.points);
  return out;
}

}  // namespace ddfcam::planning
