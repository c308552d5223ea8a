// SPDX-License-Identifier: MIT
// ddfcam: the DDF depth buffer (dissertation ch. 5): cutting stubbles by tool triangles and
// filling heights from a surface mesh along the stubbles.
#pragma once

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of the depth-buffer kernels.
struct DepthBufferParams {
  /// Process support faces in parallel (TBB). Default true.
  bool parallel = true;
  /// Restrict each raster row to the intervals inside the projected tool triangle (sec. 5.2,
  /// fig. 5.7) instead of V-shooting every raster point. Default true.
  bool restrictIntervals = true;
  /// Barycentric tolerance on the tool triangle, so that stubbles through a shared tool edge
  /// are never missed by both triangles. Default 1e-5.
  float lambdaTolerance = 1e-5f;
};

/// @brief What one cut did.
struct CutStats {
  std::size_t candidatePairs = 0;  ///< (support face, tool triangle) pairs from localization
  std::size_t pointsLowered = 0;   ///< raster heights that decreased
  std::size_t pointsClamped = 0;   ///< of those, hits below the crust bottom set to h = -1
  std::vector<int> touchedFaces;   ///< faces with at least one candidate pair, sorted
};

/// @brief Cuts @p ddf by the closed, outward-oriented triangle mesh @p tool placed at @p pose
/// (tool frame -> part frame): every stubble entering the tool gets h = min(h, max(h_tool, -1)).
/// Only tool triangles that reach into a face's crust slab cut it (localization, sec. 5.1); an
/// entry below the crust bottom clamps to h = -1, so a tool plunged through the whole crust
/// removes it as long as its surface crosses the crust nearby (as a continuous motion does).
/// Exit faces are skipped (back-face culling of the depth buffer), so a tool with inward
/// orientation is flipped first (negative signed volume). Shared edge and vertex copies are
/// synchronized afterwards (minimum).
/// @param hash localization structure built for @p ddf with its current vectors.
CutStats cutByMesh(DisplacementField& ddf, const CrustHash& hash, const TriangleMesh& tool,
                   const Eigen::Isometry3d& pose, const DepthBufferParams& params = {});

/// @brief Cuts by loose triangles in the part frame (3 corners per triangle, oriented so the
/// normal (c1-c0)x(c2-c0) points out of the tool).
CutStats cutByTriangles(DisplacementField& ddf, const CrustHash& hash,
                        std::span<const Vec3> corners, const DepthBufferParams& params = {});

/// @brief Cuts the raster of one support face by one tool triangle, without localization or
/// synchronization (the inner operation of sec. 5.2). Returns the number of lowered heights.
std::size_t cutFaceByTriangle(DisplacementField& ddf, int face, const Vec3& q1, const Vec3& q2,
                              const Vec3& q3, const DepthBufferParams& params = {});

/// @brief Reference for tests and benchmarks: the same cut by direct per-point V-shooting
/// (ray/triangle intersection in double at every raster point, no coefficients, no rows).
std::size_t cutFaceByTriangleDirect(DisplacementField& ddf, int face, const Vec3& q1,
                                    const Vec3& q2, const Vec3& q3);

/// @brief Parameters of filling heights from a surface mesh.
struct FillParams {
  DepthBufferParams kernel;   ///< kernel settings (see DepthBufferParams)
  ProgressCallback progress;  ///< progress and cancel; may be empty
};

/// @brief Result of a fill.
struct FillReport {
  std::size_t filled = 0;   ///< raster points (all copies) that got a height from the mesh
  std::size_t missing = 0;  ///< raster points whose stubble meets the mesh nowhere in [-1, 1]
  std::vector<std::uint8_t> missingMask;  ///< per stored height: 1 where missing
};

/// @brief Sets every height of @p ddf to the intersection of its stubble segment [-1, 1] with
/// @p surface that is nearest to the support (|h| smallest). Heights whose stubble misses the
/// surface keep their previous value and are reported. Used for mesh conversion and for
/// comparing surfaces on a shared support. Shared copies are synchronized (canonical face).
/// @throws Cancelled when the progress callback asks to stop; @p ddf is then unchanged.
FillReport fillFromMesh(DisplacementField& ddf, const CrustHash& hash, const TriangleMesh& surface,
                        const FillParams& params = {});

}  // namespace ddfcam::ddf
