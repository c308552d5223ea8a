// SPDX-License-Identifier: MIT
// ddfcam: streamlines by the raster walk with error compensation and low-pass filter (sec. 8.3).
#include "streamline_common.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_raster_walk.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

using namespace detail;

// A zero barycentric coordinate may decrease by this much (relative) and still count as
// entering the face: a field along a seam or an open edge.
constexpr double kEnterTolerance = 1e-6;
// Moves whose direction has at least this cosine with the field make progress; moves down to
// -kLateralCos are sideways corrections; anything further back is never taken.
constexpr double kProgressCos = 0.3;
constexpr double kLateralCos = 0.2;
// Sideways moves in a row before only progress is allowed (no loops without progress).
constexpr int kMaxSidewaysRun = 2;

// One stored copy of a raster point: the raster point (i, k) of face `face`.
struct RasterPoint {
  int face = 0;
  int i = 0;
  int k = 0;
};

// The six lattice steps (di, dk) of a triangular raster.
constexpr std::array<std::array<int, 2>, 6> kLatticeSteps{
    {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}}};

// The walker between two moves: raster point, its location, the sign-aligned field direction
// there with the surface normal, the lateral offset of the ideal line from the walker (mm)
// and the sideways moves just made.
struct State {
  RasterPoint at;
  SurfaceLocation loc;
  FieldSample field;
  Vec3 error = Vec3::Zero();
  int sideways = 0;
};

// The part of @p v across @p dir in the tangent plane of @p normal.
Vec3 lateral(const Vec3& v, const Vec3& dir, const Vec3& normal) {
  Vec3 e = v - v.dot(dir) * dir;
  return e - e.dot(normal) * normal;
}

Vec3 capped(const Vec3& v, double length) {
  const double len = v.norm();
  return len > length ? Vec3(v * (length / len)) : v;
}

class Walker {
 public:
  Walker(const FieldSampler& sampler, const StopRules& rules, const StreamlineParams& params,
         const RasterWalkParams& walk, double stepMm)
      : sampler_(sampler),
        ddf_(sampler.ddf()),
        rules_(rules),
        params_(params),
        walk_(walk),
        step_(stepMm),
        n_(ddf_.raster().steps()) {}

  HalfLine traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                     int stepBudget) const;

 private:
  SurfaceLocation locate(const RasterPoint& p) const {
    return sampler_.locate(p.face, ddf_.rasterBary(p.i, p.k));
  }
  bool onFaceBorder(const RasterPoint& p) const { return p.i == 0 || p.k == 0 || p.i + p.k == n_; }
  std::vector<RasterPoint> copies(const RasterPoint& p) const;
  // Whether direction @p t at raster point @p p enters an allowed face; else the stop
  // (Boundary: no face entered, RegionBoundary: only forbidden ones).
  std::optional<StopReason> leaves(const RasterPoint& p, const Vec3& t) const;
  // The lattice move (over the allowed faces around p) the walker makes: from the copy of p
  // in the face of the neighbour, to the neighbour.
  std::optional<std::array<RasterPoint, 2>> choose(const State& cur) const;
  // The first raster point from the seed: a corner of its raster triangle.
  std::optional<State> firstPoint(const SurfaceLocation& seed, const Vec3& dir) const;
  // Offset carried from @p from (ideal line at from.loc.point + from.error) to @p to.
  void carryError(const State& from, State& to) const;
  // One move; sets @p stop instead when the line ends at @p cur.
  std::optional<State> move(const State& cur, std::optional<StopReason>& stop) const;

  const FieldSampler& sampler_;
  const ddf::DisplacementField& ddf_;
  const StopRules& rules_;
  const StreamlineParams& params_;
  const RasterWalkParams& walk_;
  double step_;
  int n_;
};

std::vector<RasterPoint> Walker::copies(const RasterPoint& p) const {
  if (!onFaceBorder(p)) return {p};
  const ddf::RasterTopology& topo = ddf_.topology();
  std::vector<RasterPoint> out;
  topo.forEachCopy(topo.id(p.face, p.i, p.k), [&](ddf::PointCopy c) {
    const ddf::RasterCoord rc = topo.coord(c);
    out.push_back({c.face, rc.i, rc.k});
  });
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.face < b.face; });
  return out;
}

std::optional<StopReason> Walker::leaves(const RasterPoint& p, const Vec3& t) const {
  if (!onFaceBorder(p)) return std::nullopt;
  bool forbiddenEntered = false;
  for (const RasterPoint& c : copies(p)) {
    const Vec3 mu = ddf_.rasterBary(c.i, c.k);
    const Vec3 velocity = surfaceJacobian(ddf_, c.face, mu, rasterCell(ddf_, c.face, mu)).toBary(t);
    // How far t points into the face: the least velocity of the coordinates that are 0.
    const int coord[3] = {c.i, n_ - c.i - c.k, c.k};
    double score = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
      if (coord[a] == 0) score = std::min(score, velocity[a] / velocity.norm());
    if (!(score >= -kEnterTolerance)) continue;
    if (rules_.allowed(c.face)) return std::nullopt;
    forbiddenEntered = true;
  }
  return forbiddenEntered ? StopReason::RegionBoundary : StopReason::Boundary;
}

