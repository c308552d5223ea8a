// SPDX-License-Identifier: MIT
// ddfcam: evenly spaced streamlines covering a region (Jobard-Lefer on a DDF surface).
#include <ddfcam/planning/lines/evenly_spaced_streamlines.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include "../surface/surface_walk.h"
#include "separation_grid.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::SurfaceLocation;
using ddf::Vec3;
using detail::SeparationGrid;

// Candidate seeds are tried every this many d_sep of arc along a line: dense enough that a
// gap is found right where it opens, sparse enough that side walks do not dominate.
constexpr double kCandidateSpacing = 0.25;
// A seed is valid when no line is closer than this fraction of d_sep: seeds are placed at
// exactly d_sep from their origin line, and the polyline's chords lie slightly closer.
constexpr double kSeedSlack = 0.99;
// Sub-steps of the side walk to a candidate seed.
constexpr int kWalkSubSteps = 8;

constexpr double kInf = std::numeric_limits<double>::infinity();

double meanRasterSpacing(const ddf::DisplacementField& ddf) {
  const ddf::SupportMesh& mesh = ddf.support();
  double sum = 0.0;
  for (const auto& e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return mesh.n_edges() ? sum / mesh.n_edges() / ddf.raster().steps() : 0.0;
}

void checkInput(const ddf::DisplacementField& ddf, const LineField& field,
                const EvenSpacingParams& p) {
  const std::string name = "evenlySpacedStreamlines: ";
  if (field.size() != ddf.allHeights().size()) {
    throw InvalidInput(name + "line field has " + std::to_string(field.size()) +
                       " entries, expected " + std::to_string(ddf.allHeights().size()));
  }
  if (!p.faceMask.empty() && p.faceMask.size() != static_cast<std::size_t>(ddf.faceCount())) {
    throw InvalidInput(name + "face mask has " + std::to_string(p.faceMask.size()) +
                       " entries, expected " + std::to_string(ddf.faceCount()));
  }
  if (!(p.separationMm > 0.0) || !std::isfinite(p.separationMm))
    throw InvalidInput(name + "separation " + std::to_string(p.separationMm) + " mm is not > 0");
  if (!(p.testRatio > 0.0 && p.testRatio <= 1.0))
    throw InvalidInput(name + "test ratio " + std::to_string(p.testRatio) + " not in (0, 1]");
  if (!(p.minLengthRatio >= 0.0) || p.maxLines < 0)
    throw InvalidInput(name + "negative minimum length ratio or line count");
  if (p.firstSeed && (p.firstSeed->face < 0 || p.firstSeed->face >= ddf.faceCount()))
    throw InvalidInput(name + "first seed face " + std::to_string(p.firstSeed->face) +
                       " is out of range");
}

class Coverage {
 public:
  Coverage(const ddf::DisplacementField& ddf, const LineField& field, const EvenSpacingParams& p)
      : ddf_(ddf), field_(field), p_(p), grid_(p.separationMm), failed_(p.separationMm) {
    trace_ = p.trace;
    trace_.faceMask = p.faceMask;
    trace_.existingPaths.clear();
    trace_.nearPathDistanceMm = 0.0;
    trace_.progress = nullptr;
    if (trace_.stepMm <= 0.0) trace_.stepMm = 0.1 * p.separationMm;
    double area = 0.0;
    Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
    for (int f = 0; f < ddf.faceCount(); ++f) {
      if (!allowed(f)) continue;
      const Vec3 a = ddf.basePoint(f, Vec3::UnitX()), b = ddf.basePoint(f, Vec3::UnitY()),
                 c = ddf.basePoint(f, Vec3::UnitZ());
      area += 0.5 * (b - a).cross(c - a).norm();
      lo = lo.cwiseMin(a).cwiseMin(b).cwiseMin(c), hi = hi.cwiseMax(a).cwiseMax(b).cwiseMax(c);
    }
    expectedLengthMm_ = std::max(area / p.separationMm, 1e-9);
    // A kept line stays d_test from itself, so it is at most about area / d_test long: tracing
    // further (a line spiralling near a closed orbit) would only be cut away again.
    if (area > 0.0) {
      const double cap =
          4.0 * area / (p.testRatio * p.separationMm) + std::numbers::pi * (hi - lo).norm();
      trace_.maxLengthMm = std::min(trace_.maxLengthMm, cap);
    }
  }

  std::vector<Streamline> run() {
    if (const auto seed = p_.firstSeed ? p_.firstSeed : defaultSeed()) {
      tryLine(*seed);
      propagate();
    }
    if (p_.fillGaps) fillGaps();
    reportProgress(p_.progress, 1.0);
    return std::move(lines_);
  }

 private:
  bool allowed(int f) const {
    return p_.faceMask.empty() || p_.faceMask[static_cast<std::size_t>(f)] != 0;
  }
  bool full() const { return static_cast<int>(lines_.size()) >= p_.maxLines; }

  double separation(const SurfaceLocation& loc) const {
    if (!p_.separationAt) return p_.separationMm;
    const double d = p_.separationAt(loc);
    if (!(d > 0.0) || !std::isfinite(d)) {
      throw InvalidInput("evenlySpacedStreamlines: separationAt returned " + std::to_string(d) +
                         " mm at face " + std::to_string(loc.face));
    }
    return d;
  }

  SurfaceLocation rasterLocation(int f, int i, int k) const {
    const Vec3 bary = ddf_.rasterBary(i, k);
    const double h = ddf_.height(f, i, k);
    return {f, bary, h, ddf_.pointAt(f, bary, h)};
  }
  bool fieldDefined(int f, int i, int k) const {
    return !field_[static_cast<std::size_t>(f) * ddf_.pointsPerFace() + ddf_.raster().index(i, k)]
                .isZero();
  }

  // Raster points are visited with this stride so that neighbours are about one step apart.
  int rasterStride() const {
    const double spacing = meanRasterSpacing(ddf_);
    return spacing > 0.0 ? std::max(1, static_cast<int>(trace_.stepMm / spacing)) : 1;
  }

  template <typename Fn>
  void forEachSample(Fn&& fn) const {
    const int n = ddf_.raster().steps(), stride = rasterStride();
    for (int f = 0; f < ddf_.faceCount(); ++f) {
      if (!allowed(f)) continue;
      for (int k = 0; k <= n; k += stride)
        for (int i = 0; i <= n - k; i += stride) fn(f, i, k);
    }
  }

  std::optional<SurfaceLocation> defaultSeed() const {
    Vec3 sum = Vec3::Zero();
    double count = 0.0;
    forEachSample([&](int f, int i, int k) { sum += ddf_.surfacePoint(f, i, k), count += 1.0; });
    if (count == 0.0) return std::nullopt;
    const Vec3 centre = sum / count;
    std::optional<SurfaceLocation> best;
    double bestGap = kInf;
    forEachSample([&](int f, int i, int k) {
      if (!fieldDefined(f, i, k)) return;
      const SurfaceLocation loc = rasterLocation(f, i, k);
      const double gap = (loc.point - centre).norm();
      if (gap < bestGap) bestGap = gap, best = loc;
    });
    return best;
  }

  // A seed is worth tracing: far enough from every line and from seeds that failed.
  bool validSeed(const SurfaceLocation& loc, const Vec3& normal, double slack) const {
    const double d = separation(loc);
    return !grid_.near(loc.point, normal, slack * d) &&
           !failed_.near(loc.point, normal, p_.testRatio * d);
  }

  Streamline cut(Streamline line, const std::vector<Vec3>& normals, std::size_t& lo) const;
  void tryLine(const SurfaceLocation& seed);
  void propagate();
  void seedsBeside(std::size_t line);
  void fillGaps();

  const ddf::DisplacementField& ddf_;
  const LineField& field_;
  const EvenSpacingParams& p_;
  StreamlineParams trace_;
  SeparationGrid grid_;    // segments of accepted lines
  SeparationGrid failed_;  // seeds whose lines were too short (as points)
  std::vector<Streamline> lines_;
  std::vector<std::vector<Vec3>> normals_;  // surface normal per point of each line
  std::deque<std::size_t> queue_;
  double lengthMm_ = 0.0;
  double expectedLengthMm_ = 1.0;
};

// The part of @p line around its seed that stays d_test away from accepted lines (and from
// itself); @p lo receives the index of the first kept point.
Streamline Coverage::cut(Streamline line, const std::vector<Vec3>& normals, std::size_t& lo) const {
  const auto& pts = line.points;
  std::vector<double> arc(pts.size(), 0.0);
  for (std::size_t i = 1; i < pts.size(); ++i)
    arc[i] = arc[i - 1] + (pts[i].point - pts[i - 1].point).norm();
  const bool loop = line.stop == Streamline::ClosedLoop;
  SeparationGrid self(p_.separationMm);
  auto blocked = [&](std::size_t i) {
    const double test = p_.testRatio * separation(pts[i]);
    if (grid_.near(pts[i].point, normals[i], test)) return true;
    if (loop) return false;  // a closed loop ends at its own seed on purpose
    const detail::SeparationSkip skip{0, arc[i], std::numbers::pi * test};
    return self.near(pts[i].point, normals[i], test, skip);
  };
  const std::size_t s = line.seedIndex;
  std::size_t hi = s;
  for (std::size_t i = s + 1; i < pts.size() && !blocked(i); ++i) {
    self.add(pts[i - 1].point, pts[i].point, normals[i - 1], 0, arc[i - 1]);
    hi = i;
  }
  lo = s;
  for (std::size_t i = s; i-- > 0 && !blocked(i);) {
    self.add(pts[i].point, pts[i + 1].point, normals[i], 0, arc[i]);
    lo = i;
  }
  if (hi + 1 < pts.size()) line.stop = Streamline::NearExistingPath;
  if (lo > 0) line.backwardStop = Streamline::NearExistingPath;
  line.points.assign(pts.begin() + static_cast<std::ptrdiff_t>(lo),
                     pts.begin() + static_cast<std::ptrdiff_t>(hi + 1));
  line.seedIndex = s - lo;
  line.lengthMm = arc[hi] - arc[lo];
  return line;
}

void Coverage::tryLine(const SurfaceLocation& seed) {
  if (full()) return;
  reportProgress(p_.progress, 0.9 * std::min(1.0, lengthMm_ / expectedLengthMm_));
  Streamline traced = traceStreamline(ddf_, field_, seed, trace_);
  std::vector<Vec3> normals;
  normals.reserve(traced.points.size());
  for (const auto& pt : traced.points) normals.push_back(surfaceNormal(ddf_, pt));
  const SurfaceLocation start = traced.points[traced.seedIndex];
  const Vec3 startNormal = normals[traced.seedIndex];
  std::size_t lo = 0;
  Streamline line = cut(std::move(traced), normals, lo);
  if (line.points.size() < 2 || line.lengthMm < p_.minLengthRatio * separation(start)) {
    failed_.add(start.point, start.point, startNormal, -1, 0.0);
    return;
  }
  normals.erase(normals.begin(), normals.begin() + static_cast<std::ptrdiff_t>(lo));
  normals.resize(line.points.size());
  const int id = static_cast<int>(lines_.size());
  double arc = 0.0;
  for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
    grid_.add(line.points[i].point, line.points[i + 1].point, normals[i], id, arc);
    arc += (line.points[i + 1].point - line.points[i].point).norm();
  }
  lengthMm_ += line.lengthMm;
  lines_.push_back(std::move(line));
  normals_.push_back(std::move(normals));
  queue_.push_back(static_cast<std::size_t>(id));
}

