// SPDX-License-Identifier: MIT
// ddfcam: cutter-location programs from tool paths: axes per tool kind, derived normals, lifts
// between passes, linked moves, and the grouping of a project's paths for export.
#include <ddfcam/planning/placement/cl_program_builder.h>

#include <ddfcam/ddf/surface_locator.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/model/path_regions.h>
#include <ddfcam/planning/placement/cutter_tool.h>
#include <ddfcam/planning/placement/path_sampling.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace ddfcam::planning {
namespace {

std::string poseName(int index) {
  return "pose " + std::to_string(index);
}

/// [begin, end) of pass @p pass of @p path (no passStarts: one pass of all poses).
std::pair<int, int> passRange(const ToolPath& path, int pass) {
  const int poses = static_cast<int>(path.poses.size());
  if (path.passStarts.empty()) return {0, poses};
  const int next =
      pass + 1 < static_cast<int>(path.passStarts.size()) ? path.passStarts[pass + 1] : poses;
  return {path.passStarts[pass], next};
}

int passCount(const ToolPath& path) {
  if (path.passStarts.empty()) return path.poses.empty() ? 0 : 1;
  return static_cast<int>(path.passStarts.size());
}

void checkPasses(const ToolPath& path) {
  const int poses = static_cast<int>(path.poses.size());
  for (std::size_t i = 0; i < path.passStarts.size(); ++i) {
    const int start = path.passStarts[i];
    const bool ok = i == 0 ? start == 0 : start > path.passStarts[i - 1] && start < poses;
    if (!ok || start >= poses)
      throw InvalidInput("program of path '" + path.name + "': pass start " + std::to_string(i) +
                         " (" + std::to_string(start) + ") is not ascending within " +
                         std::to_string(poses) + " poses");
  }
}

void checkNormals(const ToolPath& path, const std::vector<ddf::Vec3>& normals) {
  if (!normals.empty() && normals.size() != path.poses.size())
    throw InvalidInput("program of path '" + path.name + "': " + std::to_string(normals.size()) +
                       " normals for " + std::to_string(path.poses.size()) + " poses");
}

ClProgram programHeader(const std::string& name, const Tool& tool, ClPointKind kind) {
  ClProgram program;
  program.partName = name;
  program.pointKind = kind;
  program.toolName = tool.name;
  program.cutter = clCutterOf(tool);
  return program;
}

ClPoint pointOf(const PathPose& pose, const ddf::Vec3& normal, const ddf::Vec3& axis,
                ClPointKind kind) {
  ClPoint point;
  point.positionMm =
      kind == ClPointKind::Contact ? pose.contact : ddf::Vec3(pose.pose.translation());
  point.axis = ddf::Vec3(pose.pose.linear() * axis);
  point.normal = normal;
  return point;
}

/// Lift direction at @p point: its normal, else its axis, else +z.
ddf::Vec3 liftDirection(const ClPoint& point) {
  if (point.normal) return *point.normal;
  if (point.axis) return *point.axis;
  return ddf::Vec3::UnitZ();
}

/// Appends retract, rapid and approach from @p last to @p first (see clProgramFromPath()).
void appendLift(ClProgram& program, const ClPoint& last, const ClPoint& first, double clearanceMm,
                double feed, int& pointIndex) {
  ClPoint retract = last;
  retract.positionMm += clearanceMm * liftDirection(last);
  retract.move = MoveKind::Link;
  retract.feedMmPerMin = feed;
  ClPoint rapid = first;
  rapid.positionMm += clearanceMm * liftDirection(first);
  rapid.move = MoveKind::Rapid;
  rapid.feedMmPerMin = 0.0;
  ClPoint approach = first;
  approach.move = MoveKind::Link;
  approach.feedMmPerMin = feed;
  for (ClPoint* p : {&retract, &rapid, &approach}) {
    p->path = first.path;
    p->point = pointIndex++;
    p->sourceLine = 0;
    program.points.push_back(*p);
  }
}

void checkClearance(const ClLinkParams& link) {
  if (!(link.clearanceMm >= 0.0) || !std::isfinite(link.clearanceMm))
    throw InvalidInput("program: clearance " + std::to_string(link.clearanceMm) +
                       " mm, expected finite and >= 0");
}

/// Appends the passes of @p path to @p program as paths pathCount().. (lift before each pass
/// when the program already has points and link.linkPasses).
void appendPath(ClProgram& program, const ToolPath& path, const Tool& tool,
                const std::vector<ddf::Vec3>& normals, const ClLinkParams& link) {
  checkPasses(path);
  checkNormals(path, normals);
  checkClearance(link);
  const ddf::Vec3 axis = spindleAxisInToolFrame(tool.kind);
  const int firstPath = program.pathCount();
  for (int pass = 0; pass < passCount(path); ++pass) {
    const auto [begin, end] = passRange(path, pass);
    int pointIndex = 0;
    for (int p = begin; p < end; ++p) {
      const PathPose& pose = path.poses[static_cast<std::size_t>(p)];
      ClPoint point =
          pointOf(pose, normals.empty() ? derivedContactNormal(pose, tool, p) : normals[p], axis,
                  program.pointKind);
      point.path = firstPath + pass;
      point.feedMmPerMin = path.feedMmPerMin;
      if (p == begin && link.linkPasses && !program.points.empty())
        appendLift(program, program.points.back(), point, link.clearanceMm, path.feedMmPerMin,
                   pointIndex);
      point.point = pointIndex++;
      program.points.push_back(point);
    }
  }
}

}  // namespace

