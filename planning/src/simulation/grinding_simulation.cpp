// SPDX-License-Identifier: MIT
// ddfcam: pose-by-pose grinding simulation with swept hulls, V-convexity and collision checks.
#include <ddfcam/ddf/convex_hull.h>
#include <ddfcam/ddf/stubble_probe.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/column_volume.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
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
  if (workpiece_.allHeights().size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidInput(
        "GrindingSimulation: the workpiece has more heights than the undo log "
        "can index (2^32)");
  shadow_ = workpiece_.allHeights();
  changedFlag_.assign(static_cast<std::size_t>(workpiece_.faceCount()), 0);
}

bool GrindingSimulation::isPassStart(int k) const {
  return k == 0 || std::binary_search(path_.passStarts.begin(), path_.passStarts.end(), k);
}

void GrindingSimulation::sumPassVolumes() {
  report_.removedVolumeMm3 = 0.0;
  for (const PassRemoval& p : report_.passes) report_.removedVolumeMm3 += p.removedVolumeMm3;
}

void GrindingSimulation::markChanged(int face) {
  if (changedFlag_[face]) return;
  changedFlag_[face] = 1;
  changed_.push_back(face);
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

ddf::CutStats GrindingSimulation::cutPose(int k) {
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
  return stats;
}

double GrindingSimulation::recordChanges(const std::vector<int>& touchedFaces) {
  // The cut writes the touched faces; synchronizing their edges and vertices writes copies in
  // every face sharing one of their vertices.
  std::vector<int> faces;
  for (int f : touchedFaces) {
    markChanged(f);
    for (int v : workpiece_.faceVertices(f))
      for (int g : workpiece_.topology().vertexFaces(v)) faces.push_back(g);
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  const std::vector<float>& heights = workpiece_.allHeights();
  const ddf::Raster& raster = workpiece_.raster();
  double volume = 0.0;
  for (int f : faces) {
    const std::size_t base = static_cast<std::size_t>(f) * workpiece_.pointsPerFace();
    // volumeBetween() is a sum of column terms additive in their bounds, so a pass's volume is
    // the sum over its poses' changed points: O(changed points) per pose, not O(part).
    std::optional<FaceColumnVolume> terms;
    for (int k = 0; k <= raster.steps(); ++k)
      for (int i = 0; i < raster.rowLength(k); ++i) {
        const std::size_t at = base + raster.index(i, k);
        if (heights[at] == shadow_[at]) continue;
        if (!terms) terms.emplace(workpiece_, f);
        volume += terms->column(i, k, shadow_[at], heights[at]);
        log_.push_back({static_cast<std::uint32_t>(at), shadow_[at], heights[at]});
        shadow_[at] = heights[at];
      }
    if (terms) markChanged(f);
  }
  return volume;
}

void GrindingSimulation::recordPose(const ddf::CutStats& stats) {
  report_.pointsLowered += stats.pointsLowered;
  report_.pointsClamped += stats.pointsClamped;
  PassRemoval& pass = report_.passes.back();
  pass.removedVolumeMm3 += recordChanges(stats.touchedFaces);
  if (params_.recordUndo)
    records_.push_back(
        {log_.size(), pass.removedVolumeMm3, report_.pointsLowered, report_.pointsClamped});
  else
    log_.clear();  // only the pose's volume was needed; the capacity stays as scratch
}

int GrindingSimulation::advance(int poses, const ProgressCallback& progress) {
  const Clock::time_point start = Clock::now();
  const int remaining = static_cast<int>(path_.poses.size()) - next_;
  const int count = poses < 0 ? remaining : std::min(poses, remaining);
  int done = 0;
  auto finish = [&] {
    sumPassVolumes();
    report_.seconds += std::chrono::duration<double>(Clock::now() - start).count();
  };
  try {
    reportProgress(progress, 0.0);
    for (; done < count; ++done) {
      const int k = next_;
      if (isPassStart(k)) report_.passes.push_back({k, 0, 0.0});
      checkPose(k);
      recordPose(cutPose(k));
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

void GrindingSimulation::seek(int pose) {
  const int poses = static_cast<int>(path_.poses.size());
  if (pose < 0 || pose > poses) {
    std::ostringstream msg;
    msg << "GrindingSimulation::seek: pose " << pose << " is outside [0, " << poses << "] of path '"
        << path_.name << "'";
    throw InvalidInput(msg.str());
  }
  if (pose >= next_) {
    advance(pose - next_);
    return;
  }
  if (!params_.recordUndo)
    throw InvalidInput("GrindingSimulation::seek: going back to pose " + std::to_string(pose) +
                       " needs the undo log, but recordUndo is off");
  const Clock::time_point start = Clock::now();
  seekBack(pose);
  sumPassVolumes();
  report_.seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

void GrindingSimulation::seekBack(int pose) {
  // Newest first, so each height ends at its value before the earliest undone pose.
  const std::size_t begin = pose == 0 ? 0 : records_[pose - 1].logEnd;
  std::vector<float>& heights = workpiece_.allHeights();
  const std::size_t perFace = workpiece_.pointsPerFace();
  for (std::size_t e = log_.size(); e-- > begin;) {
    const HeightChange& c = log_[e];
    heights[c.index] = shadow_[c.index] = c.before;
    markChanged(static_cast<int>(c.index / perFace));
  }
  log_.resize(begin);
  records_.resize(static_cast<std::size_t>(pose));
  next_ = report_.posesCut = pose;
  std::vector<PassRemoval>& passes = report_.passes;
  while (!passes.empty() && passes.back().firstPose >= pose) passes.pop_back();
  if (!passes.empty()) {  // then pose > its first pose >= 0, so records_ is not empty
    passes.back().poseCount = pose - passes.back().firstPose;
    passes.back().removedVolumeMm3 = records_.back().passVolumeMm3;
  }
  report_.pointsLowered = pose == 0 ? 0 : records_.back().pointsLowered;
  report_.pointsClamped = pose == 0 ? 0 : records_.back().pointsClamped;
  while (!report_.vConvexity.empty() && report_.vConvexity.back().pose >= pose) {
    report_.vConvexityStubbles -= report_.vConvexity.back().stubbles;
    report_.vConvexity.pop_back();
  }
  while (!report_.collisions.empty() && report_.collisions.back().pose >= pose)
    report_.collisions.pop_back();
}

std::vector<int> GrindingSimulation::takeChangedFaces() {
  std::vector<int> faces = std::move(changed_);
  changed_.clear();
  for (int f : faces) changedFlag_[f] = 0;
  std::sort(faces.begin(), faces.end());
  return faces;
}

std::span<const GrindingSimulation::HeightChange> GrindingSimulation::poseChanges(int pose) const {
  if (!params_.recordUndo || pose < 0 || pose >= next_)
    throw InvalidInput("GrindingSimulation::poseChanges: pose " + std::to_string(pose) +
                       " is not a recorded pose (" + std::to_string(next_) + " cut" +
                       (params_.recordUndo ? ")" : ", recordUndo off)"));
  const std::size_t begin = pose == 0 ? 0 : records_[pose - 1].logEnd;
  return std::span<const HeightChange>(log_).subspan(begin, records_[pose].logEnd - begin);
}

std::size_t GrindingSimulation::undoMemoryBytes() const {
  return shadow_.capacity() * sizeof(float) + log_.capacity() * sizeof(HeightChange) +
         records_.capacity() * sizeof(PoseRecord);
}

GrindingReport simulateGrinding(ddf::DisplacementField& workpiece, const ToolMeshes& tool,
                                const ToolPath& path, const GrindingSimulationParams& params,
                                const ProgressCallback& progress) {
  GrindingSimulationParams noUndo = params;
  noUndo.recordUndo = false;  // it never seeks
  GrindingSimulation simulation(workpiece, tool, path, noUndo);
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