// Candidate seeds on both sides of line @p li, each traced if valid.
void Coverage::seedsBeside(std::size_t li) {
  double nextArc = 0.0, arc = 0.0;
  const std::size_t count = lines_[li].points.size();
  for (std::size_t i = 0; i < count && !full(); ++i) {
    if (i > 0) arc += (lines_[li].points[i].point - lines_[li].points[i - 1].point).norm();
    if (arc < nextArc) continue;
    // Copies: tracing below appends to lines_.
    const SurfaceLocation at = lines_[li].points[i];
    const Vec3 normal = normals_[li][i];
    const Vec3 tangent = lines_[li].points[std::min(i + 1, count - 1)].point -
                         lines_[li].points[i > 0 ? i - 1 : 0].point;
    const double d = separation(at);
    nextArc = arc + kCandidateSpacing * d;
    const Vec3 side = normal.cross(tangent);
    if (!(side.norm() > 0.0)) continue;
    for (const double sign : {1.0, -1.0}) {
      const Vec3 dir = sign * side.normalized();
      // Cheap rejection before walking: the tangent-plane estimate is within 0.5 d of a line,
      // so the seed (at most ~kappa d^2 / 2 from it) is closer than 0.99 d for kappa d < 0.98.
      if (grid_.near(at.point + d * dir, normal, 0.5 * d)) continue;
      const auto seed = detail::walkOnSurface(ddf_, at, dir, d, kWalkSubSteps, p_.faceMask);
      if (!seed || !validSeed(*seed, surfaceNormal(ddf_, *seed), kSeedSlack)) continue;
      tryLine(*seed);
    }
  }
}