std::optional<std::array<RasterPoint, 2>> Walker::choose(const State& cur) const {
  const Vec3& u = cur.field.dir;
  const Vec3 ideal = cur.loc.point + cur.error;
  std::optional<std::array<RasterPoint, 2>> best;
  double bestCost = std::numeric_limits<double>::infinity(), bestAlong = 0.0;
  for (const RasterPoint& c : copies(cur.at)) {
    if (!rules_.allowed(c.face)) continue;
    for (const auto& [di, dk] : kLatticeSteps) {
      const RasterPoint q{c.face, c.i + di, c.k + dk};
      if (q.i < 0 || q.k < 0 || q.i + q.k > n_) continue;
      const Vec3 qp = ddf_.surfacePoint(q.face, q.i, q.k);
      const Vec3 d = qp - cur.loc.point;
      const double along = d.dot(u) / d.norm();
      const bool progress = along >= kProgressCos;
      if (!progress &&
          (!walk_.compensateError || along < -kLateralCos || cur.sideways >= kMaxSidewaysRun))
        continue;
      // Compensation: the neighbour nearest the ideal line (the offset the next move starts
      // with). Without: the move closest in direction to the field.
      const double cost =
          walk_.compensateError ? lateral(ideal - qp, u, cur.field.normal).norm() : -along;
      if (cost < bestCost - 1e-12 * step_ ||
          (cost <= bestCost + 1e-12 * step_ && along > bestAlong))
        best = {c, q}, bestCost = cost, bestAlong = along;
    }
  }
  return best;
}

void Walker::carryError(const State& from, State& to) const {
  if (!walk_.compensateError) return;
  const Vec3 mean = (from.field.dir + to.field.dir).normalized();
  to.error = lateral(from.loc.point + from.error - to.loc.point, mean, to.field.normal);
  // Larger offsets only arise near an undetected singularity or along a boundary, where
  // following the old line is no longer meaningful.
  to.error = capped(to.error, step_);
}

std::optional<State> Walker::firstPoint(const SurfaceLocation& seed, const Vec3& dir) const {
  const auto at = sampler_.sample(seed.face, seed.bary, dir);
  if (!at) return std::nullopt;
  const RasterCell cell = rasterCell(ddf_, seed.face, seed.bary);
  const std::size_t base = static_cast<std::size_t>(seed.face) * ddf_.pointsPerFace();
  const Vec3 t = at->dir;
  std::optional<RasterPoint> best, ahead;
  double bestAlong = -std::numeric_limits<double>::infinity();
  double aheadGap = std::numeric_limits<double>::infinity();
  for (const std::size_t index : cell.index) {
    const std::size_t local = index - base;
    int k = 0;
    while (ddf_.raster().rowOffset(k + 1) <= local) ++k;
    const RasterPoint c{seed.face, static_cast<int>(local - ddf_.raster().rowOffset(k)), k};
    const Vec3 d = ddf_.surfacePoint(c.face, c.i, c.k) - seed.point;
    const double along = d.dot(t), gap = (d - along * t).norm();
    if (along > bestAlong) bestAlong = along, best = c;
    if (along > 0.0 && gap < aheadGap) aheadGap = gap, ahead = c;
  }
  State s{ahead ? *ahead : *best, {}, {}, {}, 0};
  s.loc = locate(s.at);
  const auto field = sampler_.sample(s.loc.face, s.loc.bary, t);
  if (!field) return std::nullopt;
  s.field = *field;
  const State seedState{s.at, seed, *at, Vec3::Zero(), 0};
  carryError(seedState, s);
  return s;
}

std::optional<State> Walker::move(const State& cur, std::optional<StopReason>& stop) const {
  stop = leaves(cur.at, cur.field.dir);
  if (stop) return std::nullopt;
  const auto to = choose(cur);
  if (!to) {
    stop = StopReason::Boundary;
    return std::nullopt;
  }
  const auto& [from, dest] = *to;
  State next{dest, locate(dest), {}, {}, 0};
  // The raster triangle between both points must be coherent, and the field defined at p'.
  const Vec3 mid = 0.5 * (ddf_.rasterBary(from.i, from.k) + next.loc.bary);
  const auto field = sampler_.sample(next.loc.face, next.loc.bary, cur.field.dir);
  if (!field || !sampler_.sample(next.loc.face, mid, cur.field.dir)) {
    stop = StopReason::Singularity;
    return std::nullopt;
  }
  next.field = *field;
  const double along = (next.loc.point - cur.loc.point).normalized().dot(cur.field.dir);
  next.sideways = along >= kProgressCos ? 0 : cur.sideways + 1;
  carryError(cur, next);
  return next;
}

