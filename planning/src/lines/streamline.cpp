// SPDX-License-Identifier: MIT
// ddfcam: RK4 streamlines of a line field in the support faces' parameter domains (sec. 8.3).
#include "streamline_common.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/lines/streamline_continuous.h>
#include <ddfcam/planning/lines/streamline_raster_walk.h>

#include <algorithm>
#include <optional>
#include <string>

namespace ddfcam::planning {
namespace {

using namespace detail;

// Consecutive crossings without progress before the line gives up: more than a vertex's fan.
constexpr int kMaxIdleCrossings = 24;

class Tracer {
 public:
  Tracer(const FieldSampler& sampler, const StopRules& rules, const StreamlineParams& params,
         double stepMm)
      : sampler_(sampler), rules_(rules), params_(params), step_(stepMm) {}

  // One classical RK4 step of length s from (face, bary); nullopt at a singularity.
  std::optional<FieldSample> rk4(int face, const Vec3& bary, const Vec3& ref, double s) const {
    const auto k1 = sampler_.sample(face, bary, ref);
    if (!k1) return std::nullopt;
    const auto k2 = sampler_.sample(face, bary + 0.5 * s * k1->dBary, k1->dir);
    if (!k2) return std::nullopt;
    const auto k3 = sampler_.sample(face, bary + 0.5 * s * k2->dBary, k2->dir);
    if (!k3) return std::nullopt;
    const auto k4 = sampler_.sample(face, bary + s * k3->dBary, k3->dir);
    if (!k4) return std::nullopt;
    const Vec3 dir = k1->dir + 2.0 * k2->dir + 2.0 * k3->dir + k4->dir;
    return FieldSample{dir.normalized(),
                       s / 6.0 * (k1->dBary + 2.0 * k2->dBary + 2.0 * k3->dBary + k4->dBary),
                       k1->normal};
  }

  HalfLine traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                     int stepBudget) const;

 private:
  // Where a step from @p bary by @p delta leaves face @p face: the edge point, moved onto the
  // neighbouring face; nullopt when it stays inside. Sets @p edgeStop when there is no
  // neighbour or the mask forbids it (the point then stays in @p face).
  std::optional<SurfaceLocation> crossEdge(int face, const Vec3& bary, const Vec3& delta,
                                           std::optional<StopReason>& edgeStop) const;

  const FieldSampler& sampler_;
  const StopRules& rules_;
  const StreamlineParams& params_;
  double step_;
};

std::optional<SurfaceLocation> Tracer::crossEdge(int face, const Vec3& bary, const Vec3& delta,
                                                 std::optional<StopReason>& edgeStop) const {
  const Vec3 end = bary + delta;
  int exit = -1;
  double t = 1.0;
  for (int c = 0; c < 3; ++c) {
    if (end[c] >= -1e-14) continue;  // rounding of a step along an edge stays inside
    const double tc = bary[c] <= 0.0 ? 0.0 : bary[c] / (bary[c] - end[c]);
    if (exit < 0 || tc < t) exit = c, t = tc;
  }
  if (exit < 0) return std::nullopt;
  Vec3 cross = bary + t * delta;
  cross[exit] = 0.0;
  cross = clampBary(cross);
  const int next = faceAcross(sampler_.ddf(), face, exit);
  if (next < 0)
    edgeStop = StopReason::Boundary;
  else if (!rules_.allowed(next))
    edgeStop = StopReason::RegionBoundary;
  if (edgeStop) return sampler_.locate(face, cross);
  return sampler_.locate(next, mapAcross(sampler_.ddf(), face, next, cross, exit));
}

HalfLine Tracer::traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                           int stepBudget) const {
  HalfLine half;
  SurfaceLocation cur = seed;
  Vec3 ref = dir0;
  int idle = 0;
  for (;;) {
    const std::optional<double> length =
        nextStepLength(half, step_, lengthBudget, stepBudget, params_);
    if (!length) return half;  // MaxLength
    const double s = *length;
    const auto step = rk4(cur.face, cur.bary, ref, s);
    if (!step) {
      half.stop = StopReason::Singularity;
      return half;
    }
    ++half.steps;
    ref = step->dir;
    std::optional<StopReason> edgeStop;
    auto crossed = crossEdge(cur.face, cur.bary, step->dBary, edgeStop);
    SurfaceLocation next =
        crossed ? *crossed : sampler_.locate(cur.face, clampBary(cur.bary + step->dBary));
    const double moved = (next.point - cur.point).norm();
    if (crossed && !edgeStop && moved <= kNoProgress * step_) {
      if (++idle > kMaxIdleCrossings) {
        half.stop = StopReason::Singularity;
        return half;
      }
      cur = next;  // same point, now in the neighbouring face
      continue;
    }
    idle = 0;
    if (appendPoint(half, next, moved, edgeStop, rules_, seed)) return half;
    cur = next;
  }
}

}  // namespace

Streamline traceStreamline(const ddf::DisplacementField& ddf, const LineField& field,
                           const ddf::SurfaceLocation& seed, const StreamlineParams& params) {
  return traceWith(ddf, field, seed, params, "traceStreamline",
                   [&](const FieldSampler& sampler, const StopRules& rules, double stepMm) {
                     return Tracer(sampler, rules, params, stepMm);
                   });
}

Streamline traceStreamlineWith(StreamlineMethod method, const ddf::DisplacementField& ddf,
                               const LineField& field, const ddf::SurfaceLocation& seed,
                               const StreamlineParams& params) {
  return traceStreamlineWith(method, ddf, field, seed, params, {}, {});
}

Streamline traceStreamlineWith(StreamlineMethod method, const ddf::DisplacementField& ddf,
                               const LineField& field, const ddf::SurfaceLocation& seed,
                               const StreamlineParams& params, const RasterWalkParams& walk,
                               const ContinuousStreamlineParams& continuous) {
  switch (method) {
    case StreamlineMethod::Rk4:
      return traceStreamline(ddf, field, seed, params);
    case StreamlineMethod::RasterWalk:
      return traceStreamlineRasterWalk(ddf, field, seed, params, walk);
    case StreamlineMethod::Continuous:
      return traceStreamlineContinuous(ddf, field, seed, params, continuous);
  }
  throw InvalidInput("traceStreamlineWith: unknown streamline method " +
                     std::to_string(static_cast<int>(method)));
}

const char* streamlineMethodName(StreamlineMethod method) {
  switch (method) {
    case StreamlineMethod::Rk4:
      return "rk4";
    case StreamlineMethod::RasterWalk:
      return "raster-walk";
    case StreamlineMethod::Continuous:
      return "continuous";
  }
  return "unknown";
}

}  // namespace ddfcam::planning
