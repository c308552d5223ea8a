// SPDX-License-Identifier: MIT
// ddfcam: the tool flow field (sec. 8.1, fig. 8.4c): raw field, region mask and Ceres smoothing.
#include <ddfcam/error.h>
#include <ddfcam/planning/flow/flow_field.h>

#include "field_frames.h"
#include "flow_solver.h"
#include "flow_strokes.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>

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
  if (params.source == FlowFieldSource::UserStrokes && params.strokes.empty())
    throw InvalidInput("flowField: the UserStrokes source needs at least one stroke");
  if (!(params.smoothnessWeight >= 0.0))
    throw InvalidInput("flowField: smoothnessWeight must be >= 0");
  if (params.iterations < 1) throw InvalidInput("flowField: iterations must be >= 1");
  if (!params.faceMask.empty() &&
      params.faceMask.size() != static_cast<std::size_t>(ddf.faceCount()))
    throw InvalidInput("flowField: the face mask has " + std::to_string(params.faceMask.size()) +
                       " entries, the DDF " + std::to_string(ddf.faceCount()) + " faces");
  if (!(params.strokeRadiusSpacings > 0.0))
    throw InvalidInput("flowField: strokeRadiusSpacings must be > 0");
  if (params.relaxationSweeps < 0) throw InvalidInput("flowField: relaxationSweeps must be >= 0");
  if (params.directSolveLimit < 1) throw InvalidInput("flowField: directSolveLimit must be >= 1");
}

// A point belongs to the region when any of its copies lies on a region face.
std::vector<std::uint8_t> activePoints(const ddf::DisplacementField& ddf,
                                       const SurfaceFrames& frames, const FlowFieldParams& params) {
  std::vector<std::uint8_t> active(frames.position.size(), params.faceMask.empty() ? 1 : 0);
  if (params.faceMask.empty()) return active;
  const std::size_t perFace = ddf.pointsPerFace();
  for (std::size_t copy = 0; copy < frames.idOfCopy.size(); ++copy)
    if (params.faceMask[copy / perFace]) active[frames.idOfCopy[copy]] = 1;
  return active;
}

Vec3 sourceDirection(const CurvatureField& c, const FlowFieldParams& params, std::size_t copy) {
  switch (params.source) {
    case FlowFieldSource::MaxCurvatureDirection:
      return c.dirMax[copy];
    case FlowFieldSource::MinCurvatureDirection:
      return c.dirMin[copy];
    case FlowFieldSource::FixedDirection:
    case FlowFieldSource::UserStrokes:
      break;
  }
  return params.fixedDirection.normalized();
}

// Averaging doubled angles over the copies makes the point's line independent of every sign.
RawField directionField(const CurvatureField& c, const FlowFieldParams& params,
                        const SurfaceFrames& frames, const std::vector<std::uint8_t>& active) {
  const std::size_t points = frames.position.size();
  std::vector<Complex> sum(points, 0.0);
  std::vector<double> anisotropy(points, 0.0);
  std::vector<int> copies(points, 0);
  for (std::size_t copy = 0; copy < frames.idOfCopy.size(); ++copy) {
    const PointId p = frames.idOfCopy[copy];
    if (!active[p]) continue;
    sum[p] += detail::doubledAngle(frames, p, sourceDirection(c, params, copy));
    anisotropy[p] += std::abs(static_cast<double>(c.kMax[copy]) - c.kMin[copy]);
    ++copies[p];
  }
  const bool curvatureWeights =
      params.anisotropyWeighting && params.source != FlowFieldSource::FixedDirection;
  RawField raw{std::vector<Complex>(points, 0.0), std::vector<double>(points, 0.0)};
  for (std::size_t p = 0; p < points; ++p) {
    if (!active[p] || std::abs(sum[p]) <= 1e-6 * copies[p]) continue;
    raw.target[p] = sum[p] / std::abs(sum[p]);
    raw.weight[p] = curvatureWeights ? anisotropy[p] / copies[p] * std::sqrt(frames.area[p]) : 1.0;
  }
  return raw;
}

