// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_placement.h>

namespace ddfcam::planning {

Eigen::Isometry3d rollPoseAtContact(const ddf::Vec3& contact, const ddf::Vec3& normal,
                                    const ddf::Vec3& feed, double radiusMm, double depthMm) {
  if (!(radiusMm > 0.0)) throw InvalidInput("roll radius must be positive");
  const double normalLength = normal.norm();
  if (!(normalLength > 0.0)) throw InvalidInput("roll placement needs a non-zero surface normal");
  const ddf::Vec3 n = normal / normalLength;
  const ddf::Vec3 tangent = feed - feed.dot(n) * n;
  if (!(tangent.norm() > 1e-12 * std::max(1.0, feed.norm())))
    throw InvalidInput("roll placement: the feed direction is parallel to the surface normal");
  const ddf::Vec3 t = tangent.normalized();
  const ddf::Vec3 axis = n.cross(t);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear().col(0) = axis;
  pose.linear().col(1) = n.cross(axis);  // = t: the right-handed frame (axis, feed, normal)
  pose.linear().col(2) = n;
  pose.translation() = contact + (radiusMm - depthMm) * n;
  return pose;
}

}  // namespace ddfcam::planning
