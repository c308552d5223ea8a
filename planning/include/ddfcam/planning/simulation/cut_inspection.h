// SPDX-License-Identifier: MIT
// ddfcam: overcut inspection of a running simulation against its design (paper 003, app. A).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include <optional>
#include <vector>

namespace ddfcam::planning {

/// @brief A place where a pose cut below the design.
struct Overcut {
  int pose = -1;        ///< path pose that cut it
  double depthMm = 0;   ///< depth below the design along the design's surface normal, mm
  ddf::Vec3 point = ddf::Vec3::Zero();  ///< the design point there, mm, part frame
};

/// @brief Overcut inspection while a simulation runs: for every pose, from the heights that
/// pose changed only (its undo log), the deepest point it cut below the design beyond a
/// tolerance, so the largest overcut so far and the poses that overcut are known at any pose
/// without comparing the whole part. The depth at a raster point is (h_design - h) (v . n),
/// v its vector and n the design surface's raster normal (ddf::rasterNormal), the distance
/// along n to first order.
class CutInspection {
 public:
  /// @param design the workpiece's support and vectors with the design's heights (e.g. the
  /// project's "design" state).
  /// @param toleranceMm depths up to this are within tolerance, not overcut, mm (>= 0).
  /// @throws InvalidInput for a negative or non-finite tolerance.
  CutInspection(ddf::DisplacementField design, double toleranceMm);

  /// @brief Inspects pose poses() of @p simulation (the next one; it must be cut and recorded).
  /// @throws InvalidInput if @p simulation has not cut that pose or has another part size.
  void addPose(const GrindingSimulation& simulation);
  /// @brief Brings the inspection to the simulation's pose: forgets poses it no longer has (a
  /// backward seek), adds those it cut since.
  void follow(const GrindingSimulation& simulation);
  /// @brief Poses inspected (0..poses()-1).
  int poses() const { return static_cast<int>(perPose_.size()); }
  /// @brief The deepest overcut of the inspected poses, or nullopt if none went beyond the
  /// tolerance.
  std::optional<Overcut> largest() const;
  /// @brief Number of inspected poses that overcut beyond the tolerance.
  int overcutPoses() const { return overcutPoses_.empty() ? 0 : overcutPoses_.back(); }
  double toleranceMm() const { return toleranceMm_; }

 private:
  ddf::DisplacementField design_;
  double toleranceMm_;
  std::vector<Overcut> perPose_;    // deepest overcut of each pose (pose -1: none)
  std::vector<int> best_;           // index of the deepest overcut among poses 0..k, or -1
  std::vector<int> overcutPoses_;   // poses 0..k that overcut
};

}  // namespace ddfcam::planning