ddf::Vec3 spindleAxisInToolFrame(ToolKind kind) {
  switch (kind) {
    case ToolKind::CylinderRoll:
    case ToolKind::Sphere:
    case ToolKind::BeltContactWheel:
      return ddf::Vec3::UnitX();
    case ToolKind::BallEnd:
    case ToolKind::FlatEnd:
    case ToolKind::TorusCutter:
      return ddf::Vec3::UnitZ();
  }
  throw InvalidInput("spindle axis: unknown tool kind " + std::to_string(static_cast<int>(kind)));
}

std::optional<ClCutter> clCutterOf(const Tool& tool) {
  switch (tool.kind) {
    case ToolKind::BallEnd:
    case ToolKind::FlatEnd:
    case ToolKind::TorusCutter:
      return aptCutter(tool);
    default:
      return std::nullopt;
  }
}

ddf::Vec3 derivedContactNormal(const PathPose& pose, const Tool& tool, int index) {
  // Direction in the tool frame from the contact to the centre of curvature of the tool
  // surface there: the surface normal on the tool side for a tool touching a smooth surface.
  const ddf::Vec3 c = pose.pose.inverse() * pose.contact;
  const double radial = std::hypot(c.x(), c.y());
  const double bottomTolerance = 1e-6 * std::max(1.0, tool.radiusMm);
  ddf::Vec3 direction = -c;
  if (tool.kind == ToolKind::BallEnd) {
    direction = ddf::Vec3(0, 0, tool.radiusMm) - c;
  } else if (tool.kind == ToolKind::TorusCutter) {
    const double ring = tool.radiusMm - tool.edgeRadiusMm;
    direction =
        radial <= ring
            ? ddf::Vec3(ddf::Vec3::UnitZ())
            : ddf::Vec3(ddf::Vec3(ring * c.x() / radial, ring * c.y() / radial, tool.edgeRadiusMm) -
                        c);
  } else if (tool.kind == ToolKind::FlatEnd) {
    direction = std::abs(c.z()) <= bottomTolerance ? ddf::Vec3(ddf::Vec3::UnitZ())
                                                   : ddf::Vec3(-c.x(), -c.y(), 0.0);
  }
  const double length = direction.norm();
  if (!(length > 1e-12) || !std::isfinite(length))
    throw InvalidInput("program: " + poseName(index) +
                       ": the surface normal cannot be derived from the tool's geometry (contact "
                       "at the tool's centre or axis); pass the normals explicitly");
  return pose.pose.linear() * (direction / length);
}

