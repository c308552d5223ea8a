// SPDX-License-Identifier: MIT
// Test meshes for the mesh -> DDF conversion report: known unused vertices and duplicates, and
// a fan that no choice of vectors can make a valid DDF.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include "test_meshes.h"

namespace ddfcam::test {

/// Unused vertices and duplicate triangles added to the 3 x 3 cell grid of heightFieldMesh.
constexpr int kStrayVertices = 7, kDuplicateTriangles = 2;

/// The flat 3 x 3 mm grid (16 vertices, 18 triangles) followed by kStrayVertices vertices no
/// triangle refers to (1 mm apart, 5 mm above it: nothing welds them) and kDuplicateTriangles
/// repeats: triangle 0 as it is and triangle 3 reversed.
inline ddf::TriangleMesh gridWithStrayVerticesAndDuplicates() {
  ddf::TriangleMesh mesh =
      heightFieldMesh(0.0, 3.0, 0.0, 3.0, 3, 3, [](double, double) { return 0.0; });
  for (int i = 0; i < kStrayVertices; ++i) mesh.vertices.emplace_back(i, 0.5, 5.0);
  mesh.triangles.push_back(mesh.triangles[0]);
  const auto t = mesh.triangles[3];
  mesh.triangles.push_back({t[0], t[2], t[1]});
  return mesh;
}

/// An open fan of four triangles around vertex 0 (at the origin) whose unit normals are the
/// corners of a regular tetrahedron. Those sum to zero, so the origin is inside their hull and
/// no direction v has v . n > 0 for all four: whatever the vector of vertex 0, it points to
/// the back side of some face, and constraint 1 must fail there.
inline ddf::TriangleMesh foldedFanMesh() {
  const std::vector<ddf::Vec3> n = {
      {0, 0, 1}, {0.9428, 0, -0.3333}, {-0.4714, 0.8165, -0.3333}, {-0.4714, -0.8165, -0.3333}};
  // Face (0, i, i+1) has normal p_i x p_{i+1}: p_i is perpendicular to both neighbours.
  std::vector<ddf::Vec3> p(6, ddf::Vec3::Zero());
  p[2] = n[0].cross(n[1]);
  p[3] = n[1].cross(n[2]);
  if (p[2].cross(p[3]).dot(n[1]) < 0) p[3] = -p[3];
  p[4] = n[2].cross(n[3]);
  if (p[3].cross(p[4]).dot(n[2]) < 0) p[4] = -p[4];
  p[1] = p[2].cross(n[0]);
  p[5] = n[3].cross(p[4]);
  ddf::TriangleMesh mesh;
  mesh.vertices = p;
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  return mesh;
}

}  // namespace ddfcam::test
