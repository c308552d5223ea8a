// SPDX-License-Identifier: MIT
// ddfcam: viewDependentBounds.
#include <ddfcam/ddf/view_dependent_bounds.h>
#include <ddfcam/error.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::ddf {

void validateViewBounds(const ViewBoundsParams& v) {
  const bool angleOk = v.parallel ? v.parallelScaleMm > 0.0
                                  : v.viewAngleDeg > 0.0 && v.viewAngleDeg < 180.0;
  if (!(v.viewportHeightPx > 0) || !(v.aspect > 0.0) || !(v.pixelError > 0.0) || !angleOk ||
      !(v.direction.norm() > 0.0) || !(v.minEpsMm > 0.0) || !(v.maxEpsMm >= v.minEpsMm))
    throw InvalidInput("viewDependentBounds: the view needs a positive viewport height (" +
                       std::to_string(v.viewportHeightPx) + " px), aspect, pixel error, view " +
                       "angle or parallel scale, a direction, and 0 < minEpsMm <= maxEpsMm");
}

namespace {

// minEps * 2^j below raw, clamped to [minEps, maxEps].
float quantised(double raw, const ViewBoundsParams& v) {
  if (!(raw > v.minEpsMm)) return static_cast<float>(v.minEpsMm);
  const double levels = std::floor(std::log2(raw / v.minEpsMm));
  return static_cast<float>(std::min(v.minEpsMm * std::exp2(levels), v.maxEpsMm));
}

}  // namespace

std::vector<float> viewDependentBounds(const DisplacementField& ddf, const ViewBoundsParams& view) {
  validateViewBounds(view);
  if (view.parallel)  // a pixel is the same size at every depth
    return std::vector<float>(
        static_cast<std::size_t>(ddf.faceCount()),
        quantised(view.pixelError * 2.0 * view.parallelScaleMm / view.viewportHeightPx, view));
  const Vec3 dir = view.direction.normalized();
  const double tanHalf = std::tan(0.5 * view.viewAngleDeg * std::numbers::pi / 180.0);
  const int n = ddf.raster().steps();
  std::vector<float> out(static_cast<std::size_t>(ddf.faceCount()));
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const Vec3 corners[3] = {ddf.surfacePoint(f, 0, 0), ddf.surfacePoint(f, n, 0),
                             ddf.surfacePoint(f, 0, n)};
    const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0;
    double radius = 0.0;
    for (const Vec3& c : corners) radius = std::max(radius, (c - centre).norm());
    if (!std::isfinite(radius)) {
      out[f] = static_cast<float>(view.minEpsMm);
      continue;
    }
    const Vec3 toCentre = centre - view.eyeMm;
    const double depth = toCentre.dot(dir);
    const double nearest = depth - radius;
    // Behind the eye, or outside the frustum (the bounding sphere beyond the wider half-angle,
    // with 5 % to spare): not seen.
    const double lateral = (toCentre - depth * dir).norm();
    const double halfWidth = std::max(depth, 0.0) * tanHalf * std::max(1.0, view.aspect);
    if (depth + radius <= 0.0 || lateral - radius > halfWidth * 1.05) {
      out[f] = static_cast<float>(view.maxEpsMm);
      continue;
    }
    if (nearest <= 0.0) {
      out[f] = static_cast<float>(view.minEpsMm);  // seen, around the eye: finest
      continue;
    }
    const double pixelMm = 2.0 * nearest * tanHalf / view.viewportHeightPx;
    out[f] = quantised(view.pixelError * pixelMm, view);
  }
  return out;
}

}  // namespace ddfcam::ddf
