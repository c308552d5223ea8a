// SPDX-License-Identifier: MIT
// Benchmark workloads of the dissertation's grinding figures (fig. 8.14, fig. 8.16).
#pragma once

#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace ddfcam::bench {

/// A part, its design surface, a cylindrical grinding roll and the roll's poses along a path.
struct GrindingWorkload {
  ddf::DisplacementField ddf;
  std::shared_ptr<const ddf::HeightFieldSurface> design;
  ddf::TriangleMesh tool;                // 200 triangles
  std::vector<Eigen::Isometry3d> poses;  // tool frame -> part frame
  std::vector<float> initialHeights;     // heights before the first pass
};

/// Fig. 8.16: 100 support triangles at m = 50 on a curved B-spline patch, the 200-triangle roll
/// at 217 positions along a straight feed line, 0.3 mm deep.
GrindingWorkload fig8_16Workload();

/// Fig. 8.14: one support triangle at m = 400 carrying a curved surface, the roll at 216
/// positions along a path across it.
GrindingWorkload fig8_14Workload();

}  // namespace ddfcam::bench
