// SPDX-License-Identifier: MIT
// ddfcam: surfaceNormal, toolPathFromStreamlines and placedNormal.
#include <ddfcam/planning/lines/streamline_path.h>

#include <ddfcam/error.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::planning {

namespace {

/// Corners of the raster triangle (fig. 7.1a) that contains @p bary in @p face.
std::array<ddf::Vec3, 3> rasterTriangle(const ddf::DisplacementField& ddf, int face,
                                        const ddf::Vec3& bary) {
  const int n = ddf.resolution() - 1;
  const double a = std::clamp(bary.x(), 0.0, 1.0) * n, c = std::clamp(bary.z(), 0.0, 1.0) * n;
  const int i = std::clamp(static_cast<int>(std::floor(a)), 0, n - 1);
  const int k = std::clamp(static_cast<int>(std::floor(c)), 0, n - 1 - i);
  // The "down" triangle exists only away from the face's third edge.
  if ((a - i) + (c - k) <= 1.0 || i + k + 2 > n)
    return {ddf.surfacePoint(face, i, k), ddf.surfacePoint(face, i + 1, k),
            ddf.surfacePoint(face, i, k + 1)};
  return {ddf.surfacePoint(face, i + 1, k), ddf.surfacePoint(face, i + 1, k + 1),
          ddf.surfacePoint(face, i, k + 1)};
}

PlacementParams effectivePlacement(const StreamlinePathParams& params) {
  PlacementParams placement = params.placement;
  placement.depthMm += params.depthMm;
  return placement;
}

/// One pose per streamline point (no resampling).
ToolPath placeAtPoints(const ddf::DisplacementField& ddf,
                       const std::vector<Streamline>& streamlines, const Tool& tool, int toolIndex,
                       const StreamlinePathParams& params) {
  const PlacementParams placement = effectivePlacement(params);
  ToolPath path;
  path.name = params.name;
  path.tool = toolIndex;
  path.feedMmPerMin = params.feedMmPerMin;
  for (const Streamline& line : streamlines) {
    const auto& pts = line.points;
    if (pts.size() < 2) continue;
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const ddf::Vec3 feed =
          pts[std::min(i + 1, pts.size() - 1)].point - pts[i > 0 ? i - 1 : 0].point;
      PathPose pose;
      pose.contact = pts[i].point;
      pose.pose = placeTool(tool, pts[i].point, surfaceNormal(ddf, pts[i]), feed, placement);
      path.poses.push_back(pose);
    }
  }
  if (path.poses.empty())
    throw InvalidInput("toolPathFromStreamlines: no streamline has two points");
  return path;
}

}  // namespace

ddf::Vec3 surfaceNormal(const ddf::DisplacementField& ddf, const ddf::SurfaceLocation& location) {
  if (location.face < 0 || location.face >= ddf.faceCount())
    throw InvalidInput("surfaceNormal: face " + std::to_string(location.face) + " is out of range");
  const auto q = rasterTriangle(ddf, location.face, location.bary);
  ddf::Vec3 n = (q[1] - q[0]).cross(q[2] - q[0]);
  if (n.dot(ddf.vectorAt(location.face, location.bary)) < 0) n = -n;
  return n.normalized();
}

ToolPath toolPathFromStreamlines(const ddf::DisplacementField& ddf,
                                 const std::vector<Streamline>& streamlines, const Tool& tool,
                                 int toolIndex, const StreamlinePathParams& params) {
  return toolPathFromStreamlinesDetailed(ddf, streamlines, tool, toolIndex, params).path;
}

PlacedPath toolPathFromStreamlinesDetailed(const ddf::DisplacementField& ddf,
                                           const std::vector<Streamline>& streamlines,
                                           const Tool& tool, int toolIndex,
                                           const StreamlinePathParams& params) {
  validateTool(tool);
  if (!params.sampling) return {placeAtPoints(ddf, streamlines, tool, toolIndex, params), {}};
  PathSamplingParams sampling = *params.sampling;
  sampling.name = params.name;
  sampling.feedMmPerMin = params.feedMmPerMin;
  std::vector<std::vector<ddf::SurfaceLocation>> passes;
  passes.reserve(streamlines.size());
  for (const Streamline& line : streamlines) passes.push_back(line.points);
  return placeAlongPathDetailed(ddf, passes, tool, toolIndex, effectivePlacement(params), sampling);
}

ddf::Vec3 placedNormal(const Tool& tool, const Eigen::Isometry3d& pose,
                       const PlacementParams& placement) {
  for (const double deg : {placement.leadDeg, placement.tiltDeg})
    if (!std::isfinite(deg) || !(std::abs(deg) < 90.0))
      throw InvalidInput("placedNormal: angle " + std::to_string(deg) +
                         " deg is not within (-90, 90)");
  // placeTool: R = C L B with C = [t b n], L = Rx(tilt) Ry(lead) in the contact frame and B
  // the base permutation (wheels: tool x -> b, y -> -t, z -> n), so n = R B^T L^T e_z.
  constexpr double kDeg = std::numbers::pi / 180.0;
  const Eigen::Matrix3d local = (Eigen::AngleAxisd(placement.tiltDeg * kDeg, ddf::Vec3::UnitX()) *
                                 Eigen::AngleAxisd(placement.leadDeg * kDeg, ddf::Vec3::UnitY()))
                                    .toRotationMatrix();
  Eigen::Matrix3d base = Eigen::Matrix3d::Identity();
  if (tool.kind == ToolKind::CylinderRoll || tool.kind == ToolKind::BeltContactWheel)
    base << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return (pose.linear() * base.transpose() * local.transpose() * ddf::Vec3::UnitZ()).normalized();
}

}  // namespace ddfcam::planning