void appendClProgram(ClProgram& program, const ClProgram& more, const ClLinkParams& link) {
  checkClearance(link);
  const int firstPath = program.pathCount();
  program.points.reserve(program.points.size() + more.points.size() + 3);
  int pointIndex = 0;
  for (std::size_t i = 0; i < more.points.size(); ++i) {
    ClPoint point = more.points[i];
    point.path += firstPath;
    const bool newPath = i == 0 || more.points[i - 1].path != more.points[i].path;
    if (newPath) pointIndex = 0;
    if (i == 0 && link.linkPasses && !program.points.empty())
      appendLift(program, program.points.back(), point, link.clearanceMm,
                 point.move == MoveKind::Rapid ? 0.0 : point.feedMmPerMin, pointIndex);
    point.point = pointIndex++;
    program.points.push_back(point);
  }
}

ClProgram clProgramFromPath(const ToolPath& path, const Tool& tool, ClPointKind kind,
                            const std::vector<ddf::Vec3>& normals, const ClLinkParams& link) {
  ClProgram program = programHeader(path.name, tool, kind);
  program.points.reserve(path.poses.size() + 3 * path.passStarts.size());
  appendPath(program, path, tool, normals, link);
  return program;
}

namespace {

/// Appends the points of Cut move @p move (index @p m) from the poses of its pass; returns the
/// index of its last pose.
int appendCut(ClProgram& program, const PathMove& move, int m, const ToolPath& path,
              const Tool& tool, const std::vector<ddf::Vec3>& normals) {
  const std::string item = "program: cut move " + std::to_string(m);
  if (move.path < 0 || move.path >= passCount(path))
    throw InvalidInput(item + " refers to pass " + std::to_string(move.path) + " of " +
                       std::to_string(passCount(path)));
  const auto [begin, end] = passRange(path, move.path);
  if (static_cast<int>(move.points.size()) != end - begin)
    throw InvalidInput(item + ": " + std::to_string(move.points.size()) + " points, pass " +
                       std::to_string(move.path) + " has " + std::to_string(end - begin) +
                       " poses");
  const ddf::Vec3 axis = spindleAxisInToolFrame(tool.kind);
  int index = begin;
  for (int i = 0; i < end - begin; ++i) {
    index = move.reversed ? end - 1 - i : begin + i;
    const PathPose& pose = path.poses[static_cast<std::size_t>(index)];
    if ((pose.contact - move.points[static_cast<std::size_t>(i)]).norm() > 1e-9)
      throw InvalidInput(item + ": point " + std::to_string(i) + " is not the contact of its pose");
    ClPoint point =
        pointOf(pose, normals.empty() ? derivedContactNormal(pose, tool, index) : normals[index],
                axis, program.pointKind);
    point.path = m;
    point.point = i;
    point.feedMmPerMin = path.feedMmPerMin;
    program.points.push_back(point);
  }
  return index;
}

void appendIdle(ClProgram& program, const PathMove& move, int m, const ClPoint& from,
                const ddf::Vec3& offset, double feed) {
  for (std::size_t i = 0; i < move.points.size(); ++i) {
    ClPoint point = from;
    point.path = m;
    point.point = static_cast<int>(i);
    point.positionMm = move.points[i] + offset;
    point.feedMmPerMin = move.kind == MoveKind::Rapid ? 0.0 : feed;
    point.move = move.kind;
    program.points.push_back(point);
  }
}

}  // namespace

ClProgram clProgramFromLinked(const LinkedPaths& linked, const ToolPath& path, const Tool& tool,
                              ClPointKind kind, const std::vector<ddf::Vec3>& normals) {
  checkPasses(path);
  checkNormals(path, normals);
  ClProgram program = programHeader(path.name, tool, kind);
  int lastPose = -1;
  ClPoint lastCut;
  for (std::size_t m = 0; m < linked.moves.size(); ++m) {
    const PathMove& move = linked.moves[m];
    if (move.kind == MoveKind::Cut) {
      lastPose = appendCut(program, move, static_cast<int>(m), path, tool, normals);
      lastCut = program.points.back();
      continue;
    }
    if (lastPose < 0) throw InvalidInput("program: move 0 is not a cut");
    const PathPose& pose = path.poses[static_cast<std::size_t>(lastPose)];
    const ddf::Vec3 offset = kind == ClPointKind::Contact
                                 ? ddf::Vec3::Zero()
                                 : ddf::Vec3(pose.pose.translation() - pose.contact);
    appendIdle(program, move, static_cast<int>(m), lastCut, offset, path.feedMmPerMin);
  }
  return program;
}

}  // namespace ddfcam::planning