void Coverage::propagate() {
  while (!queue_.empty() && !full()) {
    const std::size_t li = queue_.front();
    queue_.pop_front();
    seedsBeside(li);
  }
}

void Coverage::fillGaps() {
  int facesDone = 0, witness = -1;
  const int n = ddf_.raster().steps(), stride = rasterStride();
  for (int f = 0; f < ddf_.faceCount() && !full(); ++f) {
    reportProgress(p_.progress, 0.9 + 0.1 * facesDone / std::max(1, ddf_.faceCount()));
    ++facesDone;
    if (!allowed(f)) continue;
    for (int k = 0; k <= n; k += stride)
      for (int i = 0; i <= n - k; i += stride) {
        if (!fieldDefined(f, i, k)) continue;
        const SurfaceLocation loc = rasterLocation(f, i, k);
        const Vec3 normal = surfaceNormal(ddf_, loc);
        // Neighbouring samples are usually covered by the same segment: test it first.
        const double d = separation(loc);
        if (grid_.within(witness, loc.point, normal, d)) continue;
        if (grid_.distance(loc.point, normal, d, {}, &witness) < kInf) continue;
        if (!validSeed(loc, normal, 1.0)) continue;
        tryLine(loc);
        propagate();
      }
  }
}

}  // namespace

std::vector<Streamline> evenlySpacedStreamlines(const ddf::DisplacementField& ddf,
                                                const LineField& field,
                                                const EvenSpacingParams& params) {
  checkInput(ddf, field, params);
  Coverage coverage(ddf, field, params);
  return coverage.run();
}

}  // namespace ddfcam::planning
