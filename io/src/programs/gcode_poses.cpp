// SPDX-License-Identifier: MIT
// ddfcam: the G-code writer's positions: number text, checks of its options, and the machine
// positions of every point (tool tips from contacts, the axis in force, inverse kinematics).
#include "gcode_poses.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::io::detail {
namespace {

using Mode = GCodeWriteParams::Mode;

/// Tolerance on |v| - 1 of axes and normals read from files with 6 to 9 decimals.
constexpr double kUnitTolerance = 1e-4;

/// Largest |axis - Z| of a 3-axis point (files write +Z as 0,0,1 to 6+ decimals).
constexpr double kVerticalTolerance = 1e-6;

/// Text naming point @p i of @p program for messages.
std::string pointName(const planning::ClProgram& program, std::size_t i) {
  const planning::ClPoint& p = program.points[i];
  std::string s = "G-code: point " + std::to_string(i) + " (path " + std::to_string(p.path) +
                  ", point " + std::to_string(p.point);
  if (p.sourceLine > 0) s += ", line " + std::to_string(p.sourceLine);
  return s + ")";
}

/// Ball, corner and rim radii of a cutter: {R, r} with r the corner radius.
std::pair<double, double> cutterRadii(const planning::Tool& tool) {
  planning::validateTool(tool);
  switch (tool.kind) {
    case planning::ToolKind::BallEnd:
      return {tool.radiusMm, tool.radiusMm};
    case planning::ToolKind::FlatEnd:
      return {tool.radiusMm, 0.0};
    case planning::ToolKind::TorusCutter:
      return {tool.radiusMm, tool.edgeRadiusMm};
    default:
      break;
  }
  throw InvalidInput("G-code: tool '" + tool.name + "' is a " +
                     std::string(planning::toolKindName(tool.kind)) +
                     "; G-code needs a cutter (ball_end, flat_end or torus_cutter)");
}

/// Unit version of @p v (a file's axis or normal), or an error naming the point.
ddf::Vec3 unitOf(const ddf::Vec3& v, const std::string& what, const std::string& where) {
  if (!v.allFinite()) throw InvalidInput(where + ": " + what + " is not finite");
  if (std::abs(v.norm() - 1.0) > kUnitTolerance) {
    throw InvalidInput(where + ": " + what + " " + vecText(v) + " is not a unit vector");
  }
  return v.normalized();
}

/// Tool tip of point @p i given its unit tool axis @p axis (part frame, mm).
ddf::Vec3 tipOf(const planning::ClProgram& program, std::size_t i, const ddf::Vec3& axis,
                std::pair<double, double> radii) {
  const planning::ClPoint& p = program.points[i];
  if (program.pointKind == planning::ClPointKind::ToolReference) return p.positionMm;
  const std::string where = pointName(program, i);
  if (!p.normal) throw InvalidInput(where + ": a contact point needs a surface normal");
  const ddf::Vec3 n = unitOf(*p.normal, "normal", where);
  if (n.dot(axis) < -1e-9) {
    throw InvalidInput(where + ": normal " + vecText(n) +
                       " points away from the tool (undercut not reachable)");
  }
  const ddf::Vec3 across = n - n.dot(axis) * axis;
  const double acrossLength = across.norm();
  const ddf::Vec3 h = acrossLength > 1e-12 ? ddf::Vec3(across / acrossLength) : ddf::Vec3::Zero();
  const auto [big, corner] = radii;
  // The corner circle's centre lies at corner n from the contact; the tip is below it.
  return p.positionMm + corner * n + (big - corner) * h - corner * axis;
}

/// Why a tilted axis cannot go into a 3-axis program, and what would take it.
std::string threeAxisAdvice(const ddf::Vec3& axis) {
  const double tiltDeg = std::acos(std::clamp(axis.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
  const planning::TableKinematics generic;
  if (tiltDeg <= generic.tiltMaxDeg) {
    return " is tilted by " + fixed(tiltDeg, 3) +
           " deg; a 3-axis program needs +Z: write it for a 5-axis machine (a machine file, or "
           "the generic A/C or B/C table)";
  }
  return " is tilted by " + fixed(tiltDeg, 3) +
         " deg (the tool points up at the part from below); neither a 3-axis machine nor a "
         "table tilting up to 120 deg reaches it: turn the part over (fixture it the other way "
         "up, or transform the program) so that the tool comes from above";
}

/// Unit tool axis of point @p i (part frame): the file's, else the axis in force @p inForce
/// (the last one given: a point without an axis keeps it, as APT's GOTO does), else +Z.
ddf::Vec3 axisOf(const planning::ClProgram& program, std::size_t i, Mode mode,
                 std::optional<ddf::Vec3>& inForce) {
  const planning::ClPoint& p = program.points[i];
  const std::string where = pointName(program, i);
  if (p.axis) inForce = unitOf(*p.axis, "tool axis", where);
  const ddf::Vec3 a = inForce.value_or(ddf::Vec3::UnitZ());
  if (mode == Mode::ThreeAxis && (a - ddf::Vec3::UnitZ()).norm() > kVerticalTolerance) {
    throw InvalidInput(where + ": tool axis " + vecText(a) + threeAxisAdvice(a));
  }
  return a;
}

/// Radii of the tool cutting point @p i: @p tool's, or after a tool change that tool's CUTTER.
/// Only contact programs need them; tool reference programs pass through.
std::pair<double, double> radiiAt(const planning::ClProgram& program,
                                  const planning::ClToolChange* change,
                                  const std::pair<double, double>& first) {
  if (!change || program.pointKind == planning::ClPointKind::ToolReference) return first;
  if (!change->cutter) {
    throw InvalidInput("G-code: tool T" + std::to_string(change->toolNumber) +
                       " has no CUTTER record, so the tool tips of the contact points it cuts "
                       "cannot be computed; give every tool a CUTTER");
  }
  return cutterRadii(planning::toolFromCutter(*change->cutter, change->toolName));
}

}  // namespace

/// Concatenation of @p parts (avoids GCC 12's -Wrestrict false positive on "lit" + string).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view part : parts) s.append(part);
  return s;
}

/// Fixed-point text of @p v, locale-independent, "-0.000" written as "0.000".
std::string fixed(double v, int decimals) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (res.ec != std::errc()) throw InvalidInput("G-code: number too large to write");
  std::string s(buf, res.ptr);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string vecText(const ddf::Vec3& v) {
  return cat({"(", fixed(v.x(), 6), ", ", fixed(v.y(), 6), ", ", fixed(v.z(), 6), ")"});
}

/// Comment text safe for RS274: no parentheses, printable ASCII, bounded length.
std::string commentText(std::string_view text) {
  std::string s;
  for (char c : text.substr(0, 200)) {
    if (c == '(') c = '[';
    if (c == ')') c = ']';
    if (c < 32 || c > 126) c = '?';
    s += c;
  }
  return s;
}

void validateGCodeParams(const GCodeWriteParams& p) {
  if (p.unit == LengthUnit::Metre) {
    throw InvalidInput("G-code: unit must be mm (G21) or inch (G20), not m");
  }
  if (p.decimals < 1 || p.decimals > 8 || p.angleDecimals < 1 || p.angleDecimals > 8) {
    throw InvalidInput("G-code: decimals and angleDecimals must lie in 1..8");
  }
  if (p.lineNumberStep < 1 || p.lineNumberStep > 1000) {
    throw InvalidInput("G-code: lineNumberStep must lie in 1..1000");
  }
  if (!std::isfinite(p.rapidClearanceMm) || p.rapidClearanceMm < 0.0) {
    throw InvalidInput("G-code: rapidClearanceMm must be finite and >= 0");
  }
  if (!std::isfinite(p.spindleRpm) || p.spindleRpm < 0.0) {
    throw InvalidInput("G-code: spindleRpm must be finite and >= 0");
  }
  if (!std::isfinite(p.defaultFeedMmPerMin) || p.defaultFeedMmPerMin <= 0.0) {
    throw InvalidInput("G-code: defaultFeedMmPerMin must be finite and > 0");
  }
  if (p.toolNumber != -1 && p.toolNumber < 1) {
    throw InvalidInput("G-code: toolNumber must be >= 1 (or -1 for the program's)");
  }
  if (p.mode == Mode::FiveAxis) planning::validateKinematics(p.kinematics);
}

/// The tool change starting at point @p i, if any (changes in order of firstPoint).
const planning::ClToolChange* changeAt(const planning::ClProgram& program, std::size_t i) {
  for (const planning::ClToolChange& c : program.toolChanges)
    if (c.firstPoint == i) return &c;
  return nullptr;
}

/// Positions of every point as written, in program order (mm, degrees): machine X Y Z from the
/// kinematics, or with tcpPositions the tip in the part frame.
std::vector<planning::MachinePose> machinePoses(const planning::ClProgram& program,
                                                const planning::Tool& tool,
                                                const GCodeWriteParams& params) {
  const std::pair<double, double> firstRadii = cutterRadii(tool);
  std::pair<double, double> radii = firstRadii;
  std::vector<planning::MachinePose> poses;
  poses.reserve(program.points.size());
  planning::MachinePose previous = params.startPose;
  std::optional<ddf::Vec3> inForce;
  for (std::size_t i = 0; i < program.points.size(); ++i) {
    const planning::ClPoint& p = program.points[i];
    if (!p.positionMm.allFinite() || !std::isfinite(p.feedMmPerMin) || p.feedMmPerMin < 0.0) {
      throw InvalidInput(pointName(program, i) + ": position or feed is not finite (or < 0)");
    }
    if (const planning::ClToolChange* change = changeAt(program, i))
      radii = radiiAt(program, change, firstRadii);
    const ddf::Vec3 axis = axisOf(program, i, params.mode, inForce);
    const ddf::Vec3 tip = tipOf(program, i, axis, radii);
    if (params.mode == Mode::ThreeAxis) {
      poses.push_back({tip, 0.0, 0.0});
      continue;
    }
    const planning::InverseKinematicsResult r =
        planning::inverseKinematics(params.kinematics, tip, axis, previous);
    if (!r.pose) throw InvalidInput(pointName(program, i) + ": " + r.reason);
    previous = *r.pose;
    poses.push_back(*r.pose);
    if (params.tcpPositions) poses.back().xyzMm = tip;
  }
  return poses;
}

}  // namespace ddfcam::io::detail
