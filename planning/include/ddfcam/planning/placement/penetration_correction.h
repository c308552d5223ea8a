// SPDX-License-Identifier: MIT
// ddfcam: local penetration correction of tool poses with a tangential DDF (sec. 8.4.2).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/progress.h>

#include <Eigen/Geometry>

#include <vector>

namespace ddfcam::planning {

/// @brief Parameters of correctPenetrations() and penetrationDepth().
struct PenetrationCorrectionParams {
  int gridSize = 50;  ///< tangential grid cells along each tangent axis (default 50 -> 50x50)
  /// Exact lifts at every k-th pose of each pass (and at its last pose), linear interpolation
  /// between; k = 1 computes every pose exactly (default 1).
  int every = 1;
  double marginMm = 0.0;  ///< added around the tool's footprint box, mm (default 0)
  /// Interpolated poses whose remaining penetration exceeds this are recomputed exactly, mm
  /// (default 1e-3).
  double toleranceMm = 1e-3;
  bool parallel = true;  ///< poses in parallel (TBB) (default true)
  /// #P unit surface normals at the contacts (material -> tool), part frame; empty (default) =
  /// the normal of the goal's raster triangle nearest to each contact.
  std::vector<ddf::Vec3> normals;
  ProgressCallback progress;  ///< fraction done; false cancels (default none)
};

/// @brief What correctPenetrations() did.
struct PenetrationCorrectionReport {
  std::vector<double> liftMm;   ///< #P lift applied along the contact normal, mm (>= 0)
  std::vector<char> exact;      ///< #P 1 where the lift was computed exactly (scheduled or check)
  int exactPoses = 0;           ///< poses computed exactly on the every-k schedule
  int checkedPoses = 0;         ///< interpolated poses verified by the check pass
  int correctedAfterCheck = 0;  ///< interpolated poses recomputed exactly by the check
  int penetratingPoses = 0;     ///< poses lifted by more than toleranceMm (they penetrated)
  /// Largest penetration left at the checked interpolated poses after correction, mm (<=
  /// toleranceMm; exact poses have none up to float rounding).
  double maxResidualMm = 0.0;
  double maxLiftMm = 0.0;  ///< largest lift, mm
};

/// @brief Lifts every pose of @p path off the goal surface until the tool @p toolMesh (tool
/// frame, mm) no longer penetrates it inside the tool's tangential box (sec. 8.4.2, fig. 8.17c):
/// at each scheduled pose a gridSize^2 tangential DDF on the tangent plane at the contact
/// gives lift = max(0, max over the rays of h_W - h_T); poses in between get linearly
/// interpolated lifts, then a check pass evaluates each interpolated pose with its lift and
/// replaces it by the exact value where the remaining penetration exceeds toleranceMm.
/// Poses are changed in place: translation += lift * normal (contacts unchanged).
/// @param goal the goal (or current workpiece) surface as a DDF.
/// @throws InvalidInput for an empty tool mesh, gridSize < 2, every < 1, a negative tolerance
/// or margin, a normals count other than 0 or #P, or a contact with no goal face nearby.
/// @throws Cancelled if the progress callback asks to stop (path left unchanged).
PenetrationCorrectionReport correctPenetrations(const ddf::DisplacementField& goal,
                                                const ddf::TriangleMesh& toolMesh, ToolPath& path,
                                                const PenetrationCorrectionParams& params = {});

/// @brief Penetration of one tool pose: max(0, max of h_W - h_T) over the gridSize^2
/// tangential grid at @p contact with unit normal @p normal (material -> tool), mm: the
/// lift along the normal that ends the penetration. Uses gridSize and marginMm of @p params.
/// @throws InvalidInput as correctPenetrations().
double penetrationDepth(const ddf::DisplacementField& goal, const ddf::TriangleMesh& toolMesh,
                        const Eigen::Isometry3d& pose, const ddf::Vec3& contact,
                        const ddf::Vec3& normal, const PenetrationCorrectionParams& params = {});

}  // namespace ddfcam::planning
