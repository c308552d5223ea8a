// SPDX-License-Identifier: MIT
// ddfcam: the tool flow field (sec. 8.1, fig. 8.4c): raw field and Ceres smoothing.
#include <ddfcam/error.h>
#include <ddfcam/planning/flow_field.h>

#include "field_frames.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <thread>

namespace ddfcam::planning {

namespace {

using Complex = std::complex<double>;
using ddf::PointId;
using ddf::Vec3;
using detail::SurfaceFrames;

// Per distinct raster point: the raw doubled-angle target (unit or 0) and its data weight.
struct RawField {
  std::vector<Complex> target;
  std::vector<double> weight;
};

void validate(const ddf::DisplacementField& ddf, const CurvatureField& curvature,
              const FlowFieldParams& params) {
  if (ddf.faceCount() == 0) throw InvalidInput("flowField: the DDF has no faces");
  const std::size_t expected = ddf.pointsPerFace() * ddf.faceCount();
  if (curvature.size() != expected || curvature.kMin.size() != expected ||
      curvature.dirMax.size() != expected || curvature.dirMin.size() != expected)
    throw InvalidInput("flowField: the curvature field has " + std::to_string(curvature.size()) +
                       " entries, the DDF " + std::to_string(expected) + " raster point copies");
  if (params.source == FlowFieldSource::FixedDirection &&
      !(params.fixedDirection.allFinite() && params.fixedDirection.norm() > 0.0))
    throw InvalidInput("flowField: the fixed direction must be finite and non-zero");
  if (!(params.smoothnessWeight >= 0.0))
    throw InvalidInput("flowField: smoothnessWeight must be >= 0");
  if (params.iterations < 1) throw InvalidInput("flowField: iterations must be >= 1");
}

Vec3 sourceDirection(const CurvatureField& c, const FlowFieldParams& params, std::size_t copy) {
  switch (params.source) {
    case FlowFieldSource::MaxCurvatureDirection:
      return c.dirMax[copy];
    case FlowFieldSource::MinCurvatureDirection:
      return c.dirMin[copy];
    case FlowFieldSource::FixedDirection:
      break;
  }
  return params.fixedDirection.normalized();
}

// Averaging doubled angles over the copies makes the point's line independent of every sign.
RawField rawField(const CurvatureField& c, const FlowFieldParams& params,
                  const SurfaceFrames& frames) {
  const std::size_t points = frames.position.size();
  std::vector<Complex> sum(points, 0.0);
  std::vector<double> anisotropy(points, 0.0);
  std::vector<int> copies(points, 0);
  for (std::size_t copy = 0; copy < frames.idOfCopy.size(); ++copy) {
    const PointId p = frames.idOfCopy[copy];
    sum[p] += detail::doubledAngle(frames, p, sourceDirection(c, params, copy));
    anisotropy[p] += std::abs(static_cast<double>(c.kMax[copy]) - c.kMin[copy]);
    ++copies[p];
  }
  const bool curvatureWeights =
      params.anisotropyWeighting && params.source != FlowFieldSource::FixedDirection;
  RawField raw{std::vector<Complex>(points, 0.0), std::vector<double>(points, 0.0)};
  for (std::size_t p = 0; p < points; ++p) {
    if (std::abs(sum[p]) <= 1e-6 * copies[p]) continue;
    raw.target[p] = sum[p] / std::abs(sum[p]);
    raw.weight[p] = curvatureWeights ? anisotropy[p] / copies[p] * std::sqrt(frames.area[p]) : 1.0;
  }
  return raw;
}

// r = w (z - t): ties a point's doubled-angle vector to its raw target.
class DataCost final : public ceres::SizedCostFunction<2, 2> {
 public:
  DataCost(double weight, Complex target) : w_(weight), t_(target) {}
  bool Evaluate(double const* const* x, double* r, double** jac) const override {
    r[0] = w_ * (x[0][0] - t_.real());
    r[1] = w_ * (x[0][1] - t_.imag());
    if (jac && jac[0]) {
      jac[0][0] = w_, jac[0][1] = 0.0, jac[0][2] = 0.0, jac[0][3] = w_;
    }
    return true;
  }

