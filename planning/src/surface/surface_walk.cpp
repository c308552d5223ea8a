// SPDX-License-Identifier: MIT
// ddfcam: short walks on a DDF surface across support seams (private to planning).
#include "surface_walk.h"

#include <ddfcam/ddf/v_projection.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <cmath>
#include <limits>

namespace ddfcam::planning::detail {
namespace {

// More faces than a walk of one sub-step should ever cross (a vertex fan and a seam).
constexpr int kMaxHops = 16;
// A walk ends when its straight distance is this close to the target (relative).
constexpr double kDistanceTolerance = 1e-4;

ddf::Vec3 clampBary(const ddf::Vec3& bary) {
  const ddf::Vec3 c = bary.cwiseMax(0.0);
  return c / c.sum();
}

bool allowed(const std::vector<std::uint8_t>& mask, int face) {
  return mask.empty() || mask[static_cast<std::size_t>(face)] != 0;
}

// The V-projection of q onto face whose height agrees best with the surface at its foot.
std::optional<ddf::VProjection> bestRoot(const ddf::DisplacementField& ddf, int face,
                                         const ddf::Vec3& q) {
  std::optional<ddf::VProjection> best;
  double bestGap = std::numeric_limits<double>::infinity();
  for (const ddf::VProjection& root : ddf::vProject(ddf, face, q)) {
    if (!root.mu.allFinite() || !std::isfinite(root.h) || root.mu.cwiseMax(0.0).sum() <= 0.0)
      continue;
    const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), face, clampBary(root.mu));
    const double gap = std::abs(root.h - h);
    if (gap < bestGap) bestGap = gap, best = root;
  }
  return best;
}

}  // namespace

std::optional<ddf::SurfaceLocation> locateNear(const ddf::DisplacementField& ddf, int face,
                                               const ddf::Vec3& q,
                                               const std::vector<std::uint8_t>& faceMask) {
  const ddf::RasterTopology& topo = ddf.topology();
  for (int hop = 0; hop < kMaxHops; ++hop) {
    const auto root = bestRoot(ddf, face, q);
    if (!root) return std::nullopt;
    int exit = 0;
    for (int c = 1; c < 3; ++c)
      if (root->mu[c] < root->mu[exit]) exit = c;
    if (root->mu[exit] >= -1e-12) {
      const ddf::Vec3 bary = clampBary(root->mu);
      const double h = ddf::interpolateOnFace(ddf, ddf.allHeights(), face, bary);
      return ddf::SurfaceLocation{face, bary, h, ddf.pointAt(face, bary, h)};
    }
    // Local edge opposite local vertex c is (c + 1) % 3.
    const auto& sides = topo.edgeFaces(topo.faceEdge(face, (exit + 1) % 3));
    const int next = sides[0] == face ? sides[1] : sides[0];
    if (next < 0 || !allowed(faceMask, next)) return std::nullopt;
    face = next;
  }
  return std::nullopt;
}

std::optional<ddf::SurfaceLocation> walkOnSurface(const ddf::DisplacementField& ddf,
                                                  const ddf::SurfaceLocation& start,
                                                  const ddf::Vec3& dir, double distanceMm,
                                                  int subSteps,
                                                  const std::vector<std::uint8_t>& faceMask) {
  const double sub = distanceMm / std::max(1, subSteps);
  ddf::SurfaceLocation cur = start;
  ddf::Vec3 d = dir;
  for (int it = 0; it < subSteps + 6; ++it) {
    const ddf::Vec3 w = cur.point - start.point;
    if (std::abs(w.norm() - distanceMm) <= kDistanceTolerance * distanceMm) return cur;
    const ddf::Vec3 n = surfaceNormal(ddf, cur);
    ddf::Vec3 t = d - d.dot(n) * n;
    if (!(t.norm() > 1e-9)) return std::nullopt;
    d = t.normalized();
    // The step along d that makes the straight distance exactly distanceMm.
    const double wt = w.dot(d);
    const double disc = wt * wt - w.squaredNorm() + distanceMm * distanceMm;
    if (disc < 0.0) return std::nullopt;  // the walk turned back beyond the target
    const double x = std::min(sub, -wt + std::sqrt(disc));
    const auto next = locateNear(ddf, cur.face, cur.point + x * d, faceMask);
    if (!next) return std::nullopt;
    cur = *next;
  }
  const double gap = std::abs((cur.point - start.point).norm() - distanceMm);
  return gap <= 1e-2 * distanceMm ? std::optional(cur) : std::nullopt;
}

}  // namespace ddfcam::planning::detail
