// SPDX-License-Identifier: MIT
// ddfcam: placing any tool of tool.h on a surface at a contact point with lead and tilt angles.
#pragma once

#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>

#include <Eigen/Geometry>

#include <utility>

namespace ddfcam::planning {

/// @brief How a tool is oriented and sunk at a contact point. Angles act in the contact frame
/// (t, b, n): n = unit surface normal (material -> tool), t = unit tangential part of the feed,
/// b = n x t (cross-feed). The tool orientation is R = Rot(t, tilt) * Rot(b, lead) applied to
/// the base orientation (lead first, then tilt; both right-handed rotations):
/// - cutters (BallEnd, FlatEnd, TorusCutter) and Sphere: base = tool axis +z along n, tool +x
///   along t. Lead turns the axis towards the feed (a = sin(lead) t + cos(lead) n for tilt 0:
///   the leading rim of a flat or torus cutter cuts, the heel rises behind); tilt then turns it
///   about the feed (a = sin(lead) t - cos(lead) sin(tilt) b + cos(lead) cos(tilt) n).
/// - wheels (CylinderRoll, BeltContactWheel): base = wheel axis +x along b, tool +z along n
///   (as rollPoseAtContact). Tilt turns the wheel axis out of the tangent plane
///   (axis = cos(tilt) b + sin(tilt) n), so the wheel grinds with the side of its crown or its
///   rim; lead spins the wheel about its own axis and changes nothing but the frame.
struct PlacementParams {
  double leadDeg =
      0.0;  ///< lead angle about the cross-feed direction, deg, |lead| < 90 (default 0)
  double tiltDeg = 0.0;  ///< tilt angle about the feed direction, deg, |tilt| < 90 (default 0)
  double depthMm = 0.0;  ///< infeed below the contact point along -n, mm (default 0: touching)
};

/// @brief A placed tool and where it touches.
struct ToolPlacement {
  /// Tool frame -> part frame, mm: the tool (toolProfile() of tool_profiles.h) touches the
  /// tangent plane at the contact point (shifted depthMm along -n) and lies on its tool side.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /// The tool's touching point in the tool frame, mm (the centroid of the touching set when a
  /// face or a line of the tool lies on the tangent plane: a flat bottom touches at its centre,
  /// a straight wheel mantle at its mid plane).
  ddf::Vec3 toolContact = ddf::Vec3::Zero();
  /// Offset from the contact point to the tool reference point (tool-frame origin: wheel or
  /// ball centre, cutter tip), part frame, mm: pose.translation() - contact.
  ddf::Vec3 referenceOffset = ddf::Vec3::Zero();
};

/// @brief Places @p tool at @p contact on a surface with normal @p normal, feeding along
/// @p feed, oriented by @p params (see PlacementParams); exact for the analytic profile
/// (tool_profiles.h): ball-end centre = contact + R n (tip = centre - R a), Sphere centre =
/// contact + R n, torus tube centre = contact + r n, flat end with lead: its leading rim point
/// at the contact, flat end without lead: tip (bottom centre) at the contact, wheel with tilt 0:
/// centre = contact + R n (mid plane of mantle or crown at the contact).
/// @param contact contact point, mm, part frame.
/// @param normal surface normal at the contact, from the material to the tool (any length > 0).
/// @param feed feed direction (any length; its tangential part is used).
/// @throws InvalidInput naming the problem for an invalid tool (validateTool), a zero or
/// non-finite normal or contact, a feed (nearly) parallel to the normal, |lead| or |tilt| >= 90
/// deg or a non-finite angle or depth.
ToolPlacement placeToolDetailed(const Tool& tool, const ddf::Vec3& contact, const ddf::Vec3& normal,
                                const ddf::Vec3& feed, const PlacementParams& params = {});

/// @brief placeToolDetailed(...).pose. @throws InvalidInput as placeToolDetailed().
Eigen::Isometry3d placeTool(const Tool& tool, const ddf::Vec3& contact, const ddf::Vec3& normal,
                            const ddf::Vec3& feed, const PlacementParams& params = {});

/// @brief Offset from the contact point to the tool reference point of @p pose, part frame, mm
/// (pose.translation() - contact).
ddf::Vec3 referenceOffset(const PathPose& pose);

/// @brief Lead and tilt angles (deg) of a pose made by placeTool() for @p tool, measured back
/// from the tool frame's z column z_w in the contact frame: lead = asin(z_w . t),
/// tilt = atan2(-z_w . b, z_w . n) (valid for every kind since lead never moves z_w off the
/// (t, n) plane before tilt).
/// @throws InvalidInput for a zero normal or a feed parallel to it.
std::pair<double, double> placementAnglesDeg(const Eigen::Isometry3d& pose, const ddf::Vec3& normal,
                                             const ddf::Vec3& feed);

/// @brief The two end points of the tool axis in the tool frame, mm: wheels the centres of the
/// two side faces (x = -+width/2), cutters the tip and the top centre of the cutting part
/// (z = 0, width), Sphere its poles (z = -+radius). Used as the "bottom and top centre" of
/// 004 eq. 5.8/5.9. @throws InvalidInput as validateTool().
std::pair<ddf::Vec3, ddf::Vec3> toolAxisEnds(const Tool& tool);

}  // namespace ddfcam::planning
