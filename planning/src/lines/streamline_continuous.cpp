// SPDX-License-Identifier: MIT
// ddfcam: streamlines stepped in 3D and re-projected onto the DDF by V-projection (sec. 8.3).
#include "streamline_common.h"

#include <ddfcam/ddf/v_projection.h>
#include <ddfcam/planning/lines/streamline_continuous.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace ddfcam::planning {
namespace {

using namespace detail;

// Feet this far outside a face still count as on it (rounding of a point on a seam).
constexpr double kInsideTolerance = 1e-12;
// Roots of the V-projection with |h| above this (in vector units) are far outside the +-1
// crust that holds the surface, so they cannot be the point near the surface.
constexpr double kMaxRootHeight = 2.0;
// The roots of the cubic are refined to rounding already; one Newton polish of (mu, h) is
// enough and halves the cost of a re-projection, the bulk of the method's time.
constexpr ddf::VProjectionParams kProjection{.newtonIterations = 1};
// Consecutive edge cuts without progress before the line gives up: more than a vertex's fan.
constexpr int kMaxIdleCuts = 24;

// Newton iterations of the local V-projection before the closed-form cubic takes over.
constexpr int kLocalNewtonIterations = 5;

// V-projection of @p q onto @p face by Newton's method on g(mu) + h v(mu) = q from a nearby
// (mu, h): a short step from a point on the surface lands next to it, and a few 3x3 solves
// are far cheaper than the cubic of ddf::vProject with all its roots. Returns the foot mu
// only when Newton converges; the caller checks that it lies on the face.
std::optional<Vec3> localVProjection(const ddf::DisplacementField& ddf, int face, const Vec3& q,
                                     Vec3 mu, double h) {
  const auto& fv = ddf.faceVertices(face);
  const Vec3 &p1 = ddf.position(fv[0]), &p2 = ddf.position(fv[1]), &p3 = ddf.position(fv[2]);
  const Vec3 &v1 = ddf.vector(fv[0]), &v2 = ddf.vector(fv[1]), &v3 = ddf.vector(fv[2]);
  for (int it = 0; it < kLocalNewtonIterations; ++it) {
    const Vec3 v = mu[0] * v1 + mu[1] * v2 + mu[2] * v3;
    const Vec3 r = mu[0] * p1 + mu[1] * p2 + mu[2] * p3 + h * v - q;
    Eigen::Matrix3d j;
    j.col(0) = (p1 - p2) + h * (v1 - v2);
    j.col(1) = (p3 - p2) + h * (v3 - v2);
    j.col(2) = v;
    const Vec3 d = j.partialPivLu().solve(-r);
    if (!d.allFinite()) return std::nullopt;
    mu[0] += d[0], mu[2] += d[1], mu[1] = 1.0 - mu[0] - mu[2], h += d[2];
    if (std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])}) < 1e-13)
      return std::abs(h) <= kMaxRootHeight ? std::optional<Vec3>(mu) : std::nullopt;
  }
  return std::nullopt;
}

// Runge-Kutta tableau of an explicit scheme: stage i starts at p + s sum_j a[i][j] k_j.
struct Tableau {
  int stages = 1;
  std::array<std::array<double, 3>, 4> a{};
  std::array<double, 4> b{};
};

Tableau tableau(ContinuousIntegrator integrator) {
  switch (integrator) {
    case ContinuousIntegrator::Euler:
      return {1, {}, {1.0}};
    case ContinuousIntegrator::Heun:
      return {2, {{{}, {1.0}}}, {0.5, 0.5}};
    case ContinuousIntegrator::Rk4:
      break;
  }
  return {4, {{{}, {0.5}, {0.0, 0.5}, {0.0, 0.0, 1.0}}}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};
}

// The end of one step: the next point, or a stop (with the point where the line ends, if it
// moved before stopping).
struct StepEnd {
  std::optional<SurfaceLocation> point;
  std::optional<StopReason> stop;
};