// With smoothing only points near a stroke carry data; without, every point takes its nearest.
RawField strokeField(const FlowFieldParams& params, const SurfaceFrames& frames,
                     const std::vector<std::uint8_t>& active, bool smoothing) {
  const double radius =
      smoothing ? params.strokeRadiusSpacings * detail::meanEdgeLength(frames) : 0.0;
  RawField raw{detail::strokeTargets(frames, active, params.strokes, radius), {}};
  const auto defined = [](const Complex& t) { return std::abs(t) > 0.0; };
  if (radius > 0.0 && std::none_of(raw.target.begin(), raw.target.end(), defined))
    raw.target = detail::strokeTargets(frames, active, params.strokes, 0.0);  // strokes far off
  raw.weight.resize(raw.target.size());
  for (std::size_t p = 0; p < raw.target.size(); ++p)
    raw.weight[p] = defined(raw.target[p]) ? 1.0 : 0.0;
  return raw;
}

// The least-squares problem over the region's points, numbered compactly.
detail::FieldProblem fieldProblem(const SurfaceFrames& frames, const RawField& raw,
                                  const std::vector<std::uint32_t>& local, double lambda) {
  detail::FieldProblem fp;
  for (std::size_t p = 0; p < local.size(); ++p)
    if (local[p] != std::numeric_limits<std::uint32_t>::max()) {
      fp.target.push_back(raw.target[p]);
      fp.weight2.push_back(raw.weight[p] * raw.weight[p]);
    }
  fp.edges.reserve(frames.edges.size());
  for (const auto& [p, q] : frames.edges)
    if (local[p] != std::numeric_limits<std::uint32_t>::max() &&
        local[q] != std::numeric_limits<std::uint32_t>::max()) {
      const double phase = 2.0 * detail::transportAngle(frames, p, q);
      fp.edges.push_back({local[p], local[q], lambda, phase, 0.0, std::polar(1.0, phase)});
    }
  return fp;
}

std::vector<Complex> smooth(const SurfaceFrames& frames, const RawField& raw,
                            const std::vector<std::uint8_t>& active,
                            const FlowFieldParams& params) {
  std::vector<std::uint32_t> local(active.size(), std::numeric_limits<std::uint32_t>::max());
  std::uint32_t count = 0;
  for (std::size_t p = 0; p < active.size(); ++p)
    if (active[p]) local[p] = count++;
  const detail::FieldProblem fp = fieldProblem(frames, raw, local, params.smoothnessWeight);
  detail::FieldSolveSettings settings;
  settings.direct = params.solver == FlowFieldSolver::Direct;
  settings.directSolveLimit = params.directSolveLimit;
  settings.sweeps = params.relaxationSweeps;
  settings.iterations = params.iterations;
  if (params.progress)
    settings.progress = [&params](double f) { return params.progress(0.2 + 0.7 * f); };
  reportProgress(params.progress, 0.2);
  const std::vector<Complex> z = detail::solveFieldProblem(fp, fp.target, settings);
  std::vector<Complex> out(active.size(), 0.0);
  for (std::size_t p = 0; p < active.size(); ++p)
    if (active[p]) out[p] = z[local[p]];
  return out;
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
  const std::vector<std::uint8_t> active = activePoints(ddf, frames, params);
  const bool smoothing = params.smoothing && params.smoothnessWeight > 0.0;
  const RawField raw = params.source == FlowFieldSource::UserStrokes
                           ? strokeField(params, frames, active, smoothing)
                           : directionField(curvature, params, frames, active);
  reportProgress(params.progress, 0.1);
  const bool anyData =
      std::any_of(raw.weight.begin(), raw.weight.end(), [](double w) { return w > 0.0; });
  LineField out =
      expand(frames, smoothing && anyData ? smooth(frames, raw, active, params) : raw.target);
  reportProgress(params.progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
