// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <cmath>
#include <numbers>

namespace ddfcam::planning {

ddf::TriangleMesh makeCylinderTool(const CylinderToolParams& params) {
  if (!(params.radiusMm > 0.0) || !(params.widthMm > 0.0) || params.segments < 3) {
    throw InvalidInput("cylinder tool needs radius > 0, width > 0 and at least 3 segments");
  }
  ddf::TriangleMesh mesh;
  const int s = params.segments;
  const double half = 0.5 * params.widthMm;
  // Ring vertices: [0, s) at x = -half, [s, 2s) at x = +half, then the two cap centres.
  for (int side = 0; side < 2; ++side) {
    const double x = side == 0 ? -half : half;
    for (int i = 0; i < s; ++i) {
      const double a = 2.0 * std::numbers::pi * i / s;
      mesh.vertices.emplace_back(x, params.radiusMm * std::cos(a), params.radiusMm * std::sin(a));
    }
  }
  const int c0 = 2 * s, c1 = 2 * s + 1;
  mesh.vertices.emplace_back(-half, 0.0, 0.0);
  mesh.vertices.emplace_back(half, 0.0, 0.0);
  for (int i = 0; i < s; ++i) {
    const int a = i, b = (i + 1) % s;
    // Mantle quad (a, b, b + s, a + s), outward for angle increasing about +x.
    mesh.triangles.push_back({a, b, b + s});
    mesh.triangles.push_back({a, b + s, a + s});
    mesh.triangles.push_back({c0, b, a});          // cap at -x faces -x
    mesh.triangles.push_back({c1, a + s, b + s});  // cap at +x faces +x
  }
  return mesh;
}

ddf::TriangleMesh makeSphereTool(double radiusMm, int rings, int segments) {
  if (!(radiusMm > 0.0) || rings < 2 || segments < 3) {
    throw InvalidInput("sphere tool needs radius > 0, at least 2 rings and 3 segments");
  }
  ddf::TriangleMesh mesh;
  mesh.vertices.emplace_back(0.0, 0.0, -radiusMm);  // south pole
  for (int r = 1; r < rings; ++r) {
    const double phi = std::numbers::pi * r / rings - 0.5 * std::numbers::pi;
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * std::numbers::pi * i / segments;
      mesh.vertices.emplace_back(radiusMm * std::cos(phi) * std::cos(a),
                                 radiusMm * std::cos(phi) * std::sin(a), radiusMm * std::sin(phi));
    }
  }
  mesh.vertices.emplace_back(0.0, 0.0, radiusMm);  // north pole
  const int north = static_cast<int>(mesh.vertices.size()) - 1;
  auto ring = [&](int r, int i) { return 1 + (r - 1) * segments + (i % segments); };
  for (int i = 0; i < segments; ++i) {
    mesh.triangles.push_back({0, ring(1, i + 1), ring(1, i)});
    for (int r = 1; r + 1 < rings; ++r) {
      mesh.triangles.push_back({ring(r, i), ring(r, i + 1), ring(r + 1, i + 1)});
      mesh.triangles.push_back({ring(r, i), ring(r + 1, i + 1), ring(r + 1, i)});
    }
    mesh.triangles.push_back({north, ring(rings - 1, i), ring(rings - 1, i + 1)});
  }
  return mesh;
}

}  // namespace ddfcam::planning
