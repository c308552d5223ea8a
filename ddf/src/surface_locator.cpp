// SPDX-License-Identifier: MIT
// ddfcam: locating points near a DDF's surface.
#include <ddfcam/ddf/surface_locator.h>

#include <algorithm>
#include <limits>

namespace ddfcam::ddf {

SurfaceLocator::SurfaceLocator(const DisplacementField& ddf)
    : ddf_(ddf), boxes_(static_cast<std::size_t>(ddf.faceCount())) {
  for (int f = 0; f < ddf.faceCount(); ++f) {
    Eigen::AlignedBox3d& box = boxes_[static_cast<std::size_t>(f)];
    double longest = 0.0;
    for (int v : ddf.faceVertices(f)) {
      box.extend(ddf.position(v) + ddf.vector(v));
      box.extend(ddf.position(v) - ddf.vector(v));
      longest = std::max(longest, ddf.vector(v).norm());
    }
    // A point on a curved face's surface may bulge slightly out of its vertices' hull.
    box.min().array() -= 0.1 * longest;
    box.max().array() += 0.1 * longest;
  }
}

std::optional<SurfaceLocation> SurfaceLocator::locate(const Vec3& p) const {
  std::optional<SurfaceLocation> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int f = 0; f < ddf_.faceCount(); ++f) {
    if (!boxes_[static_cast<std::size_t>(f)].contains(p)) continue;
    const auto location = locateOnFace(ddf_, f, p);
    if (!location) continue;
    const double distance = (location->point - p).norm();
    if (distance < bestDistance) {
      bestDistance = distance;
      best = location;
    }
  }
  return best;
}

}  // namespace ddfcam::ddf