 private:
  double w_;
  Complex t_;
};

// r = s (z_q - e^{i phi} z_p): the line at q against the line at p transported to q.
class EdgeCost final : public ceres::SizedCostFunction<2, 2, 2> {
 public:
  EdgeCost(double weight, double phi) : s_(weight), c_(std::cos(phi)), n_(std::sin(phi)) {}
  bool Evaluate(double const* const* x, double* r, double** jac) const override {
    const double* zp = x[0];
    const double* zq = x[1];
    r[0] = s_ * (zq[0] - (c_ * zp[0] - n_ * zp[1]));
    r[1] = s_ * (zq[1] - (n_ * zp[0] + c_ * zp[1]));
    if (jac && jac[0]) {
      jac[0][0] = -s_ * c_, jac[0][1] = s_ * n_, jac[0][2] = -s_ * n_, jac[0][3] = -s_ * c_;
    }
    if (jac && jac[1]) {
      jac[1][0] = s_, jac[1][1] = 0.0, jac[1][2] = 0.0, jac[1][3] = s_;
    }
    return true;
  }

 private:
  double s_, c_, n_;
};

// Forwards Ceres iterations to the progress callback; a refusal aborts the solve.
class ProgressForwarder final : public ceres::IterationCallback {
 public:
  explicit ProgressForwarder(const FlowFieldParams& params) : params_(params) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    const double done = std::min(1.0, (summary.iteration + 1.0) / params_.iterations);
    if (params_.progress && !params_.progress(0.2 + 0.7 * done)) {
      cancelled_ = true;
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool cancelled() const { return cancelled_; }

 private:
  const FlowFieldParams& params_;
  bool cancelled_ = false;
};

void solve(ceres::Problem& problem, const FlowFieldParams& params) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = params.iterations;
  // The problem is linear: a huge trust region makes the first step the exact Gauss-Newton one.
  options.initial_trust_region_radius = 1e12;
  options.num_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ProgressForwarder forwarder(params);
  options.callbacks.push_back(&forwarder);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (forwarder.cancelled()) throw Cancelled();
}

std::vector<Complex> smooth(const SurfaceFrames& frames, const RawField& raw,
                            const FlowFieldParams& params) {
  std::vector<Complex> z = raw.target;
  auto* data = reinterpret_cast<double*>(z.data());  // std::complex is layout-compatible
  ceres::Problem problem;
  for (std::size_t p = 0; p < z.size(); ++p) problem.AddParameterBlock(data + 2 * p, 2);
  for (std::size_t p = 0; p < z.size(); ++p)
    if (raw.weight[p] > 0.0)
      problem.AddResidualBlock(new DataCost(raw.weight[p], raw.target[p]), nullptr, data + 2 * p);
  const double s = std::sqrt(params.smoothnessWeight);
  for (const auto& [p, q] : frames.edges)
    problem.AddResidualBlock(new EdgeCost(s, 2.0 * detail::transportAngle(frames, p, q)), nullptr,
                             data + 2 * p, data + 2 * q);
  reportProgress(params.progress, 0.2);
  solve(problem, params);
  return z;
}

LineField expand(const SurfaceFrames& frames, const std::vector<Complex>& z) {
  double largest = 0.0;
  for (const Complex& v : z) largest = std::max(largest, std::abs(v));
  LineField out(frames.idOfCopy.size(), Vec3::Zero());
  for (std::size_t copy = 0; copy < out.size(); ++copy) {
    const PointId p = frames.idOfCopy[copy];
    if (std::abs(z[p]) > 1e-12 * largest) out[copy] = detail::lineOf(frames, p, z[p]);
  }
  return out;
}

}  // namespace

LineField flowField(const ddf::DisplacementField& ddf, const CurvatureField& curvature,
                    const FlowFieldParams& params) {
  validate(ddf, curvature, params);
  reportProgress(params.progress, 0.0);
  const SurfaceFrames frames = detail::buildSurfaceFrames(ddf);
  const RawField raw = rawField(curvature, params, frames);
  reportProgress(params.progress, 0.1);
  const bool anyData =
      std::any_of(raw.weight.begin(), raw.weight.end(), [](double w) { return w > 0.0; });
  const bool smoothed = params.smoothing && params.smoothnessWeight > 0.0 && anyData;
  LineField out = expand(frames, smoothed ? smooth(frames, raw, params) : raw.target);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
