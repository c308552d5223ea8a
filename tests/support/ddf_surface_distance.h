// SPDX-License-Identifier: MIT
// ddfcam tests: brute-force both-way distances between a DDF's represented surface and a mesh
// (oracles for the conversion accuracy; independent of the library's raster mesh and BVH).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <vector>

#include "brute_force_distance.h"

namespace ddfcam::test {

/// The represented surface of @p ddf as triangles of its raster lattice, each face on its own
/// (surface points q = g + h v of every stored raster point; shared points not welded).
inline ddf::TriangleMesh latticeSurface(const ddf::DisplacementField& ddf) {
  ddf::TriangleMesh out;
  const int n = ddf.resolution() - 1;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    std::vector<int> at((n + 1) * (n + 1), -1);
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        at[k * (n + 1) + i] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(ddf.surfacePoint(f, i, k));
      }
    const auto id = [&](int i, int k) { return at[k * (n + 1) + i]; };
    for (int k = 0; k < n; ++k)
      for (int i = 0; i + k < n; ++i) {
        out.triangles.push_back({id(i, k), id(i + 1, k), id(i, k + 1)});
        if (i + k + 1 < n) out.triangles.push_back({id(i + 1, k), id(i + 1, k + 1), id(i, k + 1)});
      }
  }
  return out;
}

/// The triangles of a mesh in runs of consecutive triangles, each with its bounding box: the
/// distance to the nearest triangle visits only the runs whose box lies nearer than the nearest
/// triangle found so far, and equals meshDistance() exactly (a box is never farther than its
/// triangles, and the minimum is taken over the same triangle distances).
class TriangleRuns {
 public:
  explicit TriangleRuns(const ddf::TriangleMesh& mesh) : mesh_(mesh) {
    for (std::size_t t = 0; t < mesh.triangles.size(); t += kRun) {
      Eigen::AlignedBox3d box;
      for (std::size_t u = t; u < std::min(t + kRun, mesh.triangles.size()); ++u)
        for (const int v : mesh.triangles[u]) box.extend(mesh.vertices[v]);
      boxes_.push_back(box);
    }
  }

  /// Distance from @p p to the nearest triangle, as meshDistance(mesh, p).
  double distance(const Vec3& p) const {
    std::vector<double> boxDistance(boxes_.size());
    for (std::size_t r = 0; r < boxes_.size(); ++r) boxDistance[r] = boxes_[r].exteriorDistance(p);
    double best = std::numeric_limits<double>::infinity();
    const auto nearest = std::min_element(boxDistance.begin(), boxDistance.end());
    if (nearest != boxDistance.end()) best = runDistance(nearest - boxDistance.begin(), p, best);
    for (std::size_t r = 0; r < boxes_.size(); ++r)
      if (boxDistance[r] < best) best = runDistance(r, p, best);
    return best;
  }

 private:
  static constexpr std::size_t kRun = 32;

  double runDistance(std::size_t run, const Vec3& p, double best) const {
    const auto& tri = mesh_.triangles;
    for (std::size_t t = run * kRun; t < std::min((run + 1) * kRun, tri.size()); ++t)
      best = std::min(best, triangleDistance(p, mesh_.vertices[tri[t][0]],
                                             mesh_.vertices[tri[t][1]], mesh_.vertices[tri[t][2]]));
    return best;
  }

  const ddf::TriangleMesh& mesh_;
  std::vector<Eigen::AlignedBox3d> boxes_;
};

/// Largest brute-force distance from every @p stride-th of @p points to @p mesh.
inline double largestDistance(const std::vector<Vec3>& points, const ddf::TriangleMesh& mesh,
                              int stride = 1) {
  const TriangleRuns runs(mesh);
  double worst = 0.0;
  for (std::size_t p = 0; p < points.size(); p += stride)
    worst = std::max(worst, runs.distance(points[p]));
  return worst;
}

/// Vertices, edge midpoints and centroids of every @p stride-th triangle of @p mesh.
inline std::vector<Vec3> triangleSamples(const ddf::TriangleMesh& mesh, int stride = 1) {
  std::vector<Vec3> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += stride) {
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    for (const Vec3& p : {a, b, c, Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a)),
                          Vec3((a + b + c) / 3.0)})
      out.push_back(p);
  }
  return out;
}

/// Surface points of every @p stride-th stored raster point of @p ddf.
inline std::vector<Vec3> rasterSurfacePoints(const ddf::DisplacementField& ddf, int stride = 1) {
  std::vector<Vec3> out;
  const int n = ddf.resolution() - 1;
  long long index = 0;
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        if (index++ % stride == 0) out.push_back(ddf.surfacePoint(f, i, k));
  return out;
}

}  // namespace ddfcam::test
