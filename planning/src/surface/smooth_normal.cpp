// SPDX-License-Identifier: MIT
// ddfcam: smoothSurfaceNormal: raster point normals interpolated over the raster triangle.
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

/// Sum of the cross products of the raster triangles around lattice point (i, k) inside
/// @p face (their area-weighted normal, not unit), turned to the side of the vectors.
Vec3 fanNormal(const ddf::DisplacementField& ddf, int face, int i, int k) {
  static constexpr int kRing[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  const int n = ddf.resolution() - 1;
  const Vec3 centre = ddf.surfacePoint(face, i, k);
  const auto valid = [&](int r) {
    const int a = i + kRing[r][0], c = k + kRing[r][1];
    return a >= 0 && c >= 0 && a + c <= n;
  };
  const auto edge = [&](int r) {
    return Vec3(ddf.surfacePoint(face, i + kRing[r][0], k + kRing[r][1]) - centre);
  };
  Vec3 sum = Vec3::Zero();
  for (int r = 0; r < 6; ++r)
    if (valid(r) && valid((r + 1) % 6)) sum += edge(r).cross(edge((r + 1) % 6));
  const Vec3 bary(i, n - i - k, k);
  return sum.dot(ddf.vectorAt(face, bary / n)) < 0 ? Vec3(-sum) : sum;
}

/// Unit normal of raster point (i, k) of @p face: its fan, joined with the fans of its copies
/// in the neighbouring faces when it lies on a support edge or vertex (so that the normal is
/// the same from both sides of a seam).
Vec3 rasterPointNormal(const ddf::DisplacementField& ddf, int face, int i, int k) {
  const int n = ddf.resolution() - 1;
  if (i > 0 && k > 0 && i + k < n) return fanNormal(ddf, face, i, k).normalized();
  const ddf::RasterTopology& topology = ddf.topology();
  Vec3 sum = Vec3::Zero();
  topology.forEachCopy(topology.id(face, i, k), [&](ddf::PointCopy copy) {
    const ddf::RasterCoord c = topology.coord(copy);
    sum += fanNormal(ddf, copy.face, c.i, c.k);
  });
  return sum.normalized();
}

}  // namespace

Vec3 smoothSurfaceNormal(const ddf::DisplacementField& ddf, const ddf::SurfaceLocation& loc) {
  if (loc.face < 0 || loc.face >= ddf.faceCount() || !loc.bary.allFinite())
    throw InvalidInput("smoothSurfaceNormal: face " + std::to_string(loc.face) +
                       " is out of range or the barycentric coordinates are not finite");
  const int n = ddf.resolution() - 1;
  const double a = std::clamp(loc.bary.x(), 0.0, 1.0) * n,
               c = std::clamp(loc.bary.z(), 0.0, 1.0) * n;
  const int i = std::clamp(static_cast<int>(std::floor(a)), 0, n - 1);
  const int k = std::clamp(static_cast<int>(std::floor(c)), 0, n - 1 - i);
  const double fa = a - i, fc = c - k;
  const auto unit = [&](int pi, int pk) {
    return rasterPointNormal(ddf, loc.face, pi, pk).normalized();
  };
  Vec3 sum;
  // The "down" triangle of the lattice cell exists only away from the face's third edge.
  if (fa + fc <= 1.0 || i + k + 2 > n)
    sum = (1 - fa - fc) * unit(i, k) + fa * unit(i + 1, k) + fc * unit(i, k + 1);
  else
    sum =
        (1 - fc) * unit(i + 1, k) + (fa + fc - 1) * unit(i + 1, k + 1) + (1 - fa) * unit(i, k + 1);
  if (sum.dot(ddf.vectorAt(loc.face, loc.bary)) < 0) sum = -sum;
  return sum.normalized();
}

}  // namespace ddfcam::planning
