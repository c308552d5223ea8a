// SPDX-License-Identifier: MIT
// ddfcam: placing a tool on a surface at a contact point.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <Eigen/Geometry>

namespace ddfcam::planning {

/// @brief Pose (tool frame -> part frame) of a grinding roll built by makeCylinderTool (axis
/// along tool +x, centred at the origin) that touches a surface at a contact point: the roll
/// axis lies in the tangent plane perpendicular to the feed, and the roll sinks @p depthMm
/// below the contact point along the normal (0 = just touching).
/// @param contact contact point on the surface, mm, part frame.
/// @param normal surface normal at the contact point, pointing from the material to the tool.
/// @param feed feed direction (need not be tangent or unit; its tangential part is used).
/// @param radiusMm roll radius, mm.
/// @param depthMm infeed below the contact point along the normal, mm.
/// @throws InvalidInput for a zero normal, a feed parallel to the normal, or radius <= 0.
Eigen::Isometry3d rollPoseAtContact(const ddf::Vec3& contact, const ddf::Vec3& normal,
                                    const ddf::Vec3& feed, double radiusMm, double depthMm);

}  // namespace ddfcam::planning
