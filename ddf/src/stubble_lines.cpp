// SPDX-License-Identifier: MIT
// ddfcam: displacement stubbles along the vectors of raster points.
#include <ddfcam/ddf/stubble_lines.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "canonical_points.h"

namespace ddfcam::ddf {

StubbleLines stubbleLines(const DisplacementField& ddf, const StubbleLinesParams& params) {
  const RasterTopology& topo = ddf.topology();
  const detail::PointOwners owners(ddf);
  const int n = ddf.raster().steps();
  const int stride = std::max(params.stride, 1);
  const int faces = ddf.faceCount();

  // Two passes (count, then fill at prefix offsets) keep the order deterministic.
  auto forEachDrawn = [&](int f, auto&& fn) {
    for (int k = 0; k <= n; k += stride) {
      for (int i = 0; i + k <= n; i += stride) {
        const PointId id = topo.id(f, i, k);
        if (owners.owner(id, f) == f) fn(i, k, id);
      }
    }
  };
  std::vector<std::size_t> offset(faces + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, faces), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t count = 0;
      forEachDrawn(f, [&](int, int, PointId) { ++count; });
      offset[f + 1] = count;
    }
  });
  for (int f = 0; f < faces; ++f) offset[f + 1] += offset[f];

  StubbleLines out;
  out.from.resize(offset[faces]);
  out.to.resize(offset[faces]);
  out.point.resize(offset[faces]);
  const bool fullCrust = params.range == StubbleRange::FullCrust;
  tbb::parallel_for(tbb::blocked_range<int>(0, faces), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      std::size_t s = offset[f];
      forEachDrawn(f, [&](int i, int k, PointId id) {
        const Vec3 bary = ddf.rasterBary(i, k);
        const Vec3 g = ddf.basePoint(f, bary);
        const Vec3 v = ddf.vectorAt(f, bary);
        const double lo = fullCrust ? -1.0 : 0.0;
        const double hi = fullCrust ? 1.0 : static_cast<double>(ddf.height(f, i, k));
        out.from[s] = g + lo * v;
        out.to[s] = g + hi * v;
        out.point[s] = id;
        ++s;
      });
    }
  });
  return out;
}

}  // namespace ddfcam::ddf
