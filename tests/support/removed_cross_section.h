// SPDX-License-Identifier: MIT
// The material removed from a plane z = planeZ across a line x = const, from the raster points.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include <cmath>
#include <iterator>
#include <map>

namespace ddfcam::test {

/// Removed cross-section at x = @p xMm (a line through raster points, e.g. a support edge
/// line) of a part that was the plane z = @p planeZMm: the trapezoid rule over the raster points
/// on that line of the plane height minus the represented height, mm^2.
inline double removedCrossSection(const ddf::DisplacementField& field, double xMm,
                                  double planeZMm) {
  std::map<long, double> depthAtY;  // key: y in 1e-6 mm
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k < field.resolution(); ++k)
      for (int i = 0; i + k < field.resolution(); ++i) {
        const ddf::Vec3 q = field.surfacePoint(f, i, k);
        if (std::abs(q.x() - xMm) > 1e-9) continue;
        depthAtY[std::lround(q.y() * 1e6)] = planeZMm - q.z();
      }
  double area = 0.0;
  for (auto it = depthAtY.begin(); it != depthAtY.end() && std::next(it) != depthAtY.end(); ++it) {
    const auto next = std::next(it);
    area += 0.5 * (it->second + next->second) * (next->first - it->first) * 1e-6;
  }
  return area;
}

}  // namespace ddfcam::test
