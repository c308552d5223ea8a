// SPDX-License-Identifier: MIT
// ddfcam: how long a grinding simulation of a path will take, from a timed sample of its poses.
#pragma once

#include <ddfcam/planning/simulation/grinding_simulation.h>

namespace ddfcam::planning {

/// @brief Parameters of estimateSimulation().
struct SimulationEstimateParams {
  /// Poses timed, spread evenly over the path (all of a shorter path). Default 16.
  int samplePoses = 16;
};

/// @brief Result of estimateSimulation().
struct SimulationEstimate {
  int poses = 0;              ///< poses of the path
  int sampled = 0;            ///< poses timed
  double secondsPerPose = 0;  ///< mean wall time of a sampled pose with the checks asked for, s
  double seconds = 0;         ///< poses x secondsPerPose, s
};

/// @brief Times @p params.samplePoses poses of @p path, spread evenly over it, each cut (with
/// the V-convexity and collision checks of @p simulation) on a copy of @p workpiece as a pass
/// of its own, and extrapolates to the whole path. A pose's cost depends on how many support
/// faces its tool reaches, which an even spread samples; the stock is not cut beforehand, so
/// the estimate is of a first pass over it.
/// @throws as GrindingSimulation.
SimulationEstimate estimateSimulation(const ddf::DisplacementField& workpiece,
                                      const ToolMeshes& tool, const ToolPath& path,
                                      const GrindingSimulationParams& simulation = {},
                                      const SimulationEstimateParams& params = {});

}  // namespace ddfcam::planning