class Stepper {
 public:
  Stepper(const FieldSampler& sampler, const StopRules& rules, const StreamlineParams& params,
          const ddf::CrustHash& hash, ContinuousIntegrator integrator, double stepMm)
      : sampler_(sampler),
        ddf_(sampler.ddf()),
        rules_(rules),
        params_(params),
        hash_(hash),
        tableau_(tableau(integrator)),
        step_(stepMm) {}

  HalfLine traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                     int stepBudget) const;

 private:
  // The re-projection of @p q: on prev's face if its foot lies there, else the nearest.
  std::optional<SurfaceLocation> project(const Vec3& q, const SurfaceLocation& prev) const;
  // The re-projection of @p q nearest @p prev over the hash's candidate faces; nullopt when no
  // root has its foot on an allowed face or a forbidden face is nearer.
  std::optional<SurfaceLocation> nearestProjection(const Vec3& q, const Vec3& prev) const;
  // One step of length s from @p cur with first stage @p k1 (ref of the next step in @p dir).
  StepEnd step(const SurfaceLocation& cur, const FieldSample& k1, double s, Vec3& dir) const;
  // Where the V-projection of @p q onto cur's face leaves the face from cur: the edge point,
  // moved into the neighbouring face, or a stop at an open or forbidden edge.
  StepEnd cutAtEdge(const SurfaceLocation& cur, const Vec3& q) const;

  const FieldSampler& sampler_;
  const ddf::DisplacementField& ddf_;
  const StopRules& rules_;
  const StreamlineParams& params_;
  const ddf::CrustHash& hash_;
  Tableau tableau_;
  double step_;
  mutable std::vector<int> candidates_;  // reused buffer of project()
};

std::optional<SurfaceLocation> Stepper::project(const Vec3& q, const SurfaceLocation& prev) const {
  // Nearly every step ends on the previous face: its root with the foot on the face continues
  // the line, so the hash is only asked when that face has none.
  if (rules_.allowed(prev.face)) {
    if (const auto mu = localVProjection(ddf_, prev.face, q, prev.bary, prev.h);
        mu && mu->minCoeff() >= -kInsideTolerance)
      return sampler_.locate(prev.face, clampBary(*mu));
    for (const ddf::VProjection& root : ddf::vProject(ddf_, prev.face, q, kProjection)) {
      if (root.mu.allFinite() && root.mu.minCoeff() >= -kInsideTolerance &&
          std::abs(root.h) <= kMaxRootHeight)
        return sampler_.locate(prev.face, clampBary(root.mu));
    }
  }
  return nearestProjection(q, prev.point);
}

std::optional<SurfaceLocation> Stepper::nearestProjection(const Vec3& q, const Vec3& prev) const {
  hash_.queryBox(Eigen::AlignedBox3d(q, q), candidates_);
  std::optional<SurfaceLocation> best;
  bool bestAllowed = false;
  double bestDist = std::numeric_limits<double>::infinity();
  for (const int face : candidates_) {
    const bool allowed = rules_.allowed(face);
    for (const ddf::VProjection& root : ddf::vProject(ddf_, face, q, kProjection)) {
      if (!root.mu.allFinite() || root.mu.minCoeff() < -kInsideTolerance ||
          !(std::abs(root.h) <= kMaxRootHeight))
        continue;
      const SurfaceLocation loc = sampler_.locate(face, clampBary(root.mu));
      const double dist = (loc.point - prev).norm();
      // On a seam both faces give the same point: an allowed face wins the tie.
      const bool tie = std::abs(dist - bestDist) <= kNoProgress * step_;
      if (tie ? (allowed && !bestAllowed) : dist < bestDist)
        best = loc, bestAllowed = allowed, bestDist = std::min(dist, bestDist);
    }
  }
  if (!best || !bestAllowed) return std::nullopt;
  return best;
}

