// SPDX-License-Identifier: MIT
// DDFs with known represented surfaces and mesh checks shared by the surface-extraction tests.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "../support/test_meshes.h"

namespace ddfcam::test {

/// Sets every stored copy's height to fn(face, g) with g the copy's support point.
inline void fillHeights(ddf::DisplacementField& field,
                        const std::function<double(int, const ddf::Vec3&)>& fn) {
  const int n = field.raster().steps();
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        field.heights(f)[field.raster().index(i, k)] =
            static_cast<float>(fn(f, field.basePoint(f, field.rasterBary(i, k))));
}

/// Unit octahedron with radial unit vectors: v(g) = g, so h = 1/|g| - 1 puts every q on the
/// unit sphere.
inline ddf::DisplacementField sphereDdf(int m) {
  const auto mesh = octahedronMesh(1.0);
  ddf::DisplacementField field(mesh, radialVectors(mesh, 1.0), m);
  fillHeights(field, [](int, const ddf::Vec3& g) { return 1.0 / g.norm() - 1.0; });
  return field;
}

/// Octahedron with radial vectors and smooth bumpy heights in (-0.6, 0.6). Copies of shared
/// points are left unsynchronized (each computed from its own face), plus @p copyJitter added
/// per face to make disagreement certain.
inline ddf::DisplacementField bumpyOctahedronDdf(int m, double copyJitter = 0.0) {
  const auto mesh = octahedronMesh(2.0);
  ddf::DisplacementField field(mesh, radialVectors(mesh, 0.5), m);
  fillHeights(field, [&](int f, const ddf::Vec3& g) {
    const ddf::Vec3 d = g.normalized();
    return 0.3 * std::sin(3.0 * d.x() + 1.0) * std::cos(2.0 * d.y()) +
           0.25 * std::sin(4.0 * d.z() - 2.0 * d.x()) + copyJitter * f;
  });
  return field;
}

/// Undirected edge (a < b) -> number of triangles using it.
inline std::map<std::pair<int, int>, int> edgeUse(const ddf::TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> use;
  for (const auto& t : mesh.triangles)
    for (int s = 0; s < 3; ++s) {
      const int a = t[s], b = t[(s + 1) % 3];
      ++use[{std::min(a, b), std::max(a, b)}];
    }
  return use;
}

/// Closest distance from @p p to triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
inline double pointTriangleDistance(const ddf::Vec3& p, const ddf::Vec3& a, const ddf::Vec3& b,
                                    const ddf::Vec3& c) {
  const ddf::Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const ddf::Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const ddf::Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

/// Distance from @p p to segment (a, b).
inline double pointSegmentDistance(const ddf::Vec3& p, const ddf::Vec3& a, const ddf::Vec3& b) {
  const ddf::Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

/// Closed oriented 2-manifold: every directed edge once and its reverse once, every vertex
/// used, no two vertices at the same position, V - E + F == @p euler.
inline ::testing::AssertionResult isClosedManifold(const ddf::TriangleMesh& mesh, int euler) {
  std::set<std::pair<int, int>> directed;
  std::vector<char> used(mesh.vertices.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int s = 0; s < 3; ++s) {
      const int a = mesh.triangles[t][s], b = mesh.triangles[t][(s + 1) % 3];
      if (a == b) return ::testing::AssertionFailure() << "degenerate triangle " << t;
      if (!directed.insert({a, b}).second)
        return ::testing::AssertionFailure() << "directed edge " << a << "->" << b << " twice";
      used[a] = 1;
    }
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a}))
      return ::testing::AssertionFailure() << "edge " << a << "->" << b << " has no twin";
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) return ::testing::AssertionFailure() << "vertex " << v << " unused";
  std::set<std::array<double, 3>> positions;
  for (const auto& v : mesh.vertices)
    if (!positions.insert({v.x(), v.y(), v.z()}).second)
      return ::testing::AssertionFailure() << "two vertices at " << v.transpose();
  const long chi = static_cast<long>(mesh.vertices.size()) -
                   static_cast<long>(directed.size() / 2) +
                   static_cast<long>(mesh.triangles.size());
  if (chi != euler) return ::testing::AssertionFailure() << "Euler characteristic " << chi;
  return ::testing::AssertionSuccess();
}

/// Every raster point's surface point lies within its face's bound of that face's triangles
/// of @p live (brute force over the triangles); @p worst (if given) gets the largest distance.
inline ::testing::AssertionResult withinFaceBounds(const ddf::DisplacementField& field,
                                                   const ddf::IncrementalTriangulation& live,
                                                   const std::vector<float>& bounds,
                                                   double* worst = nullptr) {
  const int n = field.raster().steps();
  double largest = 0.0;
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const ddf::Vec3 q = field.surfacePoint(f, i, k);
        double best = 1e300;
        for (const auto& t : live.faceTriangles(f))
          best = std::min(best, pointTriangleDistance(q, live.vertices()[t[0]],
                                                      live.vertices()[t[1]],
                                                      live.vertices()[t[2]]));
        largest = std::max(largest, best);
        if (best > bounds[f] + 1e-9)
          return ::testing::AssertionFailure() << "face " << f << " point (" << i << ", " << k
                                               << ") " << best << " mm from the mesh";
      }
  if (worst) *worst = largest;
  return ::testing::AssertionSuccess();
}

}  // namespace ddfcam::test
