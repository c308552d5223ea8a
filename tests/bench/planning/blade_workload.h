// SPDX-License-Identifier: MIT
// ddfcam-bench: 217 positions of a grinding roll across the shared turbine blade mesh.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace ddfcam::bench {

/// @brief The turbine blade converted to a DDF and a 200-triangle roll at 217 poses on it.
struct BladeWorkload {
  ddf::DisplacementField ddf;            ///< the blade by io::loadPart at the requested m
  ddf::TriangleMesh tool;                ///< makeCylinderTool({radius, width, 50}): 200 triangles
  std::vector<Eigen::Isometry3d> poses;  ///< tool frame -> part frame, along a straight feed
  std::vector<float> initialHeights;     ///< heights before the first pose
  double size = 0;    ///< longest bounding-box extent of the blade (mesh units, ~0.1)
  double radius = 0;  ///< roll radius: 4 % of size
  double width = 0;   ///< roll width: 8 % of size
  double depth = 0;   ///< infeed below each contact along the normal: 0.3 % of size
};

/// Raster resolution of the blade DDF (13,306 support faces).
constexpr int kBladeResolution = 10;

/// @brief Loads turbine-blade-jigsaw.stl from DDFCAM_SHARED_DATA_DIR/meshes and converts it
/// with the project's pipeline (io::loadPart). The feed runs along the longest bounding-box
/// axis through the middle of the second longest; contacts are the first hits of rays cast
/// along minus the shortest axis, normals the barycentric blend of the area-weighted vertex
/// normals there; 217 rays evenly spread over the hit span (rays that miss are dropped, so
/// poses.size() may be slightly below 217). nullopt if the file is missing.
/// @param resolution raster resolution m of the DDF (default kBladeResolution).
std::optional<BladeWorkload> bladeWorkload(int resolution = kBladeResolution);

}  // namespace ddfcam::bench
