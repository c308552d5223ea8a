// SPDX-License-Identifier: MIT
// ddfcam: closed triangle meshes of simple tools, for simulation and benchmarks.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

namespace ddfcam::planning {

/// @brief Parameters of a cylindrical grinding roll (the dissertation's cylindric tool).
struct CylinderToolParams {
  double radiusMm = 5.0;  ///< roll radius, mm (default: 5)
  double widthMm = 10.0;  ///< roll width along its axis, mm (default: 10)
  int segments = 50;      ///< facets around the circumference (default: 50 -> 200 triangles)
};

/// @brief Closed, outward-oriented cylinder mesh: axis along +x, centred at the origin.
/// With s segments it has 4 s triangles (s around the mantle twice, s per end cap).
/// @throws InvalidInput for non-positive sizes or fewer than 3 segments.
ddf::TriangleMesh makeCylinderTool(const CylinderToolParams& params);

/// @brief Closed, outward-oriented UV sphere mesh of radius @p radiusMm at the origin with
/// @p rings latitude bands and @p segments longitude segments (ball-end cutter head).
/// @throws InvalidInput for a non-positive radius, rings < 2 or segments < 3.
ddf::TriangleMesh makeSphereTool(double radiusMm, int rings, int segments);

}  // namespace ddfcam::planning
