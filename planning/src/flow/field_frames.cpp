// SPDX-License-Identifier: MIT
// ddfcam: internal tangent frames and raster triangles of a DDF surface for line fields.
#include "field_frames.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::planning::detail {

namespace {

using ddf::PointId;
using ddf::Vec3;

void mapCopies(const ddf::DisplacementField& ddf, SurfaceFrames& out) {
  const ddf::RasterTopology& topo = ddf.topology();
  const std::size_t perFace = ddf.pointsPerFace();
  out.idOfCopy.assign(perFace * ddf.faceCount(), 0);
  for (PointId p = 0; p < topo.pointCount(); ++p)
    topo.forEachCopy(p, [&](ddf::PointCopy c) { out.idOfCopy[c.face * perFace + c.local] = p; });
  out.position.assign(topo.pointCount(), Vec3::Zero());
  std::vector<char> seen(topo.pointCount(), 0);
  const int n = ddf.raster().steps();
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        const PointId p = out.idOfCopy[f * perFace + ddf.raster().index(i, k)];
        if (!seen[p]) out.position[p] = ddf.surfacePoint(f, i, k);
        seen[p] = 1;
      }
}

// Raster triangles in the (j, k) lattice of each face; both kinds keep the face's orientation.
void collectTriangles(const ddf::DisplacementField& ddf, SurfaceFrames& out) {
  const ddf::Raster& r = ddf.raster();
  const int n = r.steps();
  const std::size_t perFace = ddf.pointsPerFace();
  auto local = [&](int j, int k) { return static_cast<std::uint32_t>(r.index(n - j - k, k)); };
  auto add = [&](int f, std::array<std::uint32_t, 3> l) {
    RasterTriangle t{f, l, {}};
    for (int a = 0; a < 3; ++a) t.point[a] = out.idOfCopy[f * perFace + l[a]];
    out.triangles.push_back(t);
  };
  out.triangles.reserve(static_cast<std::size_t>(ddf.faceCount()) * n * n);
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < n; ++k)
      for (int j = 0; j + k < n; ++j) {
        add(f, {local(j, k), local(j + 1, k), local(j, k + 1)});
        if (j + k + 2 <= n) add(f, {local(j + 1, k), local(j + 1, k + 1), local(j, k + 1)});
      }
}

void computeFrames(SurfaceFrames& out) {
  const std::size_t count = out.position.size();
  out.normal.assign(count, Vec3::Zero());
  out.area.assign(count, 0.0);
  std::vector<std::array<PointId, 2>> edges;
  edges.reserve(out.triangles.size() * 3);
  for (const RasterTriangle& t : out.triangles) {
    const Vec3& x0 = out.position[t.point[0]];
    const Vec3 cross = (out.position[t.point[1]] - x0).cross(out.position[t.point[2]] - x0);
    for (int a = 0; a < 3; ++a) {
      out.normal[t.point[a]] += cross;
      out.area[t.point[a]] += cross.norm() / 6.0;
      const PointId p = t.point[a], q = t.point[(a + 1) % 3];
      edges.push_back({std::min(p, q), std::max(p, q)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  out.edges = std::move(edges);
  out.axis1.resize(count);
  out.axis2.resize(count);
  for (std::size_t p = 0; p < count; ++p) {
    out.normal[p].normalize();
    out.axis1[p] = out.normal[p].unitOrthogonal();
    out.axis2[p] = out.normal[p].cross(out.axis1[p]);
  }
}

}  // namespace

SurfaceFrames buildSurfaceFrames(const ddf::DisplacementField& ddf) {
  SurfaceFrames out;
  mapCopies(ddf, out);
  collectTriangles(ddf, out);
  computeFrames(out);
  return out;
}

double tangentAngle(const SurfaceFrames& frames, PointId p, const Vec3& d) {
  return std::atan2(d.dot(frames.axis2[p]), d.dot(frames.axis1[p]));
}

double transportAngle(const SurfaceFrames& frames, PointId p, PointId q) {
  const Vec3 d = frames.position[q] - frames.position[p];
  return tangentAngle(frames, q, d) - tangentAngle(frames, p, d);
}

double wrapAngle(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::remainder(a, kTwoPi);
  return a <= -std::numbers::pi ? a + kTwoPi : a;
}

std::complex<double> doubledAngle(const SurfaceFrames& frames, PointId p, const Vec3& d,
                                  double minLength) {
  const double x = d.dot(frames.axis1[p]), y = d.dot(frames.axis2[p]);
  if (std::hypot(x, y) < minLength) return {0.0, 0.0};
  return std::polar(1.0, 2.0 * std::atan2(y, x));
}

Vec3 lineOf(const SurfaceFrames& frames, PointId p, std::complex<double> z) {
  if (std::abs(z) == 0.0) return Vec3::Zero();
  const double a = 0.5 * std::arg(z);
  return std::cos(a) * frames.axis1[p] + std::sin(a) * frames.axis2[p];
}

}  // namespace ddfcam::planning::detail