HalfLine Walker::traceHalf(const SurfaceLocation& seed, const Vec3& dir0, double lengthBudget,
                           int stepBudget) const {
  HalfLine half;
  auto first = firstPoint(seed, dir0);
  if (!first) {
    half.stop = StopReason::Singularity;
    return half;
  }
  State cur = *first;
  const double firstMove = (cur.loc.point - seed.point).norm();
  if (firstMove > kNoProgress * step_) {
    if (firstMove > lengthBudget || stepBudget < 1) return half;  // MaxLength
    half.points.push_back(cur.loc);
    half.lengthMm = firstMove;
    half.steps = 1;
  }
  for (int moves = 0;; ++moves) {
    if (half.steps >= stepBudget) return half;  // MaxLength
    if (params_.progress && moves % 256 == 0)
      reportProgress(params_.progress, std::min(1.0, half.lengthMm / params_.maxLengthMm));
    std::optional<StopReason> stop;
    const auto next = move(cur, stop);
    if (!next) {
      half.stop = *stop;
      return half;
    }
    const double moved = (next->loc.point - cur.loc.point).norm();
    if (half.lengthMm + moved > lengthBudget) return half;  // MaxLength
    ++half.steps;
    if (appendPoint(half, next->loc, moved, std::nullopt, rules_, seed)) return half;
    cur = *next;
  }
}

// A point during low-pass filtering: its 3D position and, while every point averaged into it
// lay in one face, that face and the averaged barycentric coordinates (else face -1).
struct FilterPoint {
  int face = -1;
  Vec3 bary = Vec3::Zero();
  Vec3 xyz = Vec3::Zero();
};

// One moving-average pass (window 2k' + 1 with k' = min(k, i, N - 1 - i), ends stay).
std::vector<FilterPoint> averagePass(const std::vector<FilterPoint>& in, int k) {
  std::vector<FilterPoint> out(in.size());
  const auto n = static_cast<std::ptrdiff_t>(in.size());
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const std::ptrdiff_t half = std::min<std::ptrdiff_t>({k, i, n - 1 - i});
    FilterPoint& o = out[i];
    o.face = in[i].face;
    for (std::ptrdiff_t j = i - half; j <= i + half; ++j) {
      o.xyz += in[j].xyz, o.bary += in[j].bary;
      if (in[j].face != o.face) o.face = -1;
    }
    o.xyz /= static_cast<double>(2 * half + 1);
    o.bary /= static_cast<double>(2 * half + 1);
  }
  return out;
}

// Low-pass filters points [first, last] of @p line (both ends stay) and puts the moved points
// back on the surface: averaged in the parameter domain where the window lies in one face
// (most points), else averaged in 3D and V-projected starting from the face it was walked in.
void filterRange(const FieldSampler& sampler, const StopRules& rules, const RasterWalkParams& walk,
                 std::vector<SurfaceLocation>& points, std::size_t first, std::size_t last) {
  if (last < first + 2) return;
  std::vector<FilterPoint> filtered;
  for (std::size_t i = first; i <= last; ++i)
    filtered.push_back({points[i].face, points[i].bary, points[i].point});
  for (int pass = 0; pass < walk.filterPasses; ++pass)
    filtered = averagePass(filtered, walk.filterHalfWindow);
  for (std::size_t i = first + 1; i < last; ++i) {
    const FilterPoint& f = filtered[i - first];
    if (f.face >= 0) {
      points[i] = sampler.locate(f.face, clampBary(f.bary));
    } else if (const auto loc = relocate(sampler, rules, points[i].face, f.xyz)) {
      points[i] = *loc;
    }
  }
}

}  // namespace

Streamline traceStreamlineRasterWalk(const ddf::DisplacementField& ddf, const LineField& field,
                                     const ddf::SurfaceLocation& seed,
                                     const StreamlineParams& params, const RasterWalkParams& walk) {
  checkTraceInput(ddf, field, seed, params, "traceStreamlineRasterWalk");
  if (walk.filterHalfWindow < 0 || walk.filterPasses < 0) {
    throw InvalidInput("traceStreamlineRasterWalk: filter half window " +
                       std::to_string(walk.filterHalfWindow) + " or passes " +
                       std::to_string(walk.filterPasses) + " is negative");
  }
  return traceWith(
      ddf, field, seed, params, "traceStreamlineRasterWalk",
      [&](const FieldSampler& sampler, const StopRules& rules, double stepMm) {
        return Walker(sampler, rules, params, walk, stepMm);
      },
      [&](const FieldSampler& sampler, const StopRules& rules, Streamline& line) {
        if (walk.filterHalfWindow <= 0 || walk.filterPasses <= 0) return;
        filterRange(sampler, rules, walk, line.points, 0, line.seedIndex);
        filterRange(sampler, rules, walk, line.points, line.seedIndex, line.points.size() - 1);
        line.lengthMm = polylineLength(line.points);
      });
}

}  // namespace ddfcam::planning
