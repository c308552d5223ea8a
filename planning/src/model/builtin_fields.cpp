// SPDX-License-Identifier: MIT
// ddfcam: scalar fields every part has (height, material removed, deviation from a mesh).
#include <ddfcam/error.h>
#include <ddfcam/planning/model/builtin_fields.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning {
namespace {

// Calls fn(i, k, l) for every raster point (i, k) of a face, l its index in Raster order.
template <class Fn>
void forRasterPoints(const ddf::Raster& raster, Fn&& fn) {
  const int n = raster.steps();
  std::size_t l = 0;
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i + k <= n; ++i) fn(i, k, l++);
}

// |v| at every raster point, laid out like the heights.
std::vector<double> vectorLengths(const ddf::DisplacementField& ddf) {
  std::vector<double> out(ddf.allHeights().size());
  tbb::parallel_for(tbb::blocked_range<int>(0, ddf.faceCount()), [&](const auto& range) {
    for (int f = range.begin(); f != range.end(); ++f) {
      double* lengths = out.data() + static_cast<std::size_t>(f) * ddf.pointsPerFace();
      forRasterPoints(ddf.raster(), [&](int i, int k, std::size_t l) {
        lengths[l] = ddf.vectorAt(f, ddf.rasterBary(i, k)).norm();
      });
    }
  });
  return out;
}

// Runs fn(face) over all faces in parallel blocks sized to take about kBlockSeconds each, so
// that the calling thread reports progress (and may cancel) a few times per second.
template <class Fn>
void forFacesWithProgress(int faces, const ProgressCallback& progress, Fn&& fn) {
  auto run = [&](int begin, int end) {
    tbb::parallel_for(tbb::blocked_range<int>(begin, end), [&](const auto& range) {
      for (int f = range.begin(); f != range.end(); ++f) fn(f);
    });
  };
  if (!progress) return run(0, faces);
  constexpr double kBlockSeconds = 0.03;
  reportProgress(progress, 0.0);
  int block = std::max(1, tbb::this_task_arena::max_concurrency());
  for (int begin = 0; begin < faces;) {
    const int end = std::min(faces, begin + block);
    const auto start = std::chrono::steady_clock::now();
    run(begin, end);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    reportProgress(progress, static_cast<double>(end) / faces);
    const double scale = seconds > 0.0 ? kBlockSeconds / seconds : 4.0;
    block = std::max(1, static_cast<int>(block * std::min(scale, 4.0)));
    begin = end;
  }
}

}  // namespace

ScalarField heightField(const ddf::DisplacementField& ddf) {
  return {"height (h)", "", true, ddf.allHeights(), {}};
}

ScalarField heightMmField(const ddf::DisplacementField& ddf) {
  const std::vector<double> lengths = vectorLengths(ddf);
  ScalarField out{"height above support", "mm", true, std::vector<float>(lengths.size()), {}};
  for (std::size_t l = 0; l < lengths.size(); ++l)
    out.values[l] = static_cast<float>(ddf.allHeights()[l] * lengths[l]);
  return out;
}

ScalarField materialRemovedField(const ddf::DisplacementField& ddf,
                                 std::span<const float> referenceHeights) {
  if (referenceHeights.size() != ddf.allHeights().size()) {
    throw InvalidInput("materialRemovedField: " + std::to_string(referenceHeights.size()) +
                       " reference heights, expected " + std::to_string(ddf.allHeights().size()));
  }
  const std::vector<double> lengths = vectorLengths(ddf);
  ScalarField out{"material removed", "mm", false, std::vector<float>(lengths.size()), {}};
  for (std::size_t l = 0; l < lengths.size(); ++l) {
    const double removed = static_cast<double>(referenceHeights[l]) - ddf.allHeights()[l];
    out.values[l] = static_cast<float>(removed * lengths[l]);
  }
  return out;
}

ScalarField deviationField(const ddf::DisplacementField& ddf, const ddf::TriangleMesh& reference,
                           const ProgressCallback& progress) {
  if (reference.triangles.empty())
    throw InvalidInput("deviationField: the reference mesh has no triangles");
  const MeshDistance distance(reference);
  ScalarField out{"deviation from mesh", "mm", true,
                  std::vector<float>(ddf.allHeights().size()), {}};
  forFacesWithProgress(ddf.faceCount(), progress, [&](int f) {
    float* values = out.values.data() + static_cast<std::size_t>(f) * ddf.pointsPerFace();
    forRasterPoints(ddf.raster(), [&](int i, int k, std::size_t l) {
      const auto closest = distance.closestPoint(ddf.surfacePoint(f, i, k));
      values[l] = closest ? static_cast<float>(closest->signedDistance)
                          : std::numeric_limits<float>::quiet_NaN();
    });
  });
  reportProgress(progress, 1.0);
  return out;
}

}  // namespace ddfcam::planning
