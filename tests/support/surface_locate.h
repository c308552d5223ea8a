// SPDX-License-Identifier: MIT
// The DDF surface location nearest a point, by brute force over the face centroids.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace ddfcam::test {

/// The DDF surface location nearest to @p target: locateOnFace on the six faces whose centroids
/// are nearest (brute force over the centroids). Default-constructed when none locates it.
inline ddf::SurfaceLocation locateNear(const ddf::DisplacementField& ddf, const ddf::Vec3& target) {
  const ddf::Vec3 third = ddf::Vec3::Constant(1.0 / 3.0);
  std::vector<std::pair<double, int>> order;
  for (int f = 0; f < ddf.faceCount(); ++f)
    order.push_back({(ddf.basePoint(f, third) - target).squaredNorm(), f});
  std::partial_sort(order.begin(), order.begin() + 6, order.end());
  ddf::SurfaceLocation best;
  double bestDistance = INFINITY;
  for (int c = 0; c < 6; ++c) {
    const auto loc = ddf::locateOnFace(ddf, order[c].second, target);
    if (loc && (loc->point - target).norm() < bestDistance)
      best = *loc, bestDistance = (loc->point - target).norm();
  }
  return best;
}

}  // namespace ddfcam::test
