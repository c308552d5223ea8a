// SPDX-License-Identifier: MIT
// ddfcam: grinding a tool path into a DDF pose by pose through one crust hash.
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <chrono>

namespace ddfcam::planning {
namespace {

using Clock = std::chrono::steady_clock;

/// Reports progress every kPoseInterval poses or after kTimeInterval, whichever comes first,
/// so that both many cheap poses and few expensive ones keep a cancel responsive.
class ProgressThrottle {
 public:
  ProgressThrottle(const ProgressCallback& progress, std::size_t total)
      : progress_(progress), total_(total) {}

  void posesDone(std::size_t done) {
    const Clock::time_point now = Clock::now();
    if (done % kPoseInterval != 0 && done != total_ && now - last_ < kTimeInterval) return;
    last_ = now;
    reportProgress(progress_, static_cast<double>(done) / static_cast<double>(total_));
  }

 private:
  static constexpr std::size_t kPoseInterval = 64;
  static constexpr std::chrono::milliseconds kTimeInterval{100};

  const ProgressCallback& progress_;
  std::size_t total_;
  Clock::time_point last_ = Clock::now();
};

}  // namespace

PathSimulationReport simulatePath(ddf::DisplacementField& ddf, const Tool& tool,
                                  const ToolPath& path, const PathSimulationParams& params) {
  const Clock::time_point start = Clock::now();
  const ddf::TriangleMesh mesh = toolMesh(tool);
  PathSimulationReport report;
  reportProgress(params.progress, 0.0);
  if (path.poses.empty()) {
    reportProgress(params.progress, 1.0);
    return report;
  }
  // Cutting changes heights only, never vectors, so one hash stays valid for the whole path.
  const ddf::CrustHash hash(ddf);
  ProgressThrottle throttle(params.progress, path.poses.size());
  for (const PathPose& pose : path.poses) {
    const ddf::CutStats stats = ddf::cutByMesh(ddf, hash, mesh, pose.pose, params.depthBuffer);
    report.pointsLowered += stats.pointsLowered;
    report.pointsClamped += stats.pointsClamped;
    ++report.poses;
    throttle.posesDone(static_cast<std::size_t>(report.poses));
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return report;
}

}  // namespace ddfcam::planning