StepEnd Stepper::step(const SurfaceLocation& cur, const FieldSample& k1, double s,
                      Vec3& dir) const {
  std::array<Vec3, 4> k{k1.dir};
  for (int i = 1; i < tableau_.stages; ++i) {
    Vec3 q = cur.point;
    for (int j = 0; j < i; ++j) q += s * tableau_.a[i][j] * k[j];
    const auto at = project(q, cur);
    if (!at) return cutAtEdge(cur, cur.point + s * k1.dir);
    const auto sample = sampler_.sample(at->face, at->bary, k[i - 1]);
    if (!sample) return {std::nullopt, StopReason::Singularity};
    k[i] = sample->dir;
  }
  Vec3 q = cur.point, mean = Vec3::Zero();
  for (int i = 0; i < tableau_.stages; ++i)
    q += s * tableau_.b[i] * k[i], mean += tableau_.b[i] * k[i];
  dir = mean.normalized();
  const auto next = project(q, cur);
  if (!next) return cutAtEdge(cur, cur.point + s * k1.dir);
  return {next, std::nullopt};
}

StepEnd Stepper::cutAtEdge(const SurfaceLocation& cur, const Vec3& q) const {
  Vec3 mu = Vec3::Zero();
  double bestGap = std::numeric_limits<double>::infinity();
  for (const ddf::VProjection& root : ddf::vProject(ddf_, cur.face, q)) {
    if (!root.mu.allFinite() || !std::isfinite(root.h)) continue;
    const double gap = std::abs(root.h - sampler_.locate(cur.face, clampBary(root.mu)).h);
    if (gap < bestGap) bestGap = gap, mu = root.mu;
  }
  if (!(bestGap < std::numeric_limits<double>::infinity()))
    return {std::nullopt, StopReason::Boundary};
  if (mu.minCoeff() >= -kInsideTolerance) return {sampler_.locate(cur.face, mu), std::nullopt};
  int exit = -1;
  double t = 1.0;
  for (int c = 0; c < 3; ++c) {
    if (mu[c] >= -kInsideTolerance) continue;
    const double tc = cur.bary[c] <= 0.0 ? 0.0 : cur.bary[c] / (cur.bary[c] - mu[c]);
    if (exit < 0 || tc < t) exit = c, t = tc;
  }
  Vec3 cross = cur.bary + t * (mu - cur.bary);
  cross[exit] = 0.0;
  cross = clampBary(cross);
  const int next = faceAcross(ddf_, cur.face, exit);
  if (next < 0) return {sampler_.locate(cur.face, cross), StopReason::Boundary};
  if (!rules_.allowed(next)) return {sampler_.locate(cur.face, cross), StopReason::RegionBoundary};
  return {sampler_.locate(next, mapAcross(ddf_, cur.face, next, cross, exit)), std::nullopt};
}

HalfLine Stepper::traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
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
    const auto k1 = sampler_.sample(cur.face, cur.bary, ref);
    if (!k1) {
      half.stop = StopReason::Singularity;
      return half;
    }
    Vec3 dir = k1->dir;
    const StepEnd end = step(cur, *k1, s, dir);
    ++half.steps;
    if (!end.point) {
      half.stop = *end.stop;
      return half;
    }
    const double moved = (end.point->point - cur.point).norm();
    if (!end.stop && moved <= kNoProgress * step_) {
      if (++idle > kMaxIdleCuts) {
        half.stop = StopReason::Singularity;
        return half;
      }
      cur = *end.point;  // same point, now in the neighbouring face
      continue;
    }
    idle = 0;
    ref = dir;
    if (appendPoint(half, *end.point, moved, end.stop, rules_, seed)) return half;
    cur = *end.point;
  }
}

}  // namespace

Streamline traceStreamlineContinuous(const ddf::DisplacementField& ddf, const LineField& field,
                                     const ddf::SurfaceLocation& seed,
                                     const StreamlineParams& params,
                                     const ContinuousStreamlineParams& continuous) {
  std::optional<ddf::CrustHash> ownHash;  // built only once the input passed the checks
  return traceWith(ddf, field, seed, params, "traceStreamlineContinuous",
                   [&](const FieldSampler& sampler, const StopRules& rules, double stepMm) {
                     if (!continuous.crustHash) ownHash.emplace(ddf);
                     return Stepper(sampler, rules, params,
                                    continuous.crustHash ? *continuous.crustHash : *ownHash,
                                    continuous.integrator, stepMm);
                   });
}

}  // namespace ddfcam::planning
