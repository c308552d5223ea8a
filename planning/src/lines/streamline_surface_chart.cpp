// SPDX-License-Identifier: MIT
// ddfcam: the DDF surface as a chart of barycentric coordinates, with closest-point search.
#include "streamline_surface_chart.h"

#include "streamline_common.h"

#include <Eigen/Dense>

namespace ddfcam::planning::detail {
namespace {

// Closest-point search: Gauss-Newton steps (several are spent on seam crossings).
constexpr int kMaxSearchSteps = 16;

}  // namespace

SurfaceChart::Local SurfaceChart::local(int face, const Vec3& mu) const {
  const RasterCell cell = rasterCell(ddf_, face, mu);
  const SurfaceJacobian j = surfaceJacobian(ddf_, face, mu, cell);
  return {cellHeight(ddf_, cell), j.ja, j.jc};
}

SurfaceLocation SurfaceChart::locate(int face, const Vec3& bary) const {
  const double h = local(face, bary).h;
  return {face, bary, h, ddf_.pointAt(face, bary, h)};
}

Vec3 SurfaceChart::normal(const SurfaceLocation& at) const {
  const Local l = local(at.face, at.bary);
  return l.ja.cross(l.jc).normalized();
}

SurfaceLocation SurfaceChart::stepAcross(const SurfaceLocation& at, const Vec3& delta) const {
  const Vec3 end = at.bary + delta;
  int exit = -1;
  double t = 1.0;
  for (int c = 0; c < 3; ++c) {
    if (end[c] >= -1e-14) continue;
    const double tc = at.bary[c] <= 0.0 ? 0.0 : at.bary[c] / (at.bary[c] - end[c]);
    if (exit < 0 || tc < t) exit = c, t = tc;
  }
  if (exit < 0) return locate(at.face, end);
  const int next = faceAcross(ddf_, at.face, exit);
  if (next < 0) return locate(at.face, clampBary(end));
  Vec3 cross = at.bary + t * delta;
  cross[exit] = 0.0;
  return locate(next, mapAcross(ddf_, at.face, next, clampBary(cross), exit));
}

// Gauss-Newton on |S(mu) - target|^2 from @p start; the surface is smooth inside a raster
// triangle, so a few steps reach the foot of a target a fraction of a spacing away.
SurfaceLocation SurfaceChart::closestNear(const SurfaceLocation& start, const Vec3& target,
                                          Vec3* normal) const {
  SurfaceLocation cur = start;
  const double tolerance = 1e-12 * (1.0 + target.cwiseAbs().maxCoeff());
  for (int step = 0;; ++step) {
    const Local l = local(cur.face, cur.bary);
    const Vec3 r = target - cur.point;
    Eigen::Matrix2d gram;
    gram << l.ja.dot(l.ja), l.ja.dot(l.jc), l.jc.dot(l.ja), l.jc.dot(l.jc);
    const Eigen::Vector2d x = gram.ldlt().solve(Eigen::Vector2d(l.ja.dot(r), l.jc.dot(r)));
    if (step == kMaxSearchSteps || !x.allFinite() ||
        (x[0] * l.ja + x[1] * l.jc).norm() < tolerance) {
      if (normal) *normal = l.ja.cross(l.jc).normalized();
      return cur;
    }
    cur = stepAcross(cur, Vec3(x[0], -x[0] - x[1], x[1]));
  }
}

}  // namespace ddfcam::planning::detail
