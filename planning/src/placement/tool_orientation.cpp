// SPDX-License-Identifier: MIT
// ddfcam: placeTool: any tool of tool.h touching a tangent plane with lead and tilt angles.
#include <ddfcam/planning/placement/tool_orientation.h>

#include <ddfcam/error.h>
#include <ddfcam/planning/tools/tool_profiles.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

/// Unit normal n, unit tangential feed t and cross-feed b = n x t.
struct ContactFrame {
  Vec3 t, b, n;
};

ContactFrame contactFrame(const Vec3& normal, const Vec3& feed, const char* who) {
  const double length = normal.norm();
  if (!std::isfinite(length) || !(length > 0.0))
    throw InvalidInput(std::string(who) + ": the surface normal is zero or not finite");
  ContactFrame f;
  f.n = normal / length;
  const Vec3 tangent = feed - feed.dot(f.n) * f.n;
  if (!feed.allFinite() || !(tangent.norm() > 1e-9 * feed.norm()))
    throw InvalidInput(std::string(who) +
                       ": the feed direction is zero, not finite or parallel to the normal");
  f.t = tangent.normalized();
  f.b = f.n.cross(f.t);
  return f;
}

bool isWheel(ToolKind kind) {
  return kind == ToolKind::CylinderRoll || kind == ToolKind::BeltContactWheel;
}

/// Tool frame -> part frame rotation: Rot(t, tilt) Rot(b, lead) base (see PlacementParams).
Eigen::Matrix3d orientation(const Tool& tool, const ContactFrame& f, const PlacementParams& p) {
  Eigen::Matrix3d base;
  if (isWheel(tool.kind))
    base << f.b, f.n.cross(f.b), f.n;
  else
    base << f.t, f.b, f.n;
  return (Eigen::AngleAxisd(p.tiltDeg * kDeg, f.t) * Eigen::AngleAxisd(p.leadDeg * kDeg, f.b))
             .toRotationMatrix() *
         base;
}

Vec3 axisVector(RevolveAxis axis) {
  return axis == RevolveAxis::X ? Vec3::UnitX() : Vec3::UnitZ();
}

/// A candidate touching point in the profile half plane; `centroid` marks the middle of a
/// profile segment lying flat against the plane (the centroid of a touching line).
struct Candidate {
  double value = -1e300;
  ProfilePoint point;
  bool centroid = false;
};

void consider(Candidate& best, double value, const ProfilePoint& p, bool centroid, double eps) {
  if (value > best.value + eps || (centroid && !best.centroid && value > best.value - eps))
    best = {value, p, centroid};
}

/// Largest value of da * axial + dr * radial over the profile, with the point attaining it.
Candidate profileSupport(const ToolProfile& profile, double da, double dr, double eps) {
  Candidate best;
  const auto value = [&](const ProfilePoint& p) { return da * p.axial + dr * p.radial; };
  for (const ProfileSegment& s : profile.segments) {
    const double v0 = value(s.from), v1 = value(s.to);
    consider(best, v0, s.from, false, eps);
    consider(best, v1, s.to, false, eps);
    if (!s.isArc) {
      if (std::abs(v0 - v1) <= eps) consider(best, v0, s.at(0.5), true, eps);
      continue;
    }
    // The circle's own maximiser, if it lies on the arc.
    const double angle = std::atan2(dr, da);
    const double u = std::remainder(angle - s.startAngle, 2 * std::numbers::pi) / s.sweepAngle;
    if (u >= -1e-12 && u <= 1 + 1e-12) {
      const ProfilePoint p{s.centre.axial + s.arcRadius * std::cos(angle),
                           s.centre.radial + s.arcRadius * std::sin(angle)};
      consider(best, value(p), p, false, eps);
    }
  }
  return best;
}

/// The point of the tool surface (tool frame) farthest along @p d: the touching point when d
/// points from the tool to the plane.
Vec3 supportPoint(const ToolProfile& profile, const Vec3& d) {
  const Vec3 axis = axisVector(profile.axis);
  const double da = d.dot(axis);
  const Vec3 perp = d - da * axis;
  const double dr = perp.norm();
  const auto [lo, hi] = profile.axialRange();
  const double eps = 1e-12 * (profile.maxRadius() + hi - lo);
  const bool onAxis = dr <= 1e-12;
  const Candidate best = profileSupport(profile, da, onAxis ? 0.0 : dr, eps);
  // Along the axis the touching set is a disc or a pole: its centroid is on the axis.
  if (onAxis) return best.point.axial * axis;
  return best.point.axial * axis + best.point.radial * (perp / dr);
}

void checkParams(const PlacementParams& p) {
  const auto checkAngle = [](double deg, const char* name) {
    if (!std::isfinite(deg) || !(std::abs(deg) < 90.0))
      throw InvalidInput(std::string("tool placement: ") + name + " angle " + std::to_string(deg) +
                         " deg is not within (-90, 90)");
  };
  checkAngle(p.leadDeg, "lead");
  checkAngle(p.tiltDeg, "tilt");
  if (!std::isfinite(p.depthMm))
    throw InvalidInput("tool placement: depth " + std::to_string(p.depthMm) + " is not finite");
}

}  // namespace

ToolPlacement placeToolDetailed(const Tool& tool, const Vec3& contact, const Vec3& normal,
                                const Vec3& feed, const PlacementParams& params) {
  validateTool(tool);
  checkParams(params);
  if (!contact.allFinite()) throw InvalidInput("tool placement: the contact point is not finite");
  const ContactFrame f = contactFrame(normal, feed, "tool placement");
  const Eigen::Matrix3d rotation = orientation(tool, f, params);
  ToolPlacement out;
  out.toolContact = supportPoint(toolProfile(tool), rotation.transpose() * (-f.n));
  out.pose.linear() = rotation;
  out.pose.translation() = contact - params.depthMm * f.n - rotation * out.toolContact;
  out.referenceOffset = out.pose.translation() - contact;
  return out;
}

Eigen::Isometry3d placeTool(const Tool& tool, const Vec3& contact, const Vec3& normal,
                            const Vec3& feed, const PlacementParams& params) {
  return placeToolDetailed(tool, contact, normal, feed, params).pose;
}

Vec3 referenceOffset(const PathPose& pose) {
  return pose.pose.translation() - pose.contact;
}

std::pair<double, double> placementAnglesDeg(const Eigen::Isometry3d& pose, const Vec3& normal,
                                             const Vec3& feed) {
  const ContactFrame f = contactFrame(normal, feed, "placement angles");
  const Vec3 z = pose.linear().col(2);
  const double lead = std::asin(std::clamp(z.dot(f.t), -1.0, 1.0));
  const double tilt = std::atan2(-z.dot(f.b), z.dot(f.n));
  return {lead / kDeg, tilt / kDeg};
}

std::pair<Vec3, Vec3> toolAxisEnds(const Tool& tool) {
  const ToolProfile profile = toolProfile(tool);
  const Vec3 axis = axisVector(profile.axis);
  const auto [lo, hi] = profile.axialRange();
  return {lo * axis, hi * axis};
}

}  // namespace ddfcam::planning
