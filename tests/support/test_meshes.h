// SPDX-License-Identifier: MIT
// Small support meshes built in code for the unit tests.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace ddfcam::test {

/// Regular grid in the z = 0 plane, nx x ny quads of size (sx, sy) mm, each split in two.
inline ddf::SupportMesh gridMesh(int nx, int ny, double sx = 1.0, double sy = 1.0) {
  std::vector<ddf::Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  for (int y = 0; y <= ny; ++y)
    for (int x = 0; x <= nx; ++x) points.emplace_back(x * sx, y * sy, 0.0);
  auto at = [&](int x, int y) { return y * (nx + 1) + x; };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  return ddf::makeSupportMesh(points, triangles);
}

/// Regular octahedron with vertices at distance r from the origin (closed, genus 0).
inline ddf::SupportMesh octahedronMesh(double r = 1.0) {
  const std::vector<ddf::Vec3> points = {{r, 0, 0},  {-r, 0, 0}, {0, r, 0},
                                         {0, -r, 0}, {0, 0, r},  {0, 0, -r}};
  const std::vector<std::array<int, 3>> triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                     {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return ddf::makeSupportMesh(points, triangles);
}

/// Vectors of length @p length along +z for every vertex of @p mesh.
inline std::vector<ddf::Vec3> constantVectors(const ddf::SupportMesh& mesh,
                                              const ddf::Vec3& v = {0, 0, 1}) {
  return std::vector<ddf::Vec3>(mesh.n_vertices(), v);
}

/// Radial unit vectors (for meshes around the origin).
inline std::vector<ddf::Vec3> radialVectors(const ddf::SupportMesh& mesh, double length = 1.0) {
  std::vector<ddf::Vec3> out;
  for (const auto vh : mesh.vertices())
    out.push_back(ddf::toEigen(mesh.point(vh)).normalized() * length);
  return out;
}

/// Closed, outward-oriented axis-aligned box [lo, hi] as 12 triangles.
inline ddf::TriangleMesh boxMesh(const ddf::Vec3& lo, const ddf::Vec3& hi) {
  ddf::TriangleMesh box;
  for (int c = 0; c < 8; ++c)
    box.vertices.emplace_back(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(),
                              c & 4 ? hi.z() : lo.z());
  // Quads (a, b, c, d) counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    box.triangles.push_back({q[0], q[1], q[2]});
    box.triangles.push_back({q[0], q[2], q[3]});
  }
  return box;
}

/// The surface z = @p height(x, y) over [x0, x1] x [y0, y1] mm as nx x ny cells of two
/// counter-clockwise triangles each (normal +z for a flat surface).
inline ddf::TriangleMesh heightFieldMesh(double x0, double x1, double y0, double y1, int nx, int ny,
                                         const std::function<double(double, double)>& height) {
  ddf::TriangleMesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + (x1 - x0) * i / nx, y = y0 + (y1 - y0) * j / ny;
      mesh.vertices.emplace_back(x, y, height(x, y));
    }
  const auto at = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

/// Torus with radii (R, r) about the z axis as an nu x nv quad grid split into triangles,
/// counter-clockwise seen from outside.
inline ddf::TriangleMesh torusMesh(double R, double r, int nu, int nv) {
  ddf::TriangleMesh mesh;
  const double twoPi = 2.0 * 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = twoPi * i / nu, v = twoPi * j / nv;
      mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u),
                                 (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

/// Exact principal curvatures (k_max, k_min), 1/mm, of the torus (R, r) of torusMesh at the
/// torus point nearest to @p p, tool side (outward normal, convex positive): 1/r around the
/// tube and cos v / (R + r cos v) around the axis.
inline std::pair<double, double> torusCurvature(double R, double r, const ddf::Vec3& p) {
  const double v = std::atan2(p.z(), std::hypot(p.x(), p.y()) - R);
  const double a = 1.0 / r, b = std::cos(v) / (R + r * std::cos(v));
  return {std::max(a, b), std::min(a, b)};
}

}  // namespace ddfcam::test
