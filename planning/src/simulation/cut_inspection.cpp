// SPDX-License-Identifier: MIT
// ddfcam: CutInspection.
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/cut_inspection.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace ddfcam::planning {

CutInspection::CutInspection(ddf::DisplacementField design, double toleranceMm)
    : design_(std::move(design)), toleranceMm_(toleranceMm) {
  if (!(toleranceMm >= 0.0) || !std::isfinite(toleranceMm))
    throw InvalidInput("CutInspection: the tolerance must be >= 0 mm, got " +
                       std::to_string(toleranceMm));
}

void CutInspection::addPose(const GrindingSimulation& simulation) {
  const int pose = poses();
  const std::size_t size = simulation.workpiece().allHeights().size();
  if (size != design_.allHeights().size())
    throw InvalidInput("CutInspection: the simulated part has " + std::to_string(size) +
                       " heights, the design " + std::to_string(design_.allHeights().size()));
  Overcut deepest;
  const std::size_t per = design_.pointsPerFace();
  for (const GrindingSimulation::HeightChange& c : simulation.poseChanges(pose)) {
    // The height the pose left, not the current one: later poses may have cut deeper.
    const double below = design_.allHeights()[c.index] - c.after;
    if (!(below > 0.0)) continue;
    const int f = static_cast<int>(c.index / per);
    const ddf::RasterCoord at =
        design_.topology().coord({f, static_cast<std::uint32_t>(c.index % per)});
    const int i = at.i, k = at.k;
    const ddf::Vec3 v = design_.vectorAt(f, design_.rasterBary(i, k));
    const double depth = below * v.dot(ddf::rasterNormal(design_, f, i, k));
    if (depth > toleranceMm_ && depth > deepest.depthMm)
      deepest = {pose, depth, design_.surfacePoint(f, i, k)};
  }
  perPose_.push_back(deepest);
  const int before = best_.empty() ? -1 : best_.back();
  const bool deeper = deepest.pose >= 0 && (before < 0 || deepest.depthMm > perPose_[before].depthMm);
  best_.push_back(deeper ? pose : before);
  overcutPoses_.push_back(overcutPoses() + (deepest.pose >= 0 ? 1 : 0));
}

void CutInspection::follow(const GrindingSimulation& simulation) {
  const int target = simulation.nextPose();
  if (target < poses()) {
    perPose_.resize(target);
    best_.resize(target);
    overcutPoses_.resize(target);
  }
  while (poses() < target) addPose(simulation);
}

std::optional<Overcut> CutInspection::largest() const {
  if (best_.empty() || best_.back() < 0) return std::nullopt;
  return perPose_[best_.back()];
}

}  // namespace ddfcam::planning
