// SPDX-License-Identifier: MIT
// ddfcam: surfaceNormal and toolPathFromStreamlines.
#include <ddfcam/planning/streamline_path.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/tool_placement.h>

#include <algorithm>
#include <array>
#include <cmath>
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

Eigen::Isometry3d poseAt(const Tool& tool, const ddf::Vec3& contact, const ddf::Vec3& normal,
                         const ddf::Vec3& feed, double depthMm) {
  if (tool.kind == ToolKind::CylinderRoll)
    return rollPoseAtContact(contact, normal, feed, tool.radiusMm, depthMm);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = contact + (tool.radiusMm - depthMm) * normal;
  return pose;
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
  validateTool(tool);
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
      pose.pose = poseAt(tool, pts[i].point, surfaceNormal(ddf, pts[i]), feed, params.depthMm);
      path.poses.push_back(pose);
    }
  }
  if (path.poses.empty())
    throw InvalidInput("toolPathFromStreamlines: no streamline has two points");
  return path;
}

}  // namespace ddfcam::planning
