// SPDX-License-Identifier: MIT
// ddfcam: pose-by-pose grinding simulation with swept hulls, V-convexity and collision checks.
#include <ddfcam/ddf/convex_hull.h>
#include <ddfcam/ddf/stubble_probe.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace ddfcam::planning {
namespace {

using Clock = std::chrono::steady_clock;

void validatePasses(const ToolPath& path) {
  const int poses = static_cast<int>(path.poses.size());
  for (std::size_t i = 0; i < path.passStarts.size(); ++i) {
    const int s = path.passStarts[i];
    if (s < 0 || s >= poses || (i > 0 && s <= path.passStarts[i - 1])) {
      std::ostringstream msg;
      msg << "GrindingSimulation: path '" << path.name << "' has pass start " << s << " (entry "
          << i << ") that is not ascending within [0, " << poses << ")";
      throw InvalidInput(msg.str());
    }
  }
}

void requireConvex(const ddf::TriangleMesh& cutting) {
  const ddf::TriangleMesh hull = ddf::convexHull(cutting.vertices);
  const double volume = std::abs(cutting.signedVolume()), hullVolume = hull.signedVolume();
  if (hullVolume > 1.001 * volume) {
    std::ostringstream msg;
    msg << "GrindingSimulation: swept mode needs a convex cutting part, but its convex hull ("
        << hullVolume << " mm^3) exceeds its volume (" << volume << " mm^3) by more than 0.1 %";
    throw InvalidInput(msg.str());
  }
}

// Distinct raster points among @p crossings that satisfy @p pred.
template <class Pred>
std::size_t countPoints(const std::vector<ddf::StubbleCrossing>& crossings, Pred&& pred) {
  std::vector<ddf::PointId> ids;
  for (const ddf::StubbleCrossing& c : crossings)
    if (pred(c)) ids.push_back(c.point);
  std::sort(ids.begin(), ids.end());
  return static_cast<std::size_t>(std::unique(ids.begin(), ids.end()) - ids.begin());
}

}  // namespace

GrindingSimulation::GrindingSimulation(ddf::DisplacementField workpiece, const ToolMeshes& tool,
                                       const ToolPath& path, const GrindingSimulationParams& params)
    : workpiece_(std::move(workpiece)), tool_(tool), path_(path), params_(params) {
  if (tool_.cutting.triangles.empty())
    throw InvalidInput("GrindingSimulation: the tool has an empty cutting mesh");
  validatePasses(path_);
  if (params_.mode == SweepMode::Swept) requireConvex(tool_.cutting);
  hash_ = ddf::CrustHash(workpiece_);
}

bool GrindingSimulation::isPassStart(int k) const {
  return k == 0 || std::binary_search(path_.passStarts.begin(), path_.passStarts.end(), k);
}

void GrindingSimulation::closePassVolume() {
  if (report_.passes.empty()) return;
  report_.passes.back().removedVolumeMm3 =
      volumeBetween(workpiece_, passStartHeights_, workpiece_.allHeights());
  report_.removedVolumeMm3 = 0.0;
  for (const PassRemoval& p : report_.passes) report_.removedVolumeMm3 += p.removedVolumeMm3;
}

void GrindingSimulation::checkPose(int k) {
  const Eigen::Isometry3d& pose = path_.poses[k].pose;
  const double tol = params_.heightTolerance;
  ddf::StubbleProbeParams probe;
  probe.parallel = params_.depthBuffer.parallel;
  if (params_.checkCollisions && !tool_.nonCutting.triangles.empty()) {
    const auto hits = ddf::probeStubbles(workpiece_, hash_, tool_.nonCutting, pose, probe);
    // Material fills each stubble up to its height: touched when the part enters below it.
    const std::size_t n = countPoints(
        hits.crossings, [tol](const ddf::StubbleCrossing& c) { return c.entry < c.height - tol; });
    if (n > 0) report_.collisions.push_back({k, n});
  }
  if (params_.checkVConvexity) {
    const auto hits = ddf::probeStubbles(workpiece_, hash_, tool_.cutting, pose, probe);
    // The depth buffer sets h = entry of the lowest interval; material between its exit and
    // the current height stays in reality but is removed by the cut (fig. 8.15).
    const std::size_t n = countPoints(hits.crossings, [tol](const ddf::StubbleCrossing& c) {
      return c.entry < c.height - tol && c.exit < c.height - tol;
    });
    if (n > 0) {
      report_.vConvexity.push_back({k, n});
      report_.vConvexityStubbles += n;
    }
  }
}

void GrindingSimulation::cutPose(int k) {
  const Eigen::Isometry3d& pose = path_.poses[k].pose;
  ddf::CutStats stats;
  if (params_.mode == SweepMode::Discrete || isPassStart(k)) {
    stats = ddf::cutByMesh(workpiece_, hash_, tool_.cutting, pose, params_.depthBuffer);
  } else {
    // Swept volume of a convex body between two poses: the hull of both instances.
    const Eigen::Isometry3d& previous = path_.poses[k - 1].pose;
    std::vector<Eigen::Vector3d> points;
    points.reserve(2 * tool_.cutting.vertices.size());
    for (const auto& v : tool_.cutting.vertices) points.push_back(previous * v);
    for (const auto& v : tool_.cutting.vertices) points.push_back(pose * v);
    const ddf::TriangleMesh hull = ddf::convexHull(points);
    stats =
        ddf::cutByMesh(workpiece_, hash_, hull, Eigen::Isometry3d::Identity(), params_.depthBuffer);
  }
  report_.pointsLowered += stats.pointsLowered;
  report_.pointsClamped += stats.pointsClamped;
}

int GrindingSimulation::advance(int poses, const ProgressCallback& progress) {
  const Clock::time_point start = Clock::now();
  const int remaining = static_cast<int>(path_.poses.size()) - next_;
  const int count = poses < 0 ? remaining : std::min(poses, remaining);
  int done = 0;
  auto finish = [&] {
    closePassVolume();
    report_.seconds += std::chrono::duration<double>(Clock::now() - start).count();
  };
  try {
    reportProgress(progress, 0.0);
    for (; done < count; ++done) {
      const int k = next_;
      if (isPassStart(k)) {
        closePassVolume();
        passStartHeights_ = workpiece_.allHeights();
        report_.passes.push_back({k, 0, 0.0});
      }
      checkPose(k);
      cutPose(k);
      ++next_;
      ++report_.posesCut;
      ++report_.passes.back().poseCount;
      reportProgress(progress, static_cast<double>(done + 1) / count);
    }
  } catch (...) {
    finish();
    throw;
  }
  finish();
  return done;
}

GrindingReport simulateGrinding(ddf::DisplacementField& workpiece, const ToolMeshes& tool,
                                const ToolPath& path, const GrindingSimulationParams& params,
                                const ProgressCallback& progress) {
  GrindingSimulation simulation(workpiece, tool, path, params);
  try {
    simulation.advance(-1, progress);
  } catch (...) {
    workpiece = simulation.workpiece();
    throw;
  }
  workpiece = simulation.workpiece();
  return simulation.report();
}

}  // namespace ddfcam::planning
