// SPDX-License-Identifier: MIT
// ddfcam: estimateSimulation.
#include <ddfcam/planning/simulation/simulation_estimate.h>

#include <algorithm>
#include <chrono>

namespace ddfcam::planning {

SimulationEstimate estimateSimulation(const ddf::DisplacementField& workpiece,
                                      const ToolMeshes& tool, const ToolPath& path,
                                      const GrindingSimulationParams& simulation,
                                      const SimulationEstimateParams& params) {
  SimulationEstimate out;
  out.poses = static_cast<int>(path.poses.size());
  if (out.poses == 0) return out;
  ToolPath sample;
  sample.name = path.name;
  const int count = std::clamp(params.samplePoses, 1, out.poses);
  for (int s = 0; s < count; ++s) {
    const auto at = static_cast<std::size_t>((s + 0.5) * out.poses / count);
    sample.passStarts.push_back(s);  // each its own pass: no swept hull between far poses
    sample.poses.push_back(path.poses[std::min(at, path.poses.size() - 1)]);
  }
  GrindingSimulationParams quick = simulation;
  quick.recordUndo = false;
  GrindingSimulation run(workpiece, tool, sample, quick);
  const auto start = std::chrono::steady_clock::now();
  run.advance(-1);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.sampled = count;
  out.secondsPerPose = seconds / count;
  out.seconds = out.secondsPerPose * out.poses;
  return out;
}

}  // namespace ddfcam::planning
