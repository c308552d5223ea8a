// SPDX-License-Identifier: MIT
// ddfcam: data term of user-drawn flow directions (strokes) on the raster points.
#include "flow_strokes.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/surface/uniform_grid.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

namespace ddfcam::planning::detail {

namespace {

using ddf::Vec3;

struct Segment {
  Vec3 a, b;  // canonical order: a lexicographically before b
};

bool lexLess(const Vec3& u, const Vec3& v) {
  return std::tie(u.x(), u.y(), u.z()) < std::tie(v.x(), v.y(), v.z());
}

std::vector<Segment> segmentsOf(const std::vector<std::vector<Vec3>>& strokes) {
  std::vector<Segment> out;
  for (std::size_t s = 0; s < strokes.size(); ++s)
    for (std::size_t i = 0; i < strokes[s].size(); ++i) {
      if (!strokes[s][i].allFinite())
        throw InvalidInput("flowField: point " + std::to_string(i) + " of stroke " +
                           std::to_string(s) + " is not finite");
      if (i == 0 || strokes[s][i] == strokes[s][i - 1]) continue;
      const Vec3 &u = strokes[s][i - 1], &v = strokes[s][i];
      out.push_back(lexLess(u, v) ? Segment{u, v} : Segment{v, u});
    }
  if (out.empty())
    throw InvalidInput(
        "flowField: the UserStrokes source needs at least one stroke with two "
        "distinct points");
  return out;
}

double distance(const Segment& s, const Vec3& x) {
  const Vec3 d = s.b - s.a;
  const double t = std::clamp((x - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (s.a + t * d - x).norm();
}

// Strict order on (distance, segment endpoints): independent of how strokes are listed.
bool closer(double d, const Segment& s, double bestD, const Segment* best) {
  if (!best || d != bestD) return !best || d < bestD;
  if (s.a != best->a) return lexLess(s.a, best->a);
  return lexLess(s.b, best->b);
}

// Long segments are visited in pieces no longer than r so each piece touches few cells.
std::vector<const Segment*> nearWithin(const SurfaceFrames& frames,
                                       const std::vector<std::uint8_t>& active,
                                       const std::vector<Segment>& segments, double r) {
  UniformGrid grid(r);
  for (std::size_t p = 0; p < active.size(); ++p)
    if (active[p]) grid.add(static_cast<int>(p), frames.position[p]);
  std::vector<const Segment*> best(active.size(), nullptr);
  std::vector<double> bestD(active.size(), std::numeric_limits<double>::infinity());
  for (const Segment& s : segments) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((s.b - s.a).norm() / r)));
    for (int i = 0; i < pieces; ++i) {
      const Vec3 u = s.a + (s.b - s.a) * (double(i) / pieces);
      const Vec3 v = s.a + (s.b - s.a) * (double(i + 1) / pieces);
      const Vec3 pad = Vec3::Constant(r);
      grid.forEachInBox(u.cwiseMin(v) - pad, u.cwiseMax(v) + pad, [&](int p) {
        const double d = distance(s, frames.position[p]);
        if (d <= r && closer(d, s, bestD[p], best[p])) bestD[p] = d, best[p] = &s;
      });
    }
  }
  return best;
}

std::vector<const Segment*> nearest(const SurfaceFrames& frames,
                                    const std::vector<std::uint8_t>& active,
                                    const std::vector<Segment>& segments) {
  std::vector<const Segment*> best(active.size(), nullptr);
  tbb::parallel_for(std::size_t{0}, active.size(), [&](std::size_t p) {
    if (!active[p]) return;
    double bestD = 0.0;
    for (const Segment& s : segments) {
      const double d = distance(s, frames.position[p]);
      if (closer(d, s, bestD, best[p])) bestD = d, best[p] = &s;
    }
  });
  return best;
}

}  // namespace

StrokeTargets strokeTargets(const SurfaceFrames& frames, const std::vector<std::uint8_t>& active,
                            const std::vector<std::vector<Vec3>>& strokes, double radiusMm) {
  const std::vector<Segment> segments = segmentsOf(strokes);
  const std::vector<const Segment*> best = radiusMm > 0.0
                                               ? nearWithin(frames, active, segments, radiusMm)
                                               : nearest(frames, active, segments);
  StrokeTargets out(active.size(), 0.0);
  for (std::size_t p = 0; p < active.size(); ++p)
    if (best[p]) {
      const Vec3 tangent = (best[p]->b - best[p]->a).normalized();
      out[p] = doubledAngle(frames, static_cast<ddf::PointId>(p), tangent, 1e-6);
    }
  return out;
}

double meanEdgeLength(const SurfaceFrames& frames) {
  if (frames.edges.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& [p, q] : frames.edges) sum += (frames.position[q] - frames.position[p]).norm();
  return sum / static_cast<double>(frames.edges.size());
}

}  // namespace ddfcam::planning::detail
