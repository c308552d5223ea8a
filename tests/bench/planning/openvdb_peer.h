// SPDX-License-Identifier: MIT
// ddfcam-bench: the OpenVDB level-set peer of the grinding benchmarks.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>

namespace ddfcam::bench {

/// @brief Parameters of a narrow-band level set.
struct VdbLevelSetParams {
  /// Voxel edge length, mm; the benchmarks set it to the DDF raster spacing. Default 0.1.
  double voxelMm = 0.1;
  /// Half width of the narrow band on each side of the surface, voxels. Default 3 (OpenVDB's
  /// LEVEL_SET_HALF_WIDTH, the smallest band its CSG and resampling tools support).
  double halfWidthVoxels = 3.0;
};

/// @brief Timing of VdbPart::subtractTools, seconds of wall time.
struct VdbCsgTimes {
  double meshToLevelSetSeconds = 0.0;  ///< scan conversion of the posed tool meshes
  double csgSeconds = 0.0;             ///< csgDifference of every tool grid from the part
};

/// @brief A closed part as an OpenVDB float level set (OpenVDB is used only in here, so the
/// benchmark sources do not include its headers). Copyable state: reset() restores the part
/// as converted, so repeated benchmark runs start from the same solid.
class VdbPart {
 public:
  /// @brief Scan-converts the closed, outward-oriented @p part (mm) with meshToLevelSet.
  VdbPart(const ddf::TriangleMesh& part, const VdbLevelSetParams& params = {});
  ~VdbPart();
  VdbPart(const VdbPart&) = delete;
  VdbPart& operator=(const VdbPart&) = delete;

  /// @brief Restores the grid converted by the constructor (a deep copy of it).
  void reset();
  /// @brief Subtracts @p tool (closed, tool frame) placed at every pose (tool frame -> part
  /// frame) in order: meshToLevelSet of the transformed mesh, then csgDifference.
  VdbCsgTimes subtractTools(const ddf::TriangleMesh& tool,
                            std::span<const Eigen::Isometry3d> poses);
  /// @brief Bytes of the current part grid (Grid::memUsage: tree, nodes, buffers).
  std::size_t memoryBytes() const;
  /// @brief Active voxels of the current part grid (the narrow band).
  std::size_t activeVoxels() const;
  /// @brief z of the first zero crossing of the level set below (x, y, zTop) down to zBottom,
  /// found by marching one voxel at a time with trilinear samples and interpolating; nullopt
  /// if the column stays outside.
  std::optional<double> surfaceZ(double x, double y, double zTop, double zBottom) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// @brief The closed solid under a height-field patch: the top is the grid of
/// (x, y, @p height(x, y)) over [x0, x1] x [y0, y1] with cells of at most @p cellMm, the
/// bottom the plane z = @p bottomZ, the four sides vertical walls; outward oriented.
ddf::TriangleMesh extrudedSlab(const std::function<double(double, double)>& height,
                               const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double bottomZ,
                               double cellMm);

}  // namespace ddfcam::bench
