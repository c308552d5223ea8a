// SPDX-License-Identifier: MIT
// ddfcam: both-way distances between a converted DDF and its input, and resolution bounds.
#include "conversion_accuracy.h"

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace ddfcam::ddf::detail {
namespace {

constexpr int kMaxResolution = 256;
// Queries between two progress calls: a few hundred milliseconds on a small machine.
constexpr int kBlock = 1 << 15;

/// A distance and the point it was measured at.
struct Farthest {
  double distance = 0.0;
  Vec3 point = Vec3::Zero();
};

Farthest farther(const Farthest& a, const Farthest& b) {
  return b.distance > a.distance ? b : a;
}

/// Largest distance(point(i)) over i in [0, count), in blocks with a progress call between.
Farthest farthestOf(int count, const std::function<Vec3(int)>& point, const TriangleBvh& bvh,
                    const ProgressCallback& progress, double from, double to) {
  Farthest best;
  for (int begin = 0; begin < count; begin += kBlock) {
    reportProgress(progress, from + (to - from) * begin / std::max(count, 1));
    const int end = std::min(count, begin + kBlock);
    best = farther(best, tbb::parallel_reduce(
                             tbb::blocked_range<int>(begin, end), Farthest{},
                             [&](const tbb::blocked_range<int>& range, Farthest acc) {
                               for (int i = range.begin(); i != range.end(); ++i) {
                                 const Vec3 p = point(i);
                                 acc = farther(acc, {bvh.distance(p), p});
                               }
                               return acc;
                             },
                             farther));
  }
  return best;
}

std::string megabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  return text;
}

}  // namespace

double longestSupportEdgeMm(const SupportMesh& support) {
  double longest = 0.0;
  for (const auto e : support.edges())
    longest = std::max(longest, double(support.calc_edge_length(e)));
  return longest;
}

std::size_t storedRasterPoints(int faces, int m) {
  return static_cast<std::size_t>(faces) * static_cast<std::size_t>(m) *
         static_cast<std::size_t>(m + 1) / 2;
}

int resolutionForSpacing(double longestEdgeMm, int faces, double spacingMm,
                         std::size_t maxRasterPoints) {
  if (!(spacingMm > 0.0) || !std::isfinite(spacingMm))
    throw InvalidInput("mesh conversion: raster spacing must be > 0 mm, got " +
                       std::to_string(spacingMm));
  // The small slack keeps an edge that is an exact multiple of the spacing at that multiple.
  const double steps = std::ceil(longestEdgeMm / spacingMm * (1.0 - 1e-12));
  const double m = std::max(2.0, steps + 1.0);
  const double points = faces * m * (m + 1.0) / 2.0;
  if (m > kMaxResolution || points > static_cast<double>(maxRasterPoints))
    throw InvalidInput("mesh conversion: a raster spacing of " + std::to_string(spacingMm) +
                       " mm on the longest support edge (" + std::to_string(longestEdgeMm) +
                       " mm) needs m = " + std::to_string(static_cast<long long>(m)) + ", i.e. " +
                       std::to_string(static_cast<long long>(points)) + " raster points on " +
                       std::to_string(faces) + " support faces (" + megabytes(4.0 * points) +
                       " of heights); the limits are m = " + std::to_string(kMaxResolution) +
                       " and " + std::to_string(maxRasterPoints) +
                       " raster points: choose a larger spacing or a "
                       "reduced support");
  return static_cast<int>(m);
}

std::vector<Vec3> inputSamples(const TriangleMesh& input, std::span<const int> triangles) {
  std::vector<char> taken(input.vertices.size(), 0);
  std::vector<Vec3> out;
  out.reserve(5 * triangles.size());
  for (int t : triangles) {
    const auto& tri = input.triangles[t];
    const Vec3 &a = input.vertices[tri[0]], &b = input.vertices[tri[1]],
               &c = input.vertices[tri[2]];
    for (int v : tri)
      if (!taken[v]) taken[v] = 1, out.push_back(input.vertices[v]);
    out.push_back(0.5 * (a + b));
    out.push_back(0.5 * (b + c));
    out.push_back(0.5 * (c + a));
    out.push_back((a + b + c) / 3.0);
  }
  return out;
}

MeasuredDistances measureDistances(const DisplacementField& ddf, std::span<const Vec3> samples,
                                   const TriangleBvh& inputBvh, const ProgressCallback& progress) {
  reportProgress(progress, 0.0);
  const TriangleMesh surface = extractRasterMesh(ddf).mesh;
  const TriangleBvh surfaceBvh(surface);
  const Farthest in = farthestOf(
      static_cast<int>(samples.size()), [&](int i) { return samples[i]; }, surfaceBvh, progress,
      0.1, 0.4);
  const int perFace = static_cast<int>(ddf.pointsPerFace());
  const int n = ddf.raster().steps();
  std::vector<std::array<int, 2>> lattice;  // (i, k) in Raster order: row k, then i
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i + k <= n; ++i) lattice.push_back({i, k});
  const Farthest out = farthestOf(
      ddf.faceCount() * perFace,
      [&](int p) {
        const auto& ik = lattice[p % perFace];
        return ddf.surfacePoint(p / perFace, ik[0], ik[1]);
      },
      inputBvh, progress, 0.4, 1.0);
  reportProgress(progress, 1.0);
  return {in.distance, out.distance, in.point, out.point};
}

}  // namespace ddfcam::ddf::detail
