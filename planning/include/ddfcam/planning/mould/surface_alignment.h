// SPDX-License-Identifier: MIT
// ddfcam: rigid alignment of a formed surface to the mould (point pairs, trimmed point-to-plane
// ICP).
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <span>

namespace ddfcam::planning {

/// @brief Shown to the user whenever best fit is chosen or its result displayed.
inline constexpr const char* kBestFitWarning =
    "Best fit moves the formed part onto the mould by minimising the deviation; it hides any "
    "global springback (rigid-looking rotation or shift of the whole part). Use 'as positioned' "
    "or point pairs on fixture references to see the true springback.";

/// @brief A rigid transform moving surface -> fixed surface, with its quality.
struct RigidAlignment {
  /// Maps points of the moving (formed) frame to the fixed (mould) frame, mm.
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  double rmsMm = 0.0;        ///< RMS residual after alignment (pairs, or trimmed ICP pairs), mm
  double rmsBeforeMm = 0.0;  ///< same measure before alignment (initial transform), mm
  int iterations = 0;        ///< ICP iterations run (0 for point pairs)
  bool converged = true;     ///< ICP met its tolerance before maxIterations (true for pairs)
};

/// @brief Least-squares rigid transform with to ~ T * from (Kabsch/Horn via SVD; reflections
/// are excluded).
/// @param pairs (from, to) point pairs, mm: from in the moving frame, to in the fixed frame.
/// @return transform and RMS of |T from - to| over the pairs (rmsBeforeMm: with identity).
/// @throws InvalidInput if fewer than 3 pairs, a point is not finite, or the from points (or
/// the to points) are collinear or coincident (relative tolerance 1e-9 of their extent).
RigidAlignment alignByPointPairs(std::span<const std::array<Eigen::Vector3d, 2>> pairs);

/// @brief Parameters of the best-fit (ICP) alignment.
struct BestFitParams {
  int maxSamples = 4000;      ///< vertices of the moving mesh used (evenly strided), default 4000
  double trimFraction = 0.1;  ///< worst fraction of pairs ignored each iteration, default 10 %
  int maxIterations = 60;     ///< default 60
  /// Stop when the transform update moves no sample more than this, mm; default 1e-4.
  double toleranceMm = 1e-4;
  /// Pairs farther apart than this are ignored, mm; default infinity (only trimming).
  double maxPairDistanceMm = std::numeric_limits<double>::infinity();
  /// Start transform moving -> fixed; default identity (as positioned).
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
  ProgressCallback progress;  ///< fraction of maxIterations; may cancel; default none
};

/// @brief Rigid best fit of @p moving onto @p fixed: point-to-plane ICP of sampled moving
/// vertices against the exact closest points of @p fixed (MeshDistance), trimmed.
/// @return transform moving -> fixed; rmsMm / rmsBeforeMm are the trimmed RMS point-to-surface
/// distances after / before (at the initial transform) over the same samples.
/// @throws InvalidInput if a mesh has no triangles or bad indices, or parameters are out of range
/// (maxSamples < 3, trimFraction not in [0, 0.9], maxIterations < 1, toleranceMm <= 0).
/// @throws Cancelled if progress returns false.
RigidAlignment alignBestFit(const ddf::TriangleMesh& moving, const ddf::TriangleMesh& fixed,
                            const BestFitParams& params = {});

/// @brief Rotation angle of @p transform, degrees in [0, 180].
double rotationAngleDeg(const Eigen::Isometry3d& transform);

/// @brief Row-major 4x4 of @p transform (as in SurfaceAlignmentRecord::transform).
std::array<double, 16> toRowMajor(const Eigen::Isometry3d& transform);

/// @brief Isometry from a row-major 4x4 (the last row is ignored).
Eigen::Isometry3d fromRowMajor(const std::array<double, 16>& matrix);

}  // namespace ddfcam::planning
